"""The side-scrolling games on a course longer than the screen (sidescroll.Course, Leap): James
Bond 007, Road Runner and Private Eye; per game a scripted policy that scores and gets on, a
loss path, and the game's signature mechanics."""

from __future__ import annotations

import pytest

from glyphbench_rl import make
from glyphbench_rl.games.arcade.sidescroll import Course, Leap, fall, lay
from arcade_play import play

SEEDS = (0, 5)


@pytest.mark.parametrize("game", ["jamesbond", "privateeye", "roadrunner"])
def test_registered_on_the_atari_suite_only(game):
    from glyphbench_rl.core.registry import get_spec
    spec = get_spec(f"glyphbench/atari-{game}-v0")
    assert (spec.suite, spec.tier) == ("Atari", "extended") and spec.max_turns >= 5000
    env = make(spec.id)
    env.reset(seed=0)
    assert env.params.lives >= 3 and env.pattern == "D"
    me = {"jamesbond": "B", "privateeye": "@", "roadrunner": "R"}[game]
    for _ in range(30):                         # you are drawn once, where the course's view has you
        env.step("RIGHT" if game != "roadrunner" else "LEFT")
        if env.done:
            break
        grid = env.frame.grid
        row = [r for r, line in enumerate(grid) if me in line]
        assert len(row) == 1 and "".join(grid).count(me) == 1
        x = env.d if game == "roadrunner" else env.x
        assert grid[row[0]].index(me) == env.course.screen(x)


# -- the engine -----------------------------------------------------------------------------------
def test_course_view_follows_and_mirrors():
    cells = lay(("a", "b"), 10)
    cells[0][7] = "X"
    fwd = Course(cells, 4)
    fwd.follow(6, lead=2)                       # x at view column 1, two columns ahead of it
    assert fwd.left == 5 and fwd.view() == ["aaXa", "bbbb"] and fwd.screen(6) == 1
    assert fwd.screen(2) == -1 and fwd.seen(5) and fwd.seen(8) and not fwd.seen(9)
    fwd.follow(99, lead=2)
    assert fwd.left == 6                        # stops at the course's end
    back = Course(cells, 4, backward=True)
    back.follow(6, lead=2)
    assert back.view() == ["aXaa", "bbbb"] and back.screen(6) == 2 and back.screen(7) == 1
    back.put(0, 8, "Y")
    assert back.view()[0] == "YXaa" and back.get(0, 8) == "Y" and back.get(5, 0) == ""
    with pytest.raises(ValueError):
        Course(lay(("a",), 3), 4)


def test_fall_drops_things_a_row_onto_you_or_the_floor():
    from glyphbench_rl.games.arcade.bodies import Body
    on_you, low, high = Body(3, 5), Body(4, 9), Body(0, 2)
    things = [on_you, low, high]
    hit, landed = fall(things, 4, 5, floor=5)
    assert hit and landed == [low] and things == [high] and high.r == 1
    assert fall(things, 4, 5, floor=5) == (False, []) and things == [high]


def test_leap_lifts_along_its_arc_only_from_the_ground():
    leap = Leap((1, 2, 1))
    assert leap.lift(0) == 0 and leap.start(5)
    assert [leap.lift(t) for t in range(5, 9)] == [1, 2, 1, 0]
    assert not leap.start(6) and leap.start(8)
    leap.land()
    assert leap.lift(8) == 0


# -- Road Runner ----------------------------------------------------------------------------------
RR = "glyphbench/atari-roadrunner-v0"


def runner_policy(env):
    """Run left, steer to the nearest seed ahead, step out of a truck's lane."""
    course, lane, d = env.course, env.lane, env.d
    lanes = env.params.height - 2
    danger = {t.r for t in env.trucks if 0 <= t.c - d <= 4} | {r.r for r in env.falling if 0 <= r.c - d <= 2}
    if lane in danger:
        for step, act in ((-1, "UP"), (1, "DOWN")):
            if 1 <= lane + step <= lanes and lane + step not in danger:
                return act
    best = None
    for x in range(d + 1, d + 8):
        for r in range(1, lanes + 1):
            if course.get(r, x) == ":" and (best is None or abs(r - lane) < abs(best - lane)):
                best = r
        if best is not None:
            break
    if best is not None and best != lane and (lane + (1 if best > lane else -1)) not in danger:
        return "DOWN" if best > lane else "UP"
    return "LEFT"


