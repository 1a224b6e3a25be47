"""Alien: a crew member in the corridors of a ship's hull (a grid of pillar walls) with aliens
that close in on her. Her flamethrower burns a short way in the direction she faces. On the
Atari preset the corridors are lined with alien eggs to crush, and a cleared hull is refilled."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.params import param, require
from .arena import EMPTY, SHOT, WALL, ArenaParams, ArenaTask, you_glyphs
from .engine import register_arcade

ALIEN, EGG = "A", "o"


@dataclass(frozen=True)
class AlienParams(ArenaParams):
    width: int = param(13, 9, 41)
    height: int = param(9, 7, 41)
    goal: int = param(4, 1, 500)
    foes: int = param(4, 1, 12)
    eggs: int = param(0, 0, 1)           # 1: eggs on every open corridor crossing

    def check(self) -> None:
        require(self.foes <= self.goal or self.eggs, "foes", "at most goal without eggs", self.foes)
        require(self.width % 4 == 1, "width", "one more than a multiple of 4", self.width)


class Alien(ArenaTask):
    title = "Alien"
    rules = ("You ({lives_text}) walk the corridors of a {width}x{height} hull between pillar "
             "walls (#). {foes} aliens (A) each step one cell toward you every {every} turns; one "
             "that reaches you kills you. FIRE sends a flame (*) {reach} cells the way you face; "
             "it kills the first alien it meets.{turn_text}{egg_text}{volley_text}")
    rewards = "+{unit} for each {what}; {death} when the game is lost."
    ends = "when you have scored {goal} times or the game is lost"
    Params = AlienParams
    pattern = "D"
    FOE, foe_name, caught_text = ALIEN, "alien", "An alien caught you."

    glyphs = {EMPTY: "corridor", WALL: "pillar wall", ALIEN: "alien", EGG: "alien egg", SHOT: "your flame",
              **you_glyphs()}

    def prompt_fields(self) -> dict:
        eggs = self.params.eggs
        return {**super().prompt_fields(), "what": "alien killed or egg crushed" if eggs else "alien killed",
                "egg_text": (" Eggs (o) lie at corridor crossings: step on one to crush it. When "
                             "every egg is crushed the hull is refilled.") if eggs else ""}

    def _still(self) -> list[str]:
        p = self.params
        fill = EGG if p.eggs else EMPTY
        rows = []
        for r in range(p.height):
            if r % 2 and r < p.height - 1:
                rows.append("".join(WALL if c % 4 else EMPTY for c in range(p.width)))
            else:
                rows.append("".join(fill if c % 2 == 0 else EMPTY for c in range(p.width)))
        return rows

    def _setup(self, rng) -> None:
        p = self.params
        self.start_arena(rng, p.height - 1 - (p.height - 1) % 2, p.width // 2 // 4 * 4)
        self._clear(self.r, self.c)
        for _ in range(p.foes):
            self.add_foe(*self.spot(6))

    def _clear(self, r: int, c: int) -> None:
        if self.still[r][c] == EGG:
            self.set_still(r, c, EMPTY)

    def _enter(self, r: int, c: int) -> bool:
        if self.still[r][c] == EGG:
            self.set_still(r, c, EMPTY)
            self.score.gain()
            if not self.done and not any(EGG in row for row in self.still):
                self.say("The hull is clear: new eggs are laid.")
                self.still = self._still()
                self.still_version += 1
                self.still[r] = self.still[r][:c] + EMPTY + self.still[r][c + 1:]
        return False

    def _hit(self, foe) -> None:
        super()._hit(foe)
        if not self.done and (self.params.eggs or self.kills + len(self.foes) < self.params.goal):
            self.add_foe(*self.spot(6))


register_arcade(Alien, "alien",
                mini=dict(reach=4, every=3, max_turns=300),
                atari=dict(width=21, height=21, goal=120, unit=10.0, lives=3, foes=3, every=2,
                           reach=4, eggs=1, max_turns=10000))
