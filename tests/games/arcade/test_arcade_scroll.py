"""The scrolling family: the scroller engine (strips, channels, pacers) and, per game, a scripted
win path and loss path on each MiniAtari preset and a scripted policy that scores on each Atari
preset."""

from __future__ import annotations

import pytest

from glyphbench_rl import make
from glyphbench_rl.games.arcade.scroller import Channel, Pacer, Strip, put_one
from glyphbench_rl.games.common.lanes import Draws
from arcade_play import play

SEEDS = (0, 3, 11)
GAMES = ("riverraid", "zaxxon", "skiing", "enduro", "upndown", "choppercommand", "defender",
         "stargunner", "kungfumaster")


def toward(col: int, target: int, left: int = 1, right: int = 2, stay: int = 0) -> int:
    return stay if col == target else (left if target < col else right)


@pytest.mark.parametrize("game", GAMES)
def test_presets_registered_once_each_with_bounded_mini_returns(game):
    from glyphbench_rl.core.registry import get_spec
    from glyphbench_rl.games.arcade.engine import bound
    mini, atari = get_spec(f"glyphbench/miniatari-{game}-v0"), get_spec(f"glyphbench/atari-{game}-v0")
    assert (mini.suite, mini.tier) == ("MiniAtari", "standard") and mini.max_turns <= 512
    assert (atari.suite, atari.tier) == ("Atari", "extended") and atari.max_turns >= 5000
    assert mini.game is atari.game
    m, a = make(mini.id), make(atari.id)
    assert a.params.height * a.params.width >= m.params.height * m.params.width and a.params.goal >= m.params.goal
    lo, hi = bound(m.pattern, m.params)
    assert -1 <= lo and hi == pytest.approx(1.0)


# -- the engine -----------------------------------------------------------------------------------
def test_strip_scrolls_the_world_past_a_fixed_player():
    down = Strip(["a..", "b..", "c.."], "down")
    assert down.scroll("n..") == "c.." and down.rows == ["n..", "a..", "b.."]
    up = Strip(["a..", "b..", "c.."], "up")
    assert up.scroll("n..") == "a.." and up.rows[-1] == "n.."
    left = Strip(["ab", "cd"], "left")
    assert left.scroll("xy") == "ac" and left.rows == ["bx", "dy"] and left.shifts == 1
    left.put(0, 1, "Z")
    assert left.get(0, 1) == "Z" and left.get(5, 0) == "" and put_one("...", 1, "o") == ".o."
    fresh = iter("xyz")
    down.preroll(2, lambda: next(fresh) * 3)
    assert down.rows == ["yyy", "xxx", "n.."] and down.shifts == 3


def test_channel_wanders_one_column_a_line_within_its_widths():
    import numpy as np
    ch, draws = Channel(20, 5, 12, wander=1.0), Draws(np.random.default_rng(0))
    spans = set()
    prev = (ch.left, ch.right)
    for _ in range(500):
        left, right = ch.next(draws)
        assert 1 <= left and right <= 18 and 5 <= right - left + 1 <= 12
        assert abs(left - prev[0]) + abs(right - prev[1]) <= 1
        spans.add(right - left + 1)
        prev = (left, right)
    assert len(spans) > 3 and ch.line("#").count(".") == ch.right - ch.left + 1


def test_pacer_follows_a_changing_period():
    p = Pacer(2)
    assert [p.due(t) for t in range(1, 6)] == [False, True, False, True, False]
    p.period = 1
    assert p.due(5) and p.due(6)
    p.period = 0
    assert not p.due(20)


# -- River Raid -----------------------------------------------------------------------------------
def river_targets(env):
    rows = env.strip.rows
    for r in range(env.jet_r - 1, -1, -1):
        for c, ch in enumerate(rows[r]):
            if ch in "SH":
                yield r, c


