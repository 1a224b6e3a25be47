"""Platform games (Montezuma's Revenge, Pitfall!): scripted policies that score and reach new
rooms or screens, loss paths, and each game's signature mechanics on the platform engine."""

from __future__ import annotations

from collections import deque

import pytest

from glyphbench_rl import make
from glyphbench_rl.games.arcade import montezumarevenge as mz
from glyphbench_rl.games.arcade.platform import LADDER, ROPE, Blink, Swing, Walker

from arcade_play import play

MZ = "glyphbench/atari-montezumarevenge-v0"
NOOP, FIRE, UP, RIGHT, LEFT, DOWN, UP_RIGHT, UP_LEFT = range(8)


# -- the engine ---------------------------------------------------------------------------------
def test_walker_paces_between_its_ends_rolls_round_or_closes_in():
    w = Walker(0, 2, 1, 3, 1, "S")
    cols = []
    for t in range(1, 7):
        w.step(t)
        cols.append(w.c)
    assert cols == [3, 2, 1, 2, 3, 2]
    roll = Walker(0, 0, 0, 0, 2, "o", d=-1, wrap=5)
    roll.step(1)
    roll.step(2)
    assert roll.c == 4
    chaser = Walker(0, 5, 0, 9, 1, "X", chase=True)
    chaser.step(1, target=2)
    assert chaser.c == 4


def test_blink_and_swing_cycles():
    b = Blink([(0, 0)], "!", ".", 2, 3)
    assert [b.lit_at(t) for t in range(6)] == [True, True, False, False, False, True]
    s = Swing(1, 10, 4, 3)
    offs = [s.offset(t) for t in range(12)]
    assert offs == [-3, -2, -1, 0, 1, 2, 3, 2, 1, 0, -1, -2]
    assert s.tip(6) == (5, 13) and s.cells(6)[0] == (1, 10, ROPE) and s.cells(6)[-1] == (5, 13, ROPE)


# -- Montezuma's Revenge --------------------------------------------------------------------------
def passable(t, room, nxt):
    """Whether the link room -> nxt can be walked now (a shut door needs its key in hand)."""
    for a, b in ((room, nxt), (nxt, room)):
        for dc, door in t.plan[a]["doors"]:
            if (a[0], a[1] + dc) == b:
                rows = t.rows_of.get(a)
                shut = rows is None or any(door in row for row in rows)
                if shut and door.lower() not in t.keys:
                    return False
    return True


def doable(t, room):
    """Whether a room holds something to take now (a shut door counts only with its key)."""
    rows = t.rows_of.get(room)
    stuck = sum(1 for _, door in t.plan[room]["doors"]
                if (rows is None or any(door in row for row in rows)) and door.lower() not in t.keys)
    return t.plan[room]["left"] > stuck


def links(t, room):
    s, out = t.plan[room], []
    out += [(room[0], room[1] + dc) for dc in s["exits"]]
    if s["top"] is not None:
        out.append((room[0] - 1, room[1]))
    if s["bottom"] is not None:
        out.append((room[0] + 1, room[1]))
    return out


def next_room(t):
    """The first room on a shortest walk to the nearest room with something left to do."""
    start = t.room
    seen, queue = {start: None}, deque([start])
    while queue:
        room = queue.popleft()
        if room != start and doable(t, room):
            while seen[room] != start:
                room = seen[room]
            return room
        for nxt in links(t, room):
            if nxt not in seen and passable(t, room, nxt):
                seen[nxt] = room
                queue.append(nxt)
    return None


def foe_path(t, ticks):
    out = []
    for f in t.foes:
        c, d, path = f.c, f.d, []
        for k in range(1, ticks + 1):
            tick = t.tick + k
            if f.every and not tick % f.every:
                if not f.lo <= c + d <= f.hi:
                    d = -d
                c = min(f.hi, max(f.lo, c + d))
            path.append((f.r, c))
        out.append(path)
    return out


def safe(t, cells):
    """Whether the player's planned cells (one a tick) miss every monster's."""
    paths = foe_path(t, len(cells))
    prev = (t.r, t.c)
    for k, cell in enumerate(cells):
        for path in paths:
            before = path[k - 1] if k else None
            if path[k] == cell or (before == cell and path[k] == prev):
                return False
        prev = cell
    return True


