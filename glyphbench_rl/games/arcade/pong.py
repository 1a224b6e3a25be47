"""Pong: your paddle on the right against a scripted paddle on the left that follows the ball
with a probability each turn. The ball bounces off the top and bottom walls; off a paddle it
leaves up, straight or down by where it struck (top, middle or bottom third). A ball past a
paddle scores for the other side and the next serve leaves the centre toward the scorer's
opponent. Atari preset: a wider court, play to 21, the ball speeds up every few returns."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param
from .bodies import Body, track
from .duel import velocity_text
from .engine import EMPTY, ArcadeParams, ArcadeTask, register_arcade

WALL, BALL, YOU, CPU = "=", "o", "]", "["
ACTIONS = ActionSet([("NOOP", "keep your paddle still"), ("UP", "move your paddle one row up"),
                     ("DOWN", "move your paddle one row down")], noop="NOOP")
MOVES = (0, -1, 1)


@dataclass(frozen=True)
class PongParams(ArcadeParams):
    width: int = param(16, 8, 60)
    height: int = param(10, 6, 30)
    goal: int = param(3, 1, 50)
    unit: float = param(1 / 3, 0, 10)
    paddle: int = param(3, 1, 8)
    chance: float = param(0.75, 0, 1)        # the opponent steps toward the ball this often
    speedup: int = param(0, 0, 50)           # every this many returns the ball gains a cell a turn (0: never)
    top_speed: int = param(1, 1, 4)


class Pong(ArcadeTask):
    title = "Pong"
    rules = ("A {width}x{height} court walled (=) above and below. You move the right paddle "
             "(]), {paddle} rows tall; the left paddle ([) follows the ball with chance {chance} a "
             "turn. The ball (o) moves one column a turn and bounces off the walls; off a paddle it "
             "leaves up, straight or down by where it hit (top, middle or bottom of the paddle).{fast} "
             "A ball past a paddle is a point for the other side; then it is served again from the centre.")
    rewards = "+{unit} for each point you win, -{unit} for each point the opponent wins."
    ends = "when either side reaches {goal} points"
    ACTIONS = ACTIONS
    Params = PongParams
    pattern = "C"
    inside = True    # (the ball stays in the court)
    glyphs = {EMPTY: "court", WALL: "wall", BALL: "ball", YOU: "your paddle", CPU: "opponent paddle"}

    def prompt_fields(self) -> dict:
        p = self.params
        fast = (f" Every {p.speedup} returns the ball moves one more column a turn, up to {p.top_speed}."
                if p.speedup else "")
        return {**super().prompt_fields(), "fast": fast}

    def _still(self) -> list[str]:
        w, h = self.params.width, self.params.height
        return [WALL * w] + [EMPTY * w] * (h - 2) + [WALL * w]

    def _setup(self, rng) -> None:
        self.start(rng)
        p = self.params
        top = (p.height - p.paddle) // 2
        self.me, self.cpu = top, top           # each paddle's top row
        self.hits = 0
        self.ball = Body(0, 0)
        self._serve(toward=1 if rng.random() < 0.5 else -1)

    def _serve(self, toward: int) -> None:
        p = self.params
        b = self.ball
        b.r, b.c = p.height // 2, p.width // 2
        b.dr, b.dc = self.draws.below(3) - 1, toward
        self.hits = 0

    def _paddle_hit(self, top: int, r: int) -> int | None:
        """The ball's new row velocity off a paddle whose top is ``top``, or None on a miss."""
        off = r - top
        if not 0 <= off < self.params.paddle:
            return None
        third = off * 3 // self.params.paddle
        return third - 1

    def _play(self, action: int) -> None:
        p, b = self.params, self.ball
        low = p.height - 1 - p.paddle
        me = self.me + MOVES[action]                # (min(max(1, .), low) written out)
        me = me if me > 1 else 1
        self.me = me if me < low else low
        cpu = self.cpu + track(self.cpu + p.paddle // 2, b.r, p.chance, self.draws)
        cpu = cpu if cpu > 1 else 1
        self.cpu = cpu if cpu < low else low
        speed = 1 + (self.hits // p.speedup if p.speedup else 0)
        speed = speed if speed < p.top_speed else p.top_speed
        bottom, right = p.height - 1, p.width - 2
        for _ in range(speed):
            if b.r + b.dr == 0 or b.r + b.dr == bottom:
                b.dr = -b.dr
            col = b.c + b.dc
            if col == right or col == 1:
                top = self.me if col == right else self.cpu
                bounce = self._paddle_hit(top, b.r + b.dr)
                if bounce is not None:
                    b.dc, b.dr = -b.dc, bounce
                    self.hits += 1
                    if b.r + b.dr in (0, p.height - 1):
                        b.dr = -b.dr
                    continue
            b.r += b.dr
            b.c += b.dc
            if b.c in (0, p.width - 1):
                mine = b.c == 0
                self.score.point(mine)
                self.say("You score." if mine else "The opponent scores.")
                self._serve(toward=-1 if mine else 1)
                return

    def _rows(self) -> list[str]:
        return self.cached_rows((self.me, self.cpu), self._paddles)

    def _paddles(self) -> list[str]:
        p, rows = self.params, self.still[:]
        inner = EMPTY * (p.width - 4)
        for r in range(1, p.height - 1):
            rows[r] = (EMPTY + (CPU if 0 <= r - self.cpu < p.paddle else EMPTY) + inner
                       + (YOU if 0 <= r - self.me < p.paddle else EMPTY) + EMPTY)
        return rows

    def _sprites(self):
        return ((self.ball.r, self.ball.c, BALL),)

    def _extra_hud(self) -> str:
        return velocity_text(self.ball)


register_arcade(Pong, "pong",
                mini=dict(chance=0.7, max_turns=200),
                atari=dict(width=34, height=18, goal=21, unit=1.0, paddle=4, speedup=6,
                           top_speed=2, max_turns=5000))
