"""Video Pinball (Atari 2600, 1980): a pinball table seen from above. Kept from the original:
the plunger in a shooter lane on the right, two flippers at the foot of the table with a drain
between them and an outlane beside them, three bumpers, two spinners, rollover lanes at the top
(all of them lit earn an extra ball, as the Atari logo's rollover did), a bank of drop targets
(all down pays a bonus and they stand again), the nudge (too many in a short time tilt the
table: flippers dead, nothing scores, until the ball drains), and 3 balls. Pattern A: every
scoring event is a unit toward ``goal``, paid in native points (``unit`` a bumper's worth).
The pinball machinery is ``pinball``'s."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param, require
from .engine import EMPTY, ArcadeParams, register_atari
from .pinball import (BUMPER, DRAIN, FLIP_L, FLIP_R, FLIP_UP, LIT, POST, RAIL_L, RAIL_R, ROLL, SPINNER,
                      TARGET, TOP, WALL, Flipper, PinballTask)

BALL = "o"
ACTIONS = ActionSet([("NOOP", "leave the flippers down"),
                     ("LEFT_FLIPPER", "swing the left flipper up (on the plunger: launch the ball)"),
                     ("RIGHT_FLIPPER", "swing the right flipper up (on the plunger: launch the ball)"),
                     ("NUDGE", "shake the table (on the plunger: launch the ball)")], noop="NOOP")
VALUES = {BUMPER: 1, TARGET: 1, SPINNER: 1, ROLL: 1, "bank": 10}   # in units (a bumper's points)


@dataclass(frozen=True)
class PinballParams(ArcadeParams):
    width: int = param(12, 10, 24)
    height: int = param(24, 16, 40)
    lives: int = param(3, 1, 9)
    goal: int = param(100, 1, 1000)
    unit: float = param(100.0, 0, 1000)
    death: float = param(0.0, 0, 0)
    balls: int = param(5, 1, 9)           # the most balls you can hold (extra balls stop there)
    gap: int = param(1, 1, 4)             # drain columns between the flippers
    targets: int = param(3, 1, 6)         # drop targets in the bank
    kick: int = param(20, 4, 40)          # rows a flipper sends the ball up
    bump: int = param(4, 1, 20)           # rows a bumper kicks it up
    autolaunch: int = param(5, 1, 50)     # turns a ball waits on the plunger
    nudges: int = param(3, 1, 10)         # nudges allowed within the window; one more tilts
    window: int = param(20, 2, 200)

    def check(self) -> None:
        require(self.gap + 6 <= self.width - 4, "gap", "leave flippers of 3 cells", self.gap)
        require(self.targets <= self.width - 6, "targets", "fit the table", self.targets)
        require(self.balls >= self.lives, "balls", "be at least lives", self.balls)


class VideoPinball(PinballTask):
    title = "Video Pinball"
    rules = ("A pinball table {width} wide and {height} tall, seen from above; walls (| and -) "
             "and posts (#) reflect the ball (o), and the rails ( and ) in the top corners turn it "
             "back down. Gravity: a rising ball slows and falls. Your flippers lie on the "
             "next-to-last row, the left (\\) and the right (/), with a drain {gap} cell(s) wide "
             "between them; a flipper you swing shows as =. A ball that reaches a flipper you "
             "swing that turn flies up {kick} rows (up to 3 fewer): toward its own side off the flipper's outer "
             "third, straight up off the middle, across the table off its tip. On an idle flipper "
             "the ball rolls a cell a turn toward the tip and falls into the drain. The left "
             "outlane (outside the post) and the shooter lane on the right drain too (v marks the "
             "drains). A drained ball is lost (you have {lives_text}). A new ball waits on the plunger "
             "at the foot of the shooter lane until you act or {autolaunch} turns pass. Bumpers "
             "(O) kick the ball away; drop targets (T, a bank of {targets}) fall when struck and "
             "stand again once all are down; spinners (S) and rollovers (R, lit r) score as the "
             "ball passes. Lighting every rollover earns an extra ball (at most {balls} held). "
             "NUDGE reverses a flying ball's sideways motion (a ball falling straight is shoved "
             "toward its side); more than {nudges} nudges within {window} turns TILT the table: "
             "the flippers go dead and nothing scores until the ball drains. The HUD's Ball v gives the "
             "ball's velocity (rows, columns a turn; down and right are +).")
    rewards = ("+{bumper} for a bumper, a drop target, a spinner or a rollover; +{bank} for a whole "
               "bank of drop targets down (each of these is a scoring event).")
    ends = "after {goal} scoring events or when the last ball drains"
    ACTIONS = ACTIONS
    Params = PinballParams
    pattern = "A"
    values = VALUES
    glyphs = {EMPTY: "empty", WALL: "wall", TOP: "wall", POST: "post", RAIL_L: "rail",
              RAIL_R: "rail", BALL: "ball", FLIP_L: "left flipper", FLIP_R: "right flipper",
              FLIP_UP: "flipper swung up", BUMPER: "bumper", TARGET: "drop target", SPINNER: "spinner",
              ROLL: "rollover", LIT: "lit rollover", DRAIN: "drain"}

    def prompt_fields(self) -> dict:
        u = self.params.unit
        n = self.params.lives
        return {**super().prompt_fields(), "lives_text": "one ball" if n == 1 else f"{n} balls",
                "bumper": f"{VALUES[BUMPER] * u:g}",
                "bank": f"{VALUES['bank'] * u:g}"}

    def _still(self) -> list[str]:
        p = self.params
        w, h, lane, right = p.width, p.height, p.width - 2, p.width - 4   # right: the field's last column
        rows = [[EMPTY] * w for _ in range(h)]
        rows[0] = [TOP] * w
        rows[h - 1] = [TOP] * w
        for r in range(1, h - 1):
            rows[r][0] = rows[r][w - 1] = WALL
            if r >= 4:
                rows[r][lane - 1] = WALL
        rows[1][1], rows[1][lane] = RAIL_L, RAIL_R
        for f in self._flippers():
            for c in range(f.lo, f.hi + 1):
                rows[f.row][c] = FLIP_L if f.side < 0 else FLIP_R
        left, gap_at = self._flippers()[0], self._flippers()[0].hi + 1
        for r in (h - 5, h - 4):
            rows[r][left.lo] = POST
        for c in (1, lane, *range(gap_at, gap_at + p.gap)):
            rows[h - 1][c] = DRAIN
        for c in range(2, right, 2):
            rows[3][c] = ROLL
        rows[h // 4 + 1][1] = rows[h // 4 + 1][right] = SPINNER
        (a, b), top = [(f.lo + f.hi) // 2 for f in self._flippers()], h // 3   # over the flippers' middles
        for r, c in ((top, a), (top, b), (top + 2, (a + b + 1) // 2)):
            rows[r][c] = BUMPER
        for r, c in self._banks()[0]:
            rows[r][c] = TARGET
        return ["".join(row) for row in rows]

    def _flippers(self) -> list[Flipper]:
        p = self.params
        size = (p.width - 5 - p.gap) // 2
        lo = 2 + size + p.gap
        return [Flipper(p.height - 2, 2, 1 + size, -1), Flipper(p.height - 2, lo, p.width - 4, 1)]

    def _banks(self) -> list[list[tuple[int, int]]]:
        p = self.params
        c0 = 1 + (p.width - 4 - p.targets) // 2
        return [[(p.height // 2 + 1, c) for c in range(c0, c0 + p.targets)]]

    def _setup(self, rng) -> None:
        self.open_table(rng)

    def _play(self, action: int) -> None:
        self.flip(left=action == 1, right=action == 2)
        if action == 3 and not self.held:
            self.nudge()
        self.roll(action != 0)

    def _sprites(self):
        return ((self.ball.r, self.ball.c, BALL),)


register_atari(VideoPinball, "videopinball", max_turns=10000)
