"""The step's shortcuts give what the plain rules give: the tally's kill count (the kernel's
counts), the boss rule skipped off the boss level, and scenario tests that
compare a counter as it is rather than as a float."""

import copy

import numpy as np
import pytest

from glyphbench_rl import make
from glyphbench_rl.games.common.lanes import Draws
from glyphbench_rl.games.craftax import mobs, rules, scenarios, worldgen
from glyphbench_rl.games.craftax.packed import DRAW_AT
from glyphbench_rl.games.craftax.bestiary import MOB_NAMES
from glyphbench_rl.games.craftax.state import Settings
from glyphbench_rl.games.craftax.tables import BOSS_LEVEL, Action

# a fighter's actions: mostly strikes, some steps, arrows and fireballs
FIGHTING = [int(Action.DO)] * 6 + [int(a) for a in (Action.LEFT, Action.RIGHT, Action.UP,
                                                    Action.DOWN, Action.SHOOT_ARROW,
                                                    Action.CAST_FIREBALL)]

GROUPS = ("passive_mobs", "melee_mobs", "ranged_mobs")


def _live(state, level):
    """The plain snapshot: (class, slot, type) of every live mob of ``level``."""
    return [(k, i, getattr(state, g).type_id[level][i])
            for k, g in enumerate(GROUPS) for i, alive in enumerate(getattr(state, g).mask[level])
            if alive]


@pytest.mark.parametrize("task_id", ["glyphbench/craftax-fight-zombies-v0",
                                     "glyphbench/craftax-fight-cow-v0",
                                     "glyphbench/craftax-bow-kite-v0",
                                     "glyphbench/craftax-fight-archers-v0"])
def test_kills_counted_as_by_looking_at_every_live_slot(task_id):
    """The kills the tally counts (the kernel's kill counts) are those of the plain rule: a slot
    live before the step whose mob is gone with no health left after the mobs moved, found by
    playing the reference step on a copy of the state with the same draws."""
    task = make(task_id)
    total = 0
    for seed in range(4):
        task.reset(seed=seed)
        rng = np.random.default_rng(seed)
        plain: dict[str, int] = {}
        while not task.done:
            state = copy.deepcopy(task.state)
            p = task.packed
            task.kernel_draws.top_up(p)
            draws = Draws(copy.deepcopy(task.kernel_draws.stream),
                          first=p.draws[p.ints[DRAW_AT]:].tolist())
            level, live = state.player_level, _live(state, state.player_level)

            def after_mobs(s, level=level, live=live):
                for k, i, type_id in live:
                    group = getattr(s, GROUPS[k])
                    if not group.mask[level][i] and group.health[level][i] <= 0:
                        name = MOB_NAMES[k][type_id]
                        plain[name] = plain.get(name, 0) + 1
            action = FIGHTING[int(rng.integers(len(FIGHTING)))]
            rules.step(state, action, task.settings, draws, after_mobs=after_mobs)
            task.step(action)
        counted = {k: v for k, v in task.tally.kills.items() if k not in ("all", "monsters")}
        assert counted == plain
        assert task.tally.kills["all"] == sum(plain.values())
        total += task.tally.kills["all"]
    assert total > 0          # (the episodes did kill something)


def test_boss_rule_does_nothing_off_the_boss_level_before_the_boss_is_beaten():
    rng = np.random.default_rng(3)
    state = worldgen.generate(rng, Settings())
    for _ in range(200):
        state.player_level = int(rng.integers(0, BOSS_LEVEL))
        state.boss_progress = int(rng.integers(0, BOSS_LEVEL))
        state.boss_timesteps_to_spawn_this_round = int(rng.integers(-5, 5))
        before = state.copy()
        mobs.boss_logic(state)
        assert state.achievements.tobytes() == before.achievements.tobytes()
        assert state.boss_timesteps_to_spawn_this_round == before.boss_timesteps_to_spawn_this_round
        assert state.boss_progress == before.boss_progress


class _Counters:
    def __init__(self, values):
        self.values = values

    def getter(self, key):
        return lambda t: t.values[key]


@pytest.mark.parametrize("op", [">=", "<=", "==", ">", "<"])
def test_scenario_tests_compare_counters_as_floats_would(op):
    import operator
    as_float = {">=": operator.ge, "<=": operator.le, "==": operator.eq, ">": operator.gt,
                "<": operator.lt}[op]
    rng = np.random.default_rng(1)
    for _ in range(300):
        a = int(rng.integers(-3, 12)) if rng.random() < 0.7 else float(rng.integers(-6, 24)) / 2
        b = int(rng.integers(-3, 12)) if rng.random() < 0.7 else float(rng.integers(-6, 24)) / 2
        limit = float(rng.integers(-3, 12)) / (2 if rng.random() < 0.3 else 1)
        tally = _Counters({"x": a, "y": b})
        one = scenarios.parse_test(f"x {op} {limit:g}", tally)
        both = scenarios.parse_test(f"x {op} {limit:g} and y >= 2", tally)
        assert one(tally) is as_float(float(a), float(f"{limit:g}"))
        assert both(tally) == (as_float(float(a), float(f"{limit:g}")) and float(b) >= 2)
