"""The arena family (free-roam shooters): the engine's core mechanic, and per game a scripted
win path and loss path on the MiniAtari preset and a scoring policy on the Atari preset."""

from __future__ import annotations

import copy

import pytest

from glyphbench_rl import make

NOOP, UP, DOWN, LEFT, RIGHT, FIRE = range(6)


def play(task_id: str, policy, seed: int, turns: int | None = None):
    """Run ``policy`` (env -> action) from ``reset(seed)`` to the end or for ``turns`` turns."""
    env = make(task_id)
    env.reset(seed=seed)
    info: dict = {}
    for _ in range(turns or env.max_turns):
        *_, term, trunc, info = env.step(policy(env))
        if term or trunc:
            break
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
        near = -min(abs(dr), abs(dc)) - 0.1 * d
        sights = False
        if (dr == 0 or dc == 0) and d <= env.params.reach + 1 and clear(env, dr, dc, d):
            sights = env.face == ((dr > 0) - (dr < 0), (dc > 0) - (dc < 0))
            near += 3 if sights else 1
        if d <= 1:
            v -= 50
        elif d == 2 and not sights:
            v -= 8
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


def search(env, lives: int, ret: float, depth: int) -> float:
    """The best value reachable in ``depth`` more turns (the top three first moves explored)."""
    if depth == 0 or env.done:
        return value(env, lives, ret)
    tried = []
    for a in range(6):
        e = copy.deepcopy(env)
        e.step(a)
        tried.append((value(e, lives, ret), e))
    tried.sort(key=lambda t: -t[0])
    best = -1e9
    for v, e in tried[:3]:
        if v > -1000:
            v = 0.5 * v + 0.5 * search(e, lives, ret, depth - 1)
        best = max(best, v)
    return best


def hunter(env, depth: int = 2) -> int:
    """Lookahead over copies of the game (the foes' moves are deterministic enough)."""
    lives, ret = env.lives, env.episode_return
    scored = []
    for a in range(6):
        e = copy.deepcopy(env)
        e.step(a)
        v = value(e, lives, ret)
        if v > -1000 and not e.done:
            v = 0.5 * v + 0.5 * search(e, lives, ret, depth - 1)
        scored.append((v, -a, a))
    return max(scored)[2]


def deep_hunter(env) -> int:
    return hunter(env, 3)


def rammer(env) -> int:
    """Fly straight at the nearest foe."""
    f = min(env.foes, key=lambda f: abs(f.r - env.r) + abs(f.c - env.c))
    dr, dc = f.r - env.r, f.c - env.c
    if abs(dr) >= abs(dc) and dr:
        return DOWN if dr > 0 else UP
    return RIGHT if dc > 0 else LEFT


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
HUNTED = ["alien", "berzerk", "wizardofwor", "battlezone", "robotank", "timepilot", "asteroids"]
POLICY = {"robotank": deep_hunter}
LOSERS = {"alien": lambda e: NOOP, "berzerk": lambda e: LEFT, "wizardofwor": lambda e: NOOP,
          "battlezone": lambda e: NOOP}


@pytest.mark.parametrize("seed", [0, 1, 2])
@pytest.mark.parametrize("game", HUNTED)
def test_mini_hunter_wins(game, seed):
    env, info = play(f"glyphbench/miniatari-{game}-v0", POLICY.get(game, hunter), seed)
    assert info["won"] is True and env.episode_return == pytest.approx(1.0) and not info["clamped"]


@pytest.mark.parametrize("seed", [0, 1])
@pytest.mark.parametrize("game", sorted(LOSERS))
def test_mini_loss_path(game, seed):
    env, info = play(f"glyphbench/miniatari-{game}-v0", LOSERS[game], seed)
    assert info["won"] is False and -1 <= env.episode_return < 0 and not info["clamped"]


@pytest.mark.parametrize("game", HUNTED)
def test_atari_hunter_scores(game):
    env, _ = play(f"glyphbench/atari-{game}-v0", POLICY.get(game, hunter), 0, turns=120)
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


@pytest.mark.parametrize("seed", [0, 1])
@pytest.mark.parametrize("game", ["robotank", "timepilot", "asteroids"])
def test_a_careless_player_is_rammed_and_loses_unpaid(game, seed):
    env, info = play(f"glyphbench/miniatari-{game}-v0", rammer if game == "asteroids" else (lambda e: NOOP), seed)
    assert info["won"] is False and env.episode_return == 0 and env.turn < env.max_turns


def test_robotank_atari_hits_knock_out_systems_in_order():
    env = make("glyphbench/atari-robotank-v0")
    env.reset(seed=0)
    assert not env.broken("video")
    env.lose_life("hit")
    assert env.broken("video") and not env.broken("cannon")
    env.lose_life("hit")
    assert env.broken("cannon") and env.gun.reach == env.params.reach // 2
    foe = env.foes[0]
    foe.r, foe.c, foe.data = env.r - 2, env.c, 2
    env.step(FIRE)
    assert foe in env.foes and foe.data == 1                  # two hits to destroy a robot tank


