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
TURNS = HEADINGS[1:]                       # up, right, left, down: 3 - k reverses k
TURN_INDEX = {h: k for k, h in enumerate(TURNS)}


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

    def _steer(self) -> None:
        cpu = self.cpu
        if self.draws.random() >= self.params.chance:
            return
        r, c, hr, hc = cpu
        occ, span = self.occ, self.span
        at = (r + 1) * span + c + 1
        # the open cells straight ahead each way, in TURNS order: a C search for the first
        # occupied cell (a 1; the border ends every run)
        runs = (occ[at - span::-span].find(1), occ.find(1, at + 1) - at - 1,
                at - 1 - occ.rfind(1, 0, at), occ[at + span::span].find(1))
        k = TURN_INDEX[hr, hc]
        best, most, back = k, runs[k], 3 - k
        for j in range(4):
            if j != back and runs[j] > most:
                best, most = j, runs[j]
        cpu[2], cpu[3] = TURNS[best]

    def _play(self, action: int) -> None:
        me, cpu = self.me, self.cpu
        head = HEADINGS[action]
        if head and (head[0] != -me[2] or head[1] != -me[3]):
            me[2], me[3] = head
        self._steer()
        occ, span, still = self.occ, self.span, self.still
        for who in (me, cpu):   # each head leaves a trail (set_still's work, for both at once)
            r, c = who[0], who[1]
            occ[(r + 1) * span + c + 1] = 1
            line = still[r]
            still[r] = line[:c] + TRAIL + line[c + 1:]
        self.still_version += 2
        mr, mc, cr, cc = me[0] + me[2], me[1] + me[3], cpu[0] + cpu[2], cpu[1] + cpu[3]
        me[0], me[1], cpu[0], cpu[1] = mr, mc, cr, cc
        meet = mr == cr and mc == cc
        # (``_free`` without its bounds: a head moves at most a cell past the field, onto the border)
        lost = meet or occ[(mr + 1) * span + mc + 1] != 0
        beat = meet or occ[(cr + 1) * span + cc + 1] != 0
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
