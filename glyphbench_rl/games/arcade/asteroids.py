"""Asteroids: a ship in a field of drifting rocks that wraps around at its edges. Shoot the
rocks the way you fly; flying into one, or letting one drift into you, is a crash. On the Atari
preset big rocks split into two medium ones and medium into two small, and a cleared field is
refilled."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.params import param
from .arena import EMPTY, SHOT, ArenaParams, ArenaTask, you_glyphs
from .engine import register_arcade

BIG, MEDIUM, SMALL = "O", "o", "+"
SMALLER = {BIG: MEDIUM, MEDIUM: SMALL}
HEADINGS = ((-1, -1), (-1, 1), (1, -1), (1, 1), (-1, 0), (1, 0), (0, -1), (0, 1))


@dataclass(frozen=True)
class RocksParams(ArenaParams):
    width: int = param(14, 8, 40)
    height: int = param(12, 8, 40)
    goal: int = param(5, 1, 500)
    unit: float = param(0.2, 0, 10000)
    death: float = param(0.0, -1000, 0)
    foes: int = param(5, 1, 12)
    every: int = param(2, 1, 50)
    reach: int = param(6, 1, 40)
    wrap: int = param(1, 1, 1)
    split: int = param(0, 0, 1)          # 1: rocks split big -> medium -> small


class Asteroids(ArenaTask):
    title = "Asteroids"
    rules = ("You fly a ship ({lives_text}) in a {width}x{height} field that wraps around at its "
             "edges. {foes} rocks drift in straight lines, a cell every {every} turns. FIRE sends a "
             "shot (*) {reach} cells the way you fly; it breaks the first rock it meets. Flying "
             "into a rock, or a rock drifting into you, {crash_text}.{split_text}")
    rewards = "+{unit} for each rock shot{death_text}."
    ends = "when you have shot {goal} rocks or the game is lost"
    Params = RocksParams
    pattern = "D"
    drift = True
    FOE, foe_name, caught_text = BIG, "rock", "A rock hit your ship."
    glyphs = {EMPTY: "space", BIG: "rock", MEDIUM: "medium rock", SMALL: "small rock",
              SHOT: "your shot", **you_glyphs()}

    def prompt_fields(self) -> dict:
        p = self.params
        return {**super().prompt_fields(),
                "crash_text": "ends the game" if p.lives == 1 else "costs a life",
                "death_text": f"; {p.death} when the game is lost" if p.death else "",
                "split_text": (" A big rock (O) splits into two medium ones (o), a medium one "
                               "into two small ones (+); small ones shatter. A cleared field is "
                               "refilled.") if p.split else ""}

    def _setup(self, rng) -> None:
        p = self.params
        self.start_arena(rng, p.height // 2, p.width // 2)
        self._field()

    def _field(self) -> None:
        for _ in range(min(self.params.foes, self.params.goal - self.kills)):
            self.add_foe(*self.spot(4), *HEADINGS[self.draws.below(8)])

    def _enter(self, r: int, c: int) -> bool:
        if self.foe_at(r, c) is not None:
            self.r, self.c = r, c
            self._killed("You flew into a rock.")
            return True
        return False

    def _hit(self, foe) -> None:
        super()._hit(foe)
        if self.done:
            return
        if self.params.split and foe.glyph in SMALLER:
            k = self.draws.below(4)
            for dr, dc in (HEADINGS[k], HEADINGS[(k + 1) % 4 if k % 2 == 0 else k - 1]):
                r, c = self._where(foe.r + dr, foe.c + dc)
                if self.free(r, c) and (r, c) != (self.r, self.c):
                    self.add_foe(r, c, dr, dc, SMALLER[foe.glyph])
        if not self.foes:
            self.say("Field cleared: new rocks drift in.")
            self._field()


register_arcade(Asteroids, "asteroids",
                mini=dict(max_turns=200),
                atari=dict(width=20, height=20, goal=25, unit=20.0, death=-1.0, lives=3, foes=4,
                           split=1, max_turns=10000))
