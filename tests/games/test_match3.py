import pytest

import glyphbench_rl
from glyphbench_rl.games.classics.match3 import find_matches, makes_run, swap_matches

ID = "glyphbench/classics-match3-v0"


def board(*rows):
    return [list(row) for row in rows]


def test_matches_and_runs():
    b = board("rrrg", "gbgb", "gbrb", "gbyy")
    assert find_matches(b) == {(0, 0), (0, 1), (0, 2), (1, 0), (2, 0), (3, 0), (1, 1), (2, 1), (3, 1)}
    assert makes_run(b, 0, 1) and makes_run(b, 3, 0) and not makes_run(b, 3, 3)
    b = board("rgrr", "bygb", "gbyg", "ybgy")
    assert swap_matches(b, 0, 0, 0, 1) and b[0][:2] == ["r", "g"]    # checked, then undone
    assert not swap_matches(b, 3, 2, 3, 3)


def greedy(task):
    """The first swap that lines up gems, in action order."""
    return next(i for i, pair in enumerate(task.pairs) if swap_matches(task.board, *pair))


@pytest.mark.parametrize("seed", [0, 1, 2, 1_000_000])
def test_win_path_with_valid_swaps(seed):
    task = glyphbench_rl.make(ID)
    task.reset(seed=seed)
    while not task.done:
        _, reward, term, trunc, info = task.step(greedy(task))
        assert reward > 0 and info["frame"].message.startswith("Cleared ")
    assert term and task.won and not info["clamped"]
    assert task.episode_return == pytest.approx(1.0) and task.cleared == task.params.target


def test_loss_path_with_swaps_that_never_line_up():
    task = glyphbench_rl.make(ID)
    task.reset(seed=0)
    while not task.done:
        before = [row[:] for row in task.board]
        bad = next(i for i, pair in enumerate(task.pairs) if not swap_matches(task.board, *pair))
        _, reward, *_ = task.step(bad)
        assert reward == 0.0 and task.board == before
        assert task.frame.message == "No line: the gems swap back."
    assert task.won is None and task.episode_return == 0.0 and task.turn == task.max_turns


@pytest.mark.parametrize("seed", range(20))
def test_deals_have_no_lines_and_a_move(seed):
    task = glyphbench_rl.make(ID)
    task.reset(seed=seed)
    assert not find_matches(task.board) and task.has_move(task.board)
    assert set("".join(task.frame.grid)) <= set("rgbypo")


def test_collapse_drops_gems_and_refills_from_the_top():
    task = glyphbench_rl.make(ID, size=4, kinds=3)
    task.reset(seed=0)
    task.board = board("rgbr", "gbrg", "rrrb", "bgbg")
    task._collapse({(2, 0), (2, 1), (2, 2)})
    for c, column in enumerate(("rgb", "gbg", "brb")):   # old cells above the cleared row, then below
        kept = [task.board[r][c] for r in (1, 2, 3)]
        assert "".join(kept) == column
    assert [row[3] for row in task.board] == ["r", "g", "b", "g"]
    assert not task.has_move(board("rgbr", "gbrg", "brgb", "rgbr"))


def test_reward_stops_at_the_target():
    task = glyphbench_rl.make(ID, target=10)
    task.reset(seed=0)
    task.cleared = 9
    _, reward, term, *_ = task.step(greedy(task))
    assert term and task.won and reward == pytest.approx(0.1) and task.cleared == 10


def test_actions_and_prompt():
    task = glyphbench_rl.make(ID)
    assert task.action_space.n == 112
    assert task.actions.names[:2] == ("A1R", "B1R") and task.actions.names[56] == "A1D"
    assert glyphbench_rl.make(ID, size=6).action_space.n == 60
    obs, _ = task.reset(seed=0)
    assert obs.splitlines()[0] == "Step 0/40 | Cleared 0/80" and obs.splitlines()[1] == "  ABCDEFGH"
    r, c, r2, c2 = task.pairs[task.actions.index("C4D")]
    assert (r, c, r2, c2) == (3, 2, 4, 2)
    assert "each cleared gem gives 1/80" in task.system_prompt()


def test_bad_params():
    with pytest.raises(ValueError, match="size"):
        glyphbench_rl.make(ID, size=3)
    with pytest.raises(ValueError, match="kinds"):
        glyphbench_rl.make(ID, kinds=7)
    with pytest.raises(ValueError, match="target"):
        glyphbench_rl.make(ID, target=0)
