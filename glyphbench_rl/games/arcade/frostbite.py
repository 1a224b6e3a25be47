"""Frostbite: hop down from the shore onto rows of drifting ice floes and back. Landing on a row
of white floes turns that row blue and scores (building a block of the igloo); once every row is
blue they all turn white again. Floes carry you as they drift; a hop or a step onto open water
drowns you. On the Atari preset the cold counts down and only the shore warms you (pattern A)."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.params import param, require
from ..common.lanes import Lane, runs
from .bodies import Countdown
from .chase import ACTIONS
from .engine import ArcadeParams, ArcadeTask, register_arcade
from .hopping import Drift

WATER, SHORE, WHITE, BLUE, YOU = "~", "=", "#", "+", "B"
MOVES = ((0, 0), (0, -1), (0, 1), (-2, 0), (2, 0))


@dataclass(frozen=True)
class FrostbiteParams(ArcadeParams):
    width: int = param(16, 8, 60)
    height: int = param(10, 4, 40)        # shore, then water and floe rows in turn
    goal: int = param(4, 1, 1000)
    unit: float = param(0.25, 0, 10)
    death: float = param(0.0, 0, 0)
    floe: int = param(3, 1, 10)           # cells in a floe
    gap: int = param(3, 1, 20)            # the widest stretch of water between floes
    slowest: int = param(3, 1, 8)         # a row drifts a cell every 1..slowest turns
    cold: int = param(0, 0, 1000)         # turns you last away from the shore (0: no cold)

    def check(self) -> None:
        require(self.height % 2 == 0, "height", "even (shore, then water and floe rows in turn)", self.height)


class Frostbite(ArcadeTask):
    title = "Frostbite"
    rules = ("A {width}x{height} river below the shore (=, the top row). Rows of ice floes, each "
             "floe {floe} cells long, drift left or right over the water (~) one cell every 1 to "
             "{slowest} turns, and the river wraps round at the edges; a floe row lies every second "
             "row. Each turn the floes drift first (carrying you if you stand on one), then you act: "
             "UP and DOWN hop two rows to the next floe row (or the shore), LEFT and RIGHT step one "
             "cell. Landing on a row of white floes (#) turns the row blue (+) and scores; when "
             "every row is blue they all turn white again. Landing or stepping on water drowns you; "
             "you have {lives_text}.{cold_text}")
    rewards = "+{unit} for each landing on a row of white floes."
    ends = "when you have made {goal} scoring landings, or you drown with no lives left"
    ACTIONS = ACTIONS
    Params = FrostbiteParams
    pattern = "A"
    glyphs = {SHORE: "shore", WATER: "water", WHITE: "white floe (scores)", BLUE: "blue floe",
              YOU: "you (Frostbite Bailey)"}

    def prompt_fields(self) -> dict:
        c = self.params.cold
        text = f" Away from the shore you freeze after {c} turns; the shore warms you up again." if c else ""
        return {**super().prompt_fields(), "cold_text": text}

    def _still(self) -> list[str]:
        w = self.params.width
        return [SHORE * w] + [WATER * w] * (self.params.height - 1)

    def _setup(self, rng) -> None:
        self.start(rng)
        p = self.params
        lanes = {}
        for k, r in enumerate(range(2, p.height, 2)):
            pattern = runs(rng, p.width, WHITE, WATER, (p.floe, p.floe), (2, p.gap))
            tail = len(pattern) - len(pattern.rstrip(WHITE))
            if 0 < tail < p.floe:                 # no cut-off floe where the row wraps round
                pattern = pattern[:-tail] + WATER * tail
            if WHITE not in pattern:
                pattern = WHITE * p.floe + pattern[p.floe:]
            period = int(rng.integers(1, p.slowest + 1))
            lanes[r] = Lane(pattern, 1 if k % 2 == 0 else -1, period, int(rng.integers(period)))
        self.drift = Drift(lanes, WATER)
        self.blue: set[int] = set()
        self.clock = Countdown(p.cold)
        self._respawn()

    def _respawn(self) -> None:
        self.r, self.c = 0, self.params.width // 2
        self.clock.refill()

    def _play(self, action: int) -> None:
        p, tick = self.params, self.tick
        self.c = (self.c + self.drift.carry(self.r, tick)) % p.width
        dr, dc = MOVES[action]
        r = self.r + dr
        if not 0 <= r < p.height:
            return
        self.r, self.c = r, (self.c + dc) % p.width
        if r == 0:
            self.clock.refill()
            return
        if not self.drift.solid(r, self.c, tick):
            self.lose_life("Splash! You fell in the water.")
            return
        if dr and r not in self.blue:
            self.blue.add(r)
            if len(self.blue) == len(self.drift.lanes):
                self.blue.clear()
                self.say("Every row was blue: the floes turn white again.")
            self.score.gain()
        if p.cold and self.clock.tick():
            self.lose_life("You froze!")

    def _rows(self) -> list[str]:
        rows, tick, blue = self.still[:], self.tick, self.blue
        for r, cycle in self.drift.cycles.items():
            row = cycle[tick % len(cycle)]
            rows[r] = row.replace(WHITE, BLUE) if r in blue else row
        return rows

    def _sprites(self):
        return ((self.r, self.c, YOU),)

    def _grid(self) -> list[str]:
        rows = self._rows()             # (you are always on the field)
        line = rows[self.r]
        rows[self.r] = line[:self.c] + YOU + line[self.c + 1:]
        return rows

    def _extra_hud(self) -> str:
        return f"Cold {self.clock.left}" if self.params.cold else ""


register_arcade(Frostbite, "frostbite",
                mini=dict(max_turns=300),
                atari=dict(width=20, height=16, goal=16, unit=1.0, lives=3, floe=3, gap=5,
                           slowest=4, cold=60, max_turns=10000))