def corridor_step(t, d):
    """Walk one way along the room's floor, jumping fire and monsters, waiting out lasers."""
    low, rows = t.params.height - 2, t.still
    c = t.c
    nxt = c + d
    if 0 <= nxt < t.params.width and rows[low + 1][nxt] == mz.FIRE:
        return UP_RIGHT if d > 0 else UP_LEFT
    if t.lasers and nxt == t.params.width // 2 and any(t.lasers[0].lit_at(t.tick + k) for k in (1, 2, 3)):
        return NOOP
    walk = [(low, c + d * k) for k in range(1, 4)]
    jump = [(low - 1, c + d), (low - 1, c + 2 * d), (low - 1, c + 3 * d), (low, c + 4 * d)]
    if not t.foes or safe(t, walk):
        return RIGHT if d > 0 else LEFT
    if safe(t, jump) and rows[low + 1][min(max(c + 4 * d, 0), t.params.width - 1)] != mz.FIRE:
        return UP_RIGHT if d > 0 else UP_LEFT
    if safe(t, [(low, c)] * 3):
        return NOOP
    return LEFT if d > 0 else RIGHT


def mz_policy(env):
    t = env
    p = t.params
    h, w, low, top = p.height, p.width, p.height - 2, p.height - 7
    rows, r, c, s = t.still, t.r, t.c, t.plan[t.room]
    if t.arc is not None:
        return NOOP
    if rows[r][c] == ROPE:
        return UP_RIGHT if t.face > 0 else UP_LEFT
    goals = [(rr, cc) for rr in (top, low) for cc in range(w) if rows[rr][cc] in mz.PAY]
    goals += [(low, cc) for cc in (1, w - 2) if rows[low][cc] in mz.DOORS and rows[low][cc].lower() in t.keys]
    lc = s["ledge"]
    if goals:
        gr, gc = min(goals, key=lambda g: (g[0] != r, abs(g[1] - c)))
        exit_ = None
    else:
        room = next_room(t)
        if room is None:
            return NOOP
        exit_ = (room[0] - t.room[0], room[1] - t.room[1])
        gr = low
        gc = {(0, -1): 0, (0, 1): w - 1, (1, 0): s["bottom"], (-1, 0): s["top"]}[exit_]
    if exit_ == (-1, 0) and c == gc and rows[r][c] == LADDER:
        return UP
    span = () if lc is None else range(1, 7) if lc < w // 2 else range(w - 7, w - 1)
    on_ledge = r == top and c in span
    if on_ledge and gr == top:
        return NOOP if c == gc else RIGHT if gc > c else LEFT
    if on_ledge and gr != top:                     # on a ledge: to its ladder, then down
        return DOWN if c == lc else (RIGHT if lc > c else LEFT)
    if r < low and not on_ledge:                   # on a ladder
        return UP if gr == top and c == lc else DOWN
    if r == h - 1:                                 # in the floor's ladder hole
        return DOWN if exit_ == (1, 0) else UP
    if gr == top and r == low:
        if c == lc:
            return UP
        return corridor_step(t, 1 if lc > c else -1)
    if c == gc:
        if exit_ == (1, 0):
            return DOWN
        return {(0, -1): LEFT, (0, 1): RIGHT}.get(exit_, NOOP)
    return corridor_step(t, 1 if gc > c else -1)


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_montezuma_scripted_policy_clears_the_pyramid(seed):
    env, info = play(MZ, mz_policy, seed, 1500)
    assert env.won is True and env.score.done == 24 and len(env.map.visited) == 24
    assert env.score.points >= 24 * 100 + 4 * 400 and info["return"] == env.score.points


def test_montezuma_pyramid_always_has_a_way_through():
    for seed in range(30):
        env = make(MZ)
        env.reset(seed=seed)
        assert len(env.map.rooms) == 24
        keys, opened, reach, grew = set(), set(), {mz.START}, True
        while grew:
            grew = False
            todo = list(reach)
            while todo:
                room = todo.pop()
                keys |= {k for k in env.plan[room]["items"] if k in mz.KEYS}
                for nxt in links(env, room):
                    door = [d for a in (room, nxt) for dc, d in env.plan[a]["doors"] if (a[0], a[1] + dc) in (room, nxt)]
                    if nxt in reach or (door and door[0] not in opened):
                        continue
                    reach.add(nxt)
                    todo.append(nxt)
            for room in list(reach):
                for dc, d in env.plan[room]["doors"]:
                    if d not in opened and d.lower() in keys:
                        opened.add(d)
                        grew = True
        assert len(reach) == 24, seed
        assert {nxt for room in reach for nxt in links(env, room)} <= env.map.rooms