def test_timepilot_atari_the_boss_takes_hits_and_starts_the_next_era():
    env = make("glyphbench/atari-timepilot-v0")
    env.reset(seed=0)
    env.foes[:] = []
    env.since = env.params.boss - 1
    foe = env.add_foe(env.r - 2, env.c)
    env.step(FIRE)
    boss = next(f for f in env.foes if f.glyph == "B")
    env.foes[:] = [boss]
    boss.r, boss.c = env.r - 2, env.c
    for _ in range(env.params.boss_hp):
        boss.r, boss.c = env.r - 2, env.c
        env.step(FIRE)
        env.step(NOOP)
    assert foe not in env.foes and boss not in env.foes and env.era == 2


def test_asteroids_the_field_wraps_and_atari_rocks_split():
    env = make("glyphbench/atari-asteroids-v0")
    env.reset(seed=0)
    env.foes[:] = []
    env.r, env.c = 0, 3
    env.step(UP)
    assert (env.r, env.c) == (env.params.height - 1, 3)              # off the top, in at the bottom
    rock = env.add_foe(env.r - 2, env.c, 0, 0, "O")
    env.step(FIRE)
    assert rock not in env.foes and {f.glyph for f in env.foes} == {"o"}
    assert env.episode_return == pytest.approx(env.params.unit)


# -- yars' revenge -------------------------------------------------------------------------------
def safe(env, action: int, turns: int = 3) -> bool:
    e = copy.deepcopy(env)
    lives = e.lives
    e.step(action)
    for _ in range(turns):
        if e.done or e.lives < lives:
            break
        e.step(NOOP)
    return e.lives == lives and e.won is not False


def yar(env) -> int:
    """Break the shield block by block from a few cells away, then shoot the Qotile; dodge."""
    blocks = [r for r, row in enumerate(env.still) if "#" in row]
    row = blocks[0] if blocks else env.qrow
    col = env.params.width - 3 - env.params.reach + 1
    if env.r != row:
        want = DOWN if row > env.r else UP
    elif env.c < col:
        want = RIGHT
    elif env.face != (0, 1):
        want = RIGHT
    else:
        want = FIRE
    for a in (want, UP, DOWN, LEFT, NOOP, RIGHT):
        if safe(env, a):
            return a
    return want


@pytest.mark.parametrize("seed", [0, 1])
def test_yarsrevenge_breaking_the_shield_then_the_qotile_wins(seed):
    env, info = play("glyphbench/miniatari-yarsrevenge-v0", yar, seed)
    assert info["won"] is True and env.episode_return == pytest.approx(1.0) and not info["clamped"]


@pytest.mark.parametrize("seed", [0, 1])
def test_yarsrevenge_sitting_in_the_swirls_path_loses(seed):
    env, info = play("glyphbench/miniatari-yarsrevenge-v0", lambda e: NOOP, seed)
    assert info["won"] is False and env.episode_return == pytest.approx(-1.0)


def test_yarsrevenge_atari_scores_native_points():
    env, _ = play("glyphbench/atari-yarsrevenge-v0", yar, 0, turns=150)
    assert env.episode_return >= env.params.block_pts


# -- seaquest ------------------------------------------------------------------------------------
def diver_hunter(env) -> int:
    """Swim to the nearest diver; go up when the load is full or the air runs low; dodge."""
    p = env.params
    up = env.carried >= p.divers or env.air.left <= env.r + 4 or not env.swimmers
    if up:
        want = UP if env.r > 0 else NOOP
    else:
        d = min(env.swimmers, key=lambda d: abs(d.r - env.r) + abs(d.c - env.c))
        if d.r != env.r:
            want = DOWN if d.r > env.r else UP
        else:
            want = RIGHT if d.c > env.c else LEFT
    for a in (want, FIRE, UP, DOWN, LEFT, RIGHT, NOOP):
        if safe(env, a, 2):
            return a
    return want


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_seaquest_rescuing_a_full_load_and_surfacing_wins(seed):
    env, info = play("glyphbench/miniatari-seaquest-v0", diver_hunter, seed)
    assert info["won"] is True and env.episode_return == pytest.approx(1.0) and not info["clamped"]


@pytest.mark.parametrize("seed", [0, 1])
def test_seaquest_staying_under_runs_out_of_air(seed):
    env, info = play("glyphbench/miniatari-seaquest-v0", lambda e: DOWN if e.r < 1 else NOOP, seed)
    assert info["won"] is False and -1 <= env.episode_return < 0


def test_seaquest_air_runs_down_only_under_water():
    env = make("glyphbench/miniatari-seaquest-v0")
    env.reset(seed=0)
    env.foes[:] = []
    env.step(NOOP)
    assert env.air.left == env.params.air
    env.step(DOWN)
    env.step(NOOP)
    assert env.air.left == env.params.air - 2
    env.step(UP)
    assert env.air.left == env.params.air


def test_seaquest_atari_scores():
    env, _ = play("glyphbench/atari-seaquest-v0", diver_hunter, 0, turns=200)
    assert env.episode_return > 0
