"""Minesweeper: open every cell that holds no mine; numbers count the mines around a cell.

Mines are laid at the first reveal, away from that cell and its neighbours, so the first reveal
is always safe and opens an area.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import GlyphTask, register_variants
from ...core.params import param
from ..common.boards import Bits, cell_actions
from ..common.palette import FLOOR

HIDDEN, MINE = "■", "*"
NUMBERS = "·12345678"      # glyph of an open cell by the count of mines around it


@dataclass(frozen=True)
class MinesweeperParams:
    size: int = param(8, 4, 16)
    mines: int = param(10, 1, lambda p: p.size * p.size - 9)
    # the return opening every safe cell earns along the way
    progress_share: float = param(0.5, 0, 1, open_hi=True)
    # what opening a mine costs: a lost game never opened every safe cell, so its return is
    # progress - penalty < 0
    mine_penalty: float = param(0.5, lambda p: p.progress_share, 1)


class Minesweeper(GlyphTask):
    title = "Minesweeper"
    rules = ("{mines} mines are hidden under the cells of the {size}x{size} board. Revealing a "
             "cell opens it: a mine ends the game; otherwise it shows how many of its eight "
             "neighbours hold mines, and a cell with none opens its neighbours too. The first "
             "reveal is always safe and opens an area. Open every cell without a mine.")
    rewards = ("opening safe cells earns {progress_share:g} x (cells opened / {safe} safe cells); "
               "opening all of them adds {win_bonus:g}; revealing a mine costs {mine_penalty:g}.")
    ends = "when every safe cell is open or a mine is revealed"
    Params = MinesweeperParams
    glyphs = {HIDDEN: "hidden", FLOOR: "no mine around", **{str(k): f"{k} mine{'s' * (k > 1)} around"
                                                            for k in range(1, 9)}, MINE: "mine"}
    axes = True
    default_max_turns = 60

    def prompt_fields(self) -> dict:
        return super().prompt_fields() | {"safe": self.safe, "win_bonus": 1 - self.params.progress_share}

    def _init(self) -> None:
        n = self.params.size
        self.bits = Bits(n, n)
        self.safe = n * n - self.params.mines
        self.around = [self.bits.grow8(1 << i) & ~(1 << i) for i in range(n * n)]   # neighbour masks
        self._spots: dict[int, list[int]] = {}

    def _make_actions(self):
        n = self.params.size
        return cell_actions(n, n, [("", "reveal that cell")])

    def _setup(self, rng: np.random.Generator) -> None:
        n = self.params.size
        self.rng = rng
        self.mines = self.revealed = 0
        self._lines = [HIDDEN * n] * n
        self._chars = [HIDDEN] * (n * n)

    def _lay_mines(self, first: int) -> None:
        spots = self._spots.get(first)
        if spots is None:   # the cells a mine may take when ``first`` is revealed first
            clear = self.bits.grow8(1 << first)
            spots = self._spots[first] = [i for i in range(len(self.around)) if not clear >> i & 1]
        laid = self.rng.permutation(len(spots))[:self.params.mines].tolist()
        self.mines = sum(1 << spots[k] for k in laid)
        self.zero = self.bits.full & ~self.bits.grow8(self.mines)   # neither a mine nor next to one

    def _act(self, action: int) -> None:
        p, bits = self.params, self.bits
        bit = 1 << action
        if self.revealed & bit:
            self.say("That cell is already open.")
            return
        if not self.revealed:
            self._lay_mines(action)
        if self.mines & bit:
            self.reward(-p.mine_penalty)
            self.say("You revealed a mine.")
            self._draw(self.mines, show_mines=True)
            self.finish(won=False)
            return
        opened = bit
        if self.zero >> action & 1:
            opened = bits.grow8(bits.flood8(bit, self.zero)) & ~self.mines
        opened &= ~self.revealed
        self.revealed |= opened
        self._draw(opened)
        self.reward(p.progress_share * opened.bit_count() / self.safe)
        if self.revealed.bit_count() == self.safe:
            self.reward(1 - p.progress_share)
            self.say("Every safe cell is open.")
            self.finish(won=True)

    def _draw(self, changed: int, show_mines: bool = False) -> None:
        """Repaint the ``changed`` cells and redraw their rows."""
        n, mines, around, chars = self.params.size, self.mines, self.around, self._chars
        rows = set()
        while changed:
            low = changed & -changed
            changed ^= low
            i = low.bit_length() - 1
            chars[i] = MINE if show_mines and mines & low else NUMBERS[(around[i] & mines).bit_count()]
            rows.add(i // n)
        for r in rows:
            self._lines[r] = "".join(chars[r * n:r * n + n])

    def _grid(self) -> list[str]:
        return self._lines

    def _hud(self) -> str:
        return f"Mines {self.params.mines}"


register_variants(Minesweeper, "Classics", {
    "glyphbench/classics-minesweeper-v0": dict(size=8, mines=10, max_turns=60),
})
