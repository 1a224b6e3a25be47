"""BlockedUnlockPickup against MiniGrid's BlockedUnlockPickupEnv: same levels, same episodes,
solver wins; picking up the ball or the key does not end the episode; the horizon is 512
(MiniGrid's 576 capped)."""

from __future__ import annotations

import os

import pytest

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
pytest.importorskip("minigrid.envs")
from minigrid.envs import BlockedUnlockPickupEnv  # noqa: E402

from glyphbench_rl.games.minigrid import solver  # noqa: E402
from glyphbench_rl.games.minigrid.engine import PICKUP  # noqa: E402

import roomgrid_twin as twin  # noqa: E402

NAME = "blockedunlockpickup"


def reference():
    return BlockedUnlockPickupEnv(max_steps=512)


def test_same_level_as_minigrid():
    twin.same_levels(NAME, reference())
    assert BlockedUnlockPickupEnv().max_steps == 576


def test_same_actions_same_episode_and_view():
    twin.random_then_solver(NAME, reference())


def test_solver_wins():
    twin.solver_wins(NAME)


def test_layout():
    task = twin.make(NAME)
    for seed in range(6):
        task.reset(seed=seed)
        (door,) = solver.find(task, "door")
        assert task.grid.get(*door).is_locked and task.ball.pos == (door[0] - 1, door[1])
        assert task.obj.kind == "box" and task.obj.pos[0] > 5
        assert solver.plan(task, door, face=True) is None              # the ball blocks the door


def test_ball_and_key_pickups_do_not_end():
    def script(task):
        solver.fetch(task, task.ball.pos)
        assert task.carrying is task.ball and not task.done
        solver.drop_beside(task)
        key = solver.find(task, "key")[0]
        solver.run(task, solver.plan(task, key, face=True) + [PICKUP])
        assert task.carrying.kind == "key" and not task.done
    probe, actions = twin.record(NAME, 6, script)
    task = twin.mirror(NAME, reference(), 6, actions)                 # MiniGrid agrees step by step
    assert task.carrying.kind == "key" and not task.done and task.episode_return == 0


def test_time_out_gives_nothing():
    twin.time_out_gives_nothing(NAME)
