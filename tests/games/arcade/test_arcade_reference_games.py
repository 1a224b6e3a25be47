"""Win and loss paths for each MiniAtari reference game (pong, freeway, spaceinvaders) and a
scripted policy that scores on each Atari preset."""

from __future__ import annotations

import pytest

from glyphbench_rl import make
from arcade_play import play

NOOP = 0


# -- policies (they read the game's state, as a scripted player would read the grid) -------------
def pong_tracker(env) -> int:
    centre = env.me + env.params.paddle // 2
    return 0 if centre == env.ball.r else (1 if env.ball.r < centre else 2)


def landing(env):
    """The row where the ball reaches your paddle's column (walls reflect it)."""
    p, b = env.params, env.ball
    r, dr, c = b.r, b.dr, b.c
    while c < p.width - 2:
        if r + dr in (0, p.height - 1):
            dr = -dr
        r, c = r + dr, c + 1
    return r


def pong_aimer(env):
    p, b = env.params, env.ball
    if b.dc < 0:
        target = p.height // 2 - p.paddle // 2
    else:
        row = landing(env)
        cpu = env.cpu + p.paddle // 2
        off = p.paddle - 1 if cpu < p.height // 2 else 0   # the bottom end sends it down
        target = row - off
    target = min(max(1, target), p.height - 1 - p.paddle)
    return 0 if env.me == target else (1 if target < env.me else 2)


def freeway_careful(env) -> int:
    nxt = env.tick + 1
    if env.r - 1 == 0 or not env._car(env.r - 1, nxt):
        return 1                                # UP
    if not env._car(env.r, nxt):
        return 0
    return 2


def invaders_gunner(env) -> int:
    cells = env.wave.cells()
    if not cells:
        return NOOP
    low = max(r for r, _ in cells)
    target = min((c for r, c in cells if r == low), key=lambda c: abs(c - env.col))
    if env.params.bomb_every and any(b.c == env.col and b.r >= env.params.height - 4 for b in env.bombs.shots):
        return 1 if env.col > 1 else 2          # step out from under a bomb
    return 3 if target == env.col else (1 if target < env.col else 2)


# -- MiniAtari: winnable and losable ----------------------------------------------------------------
@pytest.mark.parametrize("seed", [0, 2, 7])
def test_pong_aiming_with_the_paddle_ends_wins_first_to_w(seed):
    env, info = play("glyphbench/miniatari-pong-v0", pong_aimer, seed)
    assert info["won"] is True and env.score.mine == env.params.goal
    assert env.episode_return == pytest.approx((env.score.mine - env.score.theirs) * env.params.unit)
    assert 0 < env.episode_return <= 1 and not info["clamped"]


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_pong_a_still_paddle_loses(seed):
    env, info = play("glyphbench/miniatari-pong-v0", lambda e: NOOP, seed)
    assert info["won"] is False and env.score.theirs == env.params.goal
    assert -1 <= env.episode_return < 0 and not info["clamped"]


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_freeway_careful_chicken_wins(seed):
    env, info = play("glyphbench/miniatari-freeway-v0", freeway_careful, seed)
    assert info["won"] is True and env.episode_return == pytest.approx(1.0)


def test_freeway_runs_into_traffic_and_is_knocked_back():
    env = make("glyphbench/miniatari-freeway-v0")
    env.reset(seed=3)
    knocked = 0
    for _ in range(env.max_turns):
        before = env.r
        _, _, term, trunc, info = env.step(1)
        knocked += env.r > before
        if term or trunc:
            break
    assert knocked > 0


@pytest.mark.parametrize("seed", [0, 1])
def test_freeway_standing_still_times_out_unwon(seed):
    env, info = play("glyphbench/miniatari-freeway-v0", lambda e: NOOP, seed)
    assert env.turn == env.max_turns and info["won"] is None and env.episode_return == 0


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_invaders_gunner_wins(seed):
    env, info = play("glyphbench/miniatari-spaceinvaders-v0", invaders_gunner, seed)
    assert info["won"] is True and env.episode_return == pytest.approx(1.0)


@pytest.mark.parametrize("seed", [0, 1])
def test_invaders_land_when_you_do_not_shoot(seed):
    env, info = play("glyphbench/miniatari-spaceinvaders-v0", lambda e: NOOP, seed)
    assert info["won"] is False and env.turn < env.max_turns
    assert env.episode_return == pytest.approx(-1.0)


def test_invaders_partial_progress_then_landing_adds_the_penalty():
    def lazy(env):                               # shoot only for the first 40 turns
        return invaders_gunner(env) if env.tick < 60 else NOOP
    env, info = play("glyphbench/miniatari-spaceinvaders-v0", lazy, 1)
    assert info["won"] is False and env.score.done > 0
    assert env.episode_return == pytest.approx(env.score.done * env.params.unit - 1)


# -- Atari: a scripted policy scores ----------------------------------------------------------------
@pytest.mark.parametrize("game,policy", [("pong", pong_aimer), ("freeway", freeway_careful),
                                         ("spaceinvaders", invaders_gunner)])
def test_atari_scripted_policy_scores(game, policy):
    env, info = play(f"glyphbench/atari-{game}-v0", policy, 0, turns=1500)
    assert env.episode_return > 0


def test_atari_invaders_shields_soak_bombs_and_lives_run_out():
    env, info = play("glyphbench/atari-spaceinvaders-v0", lambda e: NOOP, 0, turns=3000)
    shield = sum(row.count("#") for row in env.still)
    assert shield < 3 * env.params.shields      # bombs ate into the shields
    assert info["won"] is False and env.lives == 0
