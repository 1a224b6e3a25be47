"""Procgen Plunder: ships of two fleets sail across lanes of sea; your cannon at the bottom moves
left and right and fires up. Sink the enemy fleet's ships (the status line names it) and spare
the friendly fleet, before your time runs out.

As in Procgen: a timer counts down, each shot costs a little time, sinking an enemy ship wins time
back and hitting a friendly ship loses some. Differences, for a grid: lanes alternate directions
and speeds per seed, a reef row of rocks stops cannonballs over some columns, and the episode is
won once enough enemy ships are sunk."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from .engine import OPEN, PLAYER_GLYPHS
from .shooting import (FIRE, FOE, FRIEND, SHOT, Body, Gun, ShooterTask, Spawner, only, pair,
                       with_fire)

ROCK, BALL, FLEETS = "#", "o", "AB"


@dataclass(frozen=True)
class PlunderParams:
    width: int = param(20, 12, 30)
    lanes: int = param(4, 2, 5)
    rocks: int = param(3, 0, 6)
    timer: int = param(60, 20, 200)
    shot_cost: int = param(2, 0, 10)
    sink_bonus: int = param(10, 0, 50)
    goal: int = param(10, 1, 30)         # enemy ships to sink to win


class ProcgenPlunder(ShooterTask):
    title = "Procgen Plunder"
    rules = ("Ships of fleets A and B sail across {lanes} lanes of a sea {width} columns wide, "
             "entering at one edge and leaving at the other; in some lanes they move only every other "
             "turn. Your cannon sits on the "
             "bottom row and moves LEFT and RIGHT. FIRE shoots a cannonball (o) straight up, 2 rows "
             "a turn; rocks (#) stop it. Each seed names the enemy fleet in the status line "
             "(Target); the other fleet is friendly. A timer starts at {timer} and counts down a "
             "turn at a time; each shot costs {shot_cost}, sinking an enemy ship adds {sink_bonus}, "
             "hitting a friendly ship takes {sink_bonus} away.")
    rewards = "+{per:.3g} for each enemy ship sunk, -{per:.3g} for each friendly ship hit."
    ends = "when the timer runs out or you have sunk {goal} enemy ships"
    Params = PlunderParams
    solid = ROCK
    fire_dir = (-1, 0)
    ACTIONS = only(with_fire("shoot a cannonball straight up"), ("NOOP", "LEFT", "RIGHT", "FIRE"))
    action_map = (0, 1, 2, FIRE)
    glyphs = {OPEN: "sea", ROCK: "rock", "A": "ship of fleet A", "B": "ship of fleet B",
              BALL: "your cannonball", **PLAYER_GLYPHS}

    def prompt_fields(self) -> dict:
        p = self.params
        return {**super().prompt_fields(), "per": 1 / p.goal}

    def _setup(self, rng: np.random.Generator) -> None:
        p = self.params
        h, w = 2 * p.lanes + 4, p.width
        rows = [[OPEN] * w for _ in range(h)]
        for c in rng.choice(w, p.rocks, replace=False).tolist():
            rows[h - 3][c] = ROCK
        start = (h - 1, int(rng.integers(w)))
        self.start(["".join(row) for row in rows], start, Gun(BALL, 2, h, 1, hits=FOE | FRIEND))
        self.target = FLEETS[int(rng.integers(2))]
        # each lane: its row, direction and period (1: a column a turn, 2: every other turn)
        self.lane_moves = [(2 * i + 1, 1 if rng.random() < 0.5 else -1, int(rng.integers(1, 3)))
                           for i in range(p.lanes)]
        self.ships = Spawner(self.stream("ships"), int(rng.integers(3, 6)), jitter=1, first=2)
        for lane in rng.permutation(p.lanes)[: max(1, p.lanes // 2)].tolist():
            self._launch(lane, int(rng.integers(w)), FLEETS[int(rng.integers(2))])
        self.clock = p.timer
        self.sunk = self.friendly = 0

    def _launch(self, lane: int, col: int, fleet: str) -> None:
        r, d, period = self.lane_moves[lane]
        self.world.add(Body(fleet, r, col, 0, d, side=FOE if fleet == self.target else FRIEND,
                            period=period, phase=self.turn % period))

    def _think(self) -> None:
        if self.ships.due(self.turn):
            lane = self.ships.below(len(self.lane_moves))
            d = self.lane_moves[lane][1]
            fleet = self.target if self.ships.chance(0.55) else FLEETS[FLEETS.index(self.target) ^ 1]
            col = 0 if d > 0 else self.params.width - 1
            if not self.world.at(self.lane_moves[lane][0], col):
                self._launch(lane, col, fleet)

    def shoot(self):
        shot = super().shoot()
        if shot is not None:
            self.clock -= self.params.shot_cost
        return shot

    def _hit(self, a: Body, b: Body | None) -> None:
        if b is None:
            if a is not self.player:
                a.alive = False                 # a cannonball on a rock
            return
        ball, ship = pair(a, b, SHOT) or (None, None)
        if ball is None:
            return
        ball.alive = ship.alive = False
        p = self.params
        if ship.side == FOE:
            self.sunk += 1
            self.clock += p.sink_bonus
            self.reward(1 / p.goal)
            self.say("Enemy ship sunk.")
            if self.sunk >= p.goal:
                self.say("The enemy fleet is beaten.")
                self.finish(won=True)
        else:
            self.friendly += 1
            self.clock -= p.sink_bonus
            self.reward(-1 / p.goal)
            self.say("You hit a friendly ship.")

    def _after(self) -> None:
        self.clock -= 1
        if self.clock <= 0:
            self.clock = 0
            self.say("Time is up.")
            self.finish(won=None)

    def _extras(self) -> str:
        return f"Target {self.target} | Sunk {self.sunk}/{self.params.goal} | Time {self.clock}"


register_variants(ProcgenPlunder, "Procgen", {"glyphbench/procgen-plunder-v0": dict(max_turns=500)})
