"""Ski: slalom down a scrolling slope through gates, between the trees."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import ActionSet, GlyphTask, register_variants
from ...core.params import param
from ..common.palette import FLOOR, PLAYER
from ..common.view import overlay, window

TREE, FLAG, FINISH = "T", "|", "="
SKIER_ROW = 1      # the skier's row on screen; the slope scrolls up past it


@dataclass(frozen=True)
class SkiParams:
    width: int = param(13, 7, 30)
    height: int = param(9, 4, 20)            # rows in view
    gates: int = param(10, 1, 40)
    gate_gap: int = param(6, 2, 20)          # rows from one gate to the next
    gate_width: int = param(3, 1, lambda p: p.width - 4, odd=True)   # open cells between a gate's two flags
    tree_density: float = param(0.1, 0, 0.5)   # chance of a tree on each free cell off the gate rows
    crash_penalty: float = param(0.5, 0, 1)


class Ski(GlyphTask):
    title = "Ski (slalom)"
    rules = ("You ski down a slope {width} cells wide; every turn you move one row down (the view "
             "scrolls so you stay near the top) and, if you steer, one column left or right. A gate "
             "is a pair of flags on one row, {gate_width} cells apart inside; pass a gate by "
             "crossing its row between the flags. Gates come every {gate_gap} rows, {gates} in all, "
             "then the finish line. Hitting a tree is a crash; hitting a flag misses its gate.")
    rewards = "+{gate_reward:.4g} per gate passed; a crash costs {crash_penalty:g}."
    ends = "when you cross the finish line (a win if you passed every gate) or crash"
    Params = SkiParams
    ACTIONS = ActionSet([("LEFT", "steer one column left as you go down"),
                         ("STRAIGHT", "go straight down"),
                         ("RIGHT", "steer one column right as you go down")])
    glyphs = {FLOOR: "snow", TREE: "tree", FLAG: "gate flag", FINISH: "finish line", PLAYER: "skier"}
    default_max_turns = 100

    def prompt_fields(self) -> dict:
        return super().prompt_fields() | {"gate_reward": 1 / self.params.gates}

    def _setup(self, rng: np.random.Generator) -> None:
        p = self.params
        half = p.gate_width // 2
        lo, hi = half + 1, p.width - half - 2          # gate centres keep both flags on the slope
        self.finish_row = SKIER_ROW + p.gate_gap * (p.gates + 1)
        self.gate_rows = {SKIER_ROW + p.gate_gap * (i + 1): i for i in range(p.gates)}
        # A route that passes every gate, one column of steering per row at most; no tree is
        # ever put on it, so every course can be skied clean.
        col = p.width // 2
        route = [col] * (SKIER_ROW + 1)
        rows = [FLOOR * p.width] * (self.finish_row + p.height)
        for i in range(p.gates):
            reach = p.gate_gap - 1
            centre = int(rng.integers(max(lo, col - reach), min(hi, col + reach) + 1))
            for _ in range(p.gate_gap):
                col += (centre > col) - (centre < col)
                route.append(col)
            r = SKIER_ROW + p.gate_gap * (i + 1)
            rows[r] = FLOOR * (centre - half - 1) + FLAG + FLOOR * p.gate_width + FLAG + \
                FLOOR * (p.width - centre - half - 2)
        route.extend([col] * p.gate_gap)
        for r in range(SKIER_ROW + 2, self.finish_row):
            if r in self.gate_rows:
                continue
            trees = rng.random(p.width) < p.tree_density
            trees[route[r]] = False
            rows[r] = "".join(TREE if t else FLOOR for t in trees)
        rows[self.finish_row] = FINISH * p.width
        self.course = rows
        self.pos, self.col = 0, p.width // 2
        self.passed = self.missed = 0

    def _act(self, action: int) -> None:
        p = self.params
        self.pos += 1
        self.col = min(p.width - 1, max(0, self.col + action - 1))
        r = self.pos + SKIER_ROW
        cell = self.course[r][self.col]
        if cell == TREE:
            self.reward(-p.crash_penalty)
            self.say("You crashed into a tree.")
            self.finish(won=False)
            return
        if r in self.gate_rows:
            left = self.course[r].index(FLAG)
            if left < self.col <= left + p.gate_width:
                self.passed += 1
                self.reward(1 / p.gates)
                self.say("Gate passed.")
            else:
                self.missed += 1
                self.say("Missed the gate.")
        elif r == self.finish_row:
            self.say("Finish!")
            self.finish(won=self.missed == 0)

    def _grid(self) -> list[str]:
        p = self.params
        rows = window(self.course, self.pos, 0, p.height, p.width)
        overlay(rows, SKIER_ROW, self.col, PLAYER)
        return rows

    def _hud(self) -> str:
        return f"Gates {self.passed}/{self.params.gates} | Missed {self.missed}"


register_variants(Ski, "Classics", {
    "glyphbench/classics-ski-v0": dict(max_turns=100),
})
