"""Beamrider: your ship rides the bottom ends of a few vertical beams (_) and hops from beam to
beam; saucers (o) come down the beams. FIRE shoots up your beam, with a cooldown. A saucer
that reaches your beam's end rams you; on the Atari preset saucers also hop beams and shoot,
and each sector of kills makes them fall faster."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.params import param, require
from .engine import EMPTY, register_arcade
from .shooter import BOMB, CANNON, SHOT, Shooter, ShooterParams, shooter_actions

SAUCER, BEAM = "o", "_"
SECTOR_TEXT: dict[int, str] = {}         # the HUD's sector note, made once per sector


@dataclass(frozen=True)
class BeamParams(ShooterParams):
    width: int = param(14, 8, 60)
    height: int = param(12, 8, 40)
    goal: int = param(5, 1, 300)
    unit: float = param(0.2, 0, 100)
    cooldown: int = param(3, 1, 20)
    beams: int = param(5, 2, 15)
    fall: int = param(2, 1, 10)           # turns per row a saucer falls (sector 1)
    spawn: int = param(4, 1, 50)          # turns between saucers
    saucers: int = param(3, 1, 10)        # saucers on the field at once at most
    hop: float = param(0.0, 0, 1)         # chance a turn that a saucer hops to a next beam
    sector: int = param(0, 0, 100)        # kills per sector; each sector falls a turn faster (0: one)

    def check(self) -> None:
        require(2 * self.beams <= self.width, "beams", "fit the field two cells apart", self.beams)


class BeamRider(Shooter):
    title = "Beamrider"
    rules = ("Your ship (A) rides the bottom row of a {width}x{height} field, on {beams} beams (_ "
             "marks each beam's end), with {lives_text}. LEFT and RIGHT hop to the next beam. Every "
             "{spawn} turns, while fewer than {saucers} are out, a saucer (o) enters at the top of a "
             "random beam and falls a row every {fall} turns{hop_text}; a saucer reaching your "
             "beam's end rams you (a life), elsewhere it leaves. {gun_text}{bomb_text}{sector_text}")
    rewards = "+{unit} for each saucer shot{death_text}."
    ends = "when you have shot {goal} saucers or the game is lost"
    ACTIONS = shooter_actions(left="hop to the beam on the left", right="hop to the beam on the right")
    Params = BeamParams
    pattern = "D"
    glyphs = {EMPTY: "empty", BEAM: "beam end", SAUCER: "saucer", SHOT: "your shot", BOMB: "enemy shot",
              CANNON: "you (the ship)"}

    def prompt_fields(self) -> dict:
        p = self.params
        return {**super().prompt_fields(),
                "hop_text": f" and hops to a next beam with chance {p.hop:g} a turn" if p.hop else "",
                "bomb_text": (f" Each turn a saucer shoots down (!) with chance {p.bomb_chance:g}; a "
                              "hit costs a life.") if p.bomb_chance else "",
                "sector_text": (f" Every {p.sector} kills clear a sector, and saucers then fall a "
                                "turn a row faster (down to every turn).") if p.sector else ""}

    def _lanes(self) -> list[int]:
        p = self.params
        span = (p.width - 1) / p.beams
        return [int(span * (k + 0.5)) + 1 for k in range(p.beams)]

    def _still(self) -> list[str]:
        p = self.params
        rows = super()._still()
        rows[-1] = "".join(BEAM if c in self._lanes() else EMPTY for c in range(p.width))
        return rows

    def _setup(self, rng) -> None:
        self.arm(rng)
        self.sectors = 1

    def _play(self, action: int) -> None:
        p, d, lanes = self.params, self.draws, self.lane_list
        if action:
            self.steer(action)
        fall = max(1, p.fall - self.sectors + 1)
        falls, hop = self.tick % fall == 0, p.hop
        if falls or hop:
            for b in self.pack.bodies:
                if falls:
                    b.r += 1
                if hop and d.random() < hop:
                    i = lanes.index(b.c) + (1 if d.random() < 0.5 else -1)
                    if 0 <= i < len(lanes):
                        b.c = lanes[i]
        if self.gun.shots and self.shoot_down("Saucer hit!") is None:
            return
        if p.sector and 1 + self.score.done // p.sector > self.sectors:
            self.sectors += 1
            self.say(f"Sector {self.sectors}!")
        if self.touches():
            self.pack.kill(self.pack.at(self.row, self.col))
            if self.lose_life("A saucer rammed you."):
                return
        row = self.row
        for b in self.pack.bodies:   # (the list of those past you is made only when there is one)
            if b.r >= row:
                for b in [b for b in self.pack.bodies if b.r >= row]:
                    self.pack.kill(b)
                break
        if self.tick % p.spawn == 0 and len(self.pack) < p.saucers:
            self.pack.add(0, lanes[d.below(len(lanes))], SAUCER)
        if p.bomb_chance:
            self.maybe_drop()
        if self.bombs.shots and self.rain():
            self.lose_life("An enemy shot hit you.")

    def _extra_hud(self) -> str:
        if not self.params.sector:
            return ""
        text = SECTOR_TEXT.get(self.sectors)
        if text is None:
            text = SECTOR_TEXT[self.sectors] = f"Sector {self.sectors}"
        return text


register_arcade(BeamRider, "beamrider",
                mini=dict(max_turns=200),
                atari=dict(width=20, height=20, lives=3, goal=15, unit=10.0, death=0.0, beams=9,
                           fall=3, spawn=3, saucers=4, hop=0.05, sector=12, bomb_chance=0.1,
                           max_turns=10000))
