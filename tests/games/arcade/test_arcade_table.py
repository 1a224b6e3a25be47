"""The pinball and fish-guarding games (videopinball, namethisgame) and the ``pinball`` engine:
per game a scripted policy that scores on several seeds, a loss path, and each signature
mechanic set up on the table."""

from __future__ import annotations

import pytest

from glyphbench_rl import make
from glyphbench_rl.games.arcade.engine import Tally
from glyphbench_rl.games.arcade.pinball import (BUMPER, EMPTY, FLIP_UP, LIT, ROLL, TARGET, Flipper,
                                                Tilt)
from arcade_play import play

PINBALL = "glyphbench/atari-videopinball-v0"
NOOP, LEFT, RIGHT, NUDGE = 0, 1, 2, 3


def table(seed: int = 0):
    env = make(PINBALL)
    env.reset(seed=seed)
    return env, env.unwrapped


def flipper_policy(env) -> int:
    """Launch at once, then swing the flipper the ball rests over."""
    t = env.unwrapped
    b = t.ball
    if t.held:
        return LEFT
    if b.r == t.frow - 1:
        for i, f in enumerate(t.flippers):
            if f.covers(b.c):
                return LEFT + i
    return NOOP


def place(t, r: int, c: int, dr: int, dc: int, lift: int = 0) -> None:
    b = t.ball
    t.held = False
    b.r, b.c, b.dr, b.dc, b.lift = r, c, dr, dc, lift


# -- the engine ----------------------------------------------------------------------------------
def test_flipper_strike_by_part_and_roll_toward_the_tip():
    left, right = Flipper(9, 2, 4, -1), Flipper(9, 6, 8, 1)
    assert [left.strike(c) for c in (2, 3, 4)] == [-1, 0, 1]       # base: own side; tip: across
    assert [right.strike(c) for c in (6, 7, 8)] == [-1, 0, 1]      # tip (6) sends it across, left
    assert (left.roll, right.roll) == (1, -1)


def test_tilt_counts_nudges_in_a_window():
    tilt = Tilt(limit=2, window=10)
    assert not tilt.nudge(0) and not tilt.nudge(5) and tilt.recent(6) == 2
    assert not tilt.nudge(11)                                      # the one at 0 left the window
    assert tilt.nudge(12) and tilt.tilted
    tilt.clear()
    assert not tilt.tilted and tilt.recent(12) == 0


def test_points_count_events_and_pay_their_worth():
    _, t = table()
    score = Tally(t, goal=3, unit=100.0)
    score.award(1)
    score.award(10)
    assert (score.done, score.points) == (2, 1100.0) and not t.done
    score.award(1)
    assert score.done == 3 and t.done


# -- videopinball ---------------------------------------------------------------------------------
@pytest.mark.parametrize("seed", [0, 1])
def test_flipping_keeps_the_ball_and_scores(seed):
    env, _ = play(PINBALL, flipper_policy, seed, 1500)
    t = env.unwrapped
    assert t.score.done >= 30 and t.score.points >= 100.0 * t.score.done
    assert t.lives >= 2


def test_never_flipping_drains_every_ball():
    env, _ = play(PINBALL, lambda env: NOOP, 0, 2000)
    t = env.unwrapped
    assert t.done and t.lives == 0 and t.tick < 2000


def test_plunger_waits_then_launches_itself_up_the_lane():
    env, t = table()
    assert t.held and "Plunger" in t._hud()
    for _ in range(t.params.autolaunch - 1):
        env.step(NOOP)
    assert t.held
    env.step(NOOP)
    assert not t.held and t.ball.dr == -1 and t.ball.c == t.lane
    env.reset(seed=0)
    env.step(RIGHT)
    assert not t.held                                              # any action fires it at once


def test_a_swung_flipper_sends_the_ball_up_and_an_idle_one_lets_it_drain():
    env, t = table()
    left = t.flippers[0]
    place(t, t.frow - 1, left.hi, 1, 0)
    obs, *_ = env.step(LEFT)
    assert t.ball.dr == -1 and t.ball.dc == 1 and t.ball.r == t.frow - 2
    assert FLIP_UP * 3 in obs
    place(t, t.frow - 1, left.lo, 1, 0)
    lives = t.lives
    cols = []
    for _ in range(6):
        env.step(NOOP)
        cols.append(t.ball.c)
        if t.lives < lives:
            break
    assert t.lives == lives - 1 and cols[:3] == [left.lo + 1, left.hi, left.hi + 1]


def test_bumper_kicks_the_ball_away_and_scores():
    env, t = table()
    r, c = next((r, row.index(BUMPER)) for r, row in enumerate(t.still) if BUMPER in row)
    place(t, r + 1, c, -1, 0, lift=5)
    _, reward, *_ = env.step(NOOP)
    assert reward == 100.0 and t.ball.dr == 1 and t.ball.dc in (-1, 1) and t.score.done == 1


def test_a_whole_bank_of_drop_targets_pays_a_bonus_and_stands_again():
    env, t = table()
    bank = t.banks[0]
    total = 0.0
    for r, c in bank:
        place(t, r + 1, c, -1, 0, lift=5)
        _, reward, *_ = env.step(NOOP)
        total += reward
        assert t.ball.dr == 1
        if (r, c) != bank[-1]:
            assert t.still[r][c] == EMPTY
    assert total == 100.0 * len(bank) + 1000.0
    assert all(t.still[r][c] == TARGET for r, c in bank)


