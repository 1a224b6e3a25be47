"""What issue 16 asks of every Procgen game, checked on every registered one."""

import numpy as np
import pytest

import glyphbench_rl
from glyphbench_rl.core import get_spec

PROCGEN = sorted(t for t in glyphbench_rl.list_tasks() if t.startswith("glyphbench/procgen-"))


def level_key(task):
    """The world, what is drawn on it and what moves, right after reset."""
    return (tuple(task._rows()), tuple(sorted(task._sprites())), tuple(sorted(task._movers())))


def test_the_family_is_registered_as_procgen():
    assert PROCGEN and all(get_spec(t).suite == "Procgen" for t in PROCGEN)


@pytest.mark.parametrize("task_id", PROCGEN)
def test_fifty_seeds_give_forty_five_distinct_levels(task_id):
    task = glyphbench_rl.make(task_id)
    keys = set()
    for seed in range(50):
        task.reset(seed=seed)
        keys.add(level_key(task))
    assert len(keys) >= 45


@pytest.mark.parametrize("task_id", PROCGEN)
def test_horizon_view_and_return_bounds_under_random_play(task_id):
    task = glyphbench_rl.make(task_id)
    assert task.max_turns <= 512
    rng = np.random.default_rng(0)
    for seed in range(6):
        obs, _ = task.reset(seed=100 + seed)
        grid = obs.split("\n")[1:1 + task.view_h]
        assert len(grid) <= task.view_h and all(len(row) <= task.view_w for row in grid)
        done = False
        while not done:
            _, reward, term, trunc, _ = task.step(int(rng.integers(task.action_space.n)))
            assert -1.0 <= reward <= 1.0
            done = term or trunc
        assert -1.0 - 1e-9 <= task.episode_return <= 1.0 + 1e-9
