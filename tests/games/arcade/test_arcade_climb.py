"""The climbing family: the climbing engine (towers, fallers, thrust, the purse of native points)
and, per game, a scripted policy that makes progress, a loss path and each signature mechanic."""

from __future__ import annotations

import pytest

from glyphbench_rl import make
from glyphbench_rl.games.arcade.climbing import Fallers, Tower, crawl, ledges, shaft, thrust
from glyphbench_rl.games.common.lanes import Draws
from arcade_play import play

HERO = "glyphbench/atari-hero-v0"
H_NOOP, H_FIRE, H_UP, H_RIGHT, H_LEFT, H_DOWN = range(6)


# -- the engine -----------------------------------------------------------------------------------
def test_tower_pages_by_screen_and_follows_by_row():
    t = Tower([str(i) * 3 for i in range(9)], 3)
    assert t.window() == ["000", "111", "222"] and t.get(4, 1) == "4" and t.get(9, 0) == ""
    assert t.page(4) and t.top == 3 and not t.page(5) and t.page(8) and t.top == 6
    t.follow(5, below=1)
    assert t.top == 4 and t.window()[1] == "555"
    t.follow(0, below=1)
    assert t.top == 0
    t.put(0, 1, "x")
    assert t.rows[0] == "0x0"
    with pytest.raises(ValueError):
        Tower(["a"], 2)


def test_fallers_drop_a_row_a_tick_and_hit_once():
    f = Fallers()
    f.drop(0, 2)
    f.advance(bottom=5)
    assert f.cells == [(1, 2)] and not f.hits(1, 3) and f.hits(1, 2) and f.cells == []
    f.drop(5, 0)
    f.advance(bottom=5)
    assert f.cells == []


def test_thrust_lifts_or_falls_never_through_rock():
    solid = {0, 6}
    blocked = solid.__contains__
    assert thrust(3, True, 0, blocked) == 2 and thrust(1, True, 0, blocked) == 1
    assert thrust(3, False, 2, blocked) == 5 and thrust(4, False, 2, blocked) == 5
    assert thrust(3, False, 0, blocked) == 3


def test_tower_clears_a_wall_run_and_traces_a_beam():
    t = Tower(["#....#", "#.%..#", "#.%..#", "######"], 2)
    assert not t.clear_run(1, 1, "%", ".") and t.clear_run(2, 2, "%", ".")
    assert t.rows[1] == "#....#" and t.rows[2] == "#....#"
    bat = [1, 3, 0, 0, "B"]
    assert t.beam(1, 1, 1, 5, ".", [bat]) == ([2], bat, None)
    assert t.beam(1, 1, 1, 5, ".", []) == ([2, 3, 4], None, 5)
    assert t.beam(1, 4, -1, 2, ".", []) == ([3, 2], None, None)


def test_ledges_chain_each_band_into_the_next_gap_well_clear_of_the_drop():
    import numpy as np
    rows, bands = shaft(Draws(np.random.default_rng(3)), 20, 16, 3, 3, 5, "#", ".")
    assert len(rows) == 48 and len(bands) == 9 and [b.last for b in bands] == [False] * 8 + [True]
    entry = 5
    for b in bands:
        assert b.entry == entry and abs(b.near - entry) >= 4 and 1 <= b.gap <= 17
        assert "".join(rows[b.floor]).count(".") == (0 if b.last else 2)
        assert all(rows[r][0] == "#" and rows[r][19] == "#" for r in range(b.top, b.floor))
        assert len(b.between) >= 4 and b.near - b.step not in (entry, entry + 1)
        entry = b.gap
    assert [b.floor % 16 for b in bands[:3]] == [5, 10, 15] and bands[1].top == 6
    assert list(ledges(Draws(np.random.default_rng(3)), 20, 16, 3, 3, 5)) == bands


def test_crawl_turns_back_at_rock_and_only_on_the_screen():
    t = Tower(["#..#", "#..#", "####", "#..#"], 2)
    bat, far = [0, 2, 0, 1, "B"], [3, 1, 0, 1, "B"]
    crawl(t, [bat, far], 0, 2, ".")
    assert bat[:4] == [0, 1, 0, -1] and far[:2] == [3, 1]
    spider = [1, 1, 1, 0, "X"]
    crawl(t, [spider], 0, 2, ".")
    assert spider[:3] == [0, 1, -1]


