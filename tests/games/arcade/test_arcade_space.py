"""The space and arena games without a MiniAtari twin (gravitar, solaris, krull): per game a
scripted policy that scores and reaches a new place, a loss path, and the signature mechanics."""

from __future__ import annotations

import copy

import pytest

from glyphbench_rl import make
from glyphbench_rl.games.arcade.sectors import HEADINGS, SCALE, Ship, heading_to

from arcade_play import play

GRAVITAR = "glyphbench/atari-gravitar-v0"
NOOP, LEFT, RIGHT, THRUST, FIRE = range(5)


# -- gravitar ---------------------------------------------------------------------------------------
def steer(env, tr: int, tc: int, fast: int = 3):
    """A thrust controller toward cell (tr, tc): the action that closes the gap between the wanted
    velocity and the ship's, or None when the ship is there and at rest."""
    s = env.ship
    ey, ex = tr * SCALE + SCALE // 2 - s.y, tc * SCALE + SCALE // 2 - s.x
    wy = max(-fast, min(fast, ey // 4 if ey > 0 else -(-ey // 4)))
    wx = max(-fast, min(fast, ex // 4 if ex > 0 else -(-ex // 4)))
    if env.planet is not None:
        wy -= 1                                   # lean against gravity
    dy, dx = wy - s.vy, wx - s.vx
    if abs(dy) < 2 and abs(dx) < 2:
        if abs(ey) <= SCALE and abs(ex) <= SCALE:
            return None
        if abs(dy) < 1 and abs(dx) < 1:
            return NOOP
    dy = dy if abs(dy) >= 1 else 0
    dx = dx if abs(dx) >= 1 else 0
    return turn_to(s, heading_to(dy, dx)) or THRUST


def turn_to(ship, want: int):
    """The rotation toward heading ``want`` (None when the ship points that way)."""
    k = (want - ship.head) % 8
    return None if k == 0 else RIGHT if k <= 4 else LEFT


def bunker_spot(env):
    """Where to hover to shoot the nearest bunker: along a diagonal (out of its line of fire),
    else from straight above."""
    best = None
    for f in env.foes:
        for side in (-1, 1, 0):
            for d in (5, 4, 6, 3):
                r, c = f.r - d, f.c + side * d
                if not (1 <= r and 0 <= c < env.params.width):
                    continue
                line = [(f.r - k, f.c + side * k) for k in range(1, d + 1)]
                if all(env.still[a][b] == "." for a, b in line):
                    score = abs(r - env.r) + abs(c - env.c) + (20 if side == 0 else 0)
                    if best is None or score < best[0]:
                        best = (score, r, c, heading_to(1, -side))
                    break
    return best


def in_sights(env) -> bool:
    """Whether a shot now would hit a bunker (the ray along the heading, within reach)."""
    dr, dc = HEADINGS[env.ship.head]
    r, c = env.r, env.c
    for _ in range(env.params.reach):
        r, c = r + dr, c + dc
        if not (0 <= r < env.params.height and 0 <= c < env.params.width) or env.still[r][c] == "#":
            return False
        if env.foe_at(r, c):
            return not env.gun.shots
    return False


def gravitar_policy(order=(2, 3, 0, 1)):
    """Planets in ``order`` (the next one not destroyed); on a surface, for the nearest bunker:
    hover above the diagonal it can be shot along, turn to it and drop through the line, firing
    when it is in the sights; then climb back."""
    drop = {"on": False, "from": 0}

    def policy(env):
        if env.planet is None:
            drop["on"] = False
            k = next((k for k in order if env.still[env._planets()[k][0]][env._planets()[k][1]] != "x"), order[0])
            pr, pc = env._planets()[k]
            return steer(env, pr + (pr < env.params.height // 2), pc) or THRUST
        if in_sights(env):
            drop["on"] = False
            return FIRE
        spot = bunker_spot(env)
        if spot is None:
            return steer(env, 0, env.c) or THRUST
        _, r, c, aim = spot
        if drop["on"]:
            if env.r <= drop["from"] + 3 and env.ship.vy <= 2:
                return turn_to(env.ship, aim) or NOOP
            drop["on"] = False
        act = steer(env, r - 2, c, fast=2)
        if act is not None:
            return act
        drop["on"], drop["from"] = True, env.r
        return turn_to(env.ship, aim) or NOOP
    return policy


@pytest.mark.parametrize("seed", [1, 2])
def test_gravitar_policy_lands_and_shoots_bunkers(seed):
    env, _ = play(GRAVITAR, gravitar_policy(), seed, turns=1500)
    assert env.sectors.map.visited >= {(0, 0), (0, 3), (0, 4)}      # planets 3 and 4 reached
    assert env.score.done >= 6 and env.episode_return >= 6 * env.params.unit


def test_gravitar_sun_pulls_a_coasting_ship_in():
    env = make(GRAVITAR)
    env.reset(seed=0)
    while env.lives == env.params.lives:
        _, _, _, _, info = env.step(NOOP)
    assert "the sun" in info["frame"].message and env.turn < 200


def test_gravitar_crash_on_the_ground_costs_a_ship_and_all_ships_end_it():
    env = make(GRAVITAR)
    env.reset(seed=3)
    env._go(0, 1, env.params.width // 2)
    for _ in range(200):
        env.step(NOOP)
        if env.lives < env.params.lives:
            break
    assert env.lives == env.params.lives - 1 and env.planet == 0 and (env.r, env.c) == (1, env.params.width // 2)
    env, _ = play(GRAVITAR, lambda e: NOOP, 0)
    assert env.done and not env.won and env.lives == 0


def test_gravitar_gravity_and_thrust_move_the_ship():
    s = Ship(5, 5)
    s.push()
    assert (s.vy, s.vx) == (-2, 0)
    s.rotate(2)
    for _ in range(5):
        s.push()
    assert (s.vy, s.vx) == (-2, SCALE)                     # capped at a cell a turn
    assert HEADINGS[s.head] == (0, 1)


def test_gravitar_tractor_beam_takes_a_tank_and_fuel_runs_out():
    env = make(GRAVITAR)
    env.reset(seed=4)
    env._go(1, 1, 0)
    rows = env.still
    c = next(c for c in range(env.params.width) if "F" in (row[c] for row in rows))
    g = env.ground[1][c]
    env._go(1, g - 2, c)
    before = env.air.left
    env.step(NOOP)
    assert env.air.left > before and env.still[g - 1][c] == "."
    env = make(GRAVITAR, air=200)
    env.reset(seed=0)
    while not env.done:
        _, _, _, _, info = env.step(steer(env, 17, 3) or NOOP)
    assert env.lives == env.params.lives and not env.won and env.turn < 200
    assert "fuel" in info["frame"].message


def test_gravitar_last_bunker_destroys_the_planet():
    env = make(GRAVITAR)
    env.reset(seed=0)
    env._go(2, 1, 3)
    for f in env.foes[1:]:
        env._hit(f)
    _, r, c, aim = bunker_spot(env)
    env._go(2, r, c)
    env.ship.head = aim
    env.step(FIRE)
    for _ in range(4):
        if env.planet is None:
            break
        env.step(NOOP)
    assert env.planet is None and env.score.done == env.params.bunkers
    pr, pc = env._planets()[2]
    assert env.still[pr][pc] == "x"


# -- solaris ----------------------------------------------------------------------------------------
SOLARIS = "glyphbench/atari-solaris-v0"
UP, DOWN, S_LEFT, S_RIGHT, S_FIRE, WARP = 1, 2, 3, 4, 5, 6
STEPS = {(-1, 0): UP, (1, 0): DOWN, (0, -1): S_LEFT, (0, 1): S_RIGHT}


def hunter(env):
    """Face a foe in line and fire; else line up on the nearest foe's short axis."""
    best = None
    for f in env.foes:
        dr, dc = f.r - env.r, f.c - env.c
        if (dr == 0 or dc == 0) and abs(dr) + abs(dc) <= env.params.reach:
            d = ((dr > 0) - (dr < 0), (dc > 0) - (dc < 0))
            return S_FIRE if env.face == d else STEPS[d]
        key = (min(abs(dr), abs(dc)), abs(dr) + abs(dc))
        if best is None or key < best[0]:
            best = (key, dr, dc)
    if best is None:
        return NOOP
    _, dr, dc = best
    if dr and abs(dr) <= abs(dc) or not dc:    # close the short axis, or the gap in line
        return STEPS[((dr > 0) - (dr < 0), 0)]
    return STEPS[(0, (dc > 0) - (dc < 0))]


def safe(env, action: int) -> bool:
    """Whether ``action`` then a turn of waiting keeps the ship (a two-turn look ahead)."""
    memo = {id(getattr(env, k)): getattr(env, k) for k in ("_drawn", "_layers")}   # caches
    e = copy.deepcopy(env, memo)
    lives = e.lives
    e.step(action)
    if not e.done:
        e.step(NOOP)
    return e.lives == lives and not (e.done and not e.won)


def solaris_policy(env):
    if env.foes:
        act = hunter(env)
        if env.shells.shots or min(abs(f.r - env.r) + abs(f.c - env.c) for f in env.foes) <= 4:
            for a in (act, S_FIRE, UP, DOWN, S_LEFT, S_RIGHT, NOOP):
                if safe(env, a):
                    return a
        return act
    if env.air.left < 400 and env.planets.get(env.place):
        h, w = env.params.height // 2, env.params.width // 2
        return STEPS[((h > env.r) - (h < env.r), 0)] if env.r != h else STEPS[(0, (w > env.c) - (w < env.c))]
    return WARP


@pytest.mark.parametrize("seed", [0, 1])
def test_solaris_policy_warps_to_fleets_and_shoots_fighters(seed):
    env, _ = play(SOLARIS, solaris_policy, seed, turns=250)
    assert len(env.sectors.map.visited) >= 3
    assert env.score.done >= 8 and env.episode_return >= 8 * env.params.unit


def test_solaris_fleet_in_your_sector_is_fought_until_destroyed():
    env = make(SOLARIS)
    env.reset(seed=2)
    fleet = next(q for q, n in env.sectors.held.items() if n)
    env._enter_sector(fleet)
    assert len(env.foes) == env.params.foes
    n = env.params.fleet
    for k in range(n):
        env._hit(env.foes[0])
    assert env.sectors.held[fleet] is None and not env.foes and env.score.done == n
    assert env.sectors.chart(env._mark).count("@") == 1


def test_solaris_fleets_advance_on_planets_and_cost_ships():
    env = make(SOLARIS, advance=10)
    env.reset(seed=0)
    said = []
    while not env.done and all(env.planets.values()):
        _, _, _, _, info = env.step(NOOP)
        said.append(info["frame"].message)
    assert "A Zylon fleet destroyed a federation planet." in " ".join(said)
    lost = next(q for q, up in env.planets.items() if not up)
    assert env._mark(lost) == ("x" if not env.sectors.held[lost] else str(env.sectors.held[lost]))
    env, _ = play(SOLARIS, lambda e: NOOP if e.foes else WARP, 0)
    assert env.done and not env.won and env.episode_return < 0


def test_solaris_planet_refuels_and_warp_costs_fuel():
    env = make(SOLARIS)
    env.reset(seed=0)
    fuel = env.air.left
    env.step(WARP)
    assert env.air.left == fuel - env.params.jump
    env._enter_sector(next(q for q, up in env.planets.items() if up))
    env.air.left = 100
    env.r, env.c = env.params.height // 2 + 1, env.params.width // 2
    env.step(UP)
    assert env.air.left == env.params.air - 1           # refuelled, then this turn's unit


# -- krull ------------------------------------------------------------------------------------------
KRULL = "glyphbench/atari-krull-v0"
MOVE = {UP: (-1, 0), DOWN: (1, 0), S_LEFT: (0, -1), S_RIGHT: (0, 1)}


def route(env, goal) -> int:
    """The first move of a shortest way to ``goal`` (leaps on the desert, steps elsewhere)."""
    start = (env.r, env.c)
    seen, todo = {start: None}, [start]
    for at in todo:
        if at == goal:
            break
        for a, d in MOVE.items():
            q = env._landing(at, d) if env.stage == 1 else (at[0] + d[0], at[1] + d[1])
            if q in seen or q is None or not (0 <= q[0] < env.params.height and 0 <= q[1] < env.params.width):
                continue
            ch = env.still[q[0]][q[1]]
            if ch == "~" or (ch in env.SOLID and q != goal) or env.foe_at(*q):
                continue
            seen[q] = (at, a)
            todo.append(q)
    at, act = goal, NOOP
    while seen.get(at) is not None:
        at, act = seen[at]
    return act


def krull_policy(env):
    if env.stage == 1:
        door = next((r, c) for r, row in enumerate(env.still) for c, ch in enumerate(row) if ch == "D")
        return route(env, door)
    if env.stage == 0:
        act = hunter(env) if env.back is None else NOOP
    else:
        beast = env.foes[0]
        act = route(env, env.lyssa)
        dr, dc = beast.r - env.r, beast.c - env.c
        if env.back is None and env.tick >= env.stunned and (dr == 0 or dc == 0) and abs(dr) + abs(dc) <= env.params.reach:
            d = ((dr > 0) - (dr < 0), (dc > 0) - (dc < 0))
            act = S_FIRE if env.face == d else STEPS[d]
    for a in (act, NOOP, UP, DOWN, S_LEFT, S_RIGHT):
        if safe(env, a):
            return a
    return act


@pytest.mark.parametrize("seed", [0, 1])
def test_krull_policy_goes_through_the_stages(seed):
    env, _ = play(KRULL, krull_policy, seed)
    assert env.stages.visited >= {(0, 0), (0, 1), (0, 2)}
    assert env.score.done >= 2 and env.episode_return >= 2 * env.params.unit


def krull_at(stage: int, seed: int = 0):
    env = make(KRULL)
    env.reset(seed=seed)
    env.kills = env.params.slayers if stage else 0
    env._stage(stage)
    return env


def test_krull_glaive_flies_back_and_cuts_down_slayers_on_the_way():
    env = krull_at(0)
    env.foes = []
    env.step(S_FIRE)
    while env.back is None:
        env.step(NOOP)
    assert env.gun.shots == [] and env.back is not None
    env.step(S_FIRE)
    assert env.gun.shots == []                         # one glaive: not back yet
    g = env.back
    env.add_foe(g.r + 1, g.c)
    kills = env.kills
    env.step(NOOP)
    assert env.kills == kills + 1
    for _ in range(5):
        env.step(NOOP)
    assert env.back is None and env.gun.shots == []


def test_krull_slayer_carries_lyssa_off_and_waiting_loses_the_game():
    env = krull_at(0)
    lr, lc = env.lyssa
    env.foes = []
    env.add_foe(0, 0)
    env.add_foe(lr - 1, lc)                           # the second Slayer goes for Lyssa
    said = []
    while env.lives == env.params.lives:
        _, _, _, _, info = env.step(NOOP)
        said.append(info["frame"].message)
    assert "A Slayer carried Lyssa off." in said[-1]
    env, _ = play(KRULL, lambda e: NOOP, 0)
    assert env.done and not env.won and env.lives == 0 and env.episode_return == env.params.death


def test_krull_fire_mares_leap_over_swamp_and_swamp_drowns():
    env = krull_at(1)
    r, c = env.r, env.c
    env.still[r] = "." + "~" + "." + "~" * (env.params.width - 3)
    env.step(S_RIGHT)
    assert (env.r, env.c) == (r, c + 2) and env.lives == env.params.lives
    env.step(S_RIGHT)
    assert env.lives == env.params.lives - 1 and (env.r, env.c) == env.home


def test_krull_glaive_stuns_the_beast():
    env = krull_at(2)
    beast = env.foes[0]
    env.r, env.c, env.face = beast.r, beast.c - 3, (0, 1)
    env.step(S_FIRE)
    env.step(NOOP)
    assert env.stunned > env.tick
    at = (beast.r, beast.c)
    for _ in range(env.params.stun - 2):
        env.step(NOOP)
    assert (beast.r, beast.c) == at and beast in env.foes


def test_gravitar_bunker_fires_up_its_column():
    env = make(GRAVITAR)
    env.reset(seed=0)
    env._go(0, 1, 0)
    f = env.foes[0]
    env._go(0, f.r - 6, f.c)
    fired = False
    for _ in range(env.params.volley + 1):
        env.step(NOOP)
        fired = fired or any(s.c == f.c and s.r < f.r for s in env.shells.shots)
    assert fired