@pytest.mark.parametrize("seed", SEEDS)
def test_roadrunner_scripted_runner_eats_seed_and_reaches_the_next_level(seed):
    env, _ = play(RR, runner_policy, seed, turns=600)
    assert env.score.done >= 10 and env.score.points >= 1000
    assert env.level >= 2


def test_roadrunner_standing_still_the_coyote_catches_you():
    env, info = play(RR, lambda e: "NOOP", 0, turns=2000)
    assert env.done and env.lives == 0 and (env.cl, env.cd) == (env.lane, env.d)


def test_roadrunner_missing_seeds_in_a_row_makes_you_faint():
    env = make(RR)
    env.reset(seed=1)
    env.out = 10 ** 9                           # keep the Coyote away
    lives = env.lives
    for x, lane in env.seeds[:6]:               # every early pile in the lane you are not in
        env.course.put(lane, x, ".")
        env.course.put(1, x, ":")
    env.lane = env.params.height - 2
    env.seeds = [(x, 1) for x, _ in env.seeds]
    for _ in range(200):
        env.step("LEFT")
        if env.lives < lives:
            break
    assert env.lives == lives - 1 and env.misses == 0


def test_roadrunner_truck_and_mine_knock_out_the_coyote():
    env = make(RR)
    env.reset(seed=2)
    from glyphbench_rl.games.arcade.bodies import Body
    env.cd, env.cl, env.lane = env.d - 5, 1, 1     # the truck behind you, coming at him
    env.trucks = [Body(1, env.cd + 2)]
    before = env.score.done
    env.step("NOOP")
    env.step("NOOP")
    assert env.score.done == before + 1 and env.tick < env.out
    env.out = 0
    env.cd, env.cl = env.d - 8, env.lane
    for x in range(env.cd + 1, env.cd + 4):     # his own mines between him and you
        env.course.put(env.lane, x, "x")
    for _ in range(10):
        env.trucks = []
        env.step("NOOP")
        if env.score.done > before + 1:
            break
    assert env.score.done == before + 2 and env.tick < env.out and env.lives == env.params.lives


# -- James Bond 007 -------------------------------------------------------------------------------
JB = "glyphbench/atari-jamesbond-v0"


def bond_policy(env):
    """Drive right; jump craters, shoot frogmen low and helicopters with flares, wait out bombs
    and marked laser columns, shoot the mission target."""
    course, x, t = env.course, env.x, env.tick + 1     # (the turn about to be played)
    lift = env.leap.lift(t)
    if course.get(5, x + 1) == "X" or course.get(5, x + 2) == "X":
        return "DOWN"
    if any(0 <= f.c - x <= 4 for f in env.frogs) and env.lows.ready_at(t) and not lift:
        return "DOWN"
    if lift:
        return "RIGHT"                                   # (never stop over a crater)
    if env.aim >= 0 and env.aim == x:
        return "RIGHT" if course.get(6, x + 1) == "#" else "LEFT"
    if env.aim >= 0 and 0 < env.aim - x <= 1:
        return "NOOP"
    if any(abs(b.c - (x + 1)) <= 0 and b.r >= 3 for b in env.bombs):
        return "NOOP"
    if not lift and any(course.get(6, x + k) == "U" for k in (1,)):
        return "UP"
    if any(2 <= h.c - x <= 6 for h in env.helis) and env.flares.ready_at(t) and not lift:
        return "FIRE"
    if not lift and any(0 < f.c - x <= 2 for f in env.frogs):
        return "UP"
    return "RIGHT"


@pytest.mark.parametrize("seed", SEEDS)
def test_jamesbond_scripted_driver_accomplishes_a_mission(seed):
    env, _ = play(JB, bond_policy, seed, turns=1000)
    assert env.score.done >= 1 and env.score.points >= 1000 and env.mission >= 2 and env.x > 20


def test_jamesbond_driving_blindly_into_craters_loses_every_vehicle():
    env, _ = play(JB, lambda e: "RIGHT", 0, turns=500)
    assert env.done and env.lives == 0 and env.score.done == 0


def bond_at(seed=0):
    env = make(JB)
    env.reset(seed=seed)
    env.helis, env.frogs = [], []
    env.course.rows[6] = "#" * env.params.stage          # flat ground unless a test digs
    env.course.version += 1
    return env


def quiet(env):
    env.helis, env.bombs = [], []                          # no new helicopters bombing the test


