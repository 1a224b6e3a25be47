"""Wizard of Wor: a worrior in a walled dungeon hunts the monsters that stalk its corridors. The
small dungeon has a block of wall in the middle; the Atari preset's larger one adds wall stubs,
monsters that shoot, and after every few cleared waves the Wizard himself, who blinks from
place to place until he is shot."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.params import param
from .arena import EMPTY, SHELL, SHOT, WALL, ArenaParams, ArenaTask, you_glyphs
from .engine import register_arcade

MONSTER, WIZARD = "M", "W"


@dataclass(frozen=True)
class WorParams(ArenaParams):
    width: int = param(14, 10, 40)
    height: int = param(10, 8, 30)
    goal: int = param(5, 1, 500)
    unit: float = param(0.2, 0, 100)
    foes: int = param(5, 1, 12)
    reach: int = param(5, 1, 40)
    stubs: int = param(0, 0, 1)           # 1: wall stubs off the outer walls
    wizard: int = param(0, 0, 20)         # cleared waves between the Wizard's visits (0: never)
    blink: int = param(6, 1, 50)          # ticks between the Wizard's jumps


class WizardOfWor(ArenaTask):
    title = "Wizard of Wor"
    rules = ("You ({lives_text}) are a worrior in a {width}x{height} dungeon walled with #, a "
             "block of wall in its middle. {foes} monsters (M) each step one cell toward you every "
             "{every} turns; one that reaches you kills you. FIRE sends a shot (*) {reach} cells "
             "the way you face; it kills the first monster it meets.{turn_text} A cleared dungeon "
             "fills with a new wave.{volley_text}{wizard_text}")
    rewards = "+{unit} for each monster (or Wizard) shot; {death} when the game is lost."
    ends = "when you have shot {goal} foes or the game is lost"
    Params = WorParams
    pattern = "D"
    FOE, foe_name, caught_text = MONSTER, "monster", "A monster caught you."
    glyphs = {EMPTY: "dungeon floor", WALL: "wall", MONSTER: "monster", WIZARD: "the Wizard",
              SHOT: "your shot", SHELL: "monster shot", **you_glyphs()}

    def prompt_fields(self) -> dict:
        p = self.params
        return {**super().prompt_fields(), "wizard_text": (
            f" After every {p.wizard} cleared waves the Wizard (W) joins the next one; he jumps to "
            f"a random spot every {p.blink} turns.") if p.wizard else ""}

    def _still(self) -> list[str]:
        p = self.params
        w, h = p.width, p.height
        rows = [list(WALL * w)] + [list("#" + EMPTY * (w - 2) + "#") for _ in range(h - 2)] + [list(WALL * w)]
        for r in range(h // 2 - 1, h // 2 + 1):
            rows[r][w // 2 - 2:w // 2 + 2] = WALL * 4
        if p.stubs:
            for c in range(w // 4, w - 2, w // 4):
                rows[2][c] = rows[h - 3][c] = WALL
            rows[h // 2][2] = rows[h // 2][w - 3] = WALL
        return ["".join(r) for r in rows]

    def _setup(self, rng) -> None:
        p = self.params
        self.start_arena(rng, p.height - 2, 1)
        self.waves = 0
        self._wave()

    def _wave(self) -> None:
        p = self.params
        for _ in range(min(p.foes, p.goal - self.kills)):
            self.add_foe(*self.spot(6))
        if p.wizard and self.waves and self.waves % p.wizard == 0 and self.kills + len(self.foes) < p.goal:
            self.add_foe(*self.spot(6), glyph=WIZARD)
            self.say("The Wizard of Wor appears!")
        self.waves += 1

    def _hit(self, foe) -> None:
        super()._hit(foe)
        if not self.done and not self.foes:
            self._wave()

    def _turn(self) -> None:
        if self.tick % self.params.blink == 0:
            for foe in self.foes:
                if foe.glyph == WIZARD:
                    foe.r, foe.c = self.spot(3)


register_arcade(WizardOfWor, "wizardofwor",
                mini=dict(every=3, max_turns=300),
                atari=dict(width=22, height=16, goal=48, unit=100.0, lives=3, foes=6, every=2,
                           volley=8, stubs=1, wizard=2, max_turns=10000))