def test_bonus_pays_native_points_without_units():
    env = make(HERO)
    env.reset(seed=0)
    _, r, *_ = env.step(H_NOOP)
    env.score.bonus(50)
    assert env.score.points == 50 and env.score.done == 0 and env._step_reward == 50


# -- H.E.R.O. -------------------------------------------------------------------------------------
def hero_target(t) -> int:
    """The column to head for: the gap in the floor under you, or the miner."""
    h = t.params.height
    locals_ = {h - 1 - (h - 1) // 3 * j for j in range(3)}
    floor = next(y for y in range(t.r + 1, len(t.tower)) if y % h in locals_)
    if t.miner[0] == floor - 1:
        return t.miner[1]
    gaps = [x for x, ch in enumerate(t.tower.rows[floor]) if ch == "."]
    return min(gaps, key=lambda x: abs(x - t.c))


def hero_policy(t) -> int:
    r, c, tower = t.r, t.c, t.tower
    standing = tower.get(r + 1, c) != "."
    if t.tnt is not None:                       # lit: stand two cells clear of it
        if abs(c - t.tnt[1]) < 2 or r != t.tnt[0]:
            return H_LEFT if c < t.tnt[1] or (c == t.tnt[1] and t.face > 0) else H_RIGHT
        return H_NOOP
    for k in t.critters:                        # a critter in line: face it and shoot
        if k[0] == r and 0 < abs(k[1] - c) <= t.params.reach:
            d = 1 if k[1] > c else -1
            return H_FIRE if t.face == d else (H_RIGHT if d > 0 else H_LEFT)
    if not standing:
        return H_NOOP
    target = hero_target(t)
    if target == c:
        return H_NOOP
    d = 1 if target > c else -1
    if any(k[1] == c + d and abs(k[0] - r) <= 2 for k in t.critters):
        return H_NOOP                           # a spider on its thread just ahead: wait
    if tower.get(r, c + d) == "%":
        if t.face != d:
            return H_RIGHT if d > 0 else H_LEFT
        return H_DOWN if t.sticks else H_FIRE
    return H_RIGHT if d > 0 else H_LEFT


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_hero_policy_descends_and_rescues(seed):
    env, info = play(HERO, hero_policy, seed, turns=1500)
    assert env.score.points > 0 and env.score.done >= 1 and env.level >= 1, env.score.points
    assert env.lives >= 1 and info["won"] is not False


def test_hero_idle_loses_every_life():
    env, info = play(HERO, lambda t: H_NOOP, 0)
    assert info["won"] is False and env.lives == 0 and env.episode_return == -1


def test_hero_power_runs_out_a_unit_a_turn():
    env = hero_at(critters=0.0)
    while not env.done:
        env.step(H_NOOP)
    assert env.turn == env.params.lives * env.params.power * env.params.depth


def hero_at(seed=0, **over):
    env = make(HERO, **over)
    env.reset(seed=seed)
    return env


def test_hero_pack_lifts_and_gravity_pulls():
    env = hero_at()
    r = env.r
    env.step(H_UP)
    assert env.r == r        # the ceiling of the shaft
    env.step(H_NOOP)
    assert env.r == r + 1
    env.step(H_UP)
    assert env.r == r
    env.step(H_DOWN)
    assert env.r == r + 2


def wall_band(env):
    """A breakable wall cell on a floor row's row above, with air on its left to stand in."""
    for y, row in enumerate(env.tower.rows):
        for x in range(3, len(row) - 1):
            if row[x] == "%" and env.tower.get(y + 1, x) != "%" and row[x - 1] == "." \
                    and row[x - 2] == "." and row[x - 3] == "." and env.tower.get(y + 1, x - 1) == "#":
                return y, x
    raise AssertionError("no wall")


def test_hero_dynamite_blows_the_wall_and_not_you_from_two_cells():
    env = hero_at(critters=0.0)
    y, x = wall_band(env)
    env.r, env.c, env.face = y, x - 1, 1
    env.critters = []
    env.step(H_DOWN)
    assert env.tnt is not None and env.sticks == env.params.dynamite - 1
    env.step(H_LEFT)
    env.step(H_LEFT)
    points = env.score.points
    env.step(H_NOOP)
    assert env.tower.get(y, x) == "." and env.tower.get(y - 1, x) == "."
    assert env.score.points == points + env.params.wall_points and env.lives == env.params.lives


def test_hero_dynamite_next_to_you_costs_a_life():
    env = hero_at(critters=0.0)
    y, x = wall_band(env)
    env.r, env.c = y, x - 1
    env.critters = []
    for a in (H_DOWN, H_NOOP, H_NOOP, H_NOOP):
        env.step(a)
    assert env.lives == env.params.lives - 1 and env.tower.get(y, x) == "."


def test_hero_laser_burns_a_wall_cell_and_shoots_critters():
    env = hero_at(critters=0.0)
    y, x = wall_band(env)
    env.r, env.c, env.face = y, x - 2, 1
    env.critters = [[y, x - 1, 0, 0, "S"]]
    env.step(H_FIRE)
    assert env.critters == [] and env.score.points == env.params.critter_points
    for _ in range(env.params.burn):
        env.step(H_FIRE)
    assert env.tower.get(y, x) == "." and env.tower.get(y - 1, x) == "%"
    assert env.score.points == env.params.critter_points + env.params.wall_points


def test_hero_critter_touch_and_lava_cost_lives():
    env = hero_at(critters=0.0, lava_from=1)
    y, x = wall_band(env)
    env.r, env.c = y, x - 2
    env.critters = [[y, x - 1, 0, 0, "B"]]
    env.step(H_RIGHT)
    assert env.lives == env.params.lives - 1
    lava = next((y, row.index("~")) for y, row in enumerate(env.tower.rows) if "~" in row)
    env.r, env.c, env.critters = lava[0] - 1, lava[1], []
    env.step(H_NOOP)
    assert env.lives == env.params.lives - 2


def test_hero_rescue_pays_power_left_and_the_next_shaft_is_deeper():
    env = hero_at(critters=0.0)
    r, c = env.miner
    env.r, env.c = r, c - 1 if env.tower.get(r, c - 1) == "." else c + 1
    env.tower.page(r)
    depth = len(env.tower) // env.params.height
    power = env.power.left
    _, reward, *_ = env.step(H_RIGHT if env.c < c else H_LEFT)
    assert env.score.done == 1 and reward == env.params.unit + power
    assert len(env.tower) // env.params.height == depth + env.params.deeper and env.level == 1
    assert env.map.hud() == "Map @/?/?"


def test_hero_map_marks_the_screens_visited():
    env, _ = play(HERO, hero_policy, 0, turns=400)
    assert len(env.map.visited) >= 2 or env.level >= 1
    assert "@" in env.map.hud() and "Map" in env.frame.hud


# -- Crazy Climber --------------------------------------------------------------------------------
CLIMBER = "glyphbench/atari-crazyclimber-v0"
C_NOOP, C_UP, C_DOWN, C_LEFT, C_RIGHT = range(5)


def seen(t) -> list[str]:
    return t.frames[t.tick % t.params.cycle]


def threatened(t, c: int) -> bool:
    return any(pc == c and 0 <= t.r - pr <= 3 for pr, pc in t.pots.cells)


def climber_policy(t) -> int:
    rows, r, c = seen(t), t.r, t.c
    if r == 0:
        return C_RIGHT if t.copter > c else C_LEFT
    if threatened(t, c):                        # a pot coming down your column: step aside
        for x, a in ((c - 1, C_LEFT), (c + 1, C_RIGHT)):
            if rows[r][x] == "." and not threatened(t, x):
                return a
    above = rows[r - 1][c]
    if t.hand and above != "=":
        return C_UP
    if not t.hand and above in "._H":
        return C_UP
    for x, a in ((c - 1, C_LEFT), (c + 1, C_RIGHT)):   # barred: try a column whose window is open
        if rows[r][x] == "." and rows[r - 1][x] == "." and not threatened(t, x):
            return a
    return C_NOOP


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_climber_policy_finishes_buildings(seed):
    env, info = play(CLIMBER, climber_policy, seed, turns=1000)
    assert env.score.done >= 2 and env.building >= 2 and env.score.points > 2 * env.params.unit


def test_climber_who_hangs_on_is_hit_by_pots_until_no_life_is_left():
    env, info = play(CLIMBER, lambda t: C_NOOP, 0)
    assert info["won"] is False and env.lives == 0 and env.episode_return == -1 and env.turn < 400


def climber_at(**over):
    env = make(CLIMBER, **over)
    env.reset(seed=0)
    return env


def test_climber_climbs_hand_over_hand_and_the_view_scrolls():
    env = climber_at(shutters=0.0, drop=50)
    r, top = env.r, env.tower.top
    env.step(C_UP)
    assert env.r == r and env.hand and "y" in "".join(env.frame.grid)
    env.step(C_UP)
    assert env.r == r - 1 and not env.hand and env.score.points == env.params.row_points
    for _ in range(20):
        env.step(C_UP)
    assert env.r == r - 11 and env.tower.top < top
    assert env.tower.top + env.params.height - 1 - env.r == env.params.below


def shut_above(env):
    """Make the window above you shut on every turn of the cycle."""
    r, c = env.r - 1, env.c
    for rows in env.frames:
        rows[r] = rows[r][:c] + "=" + rows[r][c + 1:]


def test_climber_shut_window_bars_the_way_and_sideways_moves_too():
    env = climber_at(shutters=0.0, drop=50)
    shut_above(env)
    r = env.r
    env.step(C_UP)
    env.step(C_UP)
    assert env.r == r and not env.hand
    c = env.c
    for rows in env.frames:
        rows[r] = rows[r][:c + 1] + "=" + rows[r][c + 2:]
    env.step(C_RIGHT)
    assert env.c == c
    env.step(C_LEFT)
    assert env.c == c - 1


def test_climber_window_shutting_on_your_hand_knocks_you_down():
    env = climber_at(shutters=0.0, drop=50)
    for _ in range(7):
        env.step(C_UP)
    r = env.r
    assert env.hand
    rows = env.frames[(env.tick + 1) % env.params.cycle]
    rows[r - 1] = rows[r - 1][:env.c] + "=" + rows[r - 1][env.c + 1:]
    env.step(C_NOOP)
    assert env.r == r + env.params.knock and not env.hand


def test_climber_pot_hits_cost_a_life_and_a_side_step_dodges():
    env = climber_at(drop=50)
    env.pots.drop(env.r - 1, env.c)
    env.step(C_NOOP)
    assert env.lives == env.params.lives - 1 and env.pots.cells == []
    env.pots.drop(env.r - 1, env.c)
    env.step(C_LEFT if env.frames[env.tick % env.params.cycle][env.r][env.c - 1] == "." else C_RIGHT)
    assert env.lives == env.params.lives - 1


def test_climber_helicopter_finishes_the_building_and_the_next_is_taller():
    env = climber_at()
    tall = len(env.frames[0])
    env.r, env.c = 0, env.copter - 1 if env.copter > 1 else env.copter + 1
    _, reward, *_ = env.step(C_RIGHT if env.c < env.copter else C_LEFT)
    assert env.score.done == 1 and reward == env.params.unit and env.building == 1
    assert len(env.frames[0]) == tall + env.params.taller and env.r == len(env.frames[0]) - 1


def test_prompts_follow_the_parameters():
    hero = make(HERO, reach=4, fuse=5, depth=3).system_prompt()
    assert "laser 4 cells" in hero and "after 5 turns" in hero and "3 screens deep" in hero
    assert "Map shows the rooms" in hero
    climber = make(CLIMBER, tall=40, shut=3, cycle=10, knock=3).system_prompt()
    assert "40 rows tall" in climber and "shut for 3 turns in every 10" in climber and "3 rows down" in climber
