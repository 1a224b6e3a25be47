from collections import deque

import pytest

import glyphbench_rl
from glyphbench_rl.games.common.grid import shortest_path
from glyphbench_rl.games.procgen.engine import DELTAS
from glyphbench_rl.games.procgen.shooting import FOE, GONE, Body

GAMES = ["bigfish", "dodgeball"]


@pytest.mark.parametrize("game", GAMES)
def test_fifty_seeds_give_distinct_levels(game):
    task = glyphbench_rl.make(f"glyphbench/procgen-{game}-v0")
    levels = set()
    for seed in range(50):
        task.reset(seed=seed)
        levels.add((tuple(task._rows()), tuple(sorted(task._sprites())),
                    tuple(sorted(task._movers()))))
    assert len(levels) >= 45


# -- bigfish -----------------------------------------------------------------------------------
def eat_small_avoid_big(task):
    """A greedy fish: a step no bigger fish can reach within two turns, towards the nearest fish
    it may eat (where that fish will be next turn)."""
    p, world = task.player, task.world
    fish = [b for b in world.bodies if b.alive and b.side & FOE]
    danger = set()
    for f in fish:
        if f.hp > task.size:
            step = 1 if f.vc > 0 else -1
            danger.update((f.r, x) for x in range(f.c - step, f.c + 2 * f.vc + step, step))
    food = [(f.r, f.c + f.vc) for f in fish if f.hp <= task.size]
    best, choice = None, 0
    for action, (dr, dc) in enumerate(DELTAS):
        r, c = p.r + dr, p.c + dc
        if not world.inside(r, c) or (r, c) in danger:
            continue
        far = min((abs(r - fr) + abs(c - fc) for fr, fc in food), default=0)
        if best is None or far < best:
            best, choice = far, action
    return choice


def test_bigfish_greedy_policy_scores_positive_and_wins_seeds():
    task = glyphbench_rl.make("glyphbench/procgen-bigfish-v0")
    returns = []
    for seed in range(10):
        task.reset(seed=seed)
        while not task.done:
            task.step(eat_small_avoid_big(task))
        returns.append(task.episode_return)
        if seed in (0, 1, 2):
            assert task.won and task.size == 6 and task.episode_return == pytest.approx(1.0)
    assert sum(returns) / len(returns) > 0.5


def place(task, size, r, c, vc):
    return task.world.add(Body(str(size), r, c, 0, vc, side=FOE, hp=size, edge=GONE))


def test_bigfish_eat_equal_grow_and_die_to_a_bigger_fish():
    task = glyphbench_rl.make("glyphbench/procgen-bigfish-v0", min_fish=1)
    task.reset(seed=0)
    task.world.bodies = [task.player]
    task.spawner.next = 10 ** 6
    r, c = task.pos
    place(task, 1, r, c + 2, -1)            # a size-1 fish swims into you: eaten
    _, reward, term, _, _ = task.step("RIGHT")
    assert reward == pytest.approx(0.1) and task.eaten == 1 and task.size == 1 and not term
    place(task, 1, r, task.pos[1] - 1, 2)   # a fast one passing through you: met on its way
    _, reward, _, _, _ = task.step("NOOP")
    assert task.eaten == 2 and task.size == 2 and "grew to size 2" in task.frame.message
    place(task, 3, r + 1, task.pos[1], 0)   # a bigger fish: touching it ends the game
    _, reward, term, _, info = task.step("DOWN")
    assert term and info["won"] is False and reward == pytest.approx(-1.0)
    assert task.episode_return == pytest.approx(-0.8)


