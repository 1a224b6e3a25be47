"""Nonogram: fill the cells of a grid so each row and column shows its clue's runs.

Boards are random pictures kept only when a line solver (repeatedly fixing the cells every
arrangement of a line's runs agrees on) determines every cell: such a puzzle has exactly one
solution and can be solved one line at a time, without guessing.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from ...core import Frame, GlyphTask, register_variants
from ...core.params import param
from ..common.boards import Bits, cell_actions, cell_of, clue_char, clue_margins, runs
from ..common.palette import FLOOR

FILLED, MARK = "■", "x"
MAX_SIZE = 12
_TRIES = 2000


@dataclass(frozen=True)
class NonogramParams:
    size: int = param(5, 2, MAX_SIZE)
    density: float = param(0.6, 0.2, 0.9)    # chance that a cell of the hidden picture is filled
    time_weight: float = param(0.5, 0, 1, open_hi=True)   # share of the win reward lost by using every turn


@lru_cache(maxsize=None)
def arrangements(length: int) -> dict[tuple[int, ...], tuple[int, ...]]:
    """Clue -> every line (bitmask, bit i = cell i) of ``length`` cells that has that clue."""
    out: dict[tuple[int, ...], list[int]] = {}
    for line in range(1 << length):
        out.setdefault(runs(line, length), []).append(line)
    return {clue: tuple(lines) for clue, lines in out.items()}


def line_solve(row_clues: list[tuple[int, ...]], col_clues: list[tuple[int, ...]]) -> list[int] | None:
    """Rows (bitmasks) of the picture when line solving fixes every cell, else None (the clues
    contradict each other or leave a cell open to line logic)."""
    h, w = len(row_clues), len(col_clues)
    lines = [(arrangements(w)[c], w) for c in row_clues] + [(arrangements(h)[c], h) for c in col_clues]
    filled = [0] * (h + w)   # lines 0..h-1 are rows (bit c = column c), h.. are columns (bit r = row r)
    empty = [0] * (h + w)
    todo = set(range(h + w))
    while todo:
        i = todo.pop()
        options, n = lines[i]
        f, e = filled[i], empty[i]
        options = [m for m in options if not m & e and m & f == f]
        if not options:
            return None
        lines[i] = (options, n)
        must_fill, may_fill = (1 << n) - 1, 0
        for m in options:
            must_fill &= m
            may_fill |= m
        new_f, new_e = must_fill & ~f, ((1 << n) - 1) & ~may_fill & ~e
        if not new_f | new_e:
            continue
        filled[i] |= new_f
        empty[i] |= new_e
        base, cross = (h, i) if i < h else (0, i - h)   # the crossing lines and this line's bit in them
        for j in range(n):
            bit = 1 << j
            if (new_f | new_e) & bit:
                other = base + j
                if new_f & bit:
                    filled[other] |= 1 << cross
                else:
                    empty[other] |= 1 << cross
                todo.add(other)
    if any(filled[r] | empty[r] != (1 << w) - 1 for r in range(h)):
        return None
    return filled[:h]


class Nonogram(GlyphTask):
    title = "Nonogram"
    rules = ("Fill cells of the {size}x{size} grid to reveal a hidden picture. Each row's clue "
             "stands right of the row; each column's clue stands above its letter, one number per "
             "line, read top to bottom.{big} A clue lists the lengths of the runs of filled cells "
             "in that line, in order, with at least one blank cell between runs; 0 means no "
             "filled cell. The clues have exactly one solution. Marks ({mark}) are notes for "
             "cells you know are blank.")
    rewards = ("solving gives 1 minus {time_weight:g} x (turns used / {max_turns}); running out of "
               "turns gives nothing.")
    ends = "when the filled cells match the solution"
    Params = NonogramParams
    glyphs = {FLOOR: "blank", FILLED: "filled", MARK: "marked blank"}
    axes = True
    extra_chars = "".join(clue_char(n) for n in range(10, MAX_SIZE + 1))
    default_max_turns = 50

    def _init(self) -> None:
        n = self.params.size
        self.bits = Bits(n, n)

    def prompt_fields(self) -> dict:
        n = self.params.size
        big = (f" Above a column, a number of 10 or more is one character: {clue_char(10)} is 10, "
               f"{clue_char(11)} is 11 and so on." if n >= 10 else "")
        return super().prompt_fields() | {"big": big, "mark": MARK}

    def _make_actions(self):
        n = self.params.size
        return cell_actions(n, n, [("", "fill that cell, or clear it if filled"),
                                   ("X", "put an x (a note: blank) on the cell named after the X, or take it off")])

    def _setup(self, rng: np.random.Generator) -> None:
        p, bits = self.params, self.bits
        n = p.size
        for _ in range(_TRIES):
            cells = (rng.random(n * n) < p.density).tolist()
            picture = sum(1 << i for i, on in enumerate(cells) if on)
            rows = [runs(bits.row_bits(picture, r), n) for r in range(n)]
            cols = [runs(bits.col_bits(picture, c), n) for c in range(n)]
            if picture and line_solve(rows, cols) is not None:
                break
        else:
            raise RuntimeError(f"{self.task_id}: no line-solvable picture in {_TRIES} tries; change density")
        self.solution, self.row_clues, self.col_clues = picture, rows, cols
        self.filled = self.marked = 0
        self._lines = [FLOOR * n] * n
        self._above, self._beside = clue_margins(rows, cols)

    def _act(self, action: int) -> None:
        n = self.params.size
        mark, r, c = cell_of(action, n, n * n)
        bit = 1 << r * n + c
        if mark:
            self.marked ^= bit
            self.filled &= ~bit
        else:
            self.filled ^= bit
            self.marked &= ~bit
        whole = (1 << n) - 1
        self._lines[r] = _row(n, self.filled >> r * n & whole, self.marked >> r * n & whole)
        if self.filled == self.solution:
            self.reward(self.time_bonus(self.params.time_weight))
            self.say("Solved: every clue is satisfied.")
            self.finish(won=True)

    def _grid(self) -> list[str]:
        return self._lines

    def _build_frame(self) -> Frame:
        # the clues stand around the board, as printed (Frame.above / Frame.beside), not in the HUD
        f = super()._build_frame()
        return Frame(f.grid, f.legend, f.hud, f.message, f.axes, self._above, self._beside)


@lru_cache(maxsize=1 << 16)
def _row(n: int, filled: int, marked: int) -> str:
    return "".join(FILLED if filled >> c & 1 else MARK if marked >> c & 1 else FLOOR for c in range(n))


register_variants(Nonogram, "Classics", {
    "glyphbench/classics-nonogram-easy-v0": dict(size=5, density=0.6, max_turns=50),
    "glyphbench/classics-nonogram-hard-v0": dict(size=8, density=0.6, max_turns=150),
})
