import pytest

import glyphbench_rl
from glyphbench_rl.games.common.boards import Bits
from glyphbench_rl.games.classics.minesweeper import NUMBERS

ID = "glyphbench/classics-minesweeper-v0"


def cell(i, n=8):
    return f"{chr(65 + i % n)}{i // n + 1}"


@pytest.mark.parametrize("seed", [0, 1, 2, 1_000_000])
def test_win_path_opens_every_safe_cell(seed):
    task = glyphbench_rl.make(ID)
    task.reset(seed=seed)
    first = seed % 64
    task.step(cell(first))
    while not task.done:
        hidden_safe = Bits(8, 8).full & ~task.mines & ~task.revealed
        i = (hidden_safe & -hidden_safe).bit_length() - 1
        _, reward, term, trunc, info = task.step(cell(i))
        assert reward > 0
    assert task.won and term and not info["clamped"]
    assert task.episode_return == pytest.approx(1.0)
    assert sum(row.count("■") for row in info["frame"].grid) == 10


@pytest.mark.parametrize("first", [0, 7, 27, 63])
def test_first_reveal_is_safe_and_opens_an_area(first):
    task = glyphbench_rl.make(ID)
    for seed in range(10):
        task.reset(seed=seed)
        _, reward, term, *_ = task.step(first)
        assert not term and reward > 0
        around = Bits(8, 8).grow8(1 << first)
        assert not task.mines & around and task.revealed & around == around
        assert task.mines.bit_count() == 10


def test_counts_and_flood_follow_the_rules():
    task = glyphbench_rl.make(ID)
    task.reset(seed=3)
    task.step("D4")
    bits, grid = Bits(8, 8), task.frame.grid
    for r in range(8):
        for c in range(8):
            i = r * 8 + c
            if task.revealed >> i & 1:
                k = (bits.grow8(1 << i) & task.mines).bit_count()
                assert grid[r][c] == NUMBERS[k]
                if k == 0:   # an open empty cell opens all its neighbours
                    assert bits.grow8(1 << i) & ~task.revealed == 0
            else:
                assert grid[r][c] == "■"


@pytest.mark.parametrize("seed", [0, 5])
def test_loss_path_reveals_a_mine(seed):
    task = glyphbench_rl.make(ID)
    task.reset(seed=seed)
    task.step("E5")
    mine = (task.mines & -task.mines).bit_length() - 1
    _, reward, term, trunc, info = task.step(cell(mine))
    assert term and task.won is False and reward == -0.5
    assert -0.5 <= task.episode_return < 0
    assert sum(row.count("*") for row in info["frame"].grid) == 10
    assert "You revealed a mine." in info["frame"].message


def test_open_cell_again_does_nothing():
    task = glyphbench_rl.make(ID)
    task.reset(seed=0)
    task.step("A1")
    grid = task.frame.grid
    _, reward, *_ = task.step("A1")
    assert reward == 0.0 and task.frame.grid == grid and "already open" in task.frame.message


def test_bad_params():
    with pytest.raises(ValueError, match="size"):
        glyphbench_rl.make(ID, size=3)
    with pytest.raises(ValueError, match="mines"):
        glyphbench_rl.make(ID, mines=56)
    with pytest.raises(ValueError, match="mine_penalty"):
        glyphbench_rl.make(ID, mine_penalty=0.2)
    with pytest.raises(ValueError, match="progress_share"):
        glyphbench_rl.make(ID, progress_share=1.0)
