"""The arena family (free-roam shooters): the engine's core mechanic, and per game a scripted
win path and loss path on the MiniAtari preset and a scoring policy on the Atari preset."""

from __future__ import annotations

import copy

import pytest

from glyphbench_rl import make

NOOP, UP, DOWN, LEFT, RIGHT, FIRE = range(6)


def play(task_id: str, policy, seed: int, turns: int | None = None):
    env = make(task_id)
    env.reset(seed=seed)
    done, n = False, 0
    while not done and (turns is None or n < turns):
        _, _, term, trunc, info = env.step(policy(env))
        done, n = term or trunc, n + 1
    return env, info


def value(env, lives: int, ret: float) -> float:
    """How good a position is for a hunter: alive, paid, lined up with a foe it faces."""
    if env.lives < lives or (env.done and not env.won):
        return -1000.0
    v = 100 * (env.episode_return - ret)
    if env.won:
        return v + 500
    best = 0.0
    for f in env.foes:
        dr, dc = f.r - env.r, f.c - env.c
        d = abs(dr) + abs(dc)
        if d <= 1:
            v -= 50
        elif d == 2:
            v -= 8
        near = -min(abs(dr), abs(dc)) - 0.1 * d
        if (dr == 0 or dc == 0) and d <= env.params.reach + 1 and clear(env, dr, dc, d):
            near += 3 if (env.face == ((dr > 0) - (dr < 0), (dc > 0) - (dc < 0))) else 1
        best = max(best, near) if best else near
    mid = abs(env.r - env.params.height // 2) + abs(env.c - env.params.width // 2)
    p = env.params
    walls = sum(not (0 <= env.r + a < p.height and 0 <= env.c + b < p.width)
                or env.still[env.r + a][env.c + b] in env.SOLID for a, b in ((1, 0), (-1, 0), (0, 1), (0, -1)))
    return v + best - 0.1 * mid - walls + extra(env)


def clear(env, dr: int, dc: int, d: int) -> bool:
    sr, sc = (dr > 0) - (dr < 0), (dc > 0) - (dc < 0)
    return all(env.still[env.r + sr * k][env.c + sc * k] not in env.SOLID for k in range(1, d))


def extra(env) -> float:
    goal = getattr(env, "target", None)
    return -abs(goal[0] - env.r) - abs(goal[1] - env.c) if goal else 0.0


def hunter(env) -> int:
    """Two-ply lookahead over copies of the game (the foes' moves are deterministic enough)."""
    lives, ret = env.lives, env.episode_return
    n = len(env.action_names) if hasattr(env, "action_names") else 6
    scored = []
    for a in range(n):
        e1 = copy.deepcopy(env)
        e1.step(a)
        v1 = value(e1, lives, ret)
        if v1 > -1000 and not e1.done:
            best2 = -1e9
            for b in range(n):
                e2 = copy.deepcopy(e1)
                e2.step(b)
                best2 = max(best2, value(e2, lives, ret))
            v1 = 0.5 * v1 + 0.5 * best2
        scored.append((v1, -a, a))
    return max(scored)[2]


# -- the engine's core mechanic -----------------------------------------------------------------
def test_foes_close_on_the_dominant_axis_every_k_ticks_and_a_shot_flies_its_reach():
    env = make("glyphbench/miniatari-alien-v0")
    env.reset(seed=0)
    env.foes[:] = []
    foe = env.add_foe(env.r - 4 if env.r >= 4 else env.r + 4, env.c)
    start = (foe.r, foe.c)
    k = env.params.every
    for _ in range(k - env.tick % k - 1):
        env.step(NOOP)
    assert (foe.r, foe.c) == start
    env.step(NOOP)
    assert abs(foe.r - env.r) == 3 and foe.c == env.c          # one step along the long axis
    env.step(UP if foe.r < env.r else DOWN)                     # face it
    env.step(FIRE)
    assert env.kills == 1 and foe not in env.foes and env.episode_return == pytest.approx(env.params.unit)


# -- per game: a win path, a loss path (mini) and a scoring policy (Atari) -------------------------
HUNTED = ["alien", "berzerk", "wizardofwor", "battlezone"]
LOSERS = {"alien": lambda e: NOOP, "berzerk": lambda e: LEFT, "wizardofwor": lambda e: NOOP,
          "battlezone": lambda e: NOOP}


@pytest.mark.parametrize("seed", [0, 1, 2])
@pytest.mark.parametrize("game", HUNTED)
def test_mini_hunter_wins(game, seed):
    env, info = play(f"glyphbench/miniatari-{game}-v0", hunter, seed)
    assert info["won"] is True and env.episode_return == pytest.approx(1.0) and not info["clamped"]


@pytest.mark.parametrize("seed", [0, 1])
@pytest.mark.parametrize("game", sorted(LOSERS))
def test_mini_loss_path(game, seed):
    env, info = play(f"glyphbench/miniatari-{game}-v0", LOSERS[game], seed)
    assert info["won"] is False and -1 <= env.episode_return < 0 and not info["clamped"]


@pytest.mark.parametrize("game", HUNTED)
def test_atari_hunter_scores(game):
    env, _ = play(f"glyphbench/atari-{game}-v0", hunter, 0, turns=120)
    assert env.episode_return > 0 and env.kills > 0


def test_berzerk_touching_the_wall_kills_at_once():
    env, info = play("glyphbench/miniatari-berzerk-v0", lambda e: LEFT, 0)
    assert env.turn == 1 and env.episode_return == pytest.approx(-1.0)


def test_alien_atari_eggs_score_when_crushed():
    env = make("glyphbench/atari-alien-v0")
    env.reset(seed=0)
    env.foes[:] = []
    env.step(LEFT)
    env.step(LEFT)
    assert env.episode_return == pytest.approx(env.params.unit)


def test_battlezone_an_enemy_in_line_fires_a_shell_that_kills():
    env = make("glyphbench/miniatari-battlezone-v0")
    env.reset(seed=0)
    tank = env.foes[0]
    tank.r, tank.c = env.r, env.c - 4
    obs = ""
    while not env.done:
        obs = env.step(NOOP)[0]
    assert env.won is False and "shell hit you" in obs and env.turn <= env.params.volley + 3