def test_jamesbond_a_jump_carries_you_over_a_crater():
    env = bond_at()
    x = env.x
    env.course.put(6, x + 1, "U")
    env.course.put(6, x + 2, "U")
    for a in ("UP", "RIGHT", "RIGHT", "RIGHT", "RIGHT"):
        quiet(env)
        env.step(a)
    assert env.x == x + 4 and env.lives == env.params.lives
    env.course.put(6, env.x + 1, "U")
    quiet(env)
    env.step("RIGHT")
    assert env.lives == env.params.lives - 1                # no jump: into the crater


def test_jamesbond_flare_downs_a_helicopter_and_low_shot_a_frogman():
    from glyphbench_rl.games.arcade.bodies import Body
    env = bond_at()
    x = env.x
    heli = Body(1, x + 6, dc=-1, data=False)
    env.helis = [heli]
    env.step("FIRE")
    for _ in range(4):
        env.step("NOOP")
    assert heli not in env.helis and heli.c > x and env.flares.shots == []
    env.course.rows[6] = env.course.rows[6][:x + 3] + "~" * 6 + env.course.rows[6][x + 9:]
    env.frogs = [Body(5, x + 6, dc=-1)]
    quiet(env)
    env.step("DOWN")
    for _ in range(3):
        quiet(env)
        env.step("NOOP")
    assert env.frogs == [] and env.lives == env.params.lives


def test_jamesbond_bombs_crater_the_ground():
    from glyphbench_rl.games.arcade.bodies import Body
    env = bond_at()
    x = env.x
    env.bombs = [Body(2, x + 3)]
    for _ in range(4):
        env.helis = []
        env.step("NOOP")
    assert env.course.get(6, x + 3) == "U" and env.bombs == []


def test_jamesbond_satellite_laser_strikes_the_marked_column():
    env = bond_at()
    env.mission = env.params.laser_from
    hit, warned = None, False
    for _ in range(60):
        quiet(env)
        warned = warned or (env.aim >= 0 and env.frame.grid[1][env.course.screen(env.aim)] == "!")
        if env.aim >= 0 and env.x != env.aim:
            env.step("RIGHT" if env.aim > env.x else "LEFT")   # drive into the marked column
        else:
            env.step("NOOP")
        if env.lives < env.params.lives:
            hit = env.frame.message
            break
    assert hit and "laser" in hit and warned and env.frame.grid[0].count("S") == 1


def test_jamesbond_shooting_the_target_starts_the_next_mission():
    env = bond_at()
    target = env.params.stage - 3
    env.x = target - 4
    quiet(env)
    env.step("RIGHT")
    quiet(env)
    env.step("RIGHT")
    quiet(env)
    env.step("RIGHT")
    assert env.x == target - 1                             # the target blocks the road
    env.step("DOWN")
    assert env.mission == 2 and env.score.done == 1 and env.x < 10


# -- Private Eye ----------------------------------------------------------------------------------
PE = "glyphbench/atari-privateeye-v0"


def drive_to(env, target):
    want = max(-2, min(2, target - env.x))
    if env.v == want:
        return "NOOP"
    if want == 0:
        return "DOWN"
    return "RIGHT" if env.v < want else "LEFT"


def eye_policy(env):
    """Search the nearest unsearched building, jump for what shows at a window, take the item
    home, jump over thugs."""
    x, t = env.x, env.tick + 1
    lift = env.leap.lift(t)
    if not lift and any(abs(th.c - x) <= 2 + abs(env.v) for th in env.thugs):
        return "UP"
    if env.shown:
        if x == env.shown[0] and env.v == 0:
            return "NOOP" if lift else "UP"
        return drive_to(env, env.shown[0])
    if lift:
        return "NOOP"
    if env.phase == "find":
        todo = [i for i, b in enumerate(env.fronts) if "ABCDEFGHIJKLMNOPQRSTUVWXYZ"[i] not in env.searched]
        door = min((env.fronts[i] + 3 for i in todo), key=lambda d: abs(d - x))
    else:
        door = env.fronts[env.home] + 3
    if x == door and env.v == 0:
        return "EXAMINE"
    return drive_to(env, door)


@pytest.mark.parametrize("seed", SEEDS)
def test_privateeye_scripted_detective_closes_a_case(seed):
    env, _ = play(PE, eye_policy, seed, turns=1200)
    assert env.score.done >= 1 and env.score.points >= 1000 and env.case >= 2


