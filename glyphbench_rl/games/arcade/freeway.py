"""Freeway: a chicken crosses lanes of traffic from the bottom kerb to the far kerb at the top.
Each lane slides one way at its own pace; a car that meets the chicken knocks it back toward
the start. Every crossing scores and the chicken starts again at the bottom (pattern A)."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param, require
from ..common.lanes import Lane
from .engine import EMPTY, ArcadeParams, ArcadeTask, register_arcade

CHICKEN, RIGHT_CAR, LEFT_CAR, KERB = "C", ">", "<", "="
ACTIONS = ActionSet([("NOOP", "stay where you are"), ("UP", "step one row up (toward the far kerb)"),
                     ("DOWN", "step one row down")], noop="NOOP")
MOVES = (0, -1, 1)


@dataclass(frozen=True)
class FreewayParams(ArcadeParams):
    width: int = param(14, 8, 60)
    height: int = param(10, 5, 40)
    goal: int = param(4, 1, 100)
    unit: float = param(0.25, 0, 10)
    death: float = param(0.0, 0, 0)
    lanes: int = param(3, 1, 20)
    spacing: int = param(2, 1, 4)       # rows from one lane to the next (quiet rows between)
    cars: int = param(2, 1, 10)         # cars per lane
    slowest: int = param(3, 1, 8)       # a lane moves a cell every 1..slowest turns
    knock: int = param(2, 1, 40)        # rows a hit pushes the chicken back

    def check(self) -> None:
        require(self.height - 1 - self.spacing * self.lanes > 0, "height",
                "leaves a row above the last lane", self.height)
        require(2 * self.cars <= self.width, "cars", "fit a lane with gaps", self.cars)


class Freeway(ArcadeTask):
    title = "Freeway"
    rules = ("You are the chicken (C) on the bottom row of a {width}x{height} road with {lanes} "
             "lanes of traffic; each lane slides left (<) or right (>) one cell every 1 to "
             "{slowest} turns. Reach the far kerb (=) on the top row to score a crossing; you "
             "then start again at the bottom. A car that meets you knocks you {knock} rows back down.")
    rewards = "+{unit} for each crossing."
    ends = "when you have made {goal} crossings"
    ACTIONS = ACTIONS
    Params = FreewayParams
    pattern = "A"
    glyphs = {EMPTY: "road or pavement", KERB: "far kerb (goal)", CHICKEN: "you (the chicken)",
              RIGHT_CAR: "car moving right", LEFT_CAR: "car moving left"}

    def _still(self) -> list[str]:
        w = self.params.width
        return [KERB * w] + [EMPTY * w] * (self.params.height - 1)

    def _setup(self, rng) -> None:
        self.start(rng)
        p = self.params
        self.home, self.col = p.height - 1, p.width // 2
        self.r = self.home
        self.lanes: dict[int, Lane] = {}
        for k in range(p.lanes):
            direction = 1 if k % 2 == 0 else -1
            cells = [EMPTY] * p.width
            slots = rng.choice(p.width // 2, p.cars, replace=False).tolist()
            for s in slots:
                cells[2 * s] = RIGHT_CAR if direction > 0 else LEFT_CAR
            period = int(rng.integers(1, p.slowest + 1))
            self.lanes[self.home - p.spacing * (k + 1)] = Lane("".join(cells), direction, period,
                                                               int(rng.integers(period)))
        self.cycles = {r: self._cycle(lane) for r, lane in self.lanes.items()}

    @staticmethod
    def _cycle(lane: Lane) -> tuple[str, ...]:
        """The lane's rows over one full cycle (``period`` x width ticks): the row at tick t is
        ``cycle[t % len(cycle)]`` (``lane.row(t)``), so a turn draws every lane by indexing."""
        n, per, ph = len(lane.pattern), lane.period, lane.phase
        turns = [lane.row(k * per - ph % per) for k in range(1, n + 1)]   # once per distinct shift
        return tuple(turns[((t + ph) // per - ph // per - 1) % n] for t in range(per * n))

    def _car(self, r: int, turn: int) -> bool:
        cycle = self.cycles.get(r)
        return cycle is not None and cycle[turn % len(cycle)][self.col] != EMPTY

    def _play(self, action: int) -> None:
        p = self.params
        self.r = min(self.home, max(0, self.r + MOVES[action]))
        if self.r == 0:
            self.score.gain()
            self.say("Crossed!")
            self.r = self.home
            return
        if self._car(self.r, self.tick):
            self.r = min(self.home, self.r + p.knock)
            self.say("Hit by a car!")

    def _rows(self) -> list[str]:
        rows, tick = self.still[:], self.tick
        for r, cycle in self.cycles.items():
            rows[r] = cycle[tick % len(cycle)]
        return rows

    def _sprites(self):
        return ((self.r, self.col, CHICKEN),)


register_arcade(Freeway, "freeway",
                mini=dict(max_turns=200),
                atari=dict(width=20, height=13, lanes=10, spacing=1, cars=3, slowest=4,
                           knock=12, goal=10, unit=1.0, max_turns=10000))