def test_lighting_every_rollover_earns_an_extra_ball():
    env, t = table()
    assert t.rolls
    lives = t.lives
    for r, c in t.rolls:
        place(t, r + 1, c, -1, 0, lift=5)
        env.step(NOOP)
        assert (r, c) == t.rolls[-1] or t.still[r][c] == LIT
    assert t.lives == lives + 1 and all(t.still[r][c] == ROLL for r, c in t.rolls)


def test_too_many_nudges_tilt_the_table():
    env, t = table()
    place(t, 10, 4, 1, 1)
    env.step(NUDGE)
    assert t.ball.dc == -1                                         # the nudge reversed it
    for _ in range(t.params.nudges):
        obs, *_ = env.step(NUDGE)
    assert t.tilt.tilted and "TILT" in obs
    left = t.flippers[0]
    place(t, t.frow - 1, left.lo, 1, 0)
    obs, *_ = env.step(LEFT)
    assert t.ball.dr != -1 and FLIP_UP * 3 not in obs               # dead flippers
    while not t.done and t.tilt.tilted:
        env.step(NOOP)
    assert not t.tilt.tilted and t.held                            # cleared once the ball drained


# -- namethisgame ---------------------------------------------------------------------------------
OCTOPUS = "glyphbench/atari-namethisgame-v0"
FIRE = 3


def sea(seed: int = 0):
    env = make(OCTOPUS)
    env.reset(seed=seed)
    return env, env.unwrapped


def guard_policy(env) -> int:
    """Breathe from a lowered line when air runs short; else stand under the deepest foe (the
    shark led by its swim) and fire."""
    t = env.unwrapped
    p = t.params
    if t.line and (t.air.left < p.air // 2 or t.line == t.row - 1 and t.air.left < p.air * 3 // 4):
        goal = t.boat.c
    else:
        foe = max([x for x in t.tips if x.r > 1] + [t.shark], key=lambda x: x.r)
        goal = foe.c
        if foe is t.shark:
            goal = min(p.width - 1, max(0, foe.c + foe.dc * ((t.row - foe.r) // 4)))
    if goal == t.col:
        return FIRE
    return LEFT if goal < t.col else RIGHT


@pytest.mark.parametrize("seed", [0, 1])
def test_guarding_shoots_back_tentacles_and_sharks_to_the_goal(seed):
    env, _ = play(OCTOPUS, guard_policy, seed, 1500)
    t = env.unwrapped
    assert t.done and t.score.done == t.params.goal and t.lives >= 1
    assert t.score.points > 10.0 * t.params.goal                   # kills pay by depth, more than one row


def test_standing_still_loses_every_life_to_the_octopus():
    env = make(OCTOPUS)
    env.reset(seed=0)
    total, done = 0.0, False
    while not done:
        _, r, term, trunc, _ = env.step(NOOP)
        total, done = total + r, term or trunc
    t = env.unwrapped
    assert term and t.lives == 0 and total == -1.0 and t.tick < 2000


def test_a_shot_tip_drives_the_tentacle_back_and_pays_by_depth():
    env, t = sea()
    tip = t.tips[0]
    tip.r = 9
    t.col = tip.c
    t.shark.r, t.shark.c = 5, 0 if tip.c > 2 else t.params.width - 1
    rewards = [env.step(FIRE)[1] for _ in range(6)]
    assert tip.r == 1 and sum(rewards) == 8 * t.params.unit and t.score.done == 1


def test_the_shark_zigzags_down_pays_by_depth_and_takes_the_treasure():
    env, t = sea()
    s = t.shark
    s.r, s.c, s.dc = 6, t.params.width - 1, 1
    t.tick = t.params.swim - 1                                     # its move comes next turn
    env.step(NOOP)
    assert (s.r, s.dc, s.glyph) == (7, -1, "<")                    # turned at the wall, a row lower
    s.r, s.c, s.dc = 14, t.col, 1                                  # met by the shot before it moves on
    t.gun.shots = []
    reward = sum(env.step(FIRE)[1] for _ in range(2))
    assert reward == 13 * t.params.unit and t.shark is not s and t.shark.r == 2
    s = t.shark
    s.r, s.c, s.dc = t.row - 1, t.params.width - 1, 1
    lives = t.lives
    for _ in range(t.params.swim):
        env.step(NOOP)
    assert t.lives == lives - 1 and t.shark.r == 2 and all(x.r == 1 + t.params.reach for x in t.tips)


def test_a_tentacle_reaching_the_diver_row_takes_a_life():
    env, t = sea()
    for x in t.tips:
        x.r = t.row - 1
    lives = t.lives
    for _ in range(t.params.grow):
        env.step(NOOP)
    assert t.lives == lives - 1 and all(x.r == 1 + t.params.reach for x in t.tips)


def test_the_boat_line_refills_air_and_running_out_costs_a_life():
    env, t = sea()
    p = t.params
    while not (t.line == t.row - 1):
        env.step(NOOP)
    assert ":" in "\n".join(t._grid()) and t.air.left < p.air
    t.col = t.boat.c
    env.step(NOOP)
    assert t.air.left == p.air
    env, t = sea()
    t.air.left = 1
    lives = t.lives
    env.step(NOOP)
    assert t.lives == lives - 1 and t.air.left == p.air
