from collections import deque

import pytest

import glyphbench_rl
from glyphbench_rl.games.classics.platformer import COIN, JUMP_SPEED

ID = "glyphbench/classics-platformer-v0"


def moves(task, state):
    """(action, next state, cells passed) for each action from ``state``."""
    x, y, vy = state
    for a in range(4):
        nx, ny, nvy = task.advance(x, y, vy, a)
        lo, hi = sorted((y, min(ny, task.params.height - 1)))
        yield a, (nx, ny, nvy), [(r, nx) for r in range(lo, hi + 1)]


def bfs(task, start, goal):
    """Shortest action list from ``start`` to a move passing a cell where goal(r, c) holds
    (falling states are dead ends)."""
    prev = {start: None}
    queue = deque([start])
    while queue:
        state = queue.popleft()
        for a, nxt, cells in moves(task, state):
            if nxt[1] >= task.params.height:
                continue
            if any(goal(r, c) for r, c in cells):
                path = [a]
                while prev[state] is not None:
                    state, a0 = prev[state]
                    path.append(a0)
                return path[::-1]
            if nxt not in prev:
                prev[nxt] = (state, a)
                queue.append(nxt)
    return None


def test_every_coin_and_the_flag_are_reachable():
    for seed in range(40):
        task = glyphbench_rl.make(ID)
        task.reset(seed=seed)
        start = (task.x, task.y, task.vy)
        seen, queue, passed = {start}, deque([start]), set()
        while queue:
            for _, nxt, cells in moves(task, queue.popleft()):
                passed.update(cells)
                if nxt[1] < task.params.height and nxt not in seen:
                    seen.add(nxt)
                    queue.append(nxt)
        coins = {(r, c) for r, row in enumerate(task.level) for c, ch in enumerate(row) if ch == COIN}
        assert coins <= passed, seed
        assert any(c >= task.flag_col for _, c in passed), seed


@pytest.mark.parametrize("seed", range(4))
def test_win_path_collects_every_coin(seed):
    task = glyphbench_rl.make(ID)
    task.reset(seed=seed)
    while not task.done:
        if task.got < task.coins:
            path = bfs(task, (task.x, task.y, task.vy), lambda r, c: task.level[r][c] == COIN)
        else:
            path = bfs(task, (task.x, task.y, task.vy), lambda r, c: c >= task.flag_col)
        for a in path:
            task.step(a)
    assert task.won and task.got == task.coins
    assert task.episode_return == pytest.approx(1.0) and task.turn < task.max_turns


def test_loss_path_falls_into_a_pit():
    task = glyphbench_rl.make(ID)
    task.reset(seed=0)
    while not task.done:
        ahead = task.x + 1
        pit = not task.solid(task.params.height - 1, ahead)
        blocked = task.solid(task.y, ahead)
        _, reward, term, trunc, info = task.step("JUMP" if blocked and not pit else "RIGHT")
    assert term and task.won is False and task.episode_return < 0
    assert "fell" in info["frame"].message


def test_jump_arc():
    task = glyphbench_rl.make(ID)
    task.reset(seed=0)
    y = task.y
    heights = []
    for a in ["JUMP", "WAIT", "WAIT", "WAIT", "WAIT"]:
        task.step(a)
        heights.append(y - task.y)
    assert heights == [JUMP_SPEED, 3, 3, 2, 0] and task.vy == 0


def test_bad_params():
    with pytest.raises(ValueError, match="view"):
        glyphbench_rl.make(ID, view=100)
    with pytest.raises(ValueError, match="coin_share"):
        glyphbench_rl.make(ID, coin_share=1.0)
