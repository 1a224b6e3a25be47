"""Battlezone: a tank on an open battlefield strewn with rocks, against enemy tanks that roll
toward you and fire their cannon when they have you in line. On the Atari preset up to three
enemy tanks roam at once, one more arriving every few turns."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.params import param
from .arena import EMPTY, SHELL, SHOT, WALL, ArenaParams, ArenaTask, you_glyphs
from .engine import register_arcade

TANK = "T"


@dataclass(frozen=True)
class ZoneParams(ArenaParams):
    width: int = param(14, 8, 40)
    height: int = param(12, 8, 40)
    goal: int = param(3, 1, 500)
    unit: float = param(1 / 3, 0, 10000)
    foes: int = param(1, 1, 6)
    reach: int = param(5, 1, 40)
    volley: int = param(6, 1, 100)
    rocks: int = param(4, 0, 40)


class Battlezone(ArenaTask):
    title = "Battlezone"
    rules = ("You drive a tank ({lives_text}) on a {width}x{height} battlefield with rocks (#) "
             "that stop tanks and shells. Enemy tanks (T), {foes} at most at a time{reinforce_text}, "
             "roll one cell toward you every {every} turns. FIRE sends a shell (*) {reach} cells the "
             "way you face; it destroys the first tank it meets.{turn_text}{volley_text} A tank "
             "that rams you also kills you.")
    rewards = "+{unit} for each enemy tank destroyed; {death} when the game is lost."
    ends = "when you have destroyed {goal} tanks or the game is lost"
    Params = ZoneParams
    pattern = "D"
    FOE, foe_name, caught_text = TANK, "tank", "An enemy tank rammed you."
    glyphs = {EMPTY: "open ground", WALL: "rock", TANK: "enemy tank", SHOT: "your shell",
              SHELL: "enemy shell", **you_glyphs()}

    def prompt_fields(self) -> dict:
        p = self.params
        return {**super().prompt_fields(), "reinforce_text": (
            f" (one more every {p.reinforce} turns)") if p.reinforce else " (a new one replaces each you destroy)"}

    def _still(self) -> list[str]:
        p = self.params
        rows = [list(EMPTY * p.width) for _ in range(p.height)]
        stream = self.stream("rocks")
        for _ in range(p.rocks):
            r, c = int(stream.integers(1, p.height - 2)), int(stream.integers(1, p.width - 1))
            rows[r][c] = WALL
        return ["".join(r) for r in rows]

    def _setup(self, rng) -> None:
        p = self.params
        self.start_arena(rng, p.height - 1, p.width // 2)
        self.stock() if not p.reinforce else self.stock(one=True)

    def _hit(self, foe) -> None:
        super()._hit(foe)
        if not self.done and not self.params.reinforce:
            self.stock()


register_arcade(Battlezone, "battlezone",
                mini=dict(every=3, volley=6, max_turns=200),
                atari=dict(width=20, height=20, goal=10, unit=1000.0, lives=3, foes=3, reinforce=20,
                           every=2, volley=6, reach=6, rocks=10, max_turns=10000))
