"""Arcade engine units: presets registered with the right suite, tier and horizon; score rules
bounded; lives; swept collisions, guns, formations and scripted opponents."""

from __future__ import annotations

from dataclasses import dataclass

import pytest

from glyphbench_rl import make
from glyphbench_rl.core.actions import ActionSet
from glyphbench_rl.core.registry import get_spec
from glyphbench_rl.games.arcade.bodies import Body, Countdown, Formation, Gun, chase, sweep, track, wrap
from glyphbench_rl.games.arcade.engine import (ArcadeParams, ArcadeTask, Duel, Milestones, Tally,
                                               bound, register_arcade)

GAMES = ("pong", "freeway", "spaceinvaders")


@pytest.mark.parametrize("game", GAMES)
def test_presets_registered_with_suite_tier_and_horizon(game):
    mini, atari = get_spec(f"glyphbench/miniatari-{game}-v0"), get_spec(f"glyphbench/atari-{game}-v0")
    assert (mini.suite, mini.tier) == ("MiniAtari", "standard") and mini.max_turns <= 512
    assert (atari.suite, atari.tier) == ("Atari", "extended") and atari.max_turns >= 5000
    assert mini.game is atari.game
    m, a = make(mini.id), make(atari.id)
    assert a.params.width * a.params.height > m.params.width * m.params.height
    lo, hi = bound(m.pattern, m.params)
    assert -1 <= lo and hi <= 1 + 1e-9 and hi == pytest.approx(1.0)


class Recorder:
    def __init__(self):
        self.paid, self.won = [], "unset"

    def reward(self, x):
        self.paid.append(x)

    def finish(self, won=None):
        self.won = won


def test_tally_caps_credit_at_goal_and_wins_there():
    t = Recorder()
    tally = Tally(t, 4, 0.25)
    tally.gain(3)
    tally.gain(3)
    tally.gain()
    assert sum(t.paid) == pytest.approx(1.0) and tally.done == 4 and t.won is True
    assert tally.hud(False) == "Score 4/4" and tally.hud(True) == "Score 1 (4/4)"


def test_milestones_pay_once_per_key():
    t = Recorder()
    m = Milestones(t, 3, 1 / 3)
    m.reach("a", 0.25)
    m.reach("a", 0.25)
    m.reach("b", 0.25)
    assert sum(t.paid) == pytest.approx(0.5) and t.won == "unset"
    m.reach("c", 0.5)
    assert sum(t.paid) == pytest.approx(1.0) and t.won is True


@pytest.mark.parametrize("mine", [True, False])
def test_duel_is_first_to_w_and_bounded(mine):
    t = Recorder()
    d = Duel(t, 3, 1 / 3)
    for k in range(2):
        d.point(not mine)
    for k in range(3):
        d.point(mine)
    assert t.won is mine and -1 <= sum(t.paid) <= 1


@dataclass(frozen=True)
class Toy(ArcadeParams):
    pass


class ToyTask(ArcadeTask):
    title, rules = "Toy", "A toy."
    Params = Toy
    pattern = "D"
    ACTIONS = ActionSet([("NOOP", "wait")], noop="NOOP")
    glyphs = {".": "empty"}

    def _setup(self, rng):
        self.start(rng)
        self.respawns = 0

    def _respawn(self):
        self.respawns += 1


def test_register_arcade_refuses_a_mini_preset_outside_unit_bounds():
    with pytest.raises(ValueError, match=r"\[-1, 1\]"):
        register_arcade(ToyTask, "toyover", mini=dict(goal=8, unit=0.25, max_turns=100),
                        atari=dict(max_turns=1000))
    with pytest.raises(ValueError):
        register_arcade(ToyTask, "toydeath", mini=dict(death=-2.0, max_turns=100),
                        atari=dict(max_turns=1000))


def test_lives_respawn_until_the_last_then_death_is_paid():
    task = ToyTask(lives=3, tier="extended")
    task.reset(seed=0)
    task._step_reward = 0.0
    assert task.lose_life() is False and task.lose_life() is False
    assert task.respawns == 2 and task.lives == 1 and not task.done
    assert task.lose_life() is True
    assert task.done and task.won is False and task._step_reward == -1.0 and task.respawns == 2
    assert "Lives" in task._hud()


def test_sweep_stops_a_fast_body_at_a_thin_wall():
    ball = Body(0, 0, dr=0, dc=3)
    assert sweep(ball, lambda r, c: c == 2) == (0, 2)
    assert (ball.r, ball.c) == (0, 1)
    diag = Body(5, 5, dr=-2, dc=1)
    assert sweep(diag, lambda r, c: False) is None and (diag.r, diag.c) == (3, 6)
    assert wrap(-1, 10) == 9


def test_gun_cooldown_limit_and_reach():
    gun = Gun(cooldown=2, speed=2, reach=4, limit=2)
    assert gun.fire(0, 10, 5, -1, 0) is not None
    assert gun.fire(1, 10, 5, -1, 0) is None and not gun.ready_at(1)   # cooling down
    assert gun.fire(2, 10, 5, -1, 0) is not None
    assert gun.fire(4, 10, 5, -1, 0) is None          # two in flight
    out = list(gun.advance(lambda r, c: r == 8))
    assert [cell for _, cell in out] == [(8, 5), (8, 5)] and gun.shots == []
    gun.fire(10, 10, 5, -1, 0)
    assert list(gun.advance(lambda r, c: False)) == [] and gun.shots[0].r == 8
    gone = list(gun.advance(lambda r, c: False))
    assert len(gone) == 1 and gone[0][1] is None      # out of reach


def test_formation_sweeps_then_steps_down_at_the_edge():
    f = Formation(rows=1, cols=2, top=1, left=1, gap=2, width=8, sweep=1)
    for turn in range(1, 4):
        f.tick(turn)
    assert (f.top, f.left) == (1, 4)                  # columns 4 and 6: at the edge
    f.tick(4)
    assert (f.top, f.left, f.dx) == (2, 4, -1)
    f.kill((0, 0))
    assert set(f.cells()) == {(2, 6)} and f.bottom() == 2
    assert f.lines("M", ".") == {2: "......M."} and f.front() == [(2, 6)]


class Fixed:
    def __init__(self, x):
        self.x = x

    def random(self):
        return self.x


def test_scripted_opponents():
    assert track(3, 7, 0.75, Fixed(0.5)) == 1 and track(3, 7, 0.75, Fixed(0.9)) == 0
    assert track(7, 3, 1.0, Fixed(0.0)) == -1 and track(3, 3, 1.0, Fixed(0.0)) == 0
    assert chase(0, 0, 5, 2) == (1, 0) and chase(0, 0, 1, -4) == (0, -1)
    clock = Countdown(2)
    assert clock.tick() is False and clock.tick() is True
    clock.refill()
    assert clock.left == 2


@pytest.mark.parametrize("game", GAMES)
def test_mini_hud_is_terse_and_atari_shows_native_points(game):
    m, a = make(f"glyphbench/miniatari-{game}-v0"), make(f"glyphbench/atari-{game}-v0")
    m.reset(seed=0)
    a.reset(seed=0)
    assert m.frame.hud.startswith("Step 0/") and "Score 0" in m.frame.hud
    assert "Score 0" in a.frame.hud
