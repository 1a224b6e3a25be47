"""Demon Attack: a cannon on the bottom row under demons (W) that flap sideways, turning at
random, in the rows near the top and drop bombs. Waves of demons follow each other; from a
later wave on (Atari preset) a shot demon splits into two small demons (w) that dive at you."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.params import param
from .engine import EMPTY, register_arcade
from .shooter import BOMB, CANNON, SHOT, Shooter, ShooterParams, bounce

DEMON, DIVER = "W", "w"
WAVE_TEXT: dict[int, str] = {}           # the HUD's wave note, made once per wave


@dataclass(frozen=True)
class DemonParams(ShooterParams):
    width: int = param(14, 8, 60)
    height: int = param(10, 8, 40)
    goal: int = param(5, 1, 300)
    unit: float = param(0.2, 0, 100)
    bomb_chance: float = param(0.15, 0, 1)
    demons: int = param(5, 1, 10)         # demons on the field at once
    wave: int = param(5, 1, 50)           # demons in a wave
    band: int = param(3, 1, 10)           # demons fly in rows 1..band
    flap: int = param(2, 1, 10)           # turns per sideways step
    turn: float = param(0.3, 0, 1)        # chance a demon turns back at a step
    split: int = param(0, 0, 20)          # from this wave on, a shot demon splits (0: never)


class DemonAttack(Shooter):
    title = "Demon Attack"
    rules = ("You are the cannon (A) on the bottom row of a {width}x{height} field, with "
             "{lives_text}. Demons (W) fly in rows 1 to {band}, {demons} at a time and {wave} to a "
             "wave, stepping a cell sideways every {flap} turns and turning back at random "
             "(chance {turn}). Each turn a demon drops a bomb (!) with chance {bomb_chance}; bombs "
             "fall a cell a turn and a hit costs a life. {gun_text}{split_text}")
    rewards = "+{unit} for each demon shot{death_text}."
    ends = "when you have shot {goal} demons or the game is lost"
    Params = DemonParams
    pattern = "D"
    glyphs = {EMPTY: "empty", DEMON: "demon", DIVER: "small diving demon", SHOT: "your shot",
              BOMB: "bomb", CANNON: "you (the cannon)"}

    def prompt_fields(self) -> dict:
        p = self.params
        return {**super().prompt_fields(),
                "split_text": (f" From wave {p.split} on a shot demon splits into two small demons "
                               "(w) that dive at you a cell a turn; touching one costs a life.")
                if p.split else ""}

    def _setup(self, rng) -> None:
        self.arm(rng)
        self.waves, self.sent = 1, 0
        self._fill()

    def _fill(self) -> None:
        p, d = self.params, self.draws
        if self.sent >= p.wave:
            return
        demons = 0
        for b in self.pack.bodies:   # (a loop, once: this runs most turns of a wave)
            if b.glyph == DEMON:
                demons += 1
        while self.sent < p.wave and demons < p.demons:
            self.sent += 1
            demons += 1
            self.pack.add(1 + d.below(p.band), 1 + d.below(p.width - 2), DEMON,
                          dc=1 if d.random() < 0.5 else -1)

    def _play(self, action: int) -> None:
        p, d = self.params, self.draws
        if action:
            self.steer(action)
        flap, col, turn, right = self.tick % p.flap == 0, self.col, p.turn, p.width - 1
        # only a diver (or a demon where the band reaches your row) gets to your row or past it
        divers = p.band >= self.row
        for b in self.pack.bodies:
            if b.glyph == DIVER:
                divers = True
                b.r += 1
                b.c += (col > b.c) - (col < b.c)
            elif flap:
                if d.random() < turn:
                    b.dc = -b.dc
                bounce(b, 0, right)
        hits = self.shoot_down("Demon hit!") if self.gun.shots else []
        if hits is None:
            return
        for foe, (r, c) in hits:
            if foe.glyph == DEMON and p.split and self.waves >= p.split:
                for dc in (-1, 1):
                    if 0 <= c + dc < p.width:
                        self.pack.add(r, c + dc, DIVER)
        if divers:
            row = self.row
            for b in self.pack.bodies:   # (the list of those past you is made only when there is one)
                if b.r > row:
                    for b in [b for b in self.pack.bodies if b.r > row]:
                        self.pack.kill(b)
                    break
            if self.touches():
                self.pack.kill(self.pack.at(self.row, self.col))
                if self.lose_life("A diving demon hit you."):
                    return
        if self.sent < p.wave:
            self._fill()
        if not self.pack.bodies:
            self.waves, self.sent = self.waves + 1, 0
            self._fill()
        if p.bomb_chance:
            self.maybe_drop()
        if self.bombs.shots and self.rain():
            self.lose_life("A bomb hit you.")

    def _extra_hud(self) -> str:
        if not self.native:
            return ""
        text = WAVE_TEXT.get(self.waves)
        if text is None:
            text = WAVE_TEXT[self.waves] = f"Wave {self.waves}"
        return text


register_arcade(DemonAttack, "demonattack",
                mini=dict(max_turns=200),
                atari=dict(width=20, height=20, lives=3, goal=40, unit=10.0, death=0.0, demons=3,
                           wave=8, band=8, bomb_chance=0.2, bombs=3, split=2, max_turns=10000))
