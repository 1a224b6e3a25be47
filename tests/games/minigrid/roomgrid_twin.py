"""Shared checks for the room-grid families' tests (KeyCorridor, LockedRoom, Unlock,
UnlockPickup, BlockedUnlockPickup): our task beside its MiniGrid twin, seed for seed and action
for action, with the state and view comparisons of test_minigrid_fidelity."""

from __future__ import annotations

import numpy as np
import pytest

import glyphbench_rl
from glyphbench_rl.games.minigrid import solver

from test_minigrid_fidelity import same_state, same_view, step_both  # noqa: F401

SEEDS = (0, 1, 2, 3, 1_000_000)


def make(name: str):
    return glyphbench_rl.make(f"glyphbench/minigrid-{name}-v0")


def same_levels(name: str, env, seeds=SEEDS) -> None:
    """Same grid, agent, facing and mission as MiniGrid for every seed; same horizon."""
    task = make(name)
    assert task.max_turns == env.max_steps
    for seed in seeds:
        task.reset(seed=seed)
        env.reset(seed=seed)
        same_state(task, env)
        assert task.mission == env.mission


def record(name: str, seed: int, script=solver.solve) -> tuple[object, list[int]]:
    """Play ``script(task)`` on a fresh episode; the task and the actions it took."""
    task = make(name)
    task.reset(seed=seed)
    actions: list[int] = []
    step = task.step
    task.step = lambda a: (actions.append(a), step(a))[1]
    script(task)
    return task, actions


def mirror(name: str, env, seed: int, actions) -> object:
    """Feed ``actions`` to both from ``seed``, comparing every step; our task afterwards."""
    task = make(name)
    task.reset(seed=seed)
    env.reset(seed=seed)
    same_view(task, env)
    for action in actions:
        step_both(task, env, action)
        if task.done:
            break
    return task


def random_then_solver(name: str, env, seed: int = 1_000_001) -> None:
    """Random actions on one episode, then the solver's win path on another, fed to both."""
    rng = np.random.default_rng(7)
    mirror(name, env, 3, [int(a) for a in rng.integers(7, size=60)])
    probe, actions = record(name, seed)
    assert probe.won
    task = mirror(name, env, seed, actions)
    assert task.won and env.step_count == task.turn


def solver_wins(name: str, seeds=range(8)) -> None:
    task = make(name)
    for seed in seeds:
        task.reset(seed=seed)
        solver.solve(task)
        assert task.won, (name, seed)
        assert task.episode_return == pytest.approx(1 - 0.9 * task.turn / task.max_turns)


def time_out_gives_nothing(name: str) -> None:
    task = make(name)
    task.reset(seed=0)
    while not task.done:
        task.step(0)           # TURN_LEFT
    assert task._truncated and not task._terminated and task.turn == task.max_turns
    assert task.episode_return == 0 and not task.won
