"""RedBlueDoors (MiniGrid RedBlueDoorEnv): same levels and episodes as MiniGrid, wins, and the
ways to lose (blue first, red closed again before blue)."""

from __future__ import annotations

import os

import pytest

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
E = pytest.importorskip("minigrid.envs")

import glyphbench_rl  # noqa: E402
from glyphbench_rl.games.minigrid import solver  # noqa: E402
from glyphbench_rl.games.minigrid.engine import TOGGLE  # noqa: E402
from minigrid_reference import check_episodes, check_levels, play_both  # noqa: E402

SIZES = (6, 8)


def make(n):
    return E.RedBlueDoorEnv(size=n, max_steps=512)


@pytest.mark.parametrize("n", SIZES)
def test_same_levels_and_episodes_as_minigrid(n):
    check_levels(f"redbluedoors-{n}x{n}", make(n))
    check_episodes(f"redbluedoors-{n}x{n}", lambda: make(n))


@pytest.mark.parametrize("n", SIZES)
def test_level_layout(n):
    task = glyphbench_rl.make(f"glyphbench/minigrid-redbluedoors-{n}x{n}-v0")
    for seed in range(10):
        task.reset(seed=seed)
        assert (task.grid.width, task.grid.height) == (2 * n, n)
        assert task.red_door.pos[0] == n // 2 and task.blue_door.pos[0] == n // 2 + n - 1
        assert n // 2 < task.agent_pos[0] < n // 2 + n - 1
        assert not task.red_door.is_open and not task.blue_door.is_open


@pytest.mark.parametrize("n", SIZES)
def test_opening_blue_first_fails(n):
    for seed in range(3):
        task = glyphbench_rl.make(f"glyphbench/minigrid-redbluedoors-{n}x{n}-v0")
        task.reset(seed=seed)
        path = solver.plan(task, task.blue_door.pos, face=True) + [TOGGLE]
        task, _ = play_both(f"redbluedoors-{n}x{n}", make(n), seed, path)
        assert task.done and task.won is False and task.episode_return == 0
        assert task.blue_door.is_open and "before the red" in task.frame.message


def test_closing_red_again_before_blue_fails():
    task = glyphbench_rl.make("glyphbench/minigrid-redbluedoors-6x6-v0")
    task.reset(seed=4)
    path = solver.plan(task, task.red_door.pos, face=True) + [TOGGLE, TOGGLE]   # open, close
    solver.run(task, path)
    assert not task.done and not task.red_door.is_open
    path += solver.plan(task, task.blue_door.pos, face=True) + [TOGGLE]
    task, _ = play_both("redbluedoors-6x6", make(6), 4, path)
    assert task.done and task.won is False and task.episode_return == 0
