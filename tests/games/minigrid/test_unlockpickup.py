"""UnlockPickup against MiniGrid's UnlockPickupEnv: same levels, same episodes, solver wins;
picking up the key does not end the episode, and a box opened with TOGGLE is gone for good."""

from __future__ import annotations

import os

import pytest

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
pytest.importorskip("minigrid.envs")
from minigrid.envs import UnlockPickupEnv  # noqa: E402

from glyphbench_rl.games.minigrid import solver  # noqa: E402
from glyphbench_rl.games.minigrid.engine import PICKUP, TOGGLE  # noqa: E402

import roomgrid_twin as twin  # noqa: E402

NAME = "unlockpickup"


def test_same_level_as_minigrid():
    twin.same_levels(NAME, UnlockPickupEnv())


def test_same_actions_same_episode_and_view():
    twin.random_then_solver(NAME, UnlockPickupEnv())


def test_solver_wins():
    twin.solver_wins(NAME)


def test_layout():
    task = twin.make(NAME)
    for seed in range(6):
        task.reset(seed=seed)
        assert task.obj.kind == "box" and task.obj.pos[0] > 5 and task.mission == f"pick up the {task.obj.name}"
        (door,) = solver.find(task, "door")
        assert task.grid.get(*door).is_locked and door[0] == 5
        assert solver.find(task, "key", task.grid.get(*door).color)[0][0] < 5


def test_key_pickup_does_not_end_and_an_opened_box_is_lost():
    def script(task):
        key = solver.find(task, "key")[0]
        solver.run(task, solver.plan(task, key, face=True) + [PICKUP])
        assert task.carrying.kind == "key" and not task.done
        solver.run(task, solver.plan(task, task.obj.pos, face=True) + [TOGGLE])   # opens the box
    probe, actions = twin.record(NAME, 2, script)
    task = twin.mirror(NAME, UnlockPickupEnv(), 2, actions)       # MiniGrid agrees step by step
    assert not task.done and not solver.find(task, "box")
    assert "held nothing" in task.frame.message
    while not task.done:
        task.step(PICKUP)
    assert task._truncated and task.episode_return == 0 and not task.won


def test_time_out_gives_nothing():
    twin.time_out_gives_nothing(NAME)
