"""The arcade step's shortcuts give what the plain computations give: the blocked draws, the
row memo (on or off) and the grids that skip bounds tests."""

from __future__ import annotations

import copy
import pickle

import numpy as np
import pytest

from glyphbench_rl import list_tasks, make
from glyphbench_rl.games.arcade.engine import NONE_DRAWN
from glyphbench_rl.games.common.lanes import Draws

MEMO_GRIDS = ("alien", "bankheist", "mspacman", "riverraid", "upndown", "kangaroo", "asterix",
              "stargunner", "choppercommand", "defender", "qbert", "spaceinvaders", "icehockey",
              "zaxxon")


def test_draws_are_the_stream_in_order_and_a_copy_goes_on_alike():
    plain = np.random.default_rng(5).random(1000).tolist()
    draws = Draws(np.random.default_rng(5), 64)
    assert [draws.random() for _ in range(100)] == plain[:100]     # (across block ends)
    twin, thawed = copy.deepcopy(draws), pickle.loads(pickle.dumps(draws))
    assert [twin.random() for _ in range(300)] == plain[100:400]   # (the copy alone moves)
    assert [draws.random() for _ in range(300)] == plain[100:400]
    assert [thawed.random() for _ in range(300)] == plain[100:400]
    assert draws.below(10) == int(plain[400] * 10)


def _play(task_id: str, seed: int, steps: int = 300):
    task = make(task_id)
    task.reset(seed=seed)
    pick = np.random.default_rng(seed)
    for _ in range(steps):
        if task.done:
            return
        task.step(int(pick.integers(task.action_space.n)))
        yield task


@pytest.mark.parametrize("game", MEMO_GRIDS)
def test_grids_drawn_through_the_row_memo_match_those_drawn_afresh(game):
    for seed in (0, 1):
        for task in _play(f"glyphbench/miniatari-{game}-v0", seed):
            remembered, drawn = task._grid(), task._drawn
            task._drawn = NONE_DRAWN
            assert task._grid() == remembered
            task._drawn = drawn


INSIDE = sorted({t for t in list_tasks() if "atari-" in t and make(t).inside})


def test_some_games_draw_without_bounds_tests():
    assert {"glyphbench/miniatari-icehockey-v0", "glyphbench/miniatari-pong-v0"} <= set(INSIDE)


@pytest.mark.parametrize("task_id", INSIDE)
def test_a_game_marked_inside_keeps_every_sprite_inside_its_rows(task_id):
    for seed in (0, 1, 2):
        for task in _play(task_id, seed):
            rows = task._rows()
            for r, c, _ in task._sprites():
                assert 0 <= r < len(rows) and 0 <= c < len(rows[r]), (task.turn, r, c)