def river_gunner(env) -> int:
    target = next(river_targets(env), None)
    if env.params.fuel and env.fuel.left < 25:
        depots = [(r, c) for r in range(env.jet_r) for c, ch in enumerate(env.strip.rows[r]) if ch == "F"]
        if depots:
            target = max(depots)
    if target is None:
        water = [c for c, ch in enumerate(env.strip.rows[env.jet_r - 1]) if ch != "#"]
        return toward(env.col, (water[0] + water[-1]) // 2)
    step = toward(env.col, target[1])
    nxt = env.strip.get(env.jet_r - 1, env.col + (0, -1, 1)[step])
    if step and nxt in "#SH":
        return 3
    return 3 if step == 0 else step


def river_kamikaze(env) -> int:
    target = next(river_targets(env), None)
    return 0 if target is None else toward(env.col, target[1])


@pytest.mark.parametrize("seed", SEEDS)
def test_riverraid_shooting_everything_reaches_the_bridge(seed):
    env, info = play("glyphbench/miniatari-riverraid-v0", river_gunner, seed)
    assert info["won"] is True and env.score.done == env.params.goal
    assert env.episode_return == pytest.approx(1.0) and not info["clamped"]


@pytest.mark.parametrize("seed", SEEDS)
def test_riverraid_flying_into_an_enemy_crashes(seed):
    env, info = play("glyphbench/miniatari-riverraid-v0", river_kamikaze, seed)
    assert info["won"] is False
    assert -1 <= env.episode_return < 0 and not info["clamped"]


def test_riverraid_atari_scores_with_fuel_and_wandering_banks():
    env, info = play("glyphbench/atari-riverraid-v0", river_gunner, 1, turns=600)
    assert env.episode_return > 0 and env.channel.narrow < env.channel.wide


# -- Zaxxon ---------------------------------------------------------------------------------------
def zax_things(env, glyphs):
    out = []
    for r, row in enumerate(env.strip.rows):
        for c, ch in enumerate(row):
            if ch in glyphs and c > env.col:
                out.append((c, r))
    return sorted(out)


def zax_danger(env, r):
    if not 0 <= r < env.params.height:
        return True
    if any(b.r == r and env.col <= b.c <= env.col + 3 for b in env.flak.shots):
        return True
    return any(env.strip.get(r, c) not in (".", "") for c in (env.col, env.col + 1))


def zax_pilot(env) -> int:
    walls = [(c, r) for c, r in zax_things(env, "#") if c <= env.col + 6]
    if walls:
        c = walls[0][0]
        rows = [r for r in range(env.params.height) if env.strip.get(r, c) == "."]
        target = rows[len(rows) // 2]
    else:
        glyphs = "TF" if env.params.fuel and env.fuel.left < 40 else "T"
        things = zax_things(env, glyphs)
        target = things[0][1] if things else env.r
    if target == env.r:
        if walls or not zax_danger(env, env.r) and env.gun.ready_at(env.tick + 1):
            return 3
    else:
        step = 1 if target < env.r else 2
        if not zax_danger(env, env.r + (-1, 1)[step - 1]):
            return step
    for step in (1, 2):
        if not zax_danger(env, env.r + (-1, 1)[step - 1]):
            return step if zax_danger(env, env.r) else 3
    return 3


def zax_rammer(env) -> int:
    things = zax_things(env, "T")
    return 0 if not things else toward(env.r, things[0][1])


@pytest.mark.parametrize("seed", SEEDS)
def test_zaxxon_shooting_turrets_while_dodging_wins(seed):
    env, info = play("glyphbench/miniatari-zaxxon-v0", zax_pilot, seed)
    assert info["won"] is True and env.score.done == env.params.goal
    assert env.episode_return == pytest.approx(1.0) and not info["clamped"]


@pytest.mark.parametrize("seed", SEEDS)
def test_zaxxon_flying_at_turrets_unarmed_is_shot_down(seed):
    env, info = play("glyphbench/miniatari-zaxxon-v0", zax_rammer, seed)
    assert info["won"] is False and env.episode_return == pytest.approx(-1.0)


def test_zaxxon_atari_scores_through_walls_and_fuel():
    env, info = play("glyphbench/atari-zaxxon-v0", zax_pilot, 2, turns=800)
    assert env.score.done > 0 and env.params.wall_every > 0


# -- Skiing ---------------------------------------------------------------------------------------
def next_gate(env):
    for r in range(env.params.row + 1, env.params.height):
        left = env.strip.rows[r].find("[")
        if left >= 0:
            return r, left + 1 + env.params.gap // 2
    return None


def ski_slalom(env) -> int:
    gate = next_gate(env)
    if gate is None:
        return 0
    step = toward(env.col, gate[1])
    nxt = env.strip.get(env.params.row + 1, env.col + (0, -1, 1)[step])
    if nxt == "T":                                  # go round a tree
        for alt in (1, 2, 0):
            if env.strip.get(env.params.row + 1, env.col + (0, -1, 1)[alt]) not in ("T", ""):
                return alt
    return step


def ski_astray(env) -> int:
    gate = next_gate(env)
    if gate is None:
        return 0
    away = 0 if gate[1] > env.params.width // 2 else env.params.width - 1
    return toward(env.col, away)


@pytest.mark.parametrize("seed", SEEDS)
def test_skiing_through_every_gate_wins(seed):
    env, info = play("glyphbench/miniatari-skiing-v0", ski_slalom, seed)
    assert info["won"] is True and env.score.done == env.params.goal == env.judged
    assert env.episode_return == pytest.approx(1.0) and not info["clamped"]


@pytest.mark.parametrize("seed", SEEDS)
def test_skiing_missing_gates_ends_the_course_lost(seed):
    env, info = play("glyphbench/miniatari-skiing-v0", ski_astray, seed)
    assert info["won"] is False and env.judged == env.params.goal and env.tick < 200
    assert 0 <= env.episode_return < 1


def test_skiing_atari_trees_and_missed_gates_cost_time_only():
    env, info = play("glyphbench/atari-skiing-v0", ski_slalom, 4)
    assert env.episode_return > 0 and env.done
    slow, _ = play("glyphbench/atari-skiing-v0", ski_astray, 4)
    assert slow.tick > env.tick and slow.episode_return < env.episode_return


# -- Enduro ---------------------------------------------------------------------------------------
def gap_ahead(env, k):
    c = env.cols[k]
    return next((env.car_r - r for r in range(env.car_r, -1, -1) if env.strip.get(r, c) == "C"), 99)


def enduro_racer(env) -> int:
    best = max(range(env.params.lanes), key=lambda k: (min(gap_ahead(env, k), 6), -abs(k - env.lane)))
    mine = gap_ahead(env, env.lane)
    if best == env.lane or mine > 4:
        return 3 if env.speed < env.params.top else 0
    k = env.lane + (1 if best > env.lane else -1)
    if gap_ahead(env, k) > 1:
        return 2 if k > env.lane else 1
    return 4 if mine <= 2 else 0


def enduro_rammer(env) -> int:
    for r in range(env.car_r - 1, -1, -1):
        row = env.strip.rows[r]
        if "C" in row:
            k = min(range(env.params.lanes), key=lambda k: (row[env.cols[k]] != "C", abs(k - env.lane)))
            return 3 if k == env.lane else (1 if k < env.lane else 2)
    return 3


@pytest.mark.parametrize("seed", SEEDS)
def test_enduro_overtaking_in_free_lanes_wins(seed):
    env, info = play("glyphbench/miniatari-enduro-v0", enduro_racer, seed)
    assert info["won"] is True and env.score.done == env.params.goal and env.lives == 2
    assert env.episode_return == pytest.approx(1.0) and not info["clamped"]


@pytest.mark.parametrize("seed", SEEDS)
def test_enduro_two_collisions_end_the_race(seed):
    env, info = play("glyphbench/miniatari-enduro-v0", enduro_rammer, seed)
    assert info["won"] is False and env.lives == 0 and 0 <= env.episode_return < 1


def test_enduro_speed_sets_the_scroll_and_a_crash_stops_the_car():
    env = make("glyphbench/miniatari-enduro-v0")
    env.reset(seed=0)
    for _ in range(6):
        env.step(0)
    assert env.strip.shifts == env.params.height - 3          # standing still: no scroll
    env.step(3)
    env.step(3)
    env.step(3)
    before = env.strip.shifts
    for _ in range(4):
        env.step(0)
    assert env.speed == 3 and env.strip.shifts - before == 4   # top speed: a row a turn


def test_enduro_nightfall_ends_the_race_lost():
    env, info = play("glyphbench/miniatari-enduro-v0", lambda e: 0, 0)     # parked: passes nobody
    assert info["won"] is False and env.tick == env.params.day and env.episode_return == 0
    assert "Nightfall in 0" in env.frame.hud
    env, info = play("glyphbench/atari-enduro-v0", lambda e: 0, 0)
    assert info["won"] is False and env.tick == env.params.day < env.max_turns


def test_enduro_atari_collisions_only_cost_speed():
    env, info = play("glyphbench/atari-enduro-v0", enduro_racer, 5, turns=1500)
    assert env.score.points > 20 and not env.done or info["won"]
    rammed, _ = play("glyphbench/atari-enduro-v0", enduro_rammer, 5, turns=300)
    assert not rammed.done and rammed.lives == 1


# -- Up'n Down ------------------------------------------------------------------------------------
def car_threat(env, r, c):
    return any(car.c == c and r - 3 <= car.r <= r for car in env.cars)


def up_driver(env) -> int:
    if env.tick >= env.landing and car_threat(env, env.r, env.col):
        return 5                                    # JUMP
    flags = [(r, row.index("F")) for r, row in enumerate(env.strip.rows) if "F" in row and r <= env.r]
    if not flags:
        return 0
    fr, fc = max(flags)
    if fc != env.col:
        nc = env.col + (1 if fc > env.col else -1)
        if env.strip.get(env.r, nc) != "#" and not car_threat(env, env.r, nc):
            return 4 if fc > env.col else 3
    if fr < env.r and env.r > env.params.height // 2 and not car_threat(env, env.r - 1, env.col):
        return 1
    return 0


def up_reckless(env) -> int:
    near = [car for car in env.cars if car.r <= env.r]
    if not near:
        return 0
    car = max(near, key=lambda b: b.r)
    return 0 if car.c == env.col else (4 if car.c > env.col else 3)


@pytest.mark.parametrize("seed", SEEDS)
def test_upndown_collecting_flags_and_jumping_cars_wins(seed):
    env, info = play("glyphbench/miniatari-upndown-v0", up_driver, seed)
    assert info["won"] is True and env.score.done == env.params.goal
    assert env.episode_return == pytest.approx(1.0) and not info["clamped"]


@pytest.mark.parametrize("seed", SEEDS)
def test_upndown_driving_into_a_car_wrecks(seed):
    env, info = play("glyphbench/miniatari-upndown-v0", up_reckless, seed)
    assert info["won"] is False and 0 <= env.episode_return < 1 and "A car hit you!" in env._messages


def test_upndown_atari_scores_flags_and_crushes_on_a_wandering_road():
    env, info = play("glyphbench/atari-upndown-v0", up_driver, 1, turns=1000)
    assert env.score.done > 0 and env.channel.narrow < env.channel.wide


# -- Stargunner -----------------------------------------------------------------------------------
def gunner_pilot(env) -> int:
    if any(b.r == env.r and env.col < b.c <= env.col + 3 for b in env.bolts):
        return 1 if env.r > 0 else 2                # step out of an enemy shot's row
    if not env.enemies:
        return 0
    e = min(env.enemies, key=lambda e: e.c)
    if e.r != env.r:
        return 1 if e.r < env.r else 2
    return 5


@pytest.mark.parametrize("seed", SEEDS)
def test_stargunner_lining_up_and_firing_wins(seed):
    env, info = play("glyphbench/miniatari-stargunner-v0", gunner_pilot, seed)
    assert info["won"] is True and env.score.done == env.params.goal
    assert env.episode_return == pytest.approx(1.0) and not info["clamped"]


@pytest.mark.parametrize("seed", SEEDS)
def test_stargunner_holding_fire_lets_an_enemy_past(seed):
    env, info = play("glyphbench/miniatari-stargunner-v0", lambda env: 0, seed)
    assert info["won"] is False and env.episode_return == 0 and env.tick < 200


def test_stargunner_atari_scores_under_fire():
    env, info = play("glyphbench/atari-stargunner-v0", gunner_pilot, 0, turns=1500)
    assert env.score.done > 5


def test_camera_follows_around_a_wrapping_world():
    from glyphbench_rl.games.arcade.scroller import Camera
    cam = Camera(40, 10)
    cam.follow(2)
    assert cam.left == 37 and cam.screen(2) == 5 and cam.screen(38) == 1 and cam.screen(20) == -1
    still = Camera(10, 10)
    still.follow(7)
    assert still.left == 0 and still.screen(9) == 9
    hall = Camera(40, 10, wrap=False)
    hall.follow(2)
    assert hall.left == 0 and hall.screen(39) == -1
    hall.follow(39)
    assert hall.left == 30 and hall.screen(39) == 9


# -- Chopper Command ------------------------------------------------------------------------------
def wdist(env, a, b):
    """Signed shortest step from column a to column b in the wrapping world."""
    w = env.params.world
    d = (b - a) % w
    return d - w if d > w // 2 else d


def chopper_pilot(env) -> int:
    if not env.enemies:
        return 0
    e = min(env.enemies, key=lambda e: -e.r)          # the one closest to the trucks
    dx = wdist(env, env.x, e.c)
    if e.r == env.r and dx and abs(dx) <= env.params.reach - 3 and (dx > 0) == (env.face > 0):
        return 5
    if abs(dx) < 3 and e.r != env.r:
        return 1 if dx > 0 else 2                     # keep a lane's distance while climbing
    if e.r != env.r:
        return 3 if e.r < env.r else 4
    return 2 if dx > 0 else 1


def chopper_idle(env) -> int:
    return 3                                          # sit at the top, away from the fight


@pytest.mark.parametrize("seed", SEEDS)
def test_choppercommand_hunting_the_divers_wins(seed):
    env, info = play("glyphbench/miniatari-choppercommand-v0", chopper_pilot, seed)
    assert info["won"] is True and env.score.done == env.params.goal and env.trucks
    assert env.episode_return == pytest.approx(1.0) and not info["clamped"]


@pytest.mark.parametrize("seed", SEEDS)
def test_choppercommand_idling_loses_the_convoy(seed):
    env, info = play("glyphbench/miniatari-choppercommand-v0", chopper_idle, seed)
    assert info["won"] is False and env.episode_return < 0


def test_choppercommand_atari_scrolls_and_scores():
    env, info = play("glyphbench/atari-choppercommand-v0", chopper_pilot, 0, turns=2000)
    assert env.score.done > 3 and env.camera.left != 0


# -- Defender -------------------------------------------------------------------------------------
def defender_pilot(env) -> int:
    landers = {(lander.r, lander.c) for lander in env.landers}
    w = env.params.world
    carrying = any(m.data == 3 for m in env.people)
    if carrying:
        if (env.r - 1, env.x) in landers or (env.r - 2, env.x) in landers:
            return 5 if any(r == env.r for r, _ in landers) else 2
        return 3
    for lander in env.landers:                        # shoot one in line and in front
        dx = wdist(env, env.x, lander.c)
        if lander.r == env.r and dx and (dx > 0) == (env.face > 0) and abs(dx) <= env.params.reach:
            return 5
    free = [m for m in env.people if m.data in (0, 2)]
    grabbed = [lander for lander in env.landers if lander.data is not None]
    if grabbed:                                       # line up with a kidnapper and shoot it
        lander = max(grabbed, key=lambda b: b.r)
        dx = wdist(env, env.x, lander.c)
        if lander.r != env.r:
            if abs(dx) < 2:
                return 1 if dx >= 0 else 2
            return 3 if lander.r < env.r else 4
        return 2 if dx > 0 else 1
    if not free:
        return 0
    man = min(free, key=lambda m: abs(wdist(env, env.x, m.c)))
    dx = wdist(env, env.x, man.c)
    step = (4 if man.r > env.r else 3) if man.r != env.r else 0
    if dx and (abs(dx) > abs(man.r - env.r) or not step):
        step = 2 if dx > 0 else 1
    dr, dc = ((0, 0), (0, -1), (0, 1), (-1, 0), (1, 0))[step]
    if (env.r + dr, (env.x + dc) % w) in landers:
        return 0
    return step


@pytest.mark.parametrize("seed", SEEDS)
def test_defender_carrying_humans_off_the_top_wins(seed):
    env, info = play("glyphbench/miniatari-defender-v0", defender_pilot, seed)
    assert info["won"] is True and env.score.done == env.params.goal
    assert env.episode_return == pytest.approx(1.0) and not info["clamped"]


@pytest.mark.parametrize("seed", SEEDS)
def test_defender_idling_lets_landers_abduct(seed):
    env, info = play("glyphbench/miniatari-defender-v0", lambda env: 0, seed)
    assert info["won"] is False and env.episode_return == 0 and env.tick < 300
    assert len(env.people) < env.params.humans


def test_defender_atari_rescues_on_a_wrapping_planet():
    env, info = play("glyphbench/atari-defender-v0", defender_pilot, 0, turns=3000)
    assert env.score.done > 0 and env.params.world > env.params.width


# -- Kung-Fu Master -------------------------------------------------------------------------------
def kungfu_fighter(env) -> int:
    if any(k.c - k.dc == env.x or k.c == env.x + k.dc * -1 for k in env.knives if abs(k.c - env.x) <= 2):
        return 7                                      # DUCK a knife about to arrive
    near = sorted(env.enemies, key=lambda e: abs(e.c - env.x))
    if not near:
        return 1 if env.params.world > env.params.width else 0
    e = near[0]
    side = 1 if e.c > env.x else -1
    if side != env.face:
        return 4 if side > 0 else 3
    gap = abs(e.c - env.x)
    if gap == 1:
        return 5
    if gap == 2:
        return 6
    return 1 if env.face < 0 and gap > 3 and env.params.throwers else 0


def kungfu_flailer(env) -> int:
    return 5                                          # punches the same way forever


@pytest.mark.parametrize("seed", SEEDS)
def test_kungfumaster_facing_and_striking_wins(seed):
    env, info = play("glyphbench/miniatari-kungfumaster-v0", kungfu_fighter, seed)
    assert info["won"] is True and env.score.done == env.params.goal
    assert env.episode_return == pytest.approx(1.0) and not info["clamped"]


@pytest.mark.parametrize("seed", SEEDS)
def test_kungfumaster_never_turning_round_is_grabbed_from_behind(seed):
    env, info = play("glyphbench/miniatari-kungfumaster-v0", kungfu_flailer, seed)
    assert info["won"] is False and -1 <= env.episode_return < 0


def test_kungfumaster_atari_scores_and_climbs():
    env, info = play("glyphbench/atari-kungfumaster-v0", kungfu_fighter, 0, turns=3000)
    assert env.score.done > 5
