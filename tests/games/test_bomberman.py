from collections import deque

import pytest

import glyphbench_rl
from glyphbench_rl.games.classics.bomberman import CRATE, SAFE, START
from glyphbench_rl.games.common.grid import DELTAS, MOVES
from glyphbench_rl.games.common.palette import FLOOR, WALL

TASK = "glyphbench/classics-bomberman-v0"
NAMES = tuple(MOVES)


def bfs(task, start, ok):
    """First move and distance to every cell reachable from ``start`` through cells ``ok``."""
    seen = {start: (None, 0)}
    queue = deque([start])
    while queue:
        cur = queue.popleft()
        first, d = seen[cur]
        for i, (dr, dc) in enumerate(DELTAS):
            nxt = (cur[0] + dr, cur[1] + dc)
            if nxt not in seen and ok(nxt):
                seen[nxt] = (first or NAMES[i], d + 1)
                queue.append(nxt)
    return seen


def bot(task):
    """Scripted player: tunnel with bombs towards the exit crate (the plan reads the hidden exit
    from the state), always keeping an escape from its own blast and a cell away from enemies."""
    enemies = {e.cell for e in task.enemies}
    near = enemies | {(r + dr, c + dc) for r, c in enemies for dr, dc in DELTAS}

    def ok(cell, avoid=near):
        return task.walkable(*cell) and cell not in avoid

    if task.bomb is not None:
        danger = set(task.blast_cells(task.bomb))
        if task.player not in danger and task.player not in near:
            return "WAIT"
        for avoid in (near, enemies):
            reach = bfs(task, task.player, lambda x: ok(x, avoid))
            safe = [(d, first) for cell, (first, d) in reach.items()
                    if cell not in danger and cell not in avoid and first]
            if safe:
                return min(safe)[1]
        return "WAIT"
    if task.exit_seen:
        reach = bfs(task, task.player, lambda x: ok(x, enemies))
        if task.exit in reach:
            return reach[task.exit][0]
    reach = bfs(task, task.player, ok)
    best = None
    for cell, (first, d) in reach.items():
        hits = task.blast_cells(cell)
        crates = [x for x in hits if task.tiles[x[0]][x[1]] == CRATE]
        if not crates and not enemies & set(hits):
            continue
        danger = set(hits)
        escape = bfs(task, cell, lambda x: ok(x) and x != cell)
        if not any(x not in danger and dd <= task.params.fuse for x, (_, dd) in escape.items()):
            continue
        gap = min(abs(x[0] - task.exit[0]) + abs(x[1] - task.exit[1]) for x in crates) if crates else 99
        key = (task.exit not in crates, gap, d)
        if best is None or key < best[0]:
            best = (key, first)
    if best is None:
        return "WAIT"
    return best[1] or "BOMB"


def play_bot(seed, **kw):
    task = glyphbench_rl.make(TASK, **kw)
    task.reset(seed=seed)
    info = {}
    while not task.done:
        _, _, _, _, info = task.step(bot(task))
    return task, info


def test_win_path_scripted_bot():
    wins = 0
    for seed in range(10):
        task, info = play_bot(seed)
        if task.won:
            wins += 1
            assert 0.5 <= task.episode_return <= 1 and not info["clamped"]
            assert task.player == task.exit or not task.enemies
    assert wins >= 8


def test_bomb_kills_enemy_in_its_cross_and_clearing_wins():
    task = glyphbench_rl.make(TASK, min_enemies=1, max_enemies=1, enemy_speed=1.0)
    task.reset(seed=3)
    # Put the lone enemy in a dead end two cells right of a fresh bomb and wall it in.
    for cell in ((1, 2), (1, 3), (2, 1), (3, 1), (3, 2)):   # (2, 1) (3, 1) (3, 2): your way out
        task.set_tile(*cell, FLOOR)
    task.set_tile(1, 4, WALL)
    task.set_tile(2, 3, WALL)
    task.enemies[0].r, task.enemies[0].c = 1, 3
    for action in ("BOMB", "DOWN", "DOWN"):
        _, reward, term, _, info = task.step(action)
        assert not term
    _, reward, term, _, info = task.step("RIGHT")
    assert term and task.won and reward == pytest.approx(1.0)
    assert "Every enemy is dead." in info["frame"].message


def test_loss_path_sitting_on_your_bomb():
    task = glyphbench_rl.make(TASK)
    task.reset(seed=0)
    obs, *_ = task.step("BOMB")
    assert "Bomb in 3" in obs.splitlines()[0]
    for _ in range(task.params.fuse - 1):
        _, reward, term, _, _ = task.step("WAIT")
        assert not term
    _, reward, term, _, info = task.step("WAIT")
    assert term and task.won is False and task.episode_return <= 0 and not info["clamped"]
    assert "caught in the blast" in info["frame"].message
    assert "*" in "".join(info["frame"].grid)


def test_blast_is_cut_by_walls_and_stops_at_crates():
    task = glyphbench_rl.make(TASK)
    task.reset(seed=1)
    task.set_tile(3, 2, CRATE)
    task.set_tile(3, 1, FLOOR)
    task.set_tile(3, 3, FLOOR)
    cells = set(task.blast_cells((3, 1)))
    assert (3, 2) in cells and (3, 3) not in cells       # the crate stops the blast
    assert (3, 0) not in cells and (2, 1) in cells and (1, 1) in cells
    assert set(task.blast_cells((1, 2))) >= {(1, 1), (1, 2)} and (2, 2) not in task.blast_cells((1, 2))


def test_levels_keep_the_start_clear_and_hide_the_exit():
    task = glyphbench_rl.make(TASK)
    for seed in range(30):
        obs, _ = task.reset(seed=seed)
        assert all(task.tiles[r][c] == FLOOR for r, c in SAFE) and task.player == START
        assert task.tiles[task.exit[0]][task.exit[1]] == CRATE and "◎" not in obs
        p = task.params
        assert p.min_enemies <= len(task.enemies) <= p.max_enemies
        assert len({e.cell for e in task.enemies}) == len(task.enemies)
        assert all(task.tiles[e.r][e.c] == FLOOR for e in task.enemies)


def test_enemy_touch_loses():
    task = glyphbench_rl.make(TASK, min_enemies=1, max_enemies=1)
    task.reset(seed=2)
    task.enemies[0].r, task.enemies[0].c = 1, 2
    _, reward, term, _, info = task.step("RIGHT")
    assert term and task.won is False and reward == -task.params.death_penalty
    assert "ran into an enemy" in info["frame"].message


def test_bad_params():
    with pytest.raises(ValueError, match="size"):
        glyphbench_rl.make(TASK, size=10)
    with pytest.raises(ValueError, match="min_enemies"):
        glyphbench_rl.make(TASK, min_enemies=3, max_enemies=2)
    with pytest.raises(ValueError, match="blast_range"):
        glyphbench_rl.make(TASK, blast_range=5)
    with pytest.raises(ValueError, match="enemy_speed"):
        glyphbench_rl.make(TASK, enemy_speed=0)