def test_privateeye_thugs_mug_a_detective_who_never_jumps():
    env, _ = play(PE, lambda e: "RIGHT" if e.x < e.params.street - 3 else "LEFT", 0, turns=5000)
    assert env.done and env.lives == 0 and env.score.done == 0 and "mugged" in env.frame.message


def eye_at(seed=0):
    env = make(PE)
    env.reset(seed=seed)
    return env


def calm(env):
    env.thugs, env.pots = [], []


def test_privateeye_a_case_examine_catch_return_and_le_fiend():
    env = eye_at(3)
    wrong = (env.hide + 1) % len(env.fronts)
    if wrong == env.home:
        wrong = (wrong + 1) % len(env.fronts)
    env.x = env.fronts[wrong] + 3
    calm(env)
    env.step("EXAMINE")
    assert env.shown is None and env.searched == "ABCDEFGHIJKLMNOPQRSTUVWXYZ"[wrong] and env.phase == "find"
    env.x = env.fronts[env.hide] + 2                       # nearer the left window
    calm(env)
    env.step("EXAMINE")
    col = env.shown[0]
    assert col == env.fronts[env.hide] + 1 and env.phase == "find"
    assert "$" in env.frame.grid[2]
    env.x = col
    for a in ("UP", "NOOP"):
        calm(env)
        env.step(a)
    assert env.phase == "return" and env.shown is None and env.score.done == 0
    for _ in range(4):
        calm(env)
        env.step("NOOP")                                   # land
    env.x = env.fronts[env.home] + 3
    calm(env)
    env.step("EXAMINE")
    assert env.phase == "catch" and "&" in env.frame.grid[2]
    col = env.shown[0]
    env.x = col
    env.course.follow(col, env.params.width // 2)
    for a in ("UP", "NOOP"):
        calm(env)
        env.step(a)
    assert env.score.done == 1 and env.case == 2 and env.phase == "find"


def test_privateeye_an_item_not_caught_goes_back_in():
    env = eye_at(1)
    env.x = env.fronts[env.hide] + 3
    env.step("EXAMINE")
    assert env.shown
    for _ in range(env.params.pop):
        calm(env)
        env.step("NOOP")
    assert env.shown is None and env.phase == "find"


def test_privateeye_thug_mugs_unless_you_jump_him_and_pots_cost_clock():
    from glyphbench_rl.games.arcade.bodies import Body
    env = eye_at(2)
    env.x = 40
    env.thugs = [Body(4, 43, dc=-1)]
    env.step("UP")
    for _ in range(3):
        env.pots = []
        env.step("RIGHT")
    assert env.lives == env.params.lives and env.x > 43
    for _ in range(3):                                  # land, then stand in a thug's way
        calm(env)
        env.step("DOWN")
    env.thugs = [Body(4, env.x + 1, dc=-1)]
    env.pots = []
    env.step("NOOP")
    env.step("NOOP")
    assert env.lives == env.params.lives - 1
    calm(env)
    left = env.clock.left
    env.pots = [Body(2, env.x)]
    env.step("NOOP")
    env.step("NOOP")
    assert env.clock.left <= left - env.params.penalty


def test_privateeye_the_clock_running_out_costs_a_life():
    env = eye_at(4)
    env.clock.left = 3
    for _ in range(3):
        calm(env)
        env.step("NOOP")
    assert env.lives == env.params.lives - 1 and env.clock.left == env.params.clock


def test_roadrunner_road_end_brings_the_next_level_and_rocks_fall_on_runner_or_coyote():
    from glyphbench_rl.games.arcade.bodies import Body
    env = make(RR)
    env.reset(seed=3)
    p = env.params
    while env.level < p.rocks_from:                 # run the road to its end, level after level
        env.d = p.stage - 2
        env.out = 10 ** 9
        env.trucks = []
        env.step("LEFT")
    assert env.level == p.rocks_from and env.d < p.width
    assert any("x" in row for row in env.course.rows)      # the Coyote's mines from level 2 on
    env.out, env.trucks = 0, []
    env.cd, env.cl = env.d - 6, 1 if env.lane != 1 else 2
    env.falling = [Body(env.cl, env.cd, data=env.tick + 1)]
    before = env.score.done
    env.step("NOOP")
    assert env.score.done == before + 1 and env.tick < env.out and env.lives == p.lives
    env.trucks, env.falling = [], [Body(env.lane, env.d, data=env.tick + 1)]
    env.step("NOOP")
    assert env.lives == p.lives - 1
