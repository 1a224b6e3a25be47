"""Platform games (Montezuma's Revenge, Pitfall!): scripted policies that score and reach new
rooms or screens, loss paths, and each game's signature mechanics on the platform engine."""

from __future__ import annotations

from collections import deque

import pytest

from glyphbench_rl import make
from glyphbench_rl.games.arcade import montezumarevenge as mz
from glyphbench_rl.games.arcade import pitfall as pf
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
                if shut and door.lower() not in t.items:
                    return False
    return True


def doable(t, room):
    """Whether a room holds something to take now (a shut door counts only with its key)."""
    rows = t.rows_of.get(room)
    stuck = sum(1 for _, door in t.plan[room]["doors"]
                if (rows is None or any(door in row for row in rows)) and door.lower() not in t.items)
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
    kind, mid = t.plan[t.room]["kind"], t.params.width // 2
    if kind == "laser" and nxt == mid and any(t.blinks[0].lit_at(t.tick + k) for k in (1, 2, 3)):
        return NOOP
    if kind == "bridge" and nxt == mid - 2 * d and not all(t.blinks[0].lit_at(t.tick + k) for k in range(1, 8)):
        return NOOP
    if kind != "bridge" and 0 <= nxt < t.params.width and rows[low + 1][nxt] == mz.FIRE:
        return UP_RIGHT if d > 0 else UP_LEFT
    walk = [(low, c + d * k) for k in range(1, 4)]
    jump = [(low - 1, c + d), (low - 1, c + 2 * d), (low - 1, c + 3 * d), (low, c + 4 * d)]
    if not t.foes or safe(t, walk):
        return RIGHT if d > 0 else LEFT
    if safe(t, jump) and rows[low + 1][min(max(c + 4 * d, 0), t.params.width - 1)] not in (mz.FIRE, mz.EMPTY):
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
    goals += [(low, cc) for cc in (1, w - 2) if rows[low][cc] in mz.DOORS and rows[low][cc].lower() in t.items]
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
        for room, plan in env.plan.items():                # every treasure and door is drawn
            text = "".join(env._build(room))
            assert sum(text.count(g) for g in mz.PAY) == len(plan["items"])
            assert sum(text.count(d) for _, d in plan["doors"]) == 3 * len(plan["doors"])
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
    env.items = door.lower() + "x"
    before = env.score.points
    _, reward, *_ = env.step(LEFT if dc < 0 else RIGHT)
    assert env.c == col and env.still[low][col] == mz.EMPTY and env.items == "x"
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
    gate = env.blinks[0]
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
    assert info["return"] == pytest.approx(env.score.points - 1)   # the last life pays death = -1


# -- Pitfall! -----------------------------------------------------------------------------------------
PF = "glyphbench/atari-pitfall-v0"
P_NOOP, P_FIRE, P_UP, P_RIGHT, P_LEFT, P_DOWN = range(6)


def leap(t):
    """Jump right: FIRE when facing right, else turn right first (a step back left, then right)."""
    return P_FIRE if t.face > 0 else P_RIGHT


def pf_policy(t):
    """Run right along the ground: leap holes, fire, snakes, logs and crocodiles, swing across
    pits on the vine, wait out the quicksand; in the tunnel, run to a ladder and climb."""
    p, rows, r, c, tick = t.params, t.still, t.r, t.c, t.tick
    mid, kind = p.width // 2, t.kinds[t.screen]
    if t.held is not None:
        return P_DOWN if c >= mid + 6 else P_NOOP
    if t.arc is not None:
        return P_NOOP
    if r > pf.SURFACE:                               # below: climb out
        if rows[r][c] == LADDER:
            return P_UP
        if any(f.glyph == "X" and 0 < (f.c - c) * t.face <= 2 for f in t.foes):
            return P_FIRE
        if kind == "ladder" and not any(rows[r][k] == pf.EARTH for k in range(min(c, mid), max(c, mid))):
            return P_RIGHT if mid > c else P_LEFT
        if rows[r][c + t.face] == pf.EARTH if 0 <= c + t.face < p.width else False:
            return P_LEFT if t.face > 0 else P_RIGHT
        return P_RIGHT if t.face > 0 else P_LEFT
    if t.face < 0:
        return P_RIGHT
    nxt = c + 1
    ahead = rows[7][nxt] if nxt < p.width else pf.GROUND
    if kind in ("tar", "pond") and ahead in t.HAZARD:
        return P_FIRE if any(abs(t.swings[0].tip(tick + k)[1] - (c + k)) <= 1 for k in (1, 2, 3)) else P_NOOP
    if kind == "quicksand" and c == mid - 7:
        return P_RIGHT if not any(t.blinks[0].lit_at(tick + k) for k in range(1, 16)) else P_NOOP
    if kind == "swamp" and rows[7][c] in (pf.JAWS, pf.SHUT):
        return P_FIRE                                # from a head straight on to the next
    if kind == "swamp" and ahead in t.HAZARD:
        return P_NOOP if any(t.blinks[0].lit_at(tick + k) for k in (4, 5, 8, 9)) else P_FIRE
    if ahead == mz.EMPTY:                            # a hole by a ladder
        return P_FIRE
    for f in t.foes:
        if f.glyph == "s" and 1 <= f.c - c <= 3:
            return P_FIRE
        if f.glyph == "o" and 1 <= f.c - c <= 2:
            return P_FIRE
    if pf.FIRE in rows[pf.SURFACE][c + 1:c + 4]:
        return P_FIRE
    return P_RIGHT


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_pitfall_scripted_runner_crosses_screens_and_finds_treasure(seed):
    env, info = play(PF, pf_policy, seed, 1500)
    assert len(env.map.visited) >= 15
    assert env.score.done >= 1 and env.score.points >= 1000 and env.lives >= 2


