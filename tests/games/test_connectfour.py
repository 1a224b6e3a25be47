import pytest

import glyphbench_rl
from glyphbench_rl.games.classics.connectfour import THEM, YOU, Bitboard, tactical_moves

ID = "glyphbench/classics-connectfour-v0"


def bits(bb, cells):
    """Bitboard of (row from the bottom, column) cells."""
    return sum(1 << c * bb.h1 + r for r, c in cells)


def test_bitboard_fours_and_winning_cells():
    bb = Bitboard(6, 7)
    assert bb.has_four(bits(bb, [(0, 0), (0, 1), (0, 2), (0, 3)]))          # across
    assert bb.has_four(bits(bb, [(0, 4), (1, 4), (2, 4), (3, 4)]))          # up
    assert bb.has_four(bits(bb, [(0, 0), (1, 1), (2, 2), (3, 3)]))          # diagonal
    assert bb.has_four(bits(bb, [(3, 0), (2, 1), (1, 2), (0, 3)]))          # anti-diagonal
    assert not bb.has_four(bits(bb, [(5, 0), (0, 1), (1, 1), (2, 1)]))      # no wrap between columns
    three = bits(bb, [(0, 1), (0, 2), (0, 3)])
    assert bb.winning_cells(three, three) == bits(bb, [(0, 0), (0, 4)])
    assert [[bb.lines[1 << c * 7 + r] for c in range(7)] for r in (0, 2)] == [
        [3, 4, 5, 7, 5, 4, 3], [5, 8, 11, 13, 11, 8, 5]]


def test_opponent_search_wins_blocks_and_avoids_setting_up_a_win():
    bb = Bitboard(6, 7)
    me, you = bits(bb, [(0, 0), (0, 1), (0, 2)]), bits(bb, [(1, 0), (1, 1), (1, 2)])
    assert tactical_moves(bb, me, you) == [3]             # win now
    me, you = bits(bb, [(0, 6), (1, 6)]), bits(bb, [(0, 1), (0, 2), (0, 3)])
    assert sorted(tactical_moves(bb, me, you)) == [0, 4]  # block either open end
    # You threaten D2 (row 1 from the bottom); playing D1 under it would hand you the win.
    you = bits(bb, [(1, 0), (1, 1), (1, 2), (0, 1)])
    me = bits(bb, [(0, 0), (0, 2)])
    moves = tactical_moves(bb, me, you)
    assert moves and 3 not in moves


@pytest.mark.parametrize("seed", range(8))
def test_win_path_against_a_random_opponent(seed):
    task = glyphbench_rl.make(ID, strength=0.0)
    task.reset(seed=seed)
    while not task.done:
        _, reward, term, trunc, info = task.step(tactical_moves(task.bb, task.mine, task.theirs)[0])
    assert term and task.won and task.episode_return == 1.0 and not info["clamped"]
    assert info["frame"].message.endswith("You win. Reward +1")


ORDER = (3, 2, 4, 1, 5, 0, 6)


def negamax(bb, me, you, depth, alpha=-10**9, beta=10**9):
    """Value for the player holding ``me``, to move: wins score 1000+, leaves count threats."""
    mask = me | you
    playable = bb.playable(mask)
    if not playable:
        return 0
    if bb.winning_cells(me, mask) & playable:
        return 1000 + depth
    if depth == 0:
        return bin(bb.winning_cells(me, mask)).count("1") - bin(bb.winning_cells(you, mask)).count("1")
    best = -10**9
    for c in ORDER:
        move = playable & bb.column[c]
        if move:
            best = max(best, -negamax(bb, you, me | move, depth - 1, -beta, -alpha))
            alpha = max(alpha, best)
            if alpha >= beta:
                break
    return best


def search_move(task, depth=5):
    """A five-ply alpha-beta search: deeper than the opponent's two plies."""
    bb = task.bb
    playable = bb.playable(task.mine | task.theirs)
    moves = [(c, playable & bb.column[c]) for c in ORDER if playable & bb.column[c]]
    for c, move in moves:
        if bb.has_four(task.mine | move):
            return c
    return max(moves, key=lambda cm: -negamax(bb, task.theirs, task.mine | cm[1], depth - 1))[0]


@pytest.mark.parametrize("seed", range(8))
def test_win_path_against_the_standard_opponent(seed):
    task = glyphbench_rl.make(ID)
    task.reset(seed=seed)
    while not task.done:
        _, _, term, _, info = task.step(search_move(task))
    assert term and task.won and task.episode_return == 1.0 and not info["clamped"]


def test_loss_path_always_column_a():
    task = glyphbench_rl.make(ID)
    task.reset(seed=0)
    while not task.done:
        _, _, term, trunc, info = task.step("A")
    assert term and task.won is False and task.episode_return == -1.0
    assert info["frame"].message.endswith("You lose. Reward -1")


def test_full_column_wastes_the_turn():
    task = glyphbench_rl.make(ID)
    task.reset(seed=0)
    for i in range(6):   # fill column A by hand, alternating discs (no four)
        if i % 2:
            task.theirs |= task.drop(0, THEM)
        else:
            task.mine |= task.drop(0, YOU)
    before = task._grid()
    assert before[0] == "O······" and before[5] == "X······"
    obs, reward, term, _, info = task.step("A")
    assert reward == 0.0 and not term and task.turn == 1
    assert info["frame"].message == "Column A is full."
    assert list(info["frame"].grid) == before   # the opponent did not move either


def test_full_board_is_a_draw():
    task = glyphbench_rl.make(ID)
    task.reset(seed=0)
    bb = task.bb
    # A full board (rows bottom first) on which neither side has four.
    pattern = ["XXOOXOO", "XOXXXOO", "OOXOOXX", "XOOXXOX", "OXOXXOO", "OXOXXOX"]
    for r, row in enumerate(pattern):
        for c, ch in enumerate(row):
            if (r, c) == (5, 6):
                continue   # the last cell: yours to play
            bit = 1 << c * bb.h1 + r
            if ch == "X":
                task.mine |= bit
            else:
                task.theirs |= bit
            task.cells[5 - r][c] = ch
    assert not bb.has_four(task.mine) and not bb.has_four(task.theirs | 1 << 6 * bb.h1 + 5)
    _, reward, term, _, info = task.step("G")
    assert term and reward == 0.0 and task.won is False
    assert info["frame"].message == "Draw."


def test_rendering_and_prompt():
    task = glyphbench_rl.make(ID)
    obs, _ = task.reset(seed=0)
    assert obs.splitlines()[1] == "  ABCDEFG" and task.action_space.n == 7
    obs, *_ = task.step("D")
    grid = task.frame.grid
    assert grid[5][3] == "X" and sum(row.count("O") for row in grid) == 1
    assert "Opponent dropped in" in task.frame.message
    prompt = task.system_prompt()
    assert "With probability 0.9" in prompt and "a win gives +1, a loss -1" in prompt


def test_bad_params():
    with pytest.raises(ValueError, match="rows"):
        glyphbench_rl.make(ID, rows=3)
    with pytest.raises(ValueError, match="cols"):
        glyphbench_rl.make(ID, cols=13)
    with pytest.raises(ValueError, match="strength"):
        glyphbench_rl.make(ID, strength=1.5)
