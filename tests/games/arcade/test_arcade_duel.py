"""The duel family (paddle/ball and sports): the engine's ball physics, serves, possession and
scripted opponents; per MiniAtari task a scripted win and a scripted loss on several seeds; per
Atari task a scripted policy that scores."""

from __future__ import annotations

import pytest

from glyphbench_rl import make
from glyphbench_rl.games.arcade.duel import Ball, Match, Possession, clamp, deflect, pursue, serve
from arcade_play import play

SEEDS = (0, 3, 11)


class Fixed:
    def __init__(self, x):
        self.x = x

    def random(self):
        return self.x

    def below(self, n):
        return int(self.x * n)


# -- the engine ----------------------------------------------------------------------------------
def test_ball_reflects_off_named_walls_and_reports_open_edges():
    b = Ball(1, 5, dr=-1, dc=1)
    assert b.advance(1, 8, 1, 6) == "" and (b.r, b.c, b.dr) == (2, 6, 1)   # mirrored off the top
    b = Ball(3, 6, dr=1, dc=1)
    assert b.advance(1, 8, 1, 6) == "" and (b.c, b.dc) == (5, -1)
    b = Ball(8, 3, dr=1, dc=0)
    assert b.advance(1, 8, 1, 6, walls="tlr") == "b" and b.r == 8


def test_paddle_offset_deflects_by_third_and_serve_slants():
    assert [deflect(i, 3) for i in range(3)] == [-1, 0, 1]
    assert [deflect(i, 6) for i in range(6)] == [-1, -1, 0, 0, 1, 1] and deflect(0, 1) == 0
    b = Ball(0, 0)
    serve(b, 4, 7, -1, Fixed(0.9))
    assert (b.r, b.c, b.dr, b.dc) == (4, 7, 1, -1)
    serve(b, 4, 7, 1, Fixed(0.0), rows=True)
    assert (b.dr, b.dc) == (1, -1)


def test_pursue_steps_toward_the_target_with_a_probability():
    assert pursue(0, 0, 5, 2, 0.7, Fixed(0.5)) == (1, 0)
    assert pursue(0, 0, 1, -4, 0.7, Fixed(0.5)) == (0, -1)
    assert pursue(0, 0, 5, 2, 0.7, Fixed(0.8)) == (0, 0)
    assert clamp(9, 1, 6) == 6 and clamp(-2, 1, 6) == 1


def test_possession_and_match_points_into_games():
    side = Possession("you")
    assert side.flip() == "cpu" and not side.mine()
    m = Match(points=4, lead=2)
    assert [m.point(True) for _ in range(3)] == [None] * 3 and m.call() == "40-0"
    assert m.point(False) is None and m.point(True) is True and (m.mine, m.theirs) == (0, 0)
    m = Match(points=2, lead=1)
    assert m.point(False) is None and m.point(False) is False


# -- breakout --------------------------------------------------------------------------------------
def landing_col(env):
    """The column where the falling ball reaches the paddle row (side walls reflect it)."""
    p, b = env.params, env.ball
    r, c, dc = b.r, b.c, b.dc
    while r < env.prow:
        if not 0 <= c + dc <= p.width - 1:
            dc = -dc
        r, c = r + 1, c + dc
    return c


def rise(env, c, dc):
    """Follow a ball leaving the paddle at column ``c`` with slant ``dc`` (the ceiling and side
    walls reflect it): True if it meets a brick, else the column where it falls back."""
    p = env.params
    r, dr = env.prow - 1, -1
    while r < env.prow:
        if not 0 <= c + dc <= p.width - 1:
            dc = -dc
        if r + dr < 0:
            dr = -dr
        r, c = r + dr, c + dc
        if (r, c) in env.bricks:
            return True
    return c


def breakout_aimer(env):
    """Strike the falling ball with the paddle third that sends it into a brick, now or on the
    next return; else vary the slant."""
    p, b = env.params, env.ball
    if env.held:
        return 1
    if b.dr < 0:
        target = (p.width - p.paddle) // 2          # wait in the middle while it rises
    else:
        land = landing_col(env)
        slants = [deflect(o, p.paddle) for o in range(p.paddle)]
        ends = [rise(env, land, dc) for dc in slants]
        pick = [o for o, end in enumerate(ends) if end is True]
        pick += [o for o, end in enumerate(ends) if end is not True
                 and any(rise(env, end, dc) is True for dc in slants)]
        target = land - (pick[0] if pick else env.tick % p.paddle)
    target = clamp(target, 0, p.width - p.paddle)
    return 0 if target == env.pad else (2 if target < env.pad else 3)


