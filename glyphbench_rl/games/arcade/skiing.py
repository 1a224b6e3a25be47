"""Skiing: a slalom. The skier stays on one row while the slope scrolls up past them; steer
through each gate (between its flags [ and ]) as it arrives. A missed gate is only lost (and on
the Atari preset costs time: the skier stands still); trees knock the skier over for a while.
The course ends after its last gate (pattern A: credit per gate, no penalty)."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param, require
from .engine import EMPTY, ArcadeParams, ArcadeTask, register_arcade
from .scroller import Pacer, Strip, put_one

SKIER, LEFT_FLAG, RIGHT_FLAG, TREE = "Y", "[", "]", "T"
ACTIONS = ActionSet([("NOOP", "ski straight down"), ("LEFT", "carve one cell left"),
                     ("RIGHT", "carve one cell right")], noop="NOOP")
MOVES = (0, -1, 1)


@dataclass(frozen=True)
class SkiingParams(ArcadeParams):
    width: int = param(12, 8, 60)
    height: int = param(10, 6, 40)
    goal: int = param(10, 1, 100)         # gates on the course
    unit: float = param(0.1, 0, 100)
    death: float = param(0.0, 0, 0)
    gap: int = param(4, 1, 20)            # open cells between a gate's flags
    spacing: int = param(5, 2, 20)        # rows from one gate to the next
    row: int = param(2, 0, 20)            # the skier's row
    trees: float = param(0.0, 0, 0.5)     # chance of a tree on a row between gates
    fall: int = param(3, 0, 20)           # turns a tree keeps you down
    penalty: int = param(0, 0, 20)        # turns a missed gate costs

    def check(self) -> None:
        require(self.gap + 2 < self.width, "gap", "fit the field with its flags", self.gap)
        require(self.row < self.height - 1, "row", "lie inside the field", self.row)


class Skiing(ArcadeTask):
    title = "Skiing"
    rules = ("You are the skier (Y) on row {row} of a {width}x{height} view of the slope, which "
             "scrolls up one row a turn while you move. {goal} gates come {spacing} rows apart, "
             "each {gap} cells open between its flags [ and ]: pass through the opening as the "
             "gate reaches your row.{tree_text}{penalty_text}")
    rewards = "+{unit} for each gate passed through."
    ends = "after the last gate (won if you passed them all)"
    ACTIONS = ACTIONS
    Params = SkiingParams
    pattern = "A"
    glyphs = {EMPTY: "snow", LEFT_FLAG: "gate's left flag", RIGHT_FLAG: "gate's right flag",
              TREE: "tree", SKIER: "you (the skier)"}

    def prompt_fields(self) -> dict:
        p = self.params
        trees = (f" Skiing into a tree (T) knocks you down for {p.fall} turns." if p.trees else "")
        pen = (f" A missed gate (or a flag hit) costs {p.penalty} turns standing still."
               if p.penalty else " A missed gate (or a flag hit) earns nothing.")
        return {**super().prompt_fields(), "tree_text": trees, "penalty_text": pen}

    def _setup(self, rng) -> None:
        self.start(rng)
        p = self.params
        self.strip = Strip([EMPTY * p.width] * p.height, "up")
        self.col, self.made, self.judged, self.since = p.width // 2, 0, 0, p.spacing - 2
        self.left = (p.width - p.gap - 2) // 2
        self.pacer, self.down_until = Pacer(1), 0
        self.blank, self.note = EMPTY * p.width, f"Gates left {p.goal}"
        self.strip.preroll(p.height - p.row - 1, self._line)

    def _line(self) -> str:
        p = self.params
        self.since += 1
        line = self.blank
        if self.made < p.goal and self.since >= p.spacing:
            self.since = 0
            self.made += 1
            reach = p.spacing - 1
            lo, hi = max(0, self.left - reach), min(p.width - p.gap - 2, self.left + reach)
            self.left = lo + self.draws.below(hi - lo + 1)
            return put_one(put_one(line, self.left, LEFT_FLAG), self.left + p.gap + 1, RIGHT_FLAG)
        if p.trees and self.since not in (1, p.spacing - 1) and self.draws.random() < p.trees:
            return put_one(line, self.draws.below(p.width), TREE)
        return line

    def _play(self, action: int) -> None:
        p = self.params
        if self.tick < self.down_until:
            return
        c = self.col + MOVES[action]
        self.col = 0 if c < 0 else min(c, p.width - 1)
        self.strip.scroll(self._line())
        row = self.strip.rows[p.row]
        here = row[self.col]
        if here == TREE:
            self.down_until = self.tick + 1 + p.fall
            self.say("You hit a tree!")
        left = row.find(LEFT_FLAG)
        if left < 0:
            return
        self.judged += 1
        self.note = f"Gates left {p.goal - self.judged}"
        if left < self.col <= left + p.gap:
            self.score.gain()
            self.say("Through the gate!")
        else:
            self.down_until = self.tick + 1 + p.penalty
            self.say("Missed the gate.")
        if self.judged >= p.goal and not self.done:
            self.finish(won=False)

    def _grid(self) -> list[str]:
        rows, r, c = self.strip.rows[:], self.params.row, self.col
        rows[r] = rows[r][:c] + SKIER + rows[r][c + 1:]
        return rows

    def _extra_hud(self) -> str:
        return self.note


register_arcade(Skiing, "skiing",
                mini=dict(max_turns=200),
                atari=dict(width=20, height=24, row=3, unit=1.0, gap=4, spacing=8, trees=0.25,
                           fall=3, penalty=5, max_turns=10000))
