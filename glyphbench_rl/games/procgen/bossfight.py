"""Procgen BossFight: a boss patrols the top of an arena and attacks in phases while you shoot it
from below, hiding behind cover blocks that stop both sides' shots.

Differences from Procgen, for an agent that sees a window: the whole arena is in view (the boss
is never off-screen), the boss has no shield, and its three attack patterns (straight shots, a
three-way spread, shots aimed at you plus summoned minions) come in a per-seed order, with
per-seed rhythms, as its hit points fall."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from .engine import OPEN, PLAYER_GLYPHS
from .shooting import FOE, FOE_SHOT, PLAYER, SHOT, STOP, Body, Gun, ShooterTask, pair, with_fire

COVER, BOSS, BULLET, MINION, BOLT = "#", "B", "!", "x", "|"
PATTERNS = ("straight", "spread", "aimed")
SPREAD = {"straight": ((1, 0),), "spread": ((1, -1), (1, 0), (1, 1))}


@dataclass(frozen=True)
class BossFightParams:
    width: int = param(20, 12, 30)
    height: int = param(12, 9, 16)
    boss_hp: int = param(5, 1, 20)
    covers: int = param(3, 0, 6)
    cooldown: int = param(2, 1, 5)


class ProcgenBossFight(ShooterTask):
    title = "Procgen BossFight"
    rules = ("A boss (B) with {boss_hp} hit points patrols the top row of a {width}x{height} arena; "
             "you start at the bottom and move freely, one cell a turn. FIRE shoots a bolt (|) "
             "straight up, 2 rows a turn; after a shot the gun needs {cooldown} turns. Cover "
             "blocks (#) stop your bolts, the boss's shots (!) and you. The boss attacks in three "
             "phases as its hit points fall: straight shots down, a three-way spread, and shots "
             "aimed at you while it summons minions (x) that sink towards the bottom; their order "
             "and rhythm differ from arena to arena (the status line names the current one). "
             "A minion can be shot. A boss shot, a minion or the boss touching you ends the game.")
    rewards = "+{per_hit:.3g} for each hit on the boss, +0.5 more for destroying it, -1 for being hit."
    ends = "when the boss is destroyed or you are hit"
    Params = BossFightParams
    solid = COVER
    fire_dir = (-1, 0)
    ACTIONS = with_fire("shoot a bolt straight up")
    glyphs = {OPEN: "open", COVER: "cover block", BOSS: "the boss", BULLET: "boss shot",
              MINION: "minion", BOLT: "your bolt", **PLAYER_GLYPHS}

    def prompt_fields(self) -> dict:
        return {**super().prompt_fields(), "per_hit": 0.5 / self.params.boss_hp}

    def _setup(self, rng: np.random.Generator) -> None:
        p = self.params
        h, w = p.height, p.width
        rows = [[OPEN] * w for _ in range(h)]
        band = range(h // 2, h - 3)              # cover rows: between the boss and you
        for _ in range(p.covers):
            r, c = int(rng.choice(band)), int(rng.integers(1, w - 3))
            for dc in range(int(rng.integers(2, 4))):
                rows[r][c + dc] = COVER
        start = (h - 1, int(rng.integers(w)))
        self.start(["".join(row) for row in rows], start, Gun(BOLT, 2, h, p.cooldown))
        self.boss = self.world.add(Body(BOSS, 0, int(rng.integers(w)), 0, 1 if rng.random() < 0.5 else -1,
                                        side=FOE, hits=PLAYER, hp=p.boss_hp, period=2, edge=STOP))
        self.order = [PATTERNS[i] for i in rng.permutation(3)]     # this seed's attack variant
        self.rhythm = [int(x) for x in rng.integers(2, 5, size=3)]  # turns between attacks per phase
        self.bullet_speed = [int(x) for x in rng.integers(1, 3, size=3)]
        self.summon = int(rng.integers(4, 7))
        self.boss_rng = self.stream("boss")     # its moods (held: _think draws every turn)

    @property
    def phase(self) -> int:
        hp, full = self.boss.hp, self.params.boss_hp
        return 0 if 3 * hp > 2 * full else 1 if 3 * hp > full else 2

    def _think(self) -> None:
        boss, rng = self.boss, self.boss_rng
        if self.turn % 2 == 0 and rng.random() < 0.15:   # it changes its mind now and then
            boss.vc = -boss.vc
        k = self.phase
        pattern, speed = self.order[k], self.bullet_speed[k]
        if self.turn % self.rhythm[k] == 0:
            if pattern == "aimed":
                dc = self.pos[1] - boss.c
                aims = ((1, (dc > 0) - (dc < 0)) if abs(dc) * 2 > self.pos[0] else (1, 0),)
            else:
                aims = SPREAD[pattern]
            for dr, dc in aims:
                self.world.add(Body(BULLET, boss.r, boss.c, dr * speed, dc * speed, side=FOE_SHOT,
                                    hits=PLAYER))
        if pattern == "aimed" and self.turn % self.summon == 0:
            self.world.add(Body(MINION, boss.r + 1, boss.c, 1, 0, side=FOE, hits=PLAYER, period=2))

    def _hit(self, a: Body, b: Body | None) -> None:
        if b is None:
            if a is self.boss:
                a.vc = -a.vc                  # it turns at the walls
            elif a is not self.player:
                a.alive = False               # a shot stopped by cover
            return
        shot = pair(a, b, SHOT)
        if shot:
            bolt, foe = shot
            bolt.alive = False
            if foe is not self.boss:
                foe.alive = False
                self.say("Minion destroyed.")
                return
            before = self.phase
            foe.hp -= 1
            self.reward(0.5 / self.params.boss_hp)
            if foe.hp <= 0:
                foe.alive = False
                self.reward(0.5)
                self.say("The boss is destroyed.")
                self.finish(won=True)
            elif self.phase != before:
                self.say(f"The boss is hit and turns to {self.order[self.phase]} attacks.")
            else:
                self.say("The boss is hit.")
            return
        self.reward(-1)
        self.say("You were hit.")
        self.finish(won=False)

    def _extras(self) -> str:
        return f"Boss HP {self.boss.hp}/{self.params.boss_hp} {self.order[self.phase]} | {super()._extras()}"


register_variants(ProcgenBossFight, "Procgen", {"glyphbench/procgen-bossfight-v0": dict(max_turns=500)})
