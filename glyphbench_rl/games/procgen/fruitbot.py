"""Procgen Fruitbot: a robot carried down a long course one row a turn; steer left and right
through the gaps in the walls, picking up fruit and dodging the junk, to the finish line.

Upstream scrolls the level past a robot that steers sideways; here the robot falls through a
still course (the same thing seen from the course) and the view keeps a few rows behind it and
the rest ahead. A wall below stops the fall (a bump, which costs a little); DOWN hurries two
rows. A level is kept only if a search over these rules finds a clean run (no bump, no junk)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.actions import ActionSet
from ...core.params import param
from ..common.palette import WALL
from .engine import PLAYER_GLYPHS
from .scrolling import OPEN, LeadView, fall_route, fall_turn

FRUIT, JUNK, FINISH = "%", "x", "="
ACTIONS = ActionSet([("NOOP", "fall one row"), ("LEFT", "step left, then fall one row"),
                     ("RIGHT", "step right, then fall one row"), ("DOWN", "fall two rows")],
                    noop="NOOP")
MOVES = ((0, 0, 1), (1, -1, 1), (2, 1, 1), (3, 0, 2))   # action, sideways step, rows fallen
ARROW = (4, 1, 2, 4)       # the arrow drawn after each action: every turn falls, so NOOP is ▼


@dataclass(frozen=True)
class FruitbotParams:
    width: int = param(14, 8, 20)
    length: int = param(40, 16, 120)      # rows, the finish line included
    spacing: tuple[int, int] = param((4, 7), 3, 12)  # rows from a wall to the next (lo, hi)
    items: float = param(0.5, 0, 1)       # chance that a row between walls holds fruit or junk
    fruit_reward: float = param(0.1, 0, 0.2)
    fruit_cap: int = param(7, 0, 10)
    junk_cost: float = param(0.1, 0, 0.2)
    junk_cap: int = param(6, 0, 10)
    bump_cost: float = param(0.05, 0, 0.1)
    bump_cap: int = param(8, 0, 10)
    finish_reward: float = param(0.3, 0, 1)


class ProcgenFruitbot(LeadView):
    title = "Procgen Fruitbot"
    rules = ("You are a robot falling down a {width}-wide course of {length} rows, one row a "
             "turn (DOWN: two rows). Each turn you may first step left or right, then you fall. "
             "Walls ({wall}) cross the course with gaps to fall through; a wall below you stops "
             "your fall (a bump), and so does one beside you stop a sideways step. Fall onto fruit "
             "(%) to collect it and avoid junk (x). The finish line (=) is the bottom row.")
    rewards = ("+{fruit_reward} for each of the first {fruit_cap} fruit, -{junk_cost} for each of "
               "the first {junk_cap} pieces of junk, -{bump_cost} for each of the first "
               "{bump_cap} bumps, +{finish_reward} for reaching the finish line.")
    ends = "when you reach the finish line"
    ACTIONS = ACTIONS
    Params = FruitbotParams
    glyphs = {OPEN: "empty", WALL: "wall", FRUIT: "fruit", JUNK: "junk", FINISH: "finish line",
              **PLAYER_GLYPHS}
    view_h, view_w, lead = 20, 14, 4
    shows_motion = True

    def prompt_fields(self) -> dict:
        return {**super().prompt_fields(), "wall": WALL}

    def _setup(self, rng: np.random.Generator) -> None:
        p = self.params
        while True:
            rows = self._course(rng)
            start = (0, int(rng.integers(p.width)))
            self.rows = rows
            if fall_route(self._wall, self._junk, p.length, p.width, start, MOVES) is not None:
                break
        self.place_player(start)
        self._lines = ["".join(row) for row in rows]
        self.fruit = self.junk = self.bumps = 0
        self.vel = (1, 0)

    def _course(self, rng: np.random.Generator) -> list[list[str]]:
        p = self.params
        rows = [[OPEN] * p.width for _ in range(p.length - 1)] + [[FINISH] * p.width]
        lo, hi = p.spacing
        r = int(rng.integers(lo, hi + 1))
        while r < p.length - 2:
            rows[r] = [WALL] * p.width
            for _ in range(int(rng.integers(1, 3))):          # one or two gaps, 2-3 wide
                size = int(rng.integers(2, 4))
                at = int(rng.integers(p.width - size + 1))
                rows[r][at:at + size] = [OPEN] * size
            r += int(rng.integers(lo, hi + 1))
        for r in range(2, p.length - 1):
            if WALL in rows[r] or rng.random() >= p.items:
                continue
            for c in rng.choice(p.width, int(rng.integers(1, 3)), replace=False).tolist():
                rows[r][c] = FRUIT if rng.random() < 0.5 else JUNK
        return rows

    def _wall(self, r: int, c: int) -> bool:
        return self.rows[r][c] == WALL

    def _junk(self, r: int, c: int) -> bool:
        return self.rows[r][c] == JUNK

    def solution(self) -> list[int] | None:
        """The shortest clean run from here (the generator's own check)."""
        p = self.params
        return fall_route(self._wall, self._junk, p.length, p.width, self.pos, MOVES)

    def _rows(self) -> list[str]:
        return self._lines

    def _velocity(self) -> tuple[int, int]:
        return self.vel

    def _extras(self) -> str:
        return f"Row {self.pos[0]}/{self.params.length - 1}"

    def _act(self, action: int) -> None:
        p = self.params
        _, dc, fall = MOVES[action]
        self.facing = ARROW[action]
        r, c, bumped, entered = fall_turn(self._wall, p.length, p.width, *self.pos, dc, fall)
        self.vel = (r - self.pos[0], c - self.pos[1])
        self.pos = (r, c)
        if bumped:
            self.bumps += 1
            self.say("You bumped into a wall.")
            if self.bumps <= p.bump_cap:
                self.reward(-p.bump_cost)
        for er, ec in entered:
            ch = self.rows[er][ec]
            if ch == FRUIT or ch == JUNK:
                self.rows[er][ec] = OPEN
                self._lines[er] = "".join(self.rows[er])
                if ch == FRUIT:
                    self.fruit += 1
                    self.say("You picked up fruit.")
                    if self.fruit <= p.fruit_cap:
                        self.reward(p.fruit_reward)
                else:
                    self.junk += 1
                    self.say("You hit junk.")
                    if self.junk <= p.junk_cap:
                        self.reward(-p.junk_cost)
        if r == p.length - 1:
            self.reward(p.finish_reward)
            self.say("You reached the finish line.")
            self.finish(won=True)


register_variants(ProcgenFruitbot, "Procgen",
                  {"glyphbench/procgen-fruitbot-v0": dict(max_turns=500)})
