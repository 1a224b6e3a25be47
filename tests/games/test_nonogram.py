import numpy as np
import pytest

import glyphbench_rl
from glyphbench_rl.core import check_frame
from glyphbench_rl.games.common.boards import Bits, clue_char, clue_margins, runs
from glyphbench_rl.games.classics.nonogram import arrangements, line_solve

VARIANTS = ["easy", "hard"]


def clues_of(picture, n):
    bits = Bits(n, n)
    return (tuple(runs(bits.row_bits(picture, r), n) for r in range(n)),
            tuple(runs(bits.col_bits(picture, c), n) for c in range(n)))


def test_runs():
    assert runs(0b1101101, 7) == (1, 2, 2)
    assert runs(0, 5) == ()
    assert len(arrangements(5)[(1, 1)]) == 6


def test_clue_margins_stack_column_clues_one_character_each():
    above, beside = clue_margins([(3,), (), (1, 1), (10, 1)], [(1, 2), (), (3,), (11,), (1, 1, 1)])
    assert above == ("    1",          # the last run of a column nearest the board
                     "1   1",
                     "203⑪1")          # 0: no filled cell; ⑪: 11 in one character
    assert beside == ("3", "0", "1 1", "10 1")


def test_line_solved_pictures_are_unique_by_brute_force():
    n = 4
    clue_id = {clue: k for k, clue in enumerate(arrangements(n))}
    line_id = np.zeros(1 << n, dtype=np.int64)
    for clue, lines in arrangements(n).items():
        line_id[list(lines)] = clue_id[clue]
    pics = np.arange(1 << n * n, dtype=np.int64)
    cells = (pics[:, None] >> np.arange(n * n)) & 1                     # bit r * n + c
    rows = (cells.reshape(-1, n, n) << np.arange(n)).sum(axis=2)       # bit c of row r
    cols = (cells.reshape(-1, n, n) << np.arange(n)[:, None]).sum(axis=1)
    keys = (line_id[np.concatenate([rows, cols], axis=1)] * len(clue_id) ** np.arange(2 * n)).sum(axis=1)
    _, inverse, counts = np.unique(keys, return_inverse=True, return_counts=True)
    solved = 0
    for picture in range(0, 1 << n * n, 19):
        rows, cols = clues_of(picture, n)
        found = line_solve(list(rows), list(cols))
        if found is not None:
            solved += 1
            assert sum(row << r * n for r, row in enumerate(found)) == picture
            assert counts[inverse[picture]] == 1
    assert solved > 400


def test_line_solver_rejects_ambiguous_and_contradictory_clues():
    assert line_solve([(1,), (1,)], [(1,), (1,)]) is None      # two diagonals fit
    assert line_solve([(2,), (2,)], [(1,), (1,)]) is None      # contradiction


@pytest.mark.parametrize("variant", VARIANTS)
@pytest.mark.parametrize("seed", [0, 1, 2, 1_000_000])
def test_win_path_fills_the_solution(variant, seed):
    task = glyphbench_rl.make(f"glyphbench/classics-nonogram-{variant}-v0")
    obs, _ = task.reset(seed=seed)
    n = task.params.size
    assert line_solve(task.row_clues, task.col_clues) is not None
    assert obs.splitlines()[0] == f"Step 0/{task.max_turns}"
    cells = Bits(n, n).cells(task.solution)
    task.step("X" + "ABCDEFGH"[cells[0][1]] + str(cells[0][0] + 1))   # a wrong mark, then fill over it
    for r, c in cells:
        _, reward, term, trunc, info = task.step(f"{chr(65 + c)}{r + 1}")
    assert term and task.won and not info["clamped"]
    assert task.turn == task.solution.bit_count() + 1
    assert task.episode_return == pytest.approx(1 - 0.5 * task.turn / task.max_turns)
    assert "Solved" in info["frame"].message


@pytest.mark.parametrize("variant", VARIANTS)
def test_loss_path_fills_the_wrong_cells(variant):
    task = glyphbench_rl.make(f"glyphbench/classics-nonogram-{variant}-v0")
    task.reset(seed=5)
    n = task.params.size
    blanks = Bits(n, n).cells(Bits(n, n).full & ~task.solution)
    i = 0
    while not task.done:
        r, c = blanks[i % len(blanks)]
        _, reward, *_ = task.step(f"{chr(65 + c)}{r + 1}")
        assert reward == 0.0
        i += 1
    assert task.won is None and task.episode_return == 0.0


def test_fill_and_mark_rendering():
    task = glyphbench_rl.make("glyphbench/classics-nonogram-easy-v0")
    task.reset(seed=0)
    assert task.action_space.n == 50 and task.actions.names[25] == "XA1"
    assert glyphbench_rl.make("glyphbench/classics-nonogram-hard-v0").action_space.n == 128
    task.step("B1")
    task.step("XC2")
    grid = task.frame.grid
    assert grid[0][1] == "■" and grid[1][2] == "x"
    task.step("XB1")   # marking a filled cell clears it
    task.step("C2")    # filling a marked cell removes the mark
    grid = task.frame.grid
    assert grid[0][1] == "x" and grid[1][2] == "■"
    task.step("C2")
    assert task.frame.grid[1][2] == "·"


def test_generated_puzzles_are_varied():
    task = glyphbench_rl.make("glyphbench/classics-nonogram-hard-v0")
    pictures = set()
    for seed in range(20):
        task.reset(seed=seed)
        pictures.add(task.solution)
        assert line_solve(task.row_clues, task.col_clues) is not None
    assert len(pictures) == 20


def test_bad_params():
    with pytest.raises(ValueError, match="size"):
        glyphbench_rl.make("glyphbench/classics-nonogram-easy-v0", size=13)
    with pytest.raises(ValueError, match="density"):
        glyphbench_rl.make("glyphbench/classics-nonogram-easy-v0", density=0.1)
    with pytest.raises(ValueError, match="time_weight"):
        glyphbench_rl.make("glyphbench/classics-nonogram-easy-v0", time_weight=-0.1)


def test_clues_stand_beside_the_rows_and_above_the_columns():
    task = glyphbench_rl.make("glyphbench/classics-nonogram-hard-v0", size=12, density=0.85)
    obs, info = task.reset(seed=1)
    assert max(max(c, default=0) for c in task.row_clues + task.col_clues) >= 10
    frame = info["frame"]
    assert check_frame(frame) == [] and obs in task.observation_space
    lines = obs.splitlines()
    assert lines[0] == f"Step 0/{task.max_turns}"                 # no clues in the HUD
    depth = max(len(c) or 1 for c in task.col_clues)
    header = lines[1 + depth]
    assert header == "   ABCDEFGHIJKL"
    for c, clue in enumerate(task.col_clues):                      # read each column top-down
        stack = "".join(line[3 + c] for line in lines[1:1 + depth] if len(line) > 3 + c).strip()
        assert stack == ("".join(clue_char(n) for n in clue) or "0")
    for r, clue in enumerate(task.row_clues):
        number, cells, *numbers = lines[2 + depth + r].split()
        assert int(number) == r + 1 and cells == frame.grid[r]
        assert [int(n) for n in numbers] == (list(clue) or [0])
    assert "⑩ is 10" in task.system_prompt()
    assert "⑩" not in glyphbench_rl.make("glyphbench/classics-nonogram-hard-v0").system_prompt()
