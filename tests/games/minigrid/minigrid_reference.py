"""Side-by-side play of our MiniGrid tasks and Farama's envs, for the mission families' fidelity
tests (Memory, Fetch, GoToDoor, GoToObject, PutNear, RedBlueDoors); built on the cell-for-cell
checks of ``test_minigrid_fidelity``. Import after ``pytest.importorskip("minigrid.envs")``."""

from __future__ import annotations

import numpy as np
import pytest

import glyphbench_rl
from glyphbench_rl.games.minigrid import solver
from test_minigrid_fidelity import same_state, same_view, step_both

SEEDS = (0, 1, 2, 3, 1_000_000, 1_000_001)


def check_levels(name: str, env, seeds=SEEDS) -> None:
    """Same level, agent and mission as MiniGrid for every seed, and the same horizon."""
    task = glyphbench_rl.make(f"glyphbench/minigrid-{name}-v0")
    assert env.max_steps == task.max_turns
    for seed in seeds:
        task.reset(seed=seed)
        env.reset(seed=seed)
        same_state(task, env)
        same_view(task, env)
        assert task.mission == env.mission


def play_both(name: str, env, seed: int, actions) -> tuple:
    """Feed ``actions`` to both (until the episode ends), comparing after every step."""
    task = glyphbench_rl.make(f"glyphbench/minigrid-{name}-v0")
    task.reset(seed=seed)
    env.reset(seed=seed)
    for action in actions:
        if task.done:
            break
        step_both(task, env, action)
    return task, env


def random_actions(seed: int, n: int = 60, actions: int = 7) -> list[int]:
    return [int(a) for a in np.random.default_rng(seed).integers(actions, size=n)]


def solver_actions(name: str, seed: int) -> list[int]:
    """The actions our solver plays to win the episode of ``seed``."""
    task = glyphbench_rl.make(f"glyphbench/minigrid-{name}-v0")
    task.reset(seed=seed)
    actions: list[int] = []
    step = task.step
    task.step = lambda a: (actions.append(a), step(a))[1]
    solver.solve(task)
    assert task.won, (name, seed)
    return actions


def check_episodes(name: str, make_env, seeds=SEEDS) -> None:
    """Random actions, then the solver's winning actions, give the same episode in both."""
    env = make_env()
    for seed in seeds:
        task, env = play_both(name, env, seed, random_actions(seed))
        task, env = play_both(name, env, seed, solver_actions(name, seed))
        assert task.won and env.step_count == task.turn
        assert task.episode_return == pytest.approx(1 - 0.9 * task.turn / task.max_turns)