def fresh(seed, kind):
    """A Montezuma episode whose current room is the first of ``kind`` (entered on its floor)."""
    env = make(MZ)
    env.reset(seed=seed)
    room = next(r for r in sorted(env.plan) if env.plan[r]["kind"] == kind)
    env._enter(room, env.params.height - 2, 3 if 3 not in (env.plan[room]["top"],) else 4)
    return env


def test_montezuma_rope_carries_you_over_a_wide_fire_pit():
    env = fresh(0, "rope")
    mid, low = env.params.width // 2, env.params.height - 2
    env.place(low, mid - 3)
    env.step(UP_RIGHT)
    env.step(NOOP)
    env.step(NOOP)
    assert env.still[env.r][env.c] == ROPE           # grabbed mid-jump
    for _ in range(4):
        env.step(NOOP)
    assert env.still[env.r][env.c] == ROPE and env.lives == 5   # it holds you
    env.step(UP_RIGHT)
    for _ in range(6):
        env.step(NOOP)
    assert (env.r, env.c) == (low, mid + 4) and env.lives == 5
    env.place(low, mid - 3)                           # without the rope: into the fire
    env.step(RIGHT)
    env.step(RIGHT)
    env.step(NOOP)
    assert env.lives == 4


def test_montezuma_key_opens_one_door_of_its_colour():
    env = make(MZ)
    for seed in range(20):
        env.reset(seed=seed)
        rooms = [r for r in sorted(env.plan) if env.plan[r]["doors"]]
        if rooms:
            break
    room = rooms[0]
    dc, door = env.plan[room]["doors"][0]
    low, w = env.params.height - 2, env.params.width
    col = 1 if dc < 0 else w - 2
    env._enter(room, low, col - dc)
    env.step(LEFT if dc < 0 else RIGHT)
    assert env.c == col - dc and env.still[low][col] == door          # shut without the key
    env.keys = door.lower() + "x"
    before = env.score.points
    _, reward, *_ = env.step(LEFT if dc < 0 else RIGHT)
    assert env.c == col and env.still[low][col] == mz.EMPTY and env.keys == "x"
    assert reward == 300 and env.score.points == before + 300


def test_montezuma_fall_from_a_ledge_costs_a_life_but_a_jump_does_not():
    env = make(MZ)
    env.reset(seed=0)
    room = next(r for r in sorted(env.plan) if env.plan[r]["ledge"] is not None)
    p = env.params
    env._enter(room, p.height - 2, 3)
    lc = env.plan[room]["ledge"]
    edge, d = (6, RIGHT) if lc < p.width // 2 else (p.width - 7, LEFT)
    env.place(p.height - 7, edge)
    for _ in range(8):
        env.step(d)
        if env.lives < 5:
            break
    assert env.lives == 4 and "fell too far" in env.frame.message
    env.place(p.height - 2, 5)
    env.step(FIRE)
    for _ in range(4):
        env.step(NOOP)
    assert env.lives == 4 and env.r == p.height - 2


def test_montezuma_laser_gate_burns_only_while_lit():
    env = fresh(0, "laser")
    mid, low = env.params.width // 2, env.params.height - 2
    gate = env.lasers[0]
    while not gate.lit_at(env.tick + 1):
        env.step(NOOP)
    env.place(low, mid)
    env.step(NOOP)
    assert env.lives == 4
    while gate.lit_at(env.tick + 1) or gate.lit_at(env.tick + 2):
        env.step(NOOP)
    env.place(low, mid - 1)
    env.step(RIGHT)
    env.step(RIGHT)
    assert env.lives == 4 and env.c == mid + 1


def test_montezuma_monsters_cost_lives_until_the_game_is_lost():
    def into_the_skull(env):
        foes = env.foes
        if not foes or env.r != env.params.height - 2:
            return DOWN
        return RIGHT if foes[0].c > env.c else LEFT if foes[0].c < env.c else NOOP
    env, info = play(MZ, into_the_skull, 0, 2000)
    assert env.done and env.won is False and env.lives == 0
    assert info["return"] <= env.score.points - 1000 + 1e-9
