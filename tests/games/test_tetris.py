import pytest

import glyphbench_rl
from glyphbench_rl.games.classics.tetris import BLOCK, FLOOR, ROTATIONS

ID = "glyphbench/classics-tetris-v0"


def score(board):
    """Classic placement heuristic: few holes, low and flat stack, lines cleared."""
    full = sum(FLOOR not in row for row in board)
    rows = [row for row in board if FLOOR in row]
    h, w = len(board), len(board[0])
    rows = [[FLOOR] * w] * full + rows
    heights, holes = [], 0
    for x in range(w):
        col = [rows[y][x] for y in range(h)]
        top = next((y for y, v in enumerate(col) if v != FLOOR), h)
        heights.append(h - top)
        holes += sum(v == FLOOR for v in col[top:])
    bump = sum(abs(a - b) for a, b in zip(heights, heights[1:]))
    return 0.76 * full - 0.51 * sum(heights) - 0.36 * holes - 0.18 * bump


def best_placement(task):
    name, _, r, _ = task.piece
    best = None
    for rot in range(4 if name != "O" else 1):
        for c in range(-3, task.params.width):
            if not task.fits(name, rot, r, c):
                continue
            y = task.drop_row(name, rot, r, c)
            board = [row[:] for row in task.board]
            for cy, cx in task.cells(name, rot, y, c):
                board[cy][cx] = BLOCK
            s = score(board)
            if best is None or s > best[0]:
                best = (s, rot, c)
    return best[1], best[2]


def play_greedy(task):
    plan, piece = None, None
    while not task.done:
        if task.piece is not piece:
            piece, plan = task.piece, best_placement(task)
        rot, col = plan
        if task.piece[1] != rot:
            task.step("ROTATE")
        elif task.piece[3] < col:
            task.step("RIGHT")
        elif task.piece[3] > col:
            task.step("LEFT")
        else:
            task.step("HARD_DROP")


def test_rotations_are_quarter_turns():
    assert all(len(set(r)) <= 4 for r in ROTATIONS.values())
    assert len(set(ROTATIONS["O"])) == 1 and len(set(ROTATIONS["I"])) == 4


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_win_path(seed):
    task = glyphbench_rl.make(ID)
    task.reset(seed=seed)
    play_greedy(task)
    assert task.won and task.lines >= task.params.target
    assert task.episode_return == pytest.approx(1.0) and task.turn < task.max_turns


def test_loss_path_tops_out():
    task = glyphbench_rl.make(ID)
    task.reset(seed=0)
    while not task.done:
        _, reward, term, trunc, info = task.step("HARD_DROP")
    assert term and task.won is False and task.lines == 0
    assert task.episode_return == pytest.approx(-task.params.topout_penalty)
    assert "Topped out." in info["frame"].message


def test_gravity_locks_and_line_clear():
    task = glyphbench_rl.make(ID, width=4, height=6, target=2)
    task.reset(seed=0)
    task.board[5] = [BLOCK, BLOCK, FLOOR, FLOOR]
    task.board[4] = [BLOCK, BLOCK, FLOOR, FLOOR]
    task.piece = ["O", 0, 0, 2]
    for _ in range(4):                      # falls one row a turn to rows 4-5
        task.step("NOOP")
    assert task.piece[0:3:2] == ["O", 4] and task.lines == 0
    _, reward, *_ = task.step("NOOP")       # cannot fall: locks, two lines clear
    assert task.lines == 2 and reward == pytest.approx(1.0) and task.won


def test_seven_bag():
    task = glyphbench_rl.make(ID)
    task.reset(seed=5)
    seen = [task.piece[0]] + [task.bag.draw() for _ in range(13)]
    assert sorted(seen[:7]) == sorted("IJLOSTZ") and sorted(seen[7:]) == sorted("IJLOSTZ")


def test_bad_params():
    with pytest.raises(ValueError, match="width"):
        glyphbench_rl.make(ID, width=2)
    with pytest.raises(ValueError, match="topout_penalty"):
        glyphbench_rl.make(ID, topout_penalty=2)