# -- dodgeball ---------------------------------------------------------------------------------
def dodge_and_throw(task):
    """Out of a ball's way first; THROW when an enemy stands in a clear line ahead; otherwise the
    shortest walk (around enemies' reach and balls' paths) to a cell and facing with an enemy in
    line, or to the open exit."""
    me, world, rows = task.player, task.world, task.world.rows
    enemies = [b for b in world.bodies if b.alive and b.glyph == "E"]
    danger = set()
    for e in enemies:
        danger.update((e.r + dr, e.c + dc) for dr, dc in DELTAS)
    for b in world.bodies:
        if b.alive and b.glyph == "o":
            danger.update((b.r + b.vr * k, b.c + b.vc * k) for k in range(3))
    def open_(r, c):
        return rows[r][c] in ".◎" and (r, c) not in danger
    def aligned(r, c, d):
        dr, dc = DELTAS[d]
        for k in range(1, task.params.reach + 1):
            cell = (r + dr * k, c + dc * k)
            if rows[cell[0]][cell[1]] != ".":
                return False
            if any(e.cell == cell for e in enemies):
                return k >= 2
        return False
    ready = task.gun.ready <= task.turn
    if (me.r, me.c) in danger:          # step out of a ball's way first
        return next((a for a in range(1, 5) if open_(me.r + DELTAS[a][0], me.c + DELTAS[a][1])), 0)
    if enemies and ready and task.facing and aligned(me.r, me.c, task.facing):
        return 5
    start = (me.r, me.c, task.facing)
    def goal(s):
        return (rows[s[0]][s[1]] == "◎") if not enemies else (s[2] and aligned(*s))
    if goal(start):
        return 0 if (me.r, me.c) not in danger else next(
            (a for a in range(1, 5) if open_(me.r + DELTAS[a][0], me.c + DELTAS[a][1])), 0)
    prev = {start: None}
    queue = deque([start])
    while queue:
        s = queue.popleft()
        if goal(s):
            while prev[s][0] != start:
                s = prev[s][0]
            return prev[s][1]
        for a in range(1, 5):
            r, c = s[0] + DELTAS[a][0], s[1] + DELTAS[a][1]
            n = (r, c, a)
            if n not in prev and open_(r, c):
                prev[n] = (s, a)
                queue.append(n)
    if (me.r, me.c) not in danger:
        return 0
    return next((a for a in range(1, 5) if open_(me.r + DELTAS[a][0], me.c + DELTAS[a][1])), 0)


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_dodgeball_scripted_policy_clears_the_arena_and_leaves(seed):
    task = glyphbench_rl.make("glyphbench/procgen-dodgeball-v0")
    task.reset(seed=seed)
    while not task.done:
        task.step(dodge_and_throw(task))
    assert task.won and task.left == 0 and task.episode_return == pytest.approx(1.0)


def test_dodgeball_walking_at_the_enemies_loses():
    task = glyphbench_rl.make("glyphbench/procgen-dodgeball-v0")
    task.reset(seed=0)
    while not task.done:
        enemy = min((b for b in task.world.bodies if b.glyph == "E"),
                    key=lambda b: abs(b.r - task.pos[0]) + abs(b.c - task.pos[1]))
        path = shortest_path(task.pos, enemy.cell, lambda r, c: task.world.rows[r][c] == ".")
        task.step(path[0] if path else "NOOP")
    assert task.won is False and task.episode_return < 0
    assert task.frame.message.split(".")[0] in ("An enemy caught you", "A ball hit you")


def test_dodgeball_throw_hits_and_the_last_hit_opens_the_exit():
    task = glyphbench_rl.make("glyphbench/procgen-dodgeball-v0", enemies=1, throw_chance=0.0,
                              walls=0)
    task.reset(seed=5)
    enemy = next(b for b in task.world.bodies if b.glyph == "E")
    task.player.r, task.player.c = task.pos = r, c = (10, 5)
    enemy.r, enemy.c = r - 2, c               # two cells above you (you face up at first)
    task.turn = 0                              # the throw is turn 1, odd: the enemy stands still
    _, reward, _, _, _ = task.step("THROW")
    assert reward == pytest.approx(0.6) and task.left == 0 and not enemy.alive
    assert task.world.rows[task.exit[0]][task.exit[1]] == "◎"
    assert "exit is open" in task.frame.message
    path = shortest_path(task.pos, task.exit, lambda r, c: task.world.rows[r][c] in ".◎")
    for move in path:
        task.step(move)
    assert task.won and task.episode_return == pytest.approx(1.0)


def test_dodgeball_enemy_ball_flies_along_a_clear_line_and_kills():
    task = glyphbench_rl.make("glyphbench/procgen-dodgeball-v0", throw_chance=1.0, walls=0)
    task.reset(seed=1)
    enemies = [b for b in task.world.bodies if b.glyph == "E"]
    r, c = task.pos
    for i, e in enumerate(enemies):            # one enemy in your column, the rest far aside
        e.r, e.c = (r + 4, c) if r + 4 < task.params.height - 1 else (r - 4, c)
        if i:
            e.alive = False
    task.world.cull()
    _, _, term, _, _ = task.step("NOOP")
    ball = next(b for b in task.world.bodies if b.glyph == "o")
    assert not term and (ball.r - r) * (ball.vr) < 0 and ball.c == c
    while not task.done:
        task.step("NOOP")
    assert task.won is False and task.frame.message.startswith("A ball hit you")
