import pytest

import glyphbench_rl
from glyphbench_rl.core import check_frame
from glyphbench_rl.games.common.grid import MOVES, Board
from glyphbench_rl.games.common.palette import WALL
from glyphbench_rl.games.classics.icesliding import solve
from glyphbench_rl.games.common.grid import bfs_search

VARIANTS = ["easy", "medium", "hard"]


def make(variant, **kw):
    return glyphbench_rl.make(f"glyphbench/classics-icesliding-{variant}-v0", **kw)


def reference_moves(board, start, exit_):
    """Independent forward search that walks each slide cell by cell."""
    def neighbours(cell):
        for name, (dr, dc) in MOVES.items():
            r, c = cell
            while board[r + dr, c + dc] != WALL:
                r, c = r + dr, c + dc
                if (r, c) == exit_:
                    break
            yield name, (r, c)
    path = bfs_search(start, neighbours, lambda cell: cell == exit_)
    return None if path is None else len(path)


def test_solver_on_a_hand_made_level():
    board = Board.from_lines(["#######",
                              "#.....#",
                              "#.#...#",
                              "#.....#",
                              "#######"])
    board.rows = [[WALL if ch == "#" else "·" for ch in row] for row in board.rows]
    # from the top-left corner: RIGHT slides to the far wall, the exit (3, 3) is on no line from
    # there; DOWN to (3, 1) then RIGHT passes over the exit and stops on it
    assert solve(board, (1, 1), (3, 3)) == ["DOWN", "RIGHT"]
    assert solve(board, (3, 3), (3, 3)) == []
    board[2, 2] = WALL
    board[1, 3] = WALL   # now (1, 1) and (1, 2) only reach each other
    board[3, 2] = WALL
    board[2, 1] = WALL
    assert solve(board, (1, 1), (3, 3)) is None


@pytest.mark.parametrize("variant", VARIANTS)
def test_generated_levels_are_solvable_with_the_stated_optimum(variant):
    task = make(variant)
    p = task.params
    for seed in range(15):
        _, info = task.reset(seed=seed)
        assert check_frame(info["frame"]) == []
        grid = info["frame"].grid
        assert len(grid) == p.size + 2 and "".join(grid).count(WALL) == 4 * (p.size + 1) + p.rocks
        assert task.optimal >= p.min_moves
        assert reference_moves(task.board, task.pos, task.exit) == task.optimal
        assert task.optimal <= task.max_turns // 2


@pytest.mark.parametrize("variant", VARIANTS)
@pytest.mark.parametrize("seed", [0, 1, 1_000_003])
def test_win_path_with_optimal_moves(variant, seed):
    task = make(variant)
    task.reset(seed=seed)
    plan = solve(task.board, task.pos, task.exit)
    assert len(plan) == task.optimal
    for move in plan:
        assert not task.done
        _, reward, term, trunc, info = task.step(move)
    assert term and task.won and not info["clamped"]
    expected = 1 - task.params.time_weight * task.optimal / task.max_turns
    assert task.episode_return == pytest.approx(expected) and expected > 0.5
    assert "exit" in info["frame"].message


def test_loss_path_runs_out_of_turns_with_zero():
    task = make("medium")
    task.reset(seed=4)
    while not task.done:   # bounce between two walls that never lead to the exit
        before = task.pos
        task.step("UP")
        if task.done:
            break
        task.step("DOWN")
        assert task.pos[1] == before[1]
    if task.won:
        pytest.skip("the exit lies on this column")
    assert task._truncated and task.won is None and task.episode_return == 0.0


def test_blocked_move_changes_nothing():
    task = make("easy")
    for seed in range(10):
        task.reset(seed=seed)
        for name in MOVES:     # after a slide you rest against a wall or rock in that direction
            _, _, term, *_ = task.step(name)
            if task.pos != task.exit:
                break
        if term:
            continue
        grid = task.frame.grid
        _, reward, *_, info = task.step(name)
        assert reward == 0 and info["frame"].grid == grid and "Blocked" in info["frame"].message
        return
    pytest.fail("every first slide won")


def test_prompt_shows_the_numbers():
    prompt = make("hard").system_prompt()
    assert "10x10 room" in prompt and "1 minus 0.5 x (turns used / 80)" in prompt


@pytest.mark.parametrize("bad, field", [
    (dict(size=3), "size"), (dict(size=4.0), "size"), (dict(rocks=-1), "rocks"),
    (dict(rocks=100), "rocks"), (dict(min_moves=0), "min_moves"), (dict(time_weight=1), "time_weight"),
    (dict(colour=1), "unknown parameter 'colour'"),
])
def test_bad_params(bad, field):
    with pytest.raises(ValueError, match=field):
        make("easy", **bad)
