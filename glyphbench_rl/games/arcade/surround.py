"""Surround: a light-cycle duel. You and a scripted rival each move a cell every turn, leaving a
wall behind; steering changes your heading (a reversal is ignored). Whoever runs into a wall,
a trail or the field's edge crashes and loses the round; both crashing at once is a draw. The
rival keeps its heading, and with a probability turns toward the longest open run whenever
that is longer. Pattern C: first to ``goal`` rounds (the mini preset: a single round)."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param
from .engine import EMPTY, ArcadeParams, ArcadeTask, register_arcade

TRAIL, YOU, CPU = "#", "Y", "X"
ACTIONS = ActionSet([("NOOP", "keep your heading"), ("UP", "head up"), ("RIGHT", "head right"),
                     ("LEFT", "head left"), ("DOWN", "head down")], noop="NOOP")
HEADINGS = (None, (-1, 0), (0, 1), (0, -1), (1, 0))


@dataclass(frozen=True)
class SurroundParams(ArcadeParams):
    width: int = param(12, 6, 60)
    height: int = param(12, 6, 60)
    goal: int = param(1, 1, 50)
    unit: float = param(1.0, 0, 10)
    chance: float = param(0.8, 0, 1)      # the rival steers toward open space this often a turn


class Surround(ArcadeTask):
    title = "Surround"
    rules = ("A {width}x{height} field. You (Y) and the rival (X) each move one cell every turn in "
             "your heading, leaving a trail (#) behind; UP, DOWN, LEFT and RIGHT set your heading "
             "(reversing is ignored). Running into a trail, a head or the field's edge is a crash: "
             "the other side wins the round; both crashing at once is a draw. With chance {chance} a "
             "turn the rival turns toward the longest straight open run.")
    rewards = "+{unit} for each round you win, -{unit} for each round the rival wins; a draw pays nothing."
    ends = "when either side has won {goal} round(s), or on a draw"
    ACTIONS = ACTIONS
    Params = SurroundParams
    pattern = "C"
    glyphs = {EMPTY: "open", TRAIL: "trail", YOU: "you", CPU: "rival"}

    def _setup(self, rng) -> None:
        self.start(rng)
        self._round()

    def _round(self) -> None:
        p = self.params
        self.still = self._still()
        self.still_version += 1
        self.span = p.width + 2                   # the occupancy grid has a wall border
        self.occ = bytearray([1]) * self.span + (bytearray([1]) + bytearray(p.width) + bytearray([1])) * p.height \
            + bytearray([1]) * self.span
        self.me, self.cpu = [p.height - 3, 2, -1, 0], [2, p.width - 3, 1, 0]   # row, col, heading

    def _free(self, r: int, c: int) -> bool:
        return -1 <= r <= self.params.height and -1 <= c <= self.params.width and not self.occ[(r + 1) * self.span + c + 1]

    def run(self, r: int, c: int, dr: int, dc: int) -> int:
        """Open cells straight ahead of (r, c) along (dr, dc)."""
        occ, step = self.occ, dr * self.span + dc
        i = (r + 1) * self.span + c + 1 + step
        n = 0
        while not occ[i]:
            i, n = i + step, n + 1
        return n

    def _steer(self) -> None:
        cpu = self.cpu
        if self.draws.random() >= self.params.chance:
            return
        r, c, hr, hc = cpu
        best, most = (hr, hc), self.run(r, c, hr, hc)
        for h in HEADINGS[1:]:
            if h[0] != -hr or h[1] != -hc:
                n = self.run(r, c, h[0], h[1])
                if n > most:
                    best, most = h, n
        cpu[2], cpu[3] = best

    def _play(self, action: int) -> None:
        me, cpu = self.me, self.cpu
        head = HEADINGS[action]
        if head and head != (-me[2], -me[3]):
            me[2], me[3] = head
        self._steer()
        for who in (me, cpu):
            self.occ[(who[0] + 1) * self.span + who[1] + 1] = 1
            self.set_still(who[0], who[1], TRAIL)
        nm, nc = (me[0] + me[2], me[1] + me[3]), (cpu[0] + cpu[2], cpu[1] + cpu[3])
        me[0], me[1], cpu[0], cpu[1] = *nm, *nc
        lost, beat = not self._free(*nm) or nm == nc, not self._free(*nc) or nm == nc
        if lost and beat:
            self.say("Both crash: a draw.")
            self.finish(won=False)
        elif lost or beat:
            self.say("The rival crashes." if beat else "You crash.")
            self.score.point(beat)
            if not self.done:
                self._round()

    def _sprites(self):
        return ((self.cpu[0], self.cpu[1], CPU), (self.me[0], self.me[1], YOU))


register_arcade(Surround, "surround",
                mini=dict(max_turns=200),
                atari=dict(width=20, height=20, goal=10, unit=1.0, max_turns=10000))