def test_breakout_brick_breaks_and_reflects():
    env = make("glyphbench/miniatari-breakout-v0")
    env.reset(seed=0)
    env.held, b = False, env.ball
    b.r, b.c, b.dr, b.dc = 2, 5, -1, 0
    env.step(0)
    assert (1, 5) not in env.bricks and b.dr == 1 and b.r == 2 and env.frame.grid[1][5] == "."


# -- tennis ----------------------------------------------------------------------------------------
def arrival_col(env, row):
    """The column where the ball comes onto ``row`` (the side walls reflect it)."""
    p, b = env.params, env.ball
    r, c, dc = b.r, b.c, b.dc
    while r != row:
        if not 0 <= c + dc <= p.width - 1:
            dc = -dc
        r, c = r + b.dr, c + dc
    return c


def step_to(env, r, c, tr, tc):
    """The action (NOOP, UP, DOWN, LEFT, RIGHT) that steps from (r, c) toward (tr, tc)."""
    if c != tc:
        return 3 if tc < c else 4
    if r != tr:
        return 1 if tr < r else 2
    return 0


def tennis_placer(env):
    """Volley at the net: meet the ball on the row behind the net with the side of you that
    sends it away from the opponent (a ball already past that row is met on the baseline)."""
    p, b = env.params, env.ball
    row = p.height // 2 + 1
    if b.dr < 0:
        return step_to(env, env.me[0], env.me[1], row, env.me[1])
    if b.r > row or (b.r == row and abs(b.c - env.me[1]) > 1):
        row = p.height - 1
    land = arrival_col(env, row)
    away = 1 if env.cpu[1] < p.width // 2 else -1
    target = clamp(land - away, 0, p.width - 1)
    if abs(target - env.me[1]) + abs(row - env.me[0]) > abs(b.r - row):   # no time to place it
        target = land
    return step_to(env, env.me[0], env.me[1], row, target)


def test_tennis_return_slants_by_side_and_points_make_games():
    env = make("glyphbench/miniatari-tennis-v0")
    env.reset(seed=1)
    b, me = env.ball, env.me
    b.r, b.c, b.dr, b.dc = me[0] - 1, me[1] + 1, 1, 0
    env.step(0)
    assert b.dr == -1 and b.dc == 1                    # met on your right: it leaves right
    before = env.score.mine
    for _ in range(env.params.points):
        env._score(True)
    assert env.score.mine == before + 1 and env.match.mine == 0


# -- ice hockey ------------------------------------------------------------------------------------
def hockey_forward(env):
    """Take the puck (poke it from a carrier beside you), carry it up a lane in the mouth the
    opponent is not in, shoot when that lane is clear."""
    p, me, cpu, pk = env.params, env.me, env.cpu, env.puck
    beside = abs(me[0] - cpu[0]) + abs(me[1] - cpu[1]) == 1
    if env.has.holder == "cpu":
        return 5 if beside else step_to(env, me[0], me[1], cpu[0], cpu[1])
    if not env.has.mine():
        return step_to(env, me[0], me[1], pk.r, pk.c)
    lanes = range(env.left, env.left + p.mouth)
    lane = max(lanes, key=lambda c: abs(c - cpu[1]))
    clear = not (cpu[1] == me[1] and cpu[0] < me[0])
    if me[1] in lanes and clear and me[0] <= p.height // 2:
        return 5
    return step_to(env, me[0], me[1], 1 if me[1] == lane else me[0], lane)


def test_icehockey_shot_reflects_off_boards_and_scores_in_the_mouth():
    env = make("glyphbench/miniatari-icehockey-v0")
    env.reset(seed=0)
    env.me[:] = [2, env.left]
    env.cpu[:] = [8, 0]
    env.has.give("you")
    env.step(5)                                   # shot straight up the mouth
    env.step(0)
    assert env.score.mine == 1 and env.has.holder is None
    env.me[:], env.cpu[:] = [2, 0], [8, 0]
    env.has.give("you")
    env.step(5)                                   # outside the mouth: it slants and comes off the board
    env.step(0)
    env.step(0)
    assert env.score.mine == 1 and env.puck.dr == 1


