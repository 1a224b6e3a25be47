"""Breakout: a paddle on the bottom row, a ball and a wall of bricks near the top. The ball
bounces off the field's top and sides; a brick it meets breaks and sends it back; off the
paddle it leaves left, straight up or right by the third of the paddle it struck. A ball below
the paddle is lost. Pattern A: each brick broken is a unit, the goal-th wins. Atari preset: FIRE
serves, several rows of bricks, lives, and a cleared wall is built again."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param, require
from .duel import Ball, clamp, deflect, serve, velocity_text
from .engine import EMPTY, ArcadeParams, ArcadeTask, register_arcade

BRICK, BALL, PADDLE = "#", "o", "T"
ACTIONS = ActionSet([("NOOP", "keep the paddle still"), ("FIRE", "serve the ball when it rests on the paddle"),
                     ("LEFT", "move the paddle one column left"), ("RIGHT", "move the paddle one column right")],
                    noop="NOOP")
MOVES = (0, 0, -1, 1)


@dataclass(frozen=True)
class BreakoutParams(ArcadeParams):
    width: int = param(14, 6, 60)
    height: int = param(9, 7, 40)
    goal: int = param(11, 1, 1000)
    unit: float = param(1 / 11, 0, 10)
    death: float = param(0.0, 0, 0)
    paddle: int = param(3, 1, 9)
    rows: int = param(1, 1, 8)            # rows of bricks
    gap: int = param(1, 0, 10)            # empty rows above the bricks
    autoserve: int = param(1, 0, 20)      # the ball serves itself after this many turns (0: FIRE only)

    def check(self) -> None:
        require(self.gap + self.rows + 4 <= self.height, "rows", "leave room above the paddle", self.rows)
        require(self.paddle <= self.width, "paddle", "fit the field", self.paddle)


class Breakout(ArcadeTask):
    title = "Breakout"
    rules = ("A {width}x{height} field whose top and sides reflect the ball (o). {rows} row(s) of "
             "bricks (#) hang near the top; a brick the ball meets breaks and sends it back. You move "
             "the paddle (T, {paddle} wide) along the bottom row; off it the ball leaves left, straight "
             "up or right by the third it struck. A ball that reaches the bottom row beside the paddle "
             "is lost ({lives_text}). {serving}{rebuild}")
    rewards = "+{unit} for each brick broken."
    ends = "when you have broken {goal} bricks or lost the last ball"
    ACTIONS = ACTIONS
    Params = BreakoutParams
    pattern = "A"
    glyphs = {EMPTY: "empty", BRICK: "brick", BALL: "ball", PADDLE: "your paddle"}

    def prompt_fields(self) -> dict:
        p = self.params
        serving = ("The ball rests on the paddle until you FIRE"
                   + (f" or {p.autoserve} turn(s) pass." if p.autoserve else "."))
        return {**super().prompt_fields(), "serving": serving,
                "rebuild": " A cleared wall is built again." if self.tier != "standard" else ""}

    def _still(self) -> list[str]:
        p = self.params
        empty = EMPTY * p.width
        return [empty] * p.gap + [BRICK * p.width] * p.rows + [empty] * (p.height - p.gap - p.rows)

    def _setup(self, rng) -> None:
        self.start(rng)
        p = self.params
        self.pad = (p.width - p.paddle) // 2      # the paddle's left column
        self.prow = p.height - 1
        self._setup_bricks()
        self.ball = Ball(0, 0)
        self._respawn()

    def _respawn(self) -> None:
        self.held, self.waited = True, 0
        self._rest()

    def _rest(self) -> None:
        b = self.ball
        b.r, b.c, b.dr, b.dc = self.prow - 1, self.pad + self.params.paddle // 2, 0, 0

    def _play(self, action: int) -> None:
        p, b = self.params, self.ball
        if MOVES[action]:
            self.pad = clamp(self.pad + MOVES[action], 0, p.width - p.paddle)
        if self.held:
            self.waited += 1
            self._rest()
            if action == 1 or (p.autoserve and self.waited >= p.autoserve):
                self.held = False
                serve(b, b.r, b.c, -1, self.draws, rows=True)
            return
        r0, c0 = b.r, b.c
        b.advance(0, p.height - 1, 0, p.width - 1)
        if (b.r, b.c) in self.bricks:
            self._break(b.r, b.c)
            b.r, b.c, b.dr = r0, c0, -b.dr
        elif b.r == self.prow and 0 <= b.c - self.pad < p.paddle:
            b.r, b.dr, b.dc = r0, -1, deflect(b.c - self.pad, p.paddle)
        elif b.r == self.prow:
            self.lose_life("The ball is lost.")

    def _break(self, r: int, c: int) -> None:
        self.bricks.discard((r, c))
        self.set_still(r, c, EMPTY)
        self.score.gain(1)
        if not self.bricks and not self.done:
            self.say("The wall is built again.")
            self.still = self._still()
            self.still_version += 1
            self._setup_bricks()

    def _setup_bricks(self) -> None:
        p = self.params
        self.bricks = {(r, c) for r in range(p.gap, p.gap + p.rows) for c in range(p.width)}

    def _rows(self) -> list[str]:
        return self.cached_rows(self.pad, self._paddle_rows)

    def _paddle_rows(self) -> list[str]:
        p, rows = self.params, self.still[:]
        row = rows[self.prow]
        rows[self.prow] = row[:self.pad] + PADDLE * p.paddle + row[self.pad + p.paddle:]
        return rows

    def _sprites(self):
        return ((self.ball.r, self.ball.c, BALL),)

    def _extra_hud(self) -> str:
        return "Ball held" if self.held else velocity_text(self.ball)


register_arcade(Breakout, "breakout",
                mini=dict(max_turns=200),
                atari=dict(width=18, height=19, goal=60, unit=1.0, lives=5, rows=4, gap=3,
                           autoserve=0, max_turns=10000))