def screen_of(env, kind, start=1):
    s = next(s for s in range(start, env.params.screens) if env.kinds[s] == kind)
    env._enter(s, pf.SURFACE, 2)
    return s


def test_pitfall_vine_swings_you_over_the_tar_pit():
    env = make(PF)
    env.reset(seed=0)
    screen_of(env, "tar")
    mid = env.params.width // 2
    env.place(pf.SURFACE, mid - 7)
    while env.held is None:
        a = pf_policy(env)
        assert a in (P_NOOP, P_FIRE)
        env.step(a)
        assert env.lives == 3
    for _ in range(40):
        env.step(pf_policy(env))
        if env.held is None and env.arc is None and env.r == pf.SURFACE:
            break
    assert env.c >= mid + 6 and env.lives == 3
    env.place(pf.SURFACE, mid - 7)                   # running in: the tar takes a life
    env.step(P_RIGHT)
    env.step(P_NOOP)
    assert env.lives == 2 and "sank" in env.frame.message


def test_pitfall_hole_drops_into_the_tunnel_which_moves_three_screens():
    env = make(PF)
    env.reset(seed=0)
    s = screen_of(env, "ladder")
    mid, w = env.params.width // 2, env.params.width
    env.place(pf.SURFACE, mid - 7)
    env.step(P_RIGHT)
    for _ in range(5):
        env.step(P_NOOP)
    assert (env.r, env.lives) == (pf.TUNNEL, 3)      # a hole's fall does no harm
    away = 1 if env.wall[s] > 0 else -1               # the side away from the brick wall
    env.place(pf.TUNNEL, 1 if away < 0 else w - 2)
    env.step(P_LEFT if away < 0 else P_RIGHT)
    env.step(P_LEFT if away < 0 else P_RIGHT)
    assert env.screen == (s + 3 * away) % env.params.screens and env.r == pf.TUNNEL
    env._enter(s, pf.SURFACE, mid - 2)                # the ladder: down and back up
    env.step(P_RIGHT)
    env.step(P_RIGHT)
    for _ in range(4):
        env.step(P_DOWN)
    assert (env.r, env.c) == (pf.TUNNEL, mid)
    for _ in range(4):
        env.step(P_UP)
    assert (env.r, env.c) == (pf.SURFACE, mid)


def test_pitfall_log_costs_points_once_a_hit_and_the_clock_ends_the_run():
    env = make(PF)
    env.reset(seed=0)
    screen_of(env, "logs")
    log = env.foes[0]
    env.place(pf.SURFACE, log.c - 1)
    rewards = [env.step(P_NOOP)[1] for _ in range(6)]
    assert rewards.count(-100) == 1 and env.score.points == -100 and env.lives == 3
    env = make(PF, clock=100)
    env.reset(seed=0)
    total, done = 0.0, False
    while not done:
        _, r, done, _, info = env.step(P_NOOP)
        total += r
    assert env.turn == 100 and info["won"] is False and total == -1
    assert "Time is up" in env.frame.message


def test_pitfall_running_into_the_swamp_loses_every_life():
    env, info = play(PF, lambda env: P_RIGHT, 0, 500)
    assert env.done and env.won is False and env.lives == 0 and info["return"] == -1


def test_pitfall_crocodile_heads_hold_you_only_while_shut_and_quicksand_opens_under_you():
    env = make(PF)
    env.reset(seed=0)
    screen_of(env, "swamp")
    mid, jaws = env.params.width // 2, env.blinks[0]
    while jaws.lit_at(env.tick + 1):
        env.step(P_NOOP)
    env.place(pf.SURFACE, mid - 3)
    held = 0
    while env.lives == 3:
        env.step(P_NOOP)
        held += 1
    assert held >= 2 and not jaws.lit_at(env.tick - 1) and jaws.lit_at(env.tick)
    assert "crocodile" in env.frame.message
    screen_of(env, "quicksand")
    sand = env.blinks[0]
    while sand.lit_at(env.tick + 1):
        env.step(P_NOOP)
    env.place(pf.SURFACE, mid)
    while env.lives == 2:
        env.step(P_NOOP)
    assert sand.lit_at(env.tick) and "sank" in env.frame.message


def test_montezuma_sword_kills_the_monster_it_meets_and_is_used_up():
    env = fresh(0, "snake")
    room, low, mid = env.room, env.params.height - 2, env.params.width // 2
    env.place(low, mid - 1)
    env.items = mz.SWORD + "r"
    env.step(RIGHT)
    assert env.lives == 5 and env.foes == [] and env.items == "r" and "sword kills the snake" in env.frame.message
    env._enter(room, low, 3)
    assert env.foes == []                              # it stays dead
    env = fresh(0, "snake")
    env.place(low, mid - 1)
    env.step(RIGHT)
    assert env.lives == 4 and "snake got you" in env.frame.message


def test_montezuma_vanishing_floor_drops_you_into_the_fire():
    env = fresh(0, "bridge")
    low, mid = env.params.height - 2, env.params.width // 2
    floor = env.blinks[0]
    while not floor.lit_at(env.tick + 1):
        env.step(NOOP)
    env.place(low, mid)
    steps = 0
    while env.lives == 5:
        env.step(NOOP)
        steps += 1
    assert steps >= 2 and floor.lit_at(env.tick - 1) and not floor.lit_at(env.tick) and "burned" in env.frame.message