# -- boxing ----------------------------------------------------------------------------------------
def boxer(env):
    """Square up beside the opponent on its row; punch when ready; otherwise step out of line."""
    me, cpu = env.me, env.cpu
    lined = me[0] == cpu[0] and abs(me[1] - cpu[1]) == 1
    if lined and env.tick + 1 >= env.ready["you"]:
        return 5
    if lined:                                       # not ready: leave its row
        return 1 if me[0] > 0 else 2
    side = 1 if me[1] > cpu[1] else -1
    return step_to(env, me[0], me[1], cpu[0], clamp(cpu[1] + side, 0, env.params.width - 1))


def test_boxing_punch_lands_beside_knocks_back_and_cools_down():
    env = make("glyphbench/miniatari-boxing-v0", chance=0.0, jab=0.0)     # a still, passive opponent
    env.reset(seed=0)
    env.me[:], env.cpu[:] = [3, 5], [3, 4]
    env.step(5)
    assert env.score.mine == 1 and env.cpu[1] == 3
    env.cpu[:] = [3, 4]
    env.step(5)                                     # cooling down: no punch
    assert env.score.mine == 1
    env.me[:], env.cpu[:] = [3, 5], [4, 4]
    env.ready["you"] = 0
    env.step(5)                                     # not on your row: a miss
    assert env.score.mine == 1


# -- fishing derby ---------------------------------------------------------------------------------
def shark_next(env):
    p, (_, c, d) = env.params, env.shark
    return c + d if 0 <= c + d < p.width else c - d


def angler(env):
    """Wait in a fish's lane just ahead of it inside your half; reel unless that would take the
    fish through the shark's next cell."""
    me = env.me
    if env.caught["you"]:
        reel_ok = not (me[0] - 2 <= 1 and shark_next(env) == me[1])
        return 5 if reel_ok else 0
    free = [f for f in env.fish if not env._hooked(f)]
    best = min(free, key=lambda f: abs(f[0] - me[0]) + abs(clamp(f[1] + 2 * f[2], 0, env.half - 1) - me[1]))
    col = clamp(best[1] + 2 * best[2], 0, env.half - 1) if 0 <= best[1] < env.half else (
        env.half - 1 if best[2] < 0 else 0)
    return step_to(env, me[0], me[1], best[0], col)


def test_fishingderby_hooked_fish_rises_reels_and_the_shark_eats():
    env = make("glyphbench/miniatari-fishingderby-v0", chance=0.0)
    env.reset(seed=0)
    f = env.fish[0]
    env.caught["you"], env.me[:] = f, [5, 2]
    env.shark[:] = [1, 10, 1]
    env.step(5)
    assert env.me[0] == 3 and f[0] == 3
    env.step(5)
    env.step(0)
    assert env.score.mine == 1 and env.caught["you"] is None
    g = env.fish[1]
    env.caught["you"], env.me[:] = g, [2, 4]
    env.shark[:] = [1, 3, 1]                         # it swims onto column 4 as the fish rises
    env.step(0)
    assert env.score.mine == 1 and env.caught["you"] is None and env.me[0] == 2


# -- surround --------------------------------------------------------------------------------------
def open_area(env, r, c, blocked):
    """Cells reachable from (r, c) through open cells."""
    if not env._free(r, c) or (r, c) in blocked:
        return 0
    seen, todo = {(r, c)}, [(r, c)]
    while todo:
        r, c = todo.pop()
        for dr, dc in ((1, 0), (-1, 0), (0, 1), (0, -1)):
            n = (r + dr, c + dc)
            if n not in seen and n not in blocked and env._free(*n):
                seen.add(n)
                todo.append(n)
    return len(seen)


