"""Memory (MiniGrid MemoryEnv): same levels and episodes as MiniGrid, wins, and the wrong object."""

from __future__ import annotations

import os

import pytest

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
E = pytest.importorskip("minigrid.envs")

import glyphbench_rl  # noqa: E402
from glyphbench_rl.games.minigrid import solver  # noqa: E402
from glyphbench_rl.games.minigrid.engine import LEFT, PICKUP  # noqa: E402
from minigrid_reference import check_episodes, check_levels, play_both  # noqa: E402

SIZES = (7, 9, 11, 13, 17)


@pytest.mark.parametrize("n", SIZES)
def test_same_levels_and_episodes_as_minigrid(n):
    make = lambda: E.MemoryEnv(size=n, max_steps=min(5 * n * n, 512))  # noqa: E731
    check_levels(f"memory-s{n}", make())
    check_episodes(f"memory-s{n}", make, seeds=(0, 1, 1_000_000))


@pytest.mark.parametrize("n", SIZES)
def test_going_to_the_other_object_fails(n):
    task = glyphbench_rl.make(f"glyphbench/minigrid-memory-s{n}-v0")
    for seed in range(4):
        task.reset(seed=seed)
        actions = solver.plan(task, task.failure_pos)
        env = E.MemoryEnv(size=n, max_steps=task.max_turns)
        task, env = play_both(f"memory-s{n}", env, seed, actions)
        assert task.done and task.won is False and task.episode_return == 0
        assert task.agent_pos == task.failure_pos and "does not match" in task.frame.message


def seen(task) -> set:
    """World cells the agent sees now."""
    mask = task.grid.view_mask(task.agent_pos, task.agent_dir)
    return {task.grid.view_cell(task.agent_pos, task.agent_dir, vx, vy)
            for vx in range(7) for vy in range(7) if mask[vx][vy]}


@pytest.mark.parametrize("n", (13, 17))
def test_cue_is_seen_from_the_start_room_only(n):
    """(In the short levels, s7 and s9, the split is close enough to see the start room.)"""
    task = glyphbench_rl.make(f"glyphbench/minigrid-memory-s{n}-v0")
    for seed in range(6):
        task.reset(seed=seed)
        task.step(LEFT)                                    # face north
        assert (task.cue.pos in seen(task)) == (task.agent_pos[0] <= 4)
        solver.run(task, solver.plan(task, (n - 2, n // 2)))
        for _ in range(4):                                 # at the split, looking every way
            assert task.cue.pos not in seen(task)
            task.step(LEFT)


def test_pickup_acts_as_toggle_and_carries_nothing():
    task = glyphbench_rl.make("glyphbench/minigrid-memory-s7-v0")
    task.reset(seed=0)
    cue = task.cue.pos
    solver.run(task, solver.plan(task, cue, face=True))
    task.step(PICKUP)
    assert task.carrying is None and task.grid.get(*cue) is task.cue and not task.done
