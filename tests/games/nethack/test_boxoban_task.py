"""The three Boxoban tasks on NetHack: our generated level is the one played, the solver's moves
win with a return of exactly 1, shaping pays per boulder, and each seed has its own level."""

from __future__ import annotations

import pytest

import glyphbench_rl
from glyphbench_rl.games.nethack import boxoban


@pytest.mark.parametrize("difficulty", boxoban.DIFFICULTIES)
def test_solver_moves_win_with_return_one(difficulty):
    task = glyphbench_rl.make(f"glyphbench/minihack-boxoban-{difficulty}-v0")
    task.reset(seed=3)
    level = task.env._level
    lo, hi = boxoban.PUSHES[difficulty]
    grid = task.frame.grid
    assert sum(row.count("`") for row in grid) == boxoban.BOXES        # boulders drawn as NetHack does
    rewards = []
    for move in boxoban.solve(level):
        _, r, term, trunc, info = task.step("MOVE_" + move)
        rewards.append(r)
    assert term and info["won"] is True and not trunc
    assert task.episode_return == pytest.approx(1.0)
    assert rewards[-1] == pytest.approx(0.7)
    assert rewards.count(0.1) >= boxoban.BOXES - 1


def test_each_seed_its_own_level_and_the_same_level_again():
    task = glyphbench_rl.make("glyphbench/minihack-boxoban-unfiltered-v0")
    seen = []
    for seed in (0, 1, 0):
        task.reset(seed=seed)
        seen.append((task.env._level.text, task.frame.grid))
    assert seen[0] == seen[2] and seen[0][0] != seen[1][0]


def test_only_straight_moves_and_no_way_to_lose():
    task = glyphbench_rl.make("glyphbench/minihack-boxoban-hard-v0")
    assert task.actions.names == ("MOVE_N", "MOVE_S", "MOVE_E", "MOVE_W")
    task.reset(seed=1)
    while not task.done:                          # walking into walls until the horizon
        task.step("MOVE_N")
    assert task._truncated and task.episode_return == 0.0 and task.won is None
