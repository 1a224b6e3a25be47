"""glyphbench/craftaxfull-v0: upstream's world and reward, the episode ending only in death or
at the turn cap, and a scripted player that earns achievements."""

from __future__ import annotations

import numpy as np
import pytest

from glyphbench_rl.core import registry
from glyphbench_rl.games.craftax.planner import Planner
from glyphbench_rl.games.craftax.tables import ACHIEVEMENT_REWARD, Achievement
from glyphbench_rl.games.craftax.tables import Action as A
from glyphbench_rl.games.craftax.tables import BlockType as B

FULL = "glyphbench/craftaxfull-v0"


def start(seed: int):
    task = registry.make(FULL)
    task.reset(seed=seed)
    return task


def upstream_return(task, health0: float) -> float:
    """Upstream's reward summed: the weights of the achievements had, and a tenth of the health
    gained since the start."""
    had = task.state.achievements
    return float(np.asarray(ACHIEVEMENT_REWARD)[had].sum()) + 0.1 * (task.state.player_health - health0)


def test_registered_extended_with_upstreams_action_set_and_nine_floors():
    spec = registry.get_spec(FULL)
    assert spec.tier == "extended" and spec.suite == "FullCraftax" and spec.max_turns == 10_000
    task = start(0)
    assert task.action_space.n == 43 and task.actions.names[0] == "NOOP"
    assert task.state.map.shape == (9, 48, 48) and task.state.player_level == 0
    assert "Achievements 0/67" in task.frame.hud
    prompt = task.system_prompt()
    assert "+8 each very advanced one (9)" in prompt and "defeat necromancer" in prompt
    assert "orc soldier" in prompt and sum(1 for a in Achievement) == 67


@pytest.mark.parametrize("seed", [0, 1])
def test_scripted_player_earns_achievements_paid_as_upstream_pays_them(seed):
    task = start(seed)
    health0 = task.state.player_health
    p = Planner(task, budget=1500)
    p.gather(B.TREE, lambda: p.state.inventory.wood >= 6, dig=False)
    p.table()
    p.craft(A.MAKE_WOOD_PICKAXE)
    p.craft(A.MAKE_WOOD_SWORD)
    p.gather(B.STONE, lambda: p.state.inventory.stone >= 2)
    p.table()
    p.craft(A.MAKE_STONE_PICKAXE)
    had = {Achievement(i).name for i in np.flatnonzero(task.state.achievements)}
    assert {"COLLECT_WOOD", "PLACE_TABLE", "MAKE_WOOD_PICKAXE", "MAKE_WOOD_SWORD", "COLLECT_STONE",
            "MAKE_STONE_PICKAXE"} <= had
    assert task.episode_return == pytest.approx(upstream_return(task, health0))
    assert task.episode_return >= 6 and not task.done
    assert f"Achievements {len(had)}/67" in task.frame.hud


def test_death_ends_the_episode_lost_and_the_return_is_not_clamped():
    task = start(2)
    health0 = task.state.player_health
    task.state.player_health = 1.0           # one hit from death: idle until it comes
    total, done, turns = 0.0, False, 0
    while not done:
        _, r, term, trunc, info = task.step(A.NOOP)
        total, done, turns = total + r, term or trunc, turns + 1
    assert term and info["won"] is False and "You died." in task.frame.message
    assert total == pytest.approx(upstream_return(task, 1.0))
    # an unclamped extended task: a long run may pay more than 1
    task = start(0)
    p = Planner(task, budget=400)
    p.gather(B.TREE, lambda: p.state.inventory.wood >= 4, dig=False)
    p.table()
    p.craft(A.MAKE_WOOD_PICKAXE)
    assert task.episode_return > 1 and not info["clamped"]
    assert health0 == 9
