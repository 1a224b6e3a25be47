"""The space and arena games without a MiniAtari twin (gravitar, solaris, krull): per game a
scripted policy that scores and reaches a new place, a loss path, and the signature mechanics."""

from __future__ import annotations

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
    """Where to hover to shoot the nearest bunker along a diagonal (out of its line of fire)."""
    best = None
    for f in env.foes:
        for side in (-1, 1):
            for d in (5, 4, 6, 3):
                r, c = f.r - d, f.c + side * d
                if not (1 <= r and 0 <= c < env.params.width):
                    continue
                line = [(f.r - k, f.c + side * k) for k in range(1, d + 1)]
                if all(env.still[a][b] == "." for a, b in line):
                    score = abs(r - env.r) + abs(c - env.c)
                    if best is None or score < best[0]:
                        best = (score, r, c, heading_to(1, -side))
                    break
    return best


def gravitar_policy(target: int = 2):
    def policy(env):
        if env.planet is None:
            pr, pc = env._planets()[target]
            return steer(env, pr, pc) or THRUST
        spot = bunker_spot(env)
        if spot is None:
            return steer(env, 0, env.c) or THRUST
        _, r, c, aim = spot
        act = steer(env, r, c, fast=2)
        if act is not None:
            return act
        return turn_to(env.ship, aim) or FIRE
    return policy


@pytest.mark.parametrize("seed", [0, 1])
def test_gravitar_policy_lands_and_shoots_bunkers(seed):
    env, _ = play(GRAVITAR, gravitar_policy(), seed, turns=1500)
    assert env.sectors.map.visited >= {(0, 0), (0, 3)}      # planet 3 reached
    assert env.score.done >= 1 and env.episode_return >= env.params.unit


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
