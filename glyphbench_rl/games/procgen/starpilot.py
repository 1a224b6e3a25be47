"""Procgen StarPilot: a horizontal shooter. Enemy ships fly in from the right, some twice as
fast, drifting between lanes now and then; shoot them (FIRE shoots right) and dodge the rest.

Differences from Procgen, for an agent that sees a window: the field is a strip wider than the
view with a few asteroids (they stop shots and ships: an enemy flying into one is wrecked), the
enemies do not shoot, and a power-up gives rapid fire for a while. Every seed draws its
asteroids, its spawn rhythm and its share of fast ships."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from .engine import OPEN, PLAYER_GLYPHS
from .shooting import FOE, ITEM, PLAYER, SHOT, Body, Gun, ShooterTask, Spawner, pair, with_fire

ROCK, ENEMY, FAST, POWER, BOLT = "#", "E", "V", "$", "-"


@dataclass(frozen=True)
class StarPilotParams:
    width: int = param(40, 20, 80)
    height: int = param(12, 6, 16)
    rocks: int = param(5, 0, 12)
    shot_range: int = param(8, 2, 20)
    cooldown: int = param(2, 1, 5)
    rapid_turns: int = param(20, 1, 100)   # turns of rapid fire (cooldown 1) a power-up gives
    kills_paid: int = param(12, 1, 50)


class ProcgenStarPilot(ShooterTask):
    title = "Procgen StarPilot"
    rules = ("You fly a ship in a {height}-row strip of space {width} columns long, seen through a "
             "window that follows you; move freely, one cell a turn. Enemy ships fly in from the "
             "right edge and cross to the left: E moves 1 column a turn, V moves 2, and either "
             "sometimes drifts one row up or down. FIRE shoots a bolt (-) to the right that flies 2 "
             "columns a turn for {shot_range} columns; after a shot the gun needs {cooldown} turns "
             "(the status line says when it is ready). Asteroids (#) stop bolts and ships; an enemy "
             "flying into one is wrecked. A power-up ($) drifts in too: touch it for rapid fire "
             "(every turn) for {rapid_turns} turns. An enemy touching you, even passing "
             "through your cell within a turn, destroys you.")
    rewards = ("+{kill:.3g} for each of the first {kills_paid} enemies shot, +0.1 for each of the "
               "first 2 power-ups, -1 for being destroyed.")
    ends = "when an enemy destroys you"
    Params = StarPilotParams
    solid = ROCK
    fire_dir = (0, 1)
    ACTIONS = with_fire("shoot a bolt to the right")
    glyphs = {OPEN: "space", ROCK: "asteroid", ENEMY: "enemy ship (1 column a turn)",
              FAST: "fast enemy ship (2 columns a turn)", POWER: "power-up", BOLT: "your bolt",
              **PLAYER_GLYPHS}

    def prompt_fields(self) -> dict:
        return {**super().prompt_fields(), "kill": 0.8 / self.params.kills_paid}

    def _setup(self, rng: np.random.Generator) -> None:
        p = self.params
        h, w = p.height, p.width
        rows = [[OPEN] * w for _ in range(h)]
        for _ in range(p.rocks):
            r, c = int(rng.integers(h)), int(rng.integers(8, w - 3))
            for dc in range(int(rng.integers(1, 3))):
                rows[r][c + dc] = ROCK
        start = (int(rng.integers(1, h - 1)), 2)
        rows[start[0]][start[1]] = OPEN
        self.start(["".join(row) for row in rows], start,
                   Gun(BOLT, 2, p.shot_range, p.cooldown))
        self.fast = float(rng.uniform(0.1, 0.25))          # this seed's share of fast ships
        self.wobble = float(rng.uniform(0.3, 0.6))   # the chance a turn that one enemy drifts
        period = int(rng.integers(3, 6))
        self.enemies = Spawner(self.stream("enemies"), period, jitter=1, first=int(rng.integers(1, period + 1)))
        self.powers = Spawner(self.stream("powers"), int(rng.integers(10, 15)), jitter=2,
                              first=int(rng.integers(6, 12)))
        self.kills = self.picked = self.rapid = 0
        self.drifter: Body | None = None
        for _ in range(int(rng.integers(1, 3))):          # a first wave already on its way
            self._spawn(ENEMY, rng, int(rng.integers(w // 2, w)))

    def _spawn(self, glyph: str, rng: np.random.Generator, col: int) -> None:
        r = int(rng.random() * self.params.height)
        if self.world.is_solid(r, col) or (r, col) == self.pos:
            return
        speed = 2 if glyph == FAST else 1
        side = ITEM if glyph == POWER else FOE
        self.world.add(Body(glyph, r, col, 0, -speed, side=side, hits=PLAYER if side == FOE else 0))

    def _think(self) -> None:
        w, rng = self.params.width, self.enemies.rng     # (the "enemies" stream)
        if self.drifter is not None:            # last turn's drift ends
            self.drifter.vr = 0
            self.drifter = None
        if rng.random() < self.wobble:          # and now and then one enemy drifts a row
            foes = [b for b in self.world.bodies if b.side == FOE]
            if foes:
                b = self.drifter = foes[int(rng.random() * len(foes))]
                b.vr = 1 if (rng.random() < 0.5 and b.r + 1 < self.params.height) or b.r == 0 else -1
        if self.enemies.due(self.turn):
            self._spawn(FAST if self.enemies.chance(self.fast) else ENEMY, rng, w - 1)
        if self.powers.due(self.turn):
            self._spawn(POWER, self.powers.rng, w - 1)
        if self.rapid:
            self.rapid -= 1
            self.gun.cooldown = 1 if self.rapid else self.params.cooldown

    def _hit(self, a: Body, b: Body | None) -> None:
        if b is None:
            if a is not self.player:
                a.alive = False            # a bolt or a ship into an asteroid, a bolt's end
            return
        shot = pair(a, b, SHOT)
        if shot:
            bolt, foe = shot
            bolt.alive = foe.alive = False
            self.kills += 1
            if self.kills <= self.params.kills_paid:
                self.reward(0.8 / self.params.kills_paid)
            self.say("Enemy shot down.")
            return
        _, other = pair(a, b, PLAYER)
        if other.side == ITEM:
            other.alive = False
            self.picked += 1
            if self.picked <= 2:
                self.reward(0.1)
            self.rapid = self.params.rapid_turns + 1
            self.gun.cooldown, self.gun.ready = 1, min(self.gun.ready, self.turn + 1)
            self.say("Power-up: rapid fire.")
        else:
            self.reward(-1)
            self.say("An enemy ship destroyed you.")
            self.finish(won=False)

    def _extras(self) -> str:
        gun = super()._extras()
        return f"Kills {self.kills} | {gun}" + (f" | Rapid {self.rapid}" if self.rapid else "")


register_variants(ProcgenStarPilot, "Procgen", {"glyphbench/procgen-starpilot-v0": dict(max_turns=220)})
