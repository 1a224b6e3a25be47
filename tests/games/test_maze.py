import pytest

import glyphbench_rl
from glyphbench_rl.games.common.grid import bfs_distances, shortest_path
from glyphbench_rl.games.common.palette import WALL


@pytest.mark.parametrize("variant", ["easy", "medium", "hard"])
@pytest.mark.parametrize("seed", [0, 1, 1_000_000])
def test_win_path_is_the_shortest_path(variant, seed):
    task = glyphbench_rl.make(f"glyphbench/classics-maze-{variant}-v0")
    task.reset(seed=seed)
    path = shortest_path(task.pos, task.exit, lambda r, c: task.board[r, c] != WALL)
    assert len(path) == task.optimal > 0
    for move in path:
        _, reward, term, trunc, info = task.step(move)
    assert term and task.won and not info["clamped"]
    expected = 1 - task.params.time_weight * task.optimal / task.max_turns
    assert task.episode_return == pytest.approx(expected) and expected > 0.5


def test_loss_path_times_out_with_zero():
    task = glyphbench_rl.make("glyphbench/classics-maze-easy-v0")
    task.reset(seed=3)
    while not task.done:
        task.step("UP")
        task.step("DOWN") if not task.done else None
    assert task._truncated and task.won is None and task.episode_return == 0.0


@pytest.mark.parametrize("seed", range(10))
def test_generated_maze_is_perfect(seed):
    task = glyphbench_rl.make("glyphbench/classics-maze-medium-v0")
    task.reset(seed=seed)
    board = task.board
    open_cells = board.height * board.width - len(board.cells(WALL))
    dist = bfs_distances(task.pos, lambda r, c: board[r, c] != WALL)
    assert len(dist) == open_cells                      # connected
    edges = sum(1 for (r, c) in dist for dr, dc in ((0, 1), (1, 0)) if (r + dr, c + dc) in dist)
    assert edges == open_cells - 1                      # a tree: no loops
    assert all(board[0, c] == WALL and board[board.height - 1, c] == WALL for c in range(board.width))


def test_wall_bump_changes_nothing():
    task = glyphbench_rl.make("glyphbench/classics-maze-easy-v0")
    task.reset(seed=0)
    for move in ("UP", "DOWN", "LEFT", "RIGHT"):
        r, c = task.pos
        dr, dc = {"UP": (-1, 0), "DOWN": (1, 0), "LEFT": (0, -1), "RIGHT": (0, 1)}[move]
        if task.board[r + dr, c + dc] == WALL:
            obs_grid = task.frame.grid
            _, reward, *_ , info = task.step(move)
            assert info["frame"].grid == obs_grid and reward == 0 and "wall" in info["frame"].message
            return
    pytest.skip("no wall next to the start")
