"""Bowling, a solo lane seen from above: ten pins in a triangle at the far end, you at the
near end. Move along your row to aim, THROW, then hook the ball as it rolls a row a turn toward
the pins: once (the curve ball of Atari's game 1: from there it drifts a column a row that way),
or, with ``curve`` off, a column left or right every turn. The ball knocks down every pin it
meets; a falling pin knocks each pin diagonally behind it with a probability. A frame ends when
all pins are down or its rolls are used; the pins are then set again. Pattern A: a unit per pin,
won at ``goal`` pins; the episode ends lost when the frames run out first.
Balance: one curve a roll over a longer run-up (a per-row steer let random jiggling stay on pins)."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param, require
from .duel import clamp
from .engine import EMPTY, ArcadeParams, ArcadeTask, register_arcade

PIN, BALL, YOU = "i", "o", "@"
ACTIONS = ActionSet([("NOOP", "wait (the ball keeps its course)"), ("LEFT", "step left, or hook the rolling ball left"),
                     ("RIGHT", "step right, or hook the rolling ball right"), ("THROW", "roll the ball")],
                    noop="NOOP")
SHIFT = (0, -1, 1, 0)
THROW = 3


@dataclass(frozen=True)
class BowlingParams(ArcadeParams):
    width: int = param(12, 9, 60)
    height: int = param(11, 7, 40)
    goal: int = param(20, 1, 1000)
    unit: float = param(0.05, 0, 10)
    death: float = param(0.0, 0, 0)
    frames: int = param(2, 1, 20)
    rolls: int = param(4, 1, 9)           # rolls a frame at most
    curve: bool = param(True)             # one hook a roll, then the ball drifts that way (else a hook a row)
    scatter: float = param(0.5, 0, 1)     # a falling pin knocks each pin diagonally behind it this often

    def check(self) -> None:
        require(self.goal <= 10 * self.frames, "goal", "be at most the pins in all frames", self.goal)


def rack(width: int) -> list[tuple[int, int]]:
    """The ten pins: back row of four on row 1, the head pin on row 4, centred."""
    mid = width // 2
    return [(1 + k, mid - (3 - k) + 2 * j) for k in range(4) for j in range(4 - k)]


HUD_TEXT: dict[tuple, str] = {}   # the HUD note by its values


class Bowling(ArcadeTask):
    title = "Bowling"
    rules = ("A {width}x{height} lane seen from above; ten pins (i) stand in a triangle at the top, "
             "you (@) walk the bottom row. THROW rolls the ball (o) up one row a turn from your "
             "column; {hook_text} It knocks down every "
             "pin it meets, and a falling pin knocks each pin diagonally behind it with chance "
             "{scatter}. A frame ends when all pins are down or after {rolls} rolls; then the pins "
             "are set again. You bowl {frames} frame(s).")
    rewards = "+{unit} for each pin knocked down."
    ends = "when you have knocked down {goal} pins or the frames are over"
    ACTIONS = ACTIONS
    Params = BowlingParams
    pattern = "A"
    glyphs = {EMPTY: "lane", PIN: "pin", BALL: "ball", YOU: "you"}

    def prompt_fields(self) -> dict:
        hook = ("while it rolls straight, LEFT or RIGHT hooks it once: from then on it also moves "
                "one column that way every row." if self.params.curve else
                "while it rolls, LEFT or RIGHT hook it one column that way.")
        return {**super().prompt_fields(), "hook_text": hook}

    def _setup(self, rng) -> None:
        self.start(rng)
        self.col, self.ball, self.drift = self.params.width // 2, None, 0
        self.frame_no, self.roll = 1, 0
        self._set_pins()

    def _set_pins(self) -> None:
        self.pins = set(rack(self.params.width))
        self.still = self._still()
        for r, c in self.pins:
            self.set_still(r, c, PIN)

    def _play(self, action: int) -> None:
        p = self.params
        if self.ball is None:
            if action == THROW:
                self.ball, self.drift = [p.height - 2, self.col], 0
                self.roll += 1
                self._knock(*self.ball)
            else:
                self.col = clamp(self.col + SHIFT[action], 0, p.width - 1)
            return
        b = self.ball
        shift = SHIFT[action]
        if p.curve:                       # the first hook sets the drift for the rest of the roll
            if not self.drift:
                self.drift = shift
            shift = self.drift
        b[0] -= 1
        b[1] = clamp(b[1] + shift, 0, p.width - 1)
        self._knock(b[0], b[1])
        if b[0] <= 0 and not self.done:
            self.ball = None
            self._end_roll()

    def _knock(self, r: int, c: int) -> None:
        todo = [(r, c)]
        while todo:
            pin = todo.pop()
            if pin not in self.pins:
                continue
            self.pins.discard(pin)
            self.set_still(pin[0], pin[1], EMPTY)
            self.score.gain(1)
            for dc in (-1, 1):
                if (pin[0] - 1, pin[1] + dc) in self.pins and self.draws.random() < self.params.scatter:
                    todo.append((pin[0] - 1, pin[1] + dc))

    def _end_roll(self) -> None:
        p = self.params
        if self.pins and self.roll < p.rolls:
            return
        self.say("Strike!" if self.roll == 1 and not self.pins else f"Frame {self.frame_no} over.")
        if self.frame_no >= p.frames:
            self.finish(won=False)
            return
        self.frame_no, self.roll = self.frame_no + 1, 0
        self._set_pins()

    def _sprites(self):
        out = [(self.params.height - 1, self.col, YOU)]
        if self.ball:
            out.append((self.ball[0], self.ball[1], BALL))
        return out

    def _extra_hud(self) -> str:
        curve = (self.drift < 0) - (self.drift > 0) if self.ball and self.drift else 0
        key = (self.frame_no, self.params.frames, self.roll, self.params.rolls, curve)
        hud = HUD_TEXT.get(key)
        if hud is None:   # (made once per value)
            if len(HUD_TEXT) >= 4096:
                HUD_TEXT.clear()
            hud = f"Frame {self.frame_no}/{self.params.frames} Roll {self.roll}/{self.params.rolls}"
            if curve:
                hud += f" | Ball curving {'left' if curve > 0 else 'right'}"
            HUD_TEXT[key] = hud
        return hud


register_arcade(Bowling, "bowling",
                mini=dict(max_turns=200),
                atari=dict(width=20, height=12, goal=100, unit=1.0, frames=10, rolls=2, max_turns=10000))
