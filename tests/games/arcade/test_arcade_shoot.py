"""The fixed-bottom shooter family: the engine (cannon, lanes, gun, bombs, marching packs), and
for each game a scripted win and a loss on MiniAtari presets and a scoring policy on Atari ones."""

from __future__ import annotations

import copy

import pytest

from glyphbench_rl import make
from glyphbench_rl.games.arcade.bodies import Body
from glyphbench_rl.games.arcade.shooter import FIRE, LEFT, NOOP, RIGHT, march

SEEDS = (0, 3)


def play(task_id: str, policy, seed: int, turns: int | None = None):
    env = make(task_id)
    env.reset(seed=seed)
    done, n = False, 0
    info = {}
    while not done and (turns is None or n < turns):
        _, _, term, trunc, info = env.step(policy(env))
        done, n = term or trunc, n + 1
    return env, info


def toward(env, target: int) -> int:
    if target == env.col:
        return FIRE
    return LEFT if target < env.col else RIGHT


def threatened(env, col: int, depth: int = 3) -> bool:
    return any(b.c == col and env.row - depth <= b.r < env.row for b in env.bombs.shots)


def dodge(env) -> int | None:
    """Step aside from a bomb about to land on the cannon."""
    if not threatened(env, env.col):
        return None
    lanes = env.lane_list or list(range(env.params.width))
    i = lanes.index(env.col)
    for j in (i - 1, i + 1):
        if 0 <= j < len(lanes) and not threatened(env, lanes[j]):
            return LEFT if j < i else RIGHT
    return None


def gunner(env) -> int:
    """Dodge bombs, else go under the lowest enemy and fire (never into overheat)."""
    away = dodge(env)
    if away is not None:
        return away
    foes = env.pack.bodies
    if not foes:
        return NOOP
    low = max(b.r for b in foes)
    target = min((b.c for b in foes if b.r == low), key=lambda c: abs(c - env.col))
    act = toward(env, target)
    if act == FIRE and getattr(env, "hot", 0) + 3 >= getattr(env.params, "heat", 0) > 0:
        return NOOP
    return act


def lookahead(base, horizon: int = 8):
    """A planner: try each action, follow ``base`` for ``horizon`` turns on a copy of the game,
    keep the action that paid most without losing a life (``base``'s own choice on a tie)."""
    def policy(env) -> int:
        first = base(env)
        best, pick = None, first
        for a in [first] + [a for a in range(env.action_space.n) if a != first]:
            sim = copy.deepcopy(env)
            lives, ret, kills = sim.lives, sim.episode_return, getattr(sim, "kills", 0)
            _, _, term, trunc, _ = sim.step(a)
            for _ in range(horizon):
                if term or trunc:
                    break
                _, _, term, trunc, _ = sim.step(base(sim))
            value = (sim.won is not False or not sim.done, sim.lives >= lives,
                     sim.episode_return - ret, getattr(sim, "kills", 0) - kills)
            if best is None or value > best:
                best, pick = value, a
        return pick
    return policy


def idle(env) -> int:
    return NOOP


GAMES = ("assault", "demonattack", "phoenix", "beamrider", "centipede", "atlantis", "gopher")


@pytest.mark.parametrize("game", GAMES)
def test_presets_registered_with_suite_tier_horizon_and_bounds(game):
    from glyphbench_rl.core.registry import get_spec
    from glyphbench_rl.games.arcade.engine import bound
    mini, atari = get_spec(f"glyphbench/miniatari-{game}-v0"), get_spec(f"glyphbench/atari-{game}-v0")
    assert (mini.suite, mini.tier) == ("MiniAtari", "standard") and mini.max_turns <= 512
    assert (atari.suite, atari.tier) == ("Atari", "extended") and atari.max_turns >= 5000
    m, a = make(mini.id), make(atari.id)
    assert a.params.width * a.params.height > m.params.width * m.params.height
    lo, hi = bound(m.pattern, m.params)
    assert -1 <= lo and hi == pytest.approx(1.0)


