"""Frogger: hop across lanes of traffic and a river of drifting logs into the homes at the top."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import ActionSet, GlyphTask, register_variants
from ...core.params import param
from ..common.grid import DELTAS
from ..common.lanes import Lane, runs
from ..common.palette import FLOOR, GOAL, PLAYER, WALL
from ..common.view import overlay

WATER, FILLED = "~", "●"
CARS = {-1: "<", 1: ">"}
LOGS = {-1: "«", 1: "»"}
# the column right of the board: whether each row moves on the coming turn, and which way
MOVES_NEXT = {-1: "←", 0: "|", 1: "→"}
CAR_LENGTHS, CAR_GAPS = (1, 2), (2, 4)
LOG_LENGTHS, LOG_GAPS = (2, 4), (1, 3)


@dataclass(frozen=True)
class FroggerParams:
    width: int = param(11, 7, 26)
    river: int = param(3, 1, 6)              # lanes of river
    road: int = param(3, 1, 6)               # lanes of traffic
    homes: int = param(3, 1, lambda p: p.width // 2)
    lives: int = param(3, 1, 9)
    max_period: int = param(2, 1, 4)         # the slowest lanes move one cell every this many turns
    death_penalty: float = param(0.2, 0, lambda p: 1 / p.lives)   # all lives lost cost at most 1


class Frogger(GlyphTask):
    title = "Frogger"
    rules = ("Cross {road} lanes of traffic and {river} lanes of river to fill the {homes} homes in "
             "the hedge at the top. Every lane slides sideways one cell every 1 to {max_period} "
             "turns, wrapping around the edges; cars and logs show their direction, and the "
             "column right of the board shows each row's move on the coming turn ({right} right, "
             "{left} left, {still} none). You hop one "
             "cell per turn, then the lanes move. On the river you must stand on a log, which "
             "carries you along. A car, the water or being carried off the edge costs a life. "
             "Hopping up into an empty home fills it and a new frog starts at the bottom; the "
             "hedge and filled homes block you. You have {lives} lives.")
    rewards = ("+{step_reward:.3g} per row of new progress toward the homes (each row counts once "
               "per home), +{home_reward:.3g} per home filled; each lost life costs {death_penalty:g}.")
    ends = "when every home is filled or your last life is lost"
    Params = FroggerParams
    ACTIONS = ActionSet([(n, f"hop one cell {n.lower()}") for n in ("UP", "DOWN", "LEFT", "RIGHT")]
                        + [("WAIT", "stay where you are")], noop="WAIT")
    glyphs = {FLOOR: "ground", WATER: "water", LOGS[-1]: "log drifting left",
              LOGS[1]: "log drifting right", CARS[-1]: "car driving left",
              CARS[1]: "car driving right", WALL: "hedge", GOAL: "empty home",
              FILLED: "filled home", PLAYER: "frog", MOVES_NEXT[1]: "row moves right next turn",
              MOVES_NEXT[-1]: "row moves left next turn", MOVES_NEXT[0]: "row still next turn"}
    default_max_turns = 200

    def _init(self) -> None:
        p = self.params
        self.height = p.river + p.road + 3
        self.slots = tuple((2 * i + 1) * p.width // (2 * p.homes) for i in range(p.homes))
        self.step_reward = 0.5 / p.homes / (self.height - 2)
        self.home_reward = 0.5 / p.homes

    def prompt_fields(self) -> dict:
        return super().prompt_fields() | {"step_reward": self.step_reward, "home_reward": self.home_reward,
                                          "right": MOVES_NEXT[1], "left": MOVES_NEXT[-1], "still": MOVES_NEXT[0]}

    def _setup(self, rng: np.random.Generator) -> None:
        p = self.params
        self.lanes: dict[int, Lane] = {}
        self.river_rows = range(1, p.river + 1)
        direction = 1 if rng.random() < 0.5 else -1
        for r in range(1, self.height - 1):
            if r == p.river + 1:                       # the safe bank between river and road
                continue
            direction = -direction
            period = int(rng.integers(1, p.max_period + 1))
            if r in self.river_rows:
                pattern = runs(rng, p.width, LOGS[direction], WATER, LOG_LENGTHS, LOG_GAPS)
            else:
                pattern = runs(rng, p.width, CARS[direction], FLOOR, CAR_LENGTHS, CAR_GAPS)
            self.lanes[r] = Lane(pattern, direction, period, int(rng.integers(period)))
        self.filled: set[int] = set()
        self._paint_homes()
        self.lives = p.lives
        self.tick = 0                                  # the lanes' clock (forfeited turns stop it)
        self._new_frog()

    def _paint_homes(self) -> None:
        self.home_row = "".join((FILLED if c in self.filled else GOAL) if c in self.slots else WALL
                                for c in range(self.params.width))

    def _new_frog(self) -> None:
        self.frog = (self.height - 1, self.params.width // 2)
        self.best = self.height - 1                    # the nearest row to the homes this trip

    def hit(self, r: int, c: int, tick: int) -> bool:
        """Whether a frog at (r, c) dies in the lane state at the end of ``tick``."""
        lane = self.lanes.get(r)
        if lane is None:
            return False
        cell = lane.row(tick)[c]
        return cell == WATER if r in self.river_rows else cell != FLOOR

    def advance(self, tick: int, r: int, c: int, action: int) -> tuple[int, int, str]:
        """The frog's hop and the lanes' move during ``tick``: (row, col, outcome) with outcome
        "ok", "home", "squashed", "drowned" or "swept away". Pure, for planners."""
        if action < 4:
            dr, dc = DELTAS[action]
            nr, nc = r + dr, c + dc
            if 0 <= nr < self.height and 0 <= nc < self.params.width:
                if nr > 0:
                    r, c = nr, nc
                elif nc in self.slots and nc not in self.filled:
                    return nr, nc, "home"
        death = "drowned" if r in self.river_rows else "squashed"
        if self.hit(r, c, tick - 1):                  # hopped onto a car or into the water
            return r, c, death
        if r in self.river_rows:                      # the log carries the frog
            drift = self.lanes[r].moves_at(tick)
            if not 0 <= c + drift < self.params.width:
                return r, c, "swept away"
            c += drift
        if self.hit(r, c, tick):                      # a car drove into the frog
            return r, c, death
        return r, c, "ok"

    def _act(self, action: int) -> None:
        self.tick += 1
        r, c, outcome = self.advance(self.tick, *self.frog, action)
        if outcome == "home":
            self.filled.add(c)
            self._paint_homes()
            self.reward(self.home_reward)
            self.say("Home!")
            if len(self.filled) == self.params.homes:
                self.frog = None
                self.finish(won=True)
            else:
                self._new_frog()
            return
        if outcome == "ok":
            self.frog = (r, c)
            if r < self.best:
                self.reward(self.step_reward * (self.best - r))
                self.best = r
            return
        self.lives -= 1
        self.reward(-self.params.death_penalty)
        self.say(f"The frog was {outcome}.")
        if self.lives == 0:
            self.frog = (r, c)
            self.finish(won=False)
        else:
            self.frog = (self.height - 1, self.params.width // 2)   # same trip: progress is kept

    def _grid(self) -> list[str]:
        p, t = self.params, self.tick
        rows = [self.home_row]
        rows += [self.lanes[r].row(t) if r in self.lanes else FLOOR * p.width for r in range(1, self.height)]
        if self.frog is not None:
            overlay(rows, *self.frog, PLAYER)
        still = MOVES_NEXT[0]
        return [row + (MOVES_NEXT[self.lanes[r].moves_at(t + 1)] if r in self.lanes else still)
                for r, row in enumerate(rows)]

    def _hud(self) -> str:
        return f"Homes {len(self.filled)}/{self.params.homes} | Lives {self.lives}"


register_variants(Frogger, "Classics", {
    "glyphbench/classics-frogger-v0": dict(max_turns=200),
})
