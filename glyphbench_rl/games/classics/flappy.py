"""Flappy: flap through the gaps of scrolling pipes without touching them or the ground."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import ActionSet, GlyphTask, register_variants
from ...core.params import param
from ..common.palette import FLOOR, PLAYER, WALL
from ..common.physics import fall
from ..common.view import overlay, signed, window

GROUND = "="
FLAP, GRAVITY, MAX_FALL = -2, 1, 2   # rows per turn, positive = down
PIPE_WIDTH = 2
BIRD_COL = 2                         # the bird's column on screen


@dataclass(frozen=True)
class FlappyParams:
    height: int = param(10, 7, 20)           # rows, the ground row included
    width: int = param(12, 8, 30)
    # Narrower gaps, or pipes closer together, are not always passable at these speeds
    # (checked by exhaustive search over the reachable states in the tests).
    gap: int = param(4, 4, lambda p: p.height - 3)                # open rows in each pipe
    spacing: int = param(6, PIPE_WIDTH + 3, lambda p: p.width)    # columns from one pipe to the next
    # most rows a gap moves from one pipe to the next
    max_shift: int = param(3, 0, lambda p: p.spacing - 1)
    target: int = param(10, 1, 100)          # pipes to pass
    crash_penalty: float = param(0.5, 0, 1)


class Flappy(GlyphTask):
    title = "Flappy Bird"
    rules = ("The bird stays in column {bird_col} from the left while the pipes scroll one column "
             "left per turn. Pipes are {pipe_width} columns wide with a gap of {gap} open rows; a "
             "new pipe comes every {spacing} columns. Vy in the status line is your vertical speed "
             "in rows per turn (positive = down): FLAP sets it to {flap}, WAIT lets gravity add "
             "{gravity} (to at most +{max_fall}); then the bird moves by it. Touching a pipe or the "
             "ground kills the bird; the top edge stops it.")
    rewards = "+{pipe_reward:.4g} per pipe passed; {target} pipes win; crashing costs {crash_penalty:g}."
    ends = "when you pass {target} pipes or crash"
    Params = FlappyParams
    ACTIONS = ActionSet([("FLAP", "flap: jump upward"), ("WAIT", "glide and fall")], noop="WAIT")
    glyphs = {FLOOR: "sky", WALL: "pipe", GROUND: "ground", PLAYER: "bird"}
    default_max_turns = 150

    def prompt_fields(self) -> dict:
        return super().prompt_fields() | {
            "bird_col": BIRD_COL + 1, "pipe_width": PIPE_WIDTH, "flap": signed(FLAP),
            "gravity": GRAVITY, "max_fall": MAX_FALL, "pipe_reward": 1 / self.params.target}

    def _setup(self, rng: np.random.Generator) -> None:
        p = self.params
        sky = p.height - 1
        first = p.width - PIPE_WIDTH                        # the first pipe starts on screen
        self.pipes: list[int] = []                          # left column of each pipe, in the course
        length = first + p.target * p.spacing + p.width
        columns = [FLOOR * sky] * length
        top = int(rng.integers(1, sky - p.gap))
        for i in range(p.target):
            lo, hi = max(1, top - p.max_shift), min(sky - p.gap - 1, top + p.max_shift)
            top = int(rng.integers(lo, hi + 1))
            x = first + i * p.spacing
            self.pipes.append(x)
            column = WALL * top + FLOOR * p.gap + WALL * (sky - top - p.gap)
            columns[x:x + PIPE_WIDTH] = [column] * PIPE_WIDTH
        self.course = ["".join(col[r] for col in columns) for r in range(sky)]
        self.ground = GROUND * p.width
        self.pos = 0                                        # course column at the screen's left
        self.y, self.vy = sky // 2, 0
        self.passed = 0

    def advance(self, pos: int, y: int, vy: int, flap: bool) -> tuple[int, int, bool]:
        """One tick from screen offset ``pos``: (new y, new vy, crashed). Pure, for planners."""
        vy = FLAP if flap else fall(vy, GRAVITY, MAX_FALL)
        col = pos + 1 + BIRD_COL
        new = max(0, y + vy)
        if new >= self.params.height - 1:
            return self.params.height - 1, vy, True
        step = 1 if new >= y else -1
        course = self.course
        for r in range(y, new + step, step):                # every row swept this tick
            if course[r][col] == WALL:
                return r, vy, True
        return new, (0 if y + vy < 0 else vy), False

    def _act(self, action: int) -> None:
        self.y, self.vy, crashed = self.advance(self.pos, self.y, self.vy, action == 0)
        self.pos += 1
        if crashed:
            self.reward(-self.params.crash_penalty)
            self.say("The bird crashed.")
            self.finish(won=False)
            return
        p = self.params
        if self.passed < p.target and self.pos + BIRD_COL == self.pipes[self.passed] + PIPE_WIDTH:
            self.passed += 1
            self.reward(1 / p.target)
            self.say("Passed a pipe.")
            if self.passed == p.target:
                self.finish(won=True)

    def _grid(self) -> list[str]:
        p = self.params
        rows = window(self.course, 0, self.pos, p.height - 1, p.width)
        rows.append(self.ground)
        overlay(rows, self.y, BIRD_COL, PLAYER)
        return rows

    def _hud(self) -> str:
        return f"Pipes {self.passed}/{self.params.target} | Vy {signed(self.vy)}"


register_variants(Flappy, "Classics", {
    "glyphbench/classics-flappy-v0": dict(max_turns=150),
})