# -- the engine ------------------------------------------------------------------------------------
def test_march_sweeps_then_turns_and_steps_down_at_the_edge():
    row = [Body(1, 2), Body(1, 4)]
    dx = march(row, 1, 0, 5, False)
    assert dx == 1 and [b.c for b in row] == [3, 5] and row[0].r == 1
    dx = march(row, dx, 0, 5, False)
    assert dx == -1 and [b.c for b in row] == [3, 5] and row[0].r == 2
    march(row, 0, 0, 5, True)
    assert row[1].r == 3


def test_cannon_moves_fires_with_cooldown_and_bombs_hit_it():
    env = make("glyphbench/miniatari-assault-v0")
    env.reset(seed=0)
    env.pack.bodies.clear()
    col = env.col
    env.tick = 1
    env.steer(LEFT)
    env.steer(FIRE)
    assert env.col == col - 1 and len(env.gun.shots) == 1
    env.steer(FIRE)
    assert len(env.gun.shots) == 1                      # one shot at a time
    env.drop(env.row - 1, env.col)
    assert env.rain() is True and env.bombs.shots == []
    env.drop(env.row - 2, env.col + 1)
    assert env.rain() is False and env.bombs.shots[0].r == env.row - 1


# -- assault ---------------------------------------------------------------------------------------
@pytest.mark.parametrize("seed", SEEDS)
def test_assault_mini_win_by_shooting_the_formation(seed):
    env, info = play("glyphbench/miniatari-assault-v0", lookahead(gunner), seed)
    assert info["won"] is True and env.episode_return == pytest.approx(1.0)


@pytest.mark.parametrize("seed", SEEDS)
def test_assault_mini_loss_when_the_formation_lands(seed):
    env, info = play("glyphbench/miniatari-assault-v0", idle, seed)
    assert info["won"] is False and env.episode_return == 0 and env.tick < 200


def test_assault_atari_scores_and_overheat_costs_a_life():
    env, _ = play("glyphbench/atari-assault-v0", gunner, 0, turns=600)
    assert env.episode_return > 0
    env = make("glyphbench/atari-assault-v0")
    env.reset(seed=1)
    lives, said = env.lives, ""
    for _ in range(60):
        env.pack.bodies.clear()                         # nothing to hit: shots fly on
        env.bombs.shots.clear()
        env.step(FIRE)
        if env.lives < lives:
            said = env.frame.message
            break
    assert env.lives == lives - 1 and "overheated" in said


def bomb_seeker(env) -> int:
    """Walk under the lowest falling bomb (a way to lose)."""
    if not env.bombs.shots:
        return NOOP
    bomb = max(env.bombs.shots, key=lambda b: b.r)
    return NOOP if bomb.c == env.col else (LEFT if bomb.c < env.col else RIGHT)


# -- demon attack ----------------------------------------------------------------------------------
@pytest.mark.parametrize("seed", SEEDS)
def test_demonattack_mini_win_by_shooting_five_demons(seed):
    env, info = play("glyphbench/miniatari-demonattack-v0", lookahead(gunner), seed)
    assert info["won"] is True and env.episode_return == pytest.approx(1.0)


@pytest.mark.parametrize("seed", SEEDS)
def test_demonattack_mini_loss_under_a_bomb(seed):
    env, info = play("glyphbench/miniatari-demonattack-v0", bomb_seeker, seed)
    assert info["won"] is False and env.episode_return == pytest.approx(-1.0)


def test_demonattack_atari_scores_and_demons_split_later():
    env, _ = play("glyphbench/atari-demonattack-v0", lookahead(gunner, 6), 0, turns=150)
    assert env.episode_return > 0
    env = make("glyphbench/atari-demonattack-v0")
    env.reset(seed=0)
    env.waves = env.params.split
    env.pack.bodies[:] = [env.pack.bodies[0]]
    foe = env.pack.bodies[0]
    foe.r, foe.c, foe.dc = env.row - 2, env.col, 0
    env.tick = 0                                        # next turn does not flap
    env.step(FIRE)
    assert [b.glyph for b in env.pack.bodies].count("w") == 2 and env.score.done == 1


# -- phoenix ---------------------------------------------------------------------------------------
@pytest.mark.parametrize("seed", SEEDS)
def test_phoenix_mini_win_by_shooting_the_flock(seed):
    env, info = play("glyphbench/miniatari-phoenix-v0", lookahead(gunner), seed)
    assert info["won"] is True and env.episode_return == pytest.approx(1.0)