def cycle_rider(env):
    """Head for the largest open region (ties: keep the heading), keeping away from the rival's
    next cells."""
    me, cpu = env.me, env.cpu
    blocked = {(me[0], me[1]), (cpu[0], cpu[1])} | {(cpu[0] + dr, cpu[1] + dc) for dr, dc in ((1, 0), (-1, 0), (0, 1), (0, -1))}
    best, score = 0, None
    for a in (1, 2, 3, 4):
        dr, dc = HEADING[a]
        if (dr, dc) == (-me[2], -me[3]):
            continue
        s = (open_area(env, me[0] + dr, me[1] + dc, blocked), (dr, dc) == (me[2], me[3]))
        if score is None or s > score:
            best, score = a, s
    return best


HEADING = {1: (-1, 0), 2: (0, 1), 3: (0, -1), 4: (1, 0)}


def test_surround_reversal_ignored_trails_block_and_head_on_is_a_draw():
    env = make("glyphbench/miniatari-surround-v0", chance=0.0)
    env.reset(seed=0)
    r, c = env.me[0], env.me[1]
    env.step(4)                                       # DOWN while heading up: ignored
    assert (env.me[0], env.me[1]) == (r - 1, c) and not env._free(r, c) and env.frame.grid[r][c] == "#"
    env.me[:], env.cpu[:] = [5, 3, 0, 1], [5, 5, 0, -1]
    env.step(0)
    assert env.done and env.episode_return == 0 and env.won is False


# -- bowling ---------------------------------------------------------------------------------------
def ahead(env, r, c, drift, memo):
    """The most standing pins a ball on row ``r`` at column ``c`` can still meet on the rows
    above: drifting ``drift`` columns a row once curved, else rolling straight or taking its
    hook (with ``curve`` off, a hook is free on every row)."""
    key = (r, c, drift)
    if r <= 0:
        return 0
    if key not in memo:
        w = env.params.width
        moves = (drift,) if drift else (0, -1, 1)
        memo[key] = max(((r - 1, min(w - 1, max(0, c + d))) in env.pins)
                        + ahead(env, r - 1, min(w - 1, max(0, c + d)), d if env.params.curve else 0, memo)
                        for d in moves)
    return memo[key]


def bowler(env):
    """Stand under the column that starts the richest path, throw, then hook where it pays."""
    p, memo = env.params, {}
    if env.ball is None:
        start = p.height - 2
        aim = max(range(p.width), key=lambda c: (ahead(env, start, c, 0, memo) + ((start, c) in env.pins),
                                                 -abs(c - env.col)))
        if aim != env.col:
            return 1 if aim < env.col else 2
        return 3
    r, c = env.ball
    if env.drift:
        return 0
    moves = [a for a in (0, 1, 2) if 0 <= c + (0, -1, 1)[a] < p.width]
    d = (0, -1, 1)
    return max(moves, key=lambda a: ((r - 1, c + d[a]) in env.pins)
               + ahead(env, r - 1, c + d[a], d[a] if p.curve else 0, memo))


def test_bowling_ball_knocks_what_it_meets_and_frames_reset_the_rack():
    env = make("glyphbench/miniatari-bowling-v0", scatter=0.0)
    env.reset(seed=0)
    head = max(env.pins)                              # the head pin, nearest you
    env.col = head[1]
    env.step(3)
    while env.ball is not None:
        env.step(0)
    assert head not in env.pins and env.score.done == 2 and env.roll == 1   # head pin and the one behind it in line
    for _ in range(3):
        env.step(3)
        while env.ball is not None:
            env.step(0)
    assert env.frame_no == 2 and len(env.pins) == 10 and env.roll == 0


def test_bowling_curve_ball_takes_one_hook_then_drifts():
    env = make("glyphbench/miniatari-bowling-v0")
    env.reset(seed=0)
    env.pins.clear()                                  # an empty lane: nothing stops the ball
    env.step(3)
    env.step(0)
    col = env.ball[1]
    assert env.drift == 0 and col == env.col          # rolling straight
    env.step(2)                                       # the hook: right, for the rest of the roll
    env.step(1)                                       # a second hook does nothing
    env.step(0)
    assert env.drift == 1 and env.ball[1] == col + 3 and "curving right" in env.frame.hud


