import pytest

import glyphbench_rl
from glyphbench_rl.games.common.grid import bfs_search, shortest_path
from glyphbench_rl.games.common.palette import WALL

GAMES = ["maze", "heist", "chaser", "miner"]


@pytest.mark.parametrize("game", GAMES)
def test_fifty_seeds_give_distinct_levels(game):
    task = glyphbench_rl.make(f"glyphbench/procgen-{game}-v0")
    levels = {tuple(task._rows()) for seed in range(50) if task.reset(seed=seed)}
    assert len(levels) >= 45


@pytest.mark.parametrize("seed", [0, 1, 7])
def test_maze_win_path(seed):
    task = glyphbench_rl.make("glyphbench/procgen-maze-v0")
    task.reset(seed=seed)
    for move in shortest_path(task.pos, task.goal, lambda r, c: task.board[r, c] != WALL):
        _, _, term, _, info = task.step(move)
    assert term and task.won and task.episode_return == 1.0 and not info["clamped"]


@pytest.mark.parametrize("seed", [0, 1, 7])
def test_heist_win_path_takes_every_key(seed):
    task = glyphbench_rl.make("glyphbench/procgen-heist-v0")
    task.reset(seed=seed)
    for action in task.solution():
        task.step(action)
    assert task.won and task.held == 0b111 and task.episode_return == pytest.approx(1.0)


@pytest.mark.parametrize("seed", [0, 3])
def test_chaser_win_path_without_ghosts(seed):
    task = glyphbench_rl.make("glyphbench/procgen-chaser-v0", ghosts=0)
    task.reset(seed=seed)
    while not task.done:
        def neighbours(cell):
            return [(a, n) for a, n in zip(range(1, 5), ((cell[0], cell[1] - 1), (cell[0], cell[1] + 1),
                    (cell[0] - 1, cell[1]), (cell[0] + 1, cell[1]))) if task.rows[n[0]][n[1]] != WALL]
        for action in bfs_search(task.pos, neighbours, lambda c: task.rows[c[0]][c[1]] in "oO"):
            task.step(action)
    assert task.won and task.episode_return == pytest.approx(0.8)


def test_chaser_caught_ends_with_nothing_lost():
    task = glyphbench_rl.make("glyphbench/procgen-chaser-v0")
    task.reset(seed=0)
    while not task.done:
        task.step("NOOP")
    assert task.won is False and task.episode_return == 0.0 and task.turn < 200


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_miner_tunnel_wins(seed):
    task = glyphbench_rl.make("glyphbench/procgen-miner-v0")
    task.reset(seed=seed)
    for move in ["RIGHT"] * 17 + ["DOWN"] * 17:
        task.step(move)
    assert task.won and task.episode_return == pytest.approx(0.2)


def test_miner_falling_boulder_crushes():
    task = glyphbench_rl.make("glyphbench/procgen-miner-v0")
    task.reset(seed=0)
    rows = task.rows
    for r in range(2, 6):
        rows[r][3] = "."
    rows[2][3] = "O"
    task.pos = (3, 3)               # holding up the boulder
    task.step("NOOP")
    assert not task.done
    task.step("DOWN")               # the boulder falls behind
    assert not task.done
    task.step("NOOP")               # and lands
    assert task.done and task.won is False and task.episode_return == -1.0


def test_chaser_scared_ghost_is_eaten_and_sent_home_and_a_hunting_one_catches():
    task = glyphbench_rl.make("glyphbench/procgen-chaser-v0")
    task.reset(seed=4)
    r, c = task.pos
    moves = {"RIGHT": (r, c + 1), "DOWN": (r + 1, c)}
    name, cell = next((n, x) for n, x in moves.items() if task.rows[x[0]][x[1]] != WALL)
    task.ghosts[0], task.scared = cell, [True] * len(task.ghosts)
    task.timer = 5
    _, reward, term, _, _ = task.step(name)
    home = task.lairs[0]                                    # sent home (and it moved on from there)
    assert not term and abs(task.ghosts[0][0] - home[0]) + abs(task.ghosts[0][1] - home[1]) <= 1
    assert not task.scared[0]
    assert reward == pytest.approx(0.1 + (0.5 / task.total if task.pellets < task.total else 0.0))
    assert "You ate a ghost." in task.frame.message
    back = {"RIGHT": "LEFT", "DOWN": "UP"}[name]
    task.ghosts[1], task.scared[1] = (r, c), False          # a hunting ghost where you step next
    _, reward, term, _, info = task.step(back)
    assert term and info["won"] is False and "A ghost caught you." in task.frame.message


def _miner_collect_all(task):
    """Dig to the nearest diamond, then the exit, re-planning every turn; a move is taken only
    if the real game (a copy of it) survives it and some move of the next turn."""
    import copy

    from glyphbench_rl.games.common.grid import DELTAS
    names = {(0, -1): "LEFT", (0, 1): "RIGHT", (-1, 0): "UP", (1, 0): "DOWN"}
    while not task.done and task.turn < 400:
        def neighbours(cell):
            for dr, dc in DELTAS:
                nxt = (cell[0] + dr, cell[1] + dc)
                if task.rows[nxt[0]][nxt[1]] not in "█O":
                    yield names[(dr, dc)], nxt
        target = "*" if task.left else "◎"
        plan = bfs_search(task.pos, neighbours, lambda c: task.rows[c[0]][c[1]] == target)
        assert plan, f"no way to a {target!r} from {task.pos}"
        def survives(game, move, depth):
            trial = copy.deepcopy(game)
            trial.step(move)
            if trial.done or depth == 1:
                return trial.won is not False
            return any(survives(trial, nxt, depth - 1) for nxt in ("NOOP", *names.values()))
        move = next(m for m in (plan[0], "NOOP", *names.values()) if survives(task, m, 2))
        task.step(move)


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_miner_every_diamond_can_be_dug_out(seed):
    task = glyphbench_rl.make("glyphbench/procgen-miner-v0")
    task.reset(seed=seed)
    diamonds = task.left
    assert diamonds >= 8
    _miner_collect_all(task)
    assert task.won and task.taken == diamonds
    assert task.episode_return == pytest.approx(0.1 * 8 + 0.2)
