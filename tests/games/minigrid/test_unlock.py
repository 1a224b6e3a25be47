"""Unlock against MiniGrid's UnlockEnv: same levels, same episodes, solver wins; only the
TOGGLE that opens the door ends the episode (picking up the key does not)."""

from __future__ import annotations

import os

import pytest

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
pytest.importorskip("minigrid.envs")
from minigrid.envs import UnlockEnv  # noqa: E402

from glyphbench_rl.games.minigrid import solver  # noqa: E402
from glyphbench_rl.games.minigrid.engine import PICKUP, TOGGLE  # noqa: E402

import roomgrid_twin as twin  # noqa: E402

NAME = "unlock"


def test_same_level_as_minigrid():
    twin.same_levels(NAME, UnlockEnv())


def test_same_actions_same_episode_and_view():
    twin.random_then_solver(NAME, UnlockEnv())


def test_solver_wins():
    twin.solver_wins(NAME)


def test_layout():
    task = twin.make(NAME)
    for seed in range(6):
        task.reset(seed=seed)
        assert task.grid.width == 11 and task.grid.height == 6 and task.mission == "open the door"
        assert task.door.is_locked and task.door.pos[0] == 5
        (key,) = solver.find(task, "key")
        assert task.grid.get(*key).color == task.door.color and key[0] < 5 and task.agent_pos[0] < 5


def test_key_pickup_and_toggle_without_key_do_not_end():
    def script(task):
        solver.run(task, solver.plan(task, task.door.pos, face=True) + [TOGGLE])   # locked: nothing
        assert task.door.is_locked and not task.done
        key = solver.find(task, "key")[0]
        solver.run(task, solver.plan(task, key, face=True) + [PICKUP])
        assert task.carrying is not None and not task.done
    probe, actions = twin.record(NAME, 5, script)
    task = twin.mirror(NAME, UnlockEnv(), 5, actions)
    assert not task.done and task.episode_return == 0
    solver.solve(task)
    assert task.won


def test_time_out_gives_nothing():
    twin.time_out_gives_nothing(NAME)
