import pytest

import glyphbench_rl
from glyphbench_rl.games.classics.twenty48 import slide, slide_row

ID = "glyphbench/classics-2048-v0"


def test_slide_rules():
    assert slide_row([1, 1, 1, 1]) == [2, 2, 0, 0]      # each tile merges once per move
    assert slide_row([0, 2, 2, 3]) == [3, 3, 0, 0]
    assert slide_row([1, 0, 0, 1]) == [2, 0, 0, 0]
    board = [[1, 0], [1, 2]]
    assert slide(board, "UP") == [[2, 2], [0, 0]]
    assert slide(board, "DOWN") == [[0, 0], [2, 2]]
    assert slide(board, "RIGHT") == [[0, 1], [1, 2]]


def greedy(task):
    """One-step lookahead: the move leaving the most empty cells (ties: fixed order)."""
    best, best_empty = None, -1
    for name in ("DOWN", "LEFT", "RIGHT", "UP"):
        new = slide(task.board, name)
        if new != task.board:
            empty = sum(v == 0 for row in new for v in row)
            if empty > best_empty:
                best, best_empty = name, empty
    return best


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_win_path_reaches_target(seed):
    task = glyphbench_rl.make(ID, target=128)
    task.reset(seed=seed)
    while not task.done:
        _, _, term, trunc, info = task.step(greedy(task))
    assert task.won and term
    assert task.episode_return == pytest.approx(1.0) and not info["clamped"]


def test_loss_path_is_negative():
    task = glyphbench_rl.make(ID, size=3)
    task.reset(seed=0)
    order = ("UP", "LEFT", "RIGHT", "DOWN")
    while not task.done:
        move = next(m for m in order if slide(task.board, m) != task.board)
        task.step(move)
    assert task.won is False and task.episode_return < 0
    assert "No move is possible." in task.frame.message


def test_reward_counts_growth_of_the_largest_tile():
    task = glyphbench_rl.make(ID)
    task.reset(seed=0)
    task.board = [[3, 3, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]]   # two 8s
    task.largest = 3
    _, reward, *_ = task.step("LEFT")
    assert reward == pytest.approx((16 - 8) / (512 - 4))


def test_bad_target():
    with pytest.raises(ValueError, match="target"):
        glyphbench_rl.make(ID, target=100)


def test_tiles_are_letters_named_with_their_values_in_the_legend():
    """No digit on the board stands for another number: tile 2**k is the k-th letter, and the
    legend gives the values of the tiles on the board (only those)."""
    task = glyphbench_rl.make(ID, target=2048)
    task.reset(seed=0)
    task.board = [[1, 2, 3, 0], [9, 10, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]]
    task.largest = 10
    obs, *_ , info = task.step("DOWN")           # a move that changes the board redraws it
    frame = info["frame"]
    assert not any(ch.isdigit() for row in frame.grid for ch in row)
    legend = frame.legend_dict()
    values = {v for row in task.board for v in row if v}
    assert legend == {"·": "empty"} | {chr(ord("a") + v - 1): f"tile {1 << v}" for v in values}
    assert {"a", "b", "c", "i", "j"} <= set(legend)
    assert "a is 2, b is 4, c is 8" in task.system_prompt()
