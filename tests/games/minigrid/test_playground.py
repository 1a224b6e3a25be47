"""Playground against MiniGrid's PlaygroundEnv (MiniGrid-Playground-v0): same levels, whole
episodes of the same actions give the same states, views and zero rewards; nothing ends the
episode before the horizon; every room can be reached (the clearing solver opens every door)."""

from __future__ import annotations

import os

import numpy as np
import pytest

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
pytest.importorskip("minigrid.envs")
from minigrid.envs import PlaygroundEnv  # noqa: E402

from glyphbench_rl.games.minigrid import playground, solver  # noqa: E402, F401
from glyphbench_rl.games.minigrid.engine import DONE, PICKUP, TOGGLE  # noqa: E402

import roomgrid_twin as twin  # noqa: E402

NAME = "playground"


def test_same_level_as_minigrid():
    twin.same_levels(NAME, PlaygroundEnv(), seeds=range(12))


@pytest.mark.parametrize("seed", [3, 1_000_001])
def test_a_whole_episode_of_random_actions_is_minigrids(seed):
    """100 random actions: same states and views every step, reward 0, truncated at 100 in both."""
    env = PlaygroundEnv()
    actions = [int(a) for a in np.random.default_rng(seed).integers(7, size=100)]
    task = twin.mirror(NAME, env, seed, actions)
    assert task.turn == env.step_count == 100 and task._truncated and not task._terminated
    assert task.episode_return == 0 and not task.won


def test_every_room_can_be_reached_and_nothing_ends_the_episode():
    task = playground.Playground(max_turns=500)          # time enough to open all twelve doors
    for seed in range(4):
        task.reset(seed=seed)
        doors = solver.find(task, "door")
        things = [o for o in task.grid.objects() if o.kind in ("key", "ball", "box")]
        assert len(doors) == 12 and len(things) == 12
        for pos in doors:
            if not task.grid.get(*pos).is_open:
                assert solver.reach(task, pos), (seed, pos)
                task.step(TOGGLE)
        assert not task.done and all(task.grid.get(*d).is_open for d in doors)
        assert task.episode_return == 0


def test_pickup_toggle_and_done_do_not_end_the_episode():
    task = twin.make(NAME)
    task.reset(seed=1)
    box = next((o for o in task.grid.objects() if o.kind == "box"), None)
    thing = next(o for o in task.grid.objects() if o.kind in ("key", "ball"))
    assert solver.pick_up(task, thing) and not task.done
    task.step(DONE)
    if box is not None:
        solver.reach(task, box.pos)
        task.step(TOGGLE)
    task.step(PICKUP)
    assert not task.done and task.episode_return == 0 and task.frame.hud.startswith("Step")


def test_time_out_gives_nothing():
    twin.time_out_gives_nothing(NAME)
    task = twin.make(NAME)
    task.reset(seed=0)
    assert "Mission: none" in task.frame.render() and task.mission == ""