@pytest.mark.parametrize("seed", SEEDS)
def test_phoenix_mini_loss_when_a_bird_lands(seed):
    env, info = play("glyphbench/miniatari-phoenix-v0", idle, seed)
    assert info["won"] is False and env.episode_return == pytest.approx(-1.0)


def test_phoenix_atari_scores_and_the_shield_stops_a_bomb():
    env, _ = play("glyphbench/atari-phoenix-v0", lookahead(gunner, 6), 0, turns=150)
    assert env.episode_return > 0
    env = make("glyphbench/atari-phoenix-v0")
    env.reset(seed=0)
    env.pack.bodies.clear()
    lives = env.lives
    env.step(4)                                         # SHIELD
    env.drop(env.row - 1, env.col)
    env.step(LEFT)                                      # held in place under the shield
    assert env.lives == lives and env.frame.grid[env.row][env.col] == "@"


# -- beamrider -------------------------------------------------------------------------------------
def rammed(env) -> int:
    """Ride under the lowest saucer and never shoot (a way to lose)."""
    if not env.pack.bodies:
        return NOOP
    low = max(env.pack.bodies, key=lambda b: b.r)
    return NOOP if low.c == env.col else (LEFT if low.c < env.col else RIGHT)


def test_beamrider_ship_hops_between_beams():
    env = make("glyphbench/miniatari-beamrider-v0")
    env.reset(seed=0)
    lanes = env.lane_list
    assert len(lanes) == env.params.beams and env.col in lanes
    env.step(RIGHT)
    assert env.col == lanes[lanes.index(lanes[len(lanes) // 2]) + 1]
    for _ in range(len(lanes)):
        env.step(RIGHT)
    assert env.col == lanes[-1] and env.frame.grid[env.row][lanes[0]] == "_"


@pytest.mark.parametrize("seed", SEEDS)
def test_beamrider_mini_win_by_shooting_saucers(seed):
    env, info = play("glyphbench/miniatari-beamrider-v0", lookahead(gunner), seed)
    assert info["won"] is True and env.episode_return == pytest.approx(1.0)


@pytest.mark.parametrize("seed", SEEDS)
def test_beamrider_mini_loss_when_rammed(seed):
    env, info = play("glyphbench/miniatari-beamrider-v0", rammed, seed)
    assert info["won"] is False and env.episode_return == pytest.approx(-1.0)


def test_beamrider_atari_scores():
    env, _ = play("glyphbench/atari-beamrider-v0", lookahead(gunner, 6), 0, turns=150)
    assert env.episode_return > 0


# -- centipede -------------------------------------------------------------------------------------
def test_centipede_shot_segment_becomes_a_mushroom_and_splits_the_body():
    env = make("glyphbench/miniatari-centipede-v0")
    env.reset(seed=0)
    env.still = ["." * env.params.width] * env.params.height
    env.still_version += 1
    env.pack.bodies[:] = env.pack.bodies[:3]            # head at column 7, body at 6 and 5
    for b in env.pack.bodies:
        b.r = 5
    mid = env.pack.bodies[1]
    env.col = mid.c + 1                                 # the body steps into the shot's path
    env.tick = 0
    env.step(FIRE)
    env.step(NOOP)
    assert env.score.done == 1 and "#" in env.frame.grid[5]
    assert [b.glyph for b in env.pack.bodies] == ["O", "O"]
    env._crawl(env.pack.bodies[1])                      # the new head meets the mushroom: down
    assert env.pack.bodies[1].r == 6


@pytest.mark.parametrize("seed", SEEDS)
def test_centipede_mini_win_by_shooting_every_segment(seed):
    env, info = play("glyphbench/miniatari-centipede-v0", lookahead(gunner), seed)
    assert info["won"] is True and env.episode_return == pytest.approx(1.0)


@pytest.mark.parametrize("seed", SEEDS)
def test_centipede_mini_loss_when_it_reaches_the_bottom(seed):
    env, info = play("glyphbench/miniatari-centipede-v0", idle, seed)
    assert info["won"] is False and env.episode_return == 0 and env.tick < env.max_turns


def test_centipede_atari_scores():
    env, _ = play("glyphbench/atari-centipede-v0", lookahead(gunner, 6), 0, turns=150)
    assert env.episode_return > 0


# -- atlantis --------------------------------------------------------------------------------------
def test_atlantis_turrets_fire_diagonally_and_straight():
    env = make("glyphbench/atari-atlantis-v0")
    env.reset(seed=0)
    towers = env._towers()
    for a in (1, 2, 3):
        env.guns[a - 1].fire(0, env.params.height - 1, towers[a - 1], *((-1, 1), (-1, 0), (-1, -1))[a - 1])
    env.pack.bodies.clear()
    env.sent = env.params.wave
    env.step(NOOP)
    s = env.params.shot_speed
    assert [(g.shots[0].r, g.shots[0].c) for g in env.guns] == [
        (env.params.height - 1 - s, towers[0] + s), (env.params.height - 1 - s, towers[1]),
        (env.params.height - 1 - s, towers[2] - s)]


def test_atlantis_atari_raiders_drop_several_rows_a_pass_and_buildings_stand_clear_of_turrets():
    env = make("glyphbench/atari-atlantis-v0")
    env.reset(seed=0)
    city = env.frame.grid[-1]
    assert city.count("H") == env.params.lives and city.count("T") == 3
    env.pack.bodies.clear()
    env.sent = env.params.wave
    env.pack.add(0, env.params.width - 1, ">", dc=1)
    env.step(NOOP)
    raider = env.pack.bodies[0]
    assert (raider.r, raider.c, raider.glyph) == (env.params.drop, env.params.width - 1, "<")


@pytest.mark.parametrize("seed", SEEDS)
def test_atlantis_mini_win_by_repelling_every_wave(seed):
    env, info = play("glyphbench/miniatari-atlantis-v0", lookahead(idle, 10), seed)
    assert info["won"] is True and env.episode_return == pytest.approx(1.0)


@pytest.mark.parametrize("seed", SEEDS)
def test_atlantis_mini_loss_when_a_raider_reaches_the_city(seed):
    env, info = play("glyphbench/miniatari-atlantis-v0", idle, seed)
    assert info["won"] is False and env.episode_return == pytest.approx(-1.0)


def test_atlantis_atari_scores_and_loses_a_building_per_raider_landed():
    env, _ = play("glyphbench/atari-atlantis-v0", lookahead(idle, 10), 0, turns=150)
    assert env.episode_return > 0
    env, info = play("glyphbench/atari-atlantis-v0", idle, 0)
    assert info["won"] is False and "H" not in env.frame.grid[-1] and env.waves >= 1


# -- gopher ----------------------------------------------------------------------------------------
def guard(env) -> int:
    """Stand over the gopher's shaft (or the carrot it is heading for) and fill it."""
    g = env.gopher
    col = g.c if g.r < env.params.height - 1 else env.target
    if col != env.col:
        return LEFT if col < env.col else RIGHT
    return 3 if g.r < env.params.height - 1 else NOOP


def test_gopher_fill_plugs_the_shaft_top_and_bonks_the_gopher():
    env = make("glyphbench/miniatari-gopher-v0")
    env.reset(seed=0)
    g = env.gopher
    g.r, g.c = 3, env.col
    for r in (3, 4, 5):
        env.set_still(r, env.col, ".")
    env._fill()
    assert env.still[3][env.col] == "#" and (g.r, g.c) != (3, env.col) and g.r == env.params.height - 1


@pytest.mark.parametrize("seed", SEEDS)
def test_gopher_mini_win_by_holding_every_carrot(seed):
    env, info = play("glyphbench/miniatari-gopher-v0", guard, seed)
    assert info["won"] is True and env.episode_return == pytest.approx(1.0) and env.lives == 3


@pytest.mark.parametrize("seed", SEEDS)
def test_gopher_mini_loss_when_every_carrot_is_eaten(seed):
    env, info = play("glyphbench/miniatari-gopher-v0", idle, seed)
    assert info["won"] is False and env.episode_return == pytest.approx(-1.0)
    assert "Y" not in env.frame.grid[0]


def test_gopher_atari_scores_by_bonking():
    env, _ = play("glyphbench/atari-gopher-v0", guard, 0, turns=600)
    assert env.episode_return > 0 and env.score.done >= 1