# -- double dunk -----------------------------------------------------------------------------------
def dunker(env):
    """On offence drive round the defender to the hoop and shoot close in when nobody is beside
    you; on defence stand in front of the carrier and swipe."""
    from glyphbench_rl.games.arcade.doubledunk import distance
    me, cpu, hoop = env.me, env.cpu, env.hoop
    near = distance(me, tuple(cpu)) == 1
    if not env.has.mine():
        return 5 if near else step_to(env, me[0], me[1], cpu[0] - 1, cpu[1])
    if distance(me, hoop) <= 2 and (not near or env.tick % 6 == 0):
        return 5
    if me[1] == cpu[1] and cpu[0] < me[0]:          # the defender is in front: sidestep
        return 3 if me[1] > 0 and me[1] > env.params.width // 2 - 2 else 4
    return step_to(env, me[0], me[1], 1, hoop[1])


def test_doubledunk_possession_changes_after_every_shot_and_points_by_distance():
    env = make("glyphbench/atari-doubledunk-v0", chance=0.0)
    env.reset(seed=0)
    env.has.give("you")
    env.me[:], env.cpu[:] = [1, env.hoop[1] + 1], [10, 0]
    tries = 0
    while env.score.mine == 0 and tries < 50:
        env.has.give("you")
        env.me[:], env.cpu[:] = [1, env.hoop[1] + 1], [10, 0]
        env.step(5)
        assert env.has.holder == "cpu" and env.cpu[0] == env.params.height - 1   # the opponent checks it
        tries += 1
    assert env.score.mine == env.params.inside
    while env.score.mine == env.params.inside and tries < 200:
        env.has.give("you")
        env.me[:], env.cpu[:] = [env.params.height - 1, 0], [1, 0]
        env.step(5)
        tries += 1
    assert env.score.mine == env.params.inside + env.params.outside


# -- every game: the MiniAtari win and loss paths, the Atari scorer ---------------------------------
def mini_policies():
    """(game, a scripted winner, a scripted loser)."""
    return [
        ("breakout", breakout_aimer, lambda e: 2),                       # the paddle parked left
        ("tennis", tennis_placer, lambda e: 3),                          # standing in the left corner
        ("icehockey", hockey_forward, lambda e: 3),                      # skating off to the left
        ("doubledunk", dunker, lambda e: 0),                             # standing still
        ("boxing", boxer, lambda e: 0),
        ("fishingderby", angler, lambda e: 1),                           # the hook kept high
        ("surround", cycle_rider, lambda e: 0),                          # riding straight on
        ("bowling", bowler, lambda e: 1 if e.ball is None and e.col > 0 else 3),   # gutter balls
    ]


WIN_LOSS = [(g, w, lose, seed) for g, w, lose in mini_policies() for seed in SEEDS]


@pytest.mark.parametrize("game,winner,loser,seed", WIN_LOSS, ids=[f"{g}-{s}" for g, _, _, s in WIN_LOSS])
def test_mini_scripted_win_and_loss(game, winner, loser, seed):
    env, info = play(f"glyphbench/miniatari-{game}-v0", winner, seed)
    assert info["won"] is True and env.episode_return == pytest.approx(env.score.points if env.pattern == "A"
                                                                       else (env.score.mine - env.score.theirs) * env.params.unit)
    assert env.episode_return > 0 and not info["clamped"]
    if env.pattern == "A":
        assert env.score.done == env.params.goal and env.episode_return == pytest.approx(1)
    else:
        assert env.score.mine == env.params.goal
    env, info = play(f"glyphbench/miniatari-{game}-v0", loser, seed)
    assert info["won"] is False and env.done and env.turn < env.max_turns
    if env.pattern == "A":
        assert env.episode_return < 1
    else:
        assert env.score.theirs == env.params.goal and env.episode_return < 0


ATARI = [("breakout", breakout_aimer, 1500), ("tennis", tennis_placer, 3000), ("icehockey", hockey_forward, 3000),
         ("doubledunk", dunker, 3000), ("boxing", boxer, 2000), ("fishingderby", angler, 2000),
         ("surround", cycle_rider, 3000), ("bowling", bowler, 3000)]


@pytest.mark.parametrize("game,policy,turns", ATARI, ids=[g for g, _, _ in ATARI])
def test_atari_scripted_policy_scores(game, policy, turns):
    env, info = play(f"glyphbench/atari-{game}-v0", policy, 0, turns=turns)
    assert env.episode_return > 0 and (env.score.done if env.pattern == "A" else env.score.mine) > 0
