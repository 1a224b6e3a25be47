"""Connect Four against a two-ply tactical opponent.

The board is kept as bitboards (one Python int per player, column-major with a sentinel bit on
top of each column, as in Pascal Pons' solver), so win tests and the opponent's search are a few
shifts and masks rather than walks over cells.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import ActionSet, register_variants
from ...core.params import param
from ..common.palette import FLOOR
from .versus import DRAW, LOSS, OUTCOME_REWARDS, WIN, VersusTask, choose

YOU, THEM = "X", "O"


@dataclass(frozen=True)
class ConnectFourParams:
    rows: int = param(6, 4, 10)
    cols: int = param(7, 4, 12)
    # probability that the opponent plays its search's move, else a random one
    strength: float = param(0.9, 0, 1)


class Bitboard:
    """Column-major bit layout: cell (row from the bottom r, column c) is bit c * (rows + 1) + r."""

    def __init__(self, rows: int, cols: int) -> None:
        self.rows, self.cols, self.h1 = rows, cols, rows + 1
        self.bottom = sum(1 << c * self.h1 for c in range(cols))
        self.full = self.bottom * ((1 << rows) - 1)
        self.column = [((1 << rows) - 1) << c * self.h1 for c in range(cols)]
        # The classic static evaluation: how many lines of four pass through each cell (bit).
        self.lines = {}
        for r in range(rows):
            for c in range(cols):
                self.lines[1 << c * self.h1 + r] = sum(
                    1 for dr, dc in ((0, 1), (1, 0), (1, 1), (1, -1)) for k in range(4)
                    if 0 <= r - k * dr and r + (3 - k) * dr < rows
                    and 0 <= c - k * dc < cols and 0 <= c + (3 - k) * dc < cols)

    def has_four(self, p: int) -> bool:
        for s in (1, self.h1, self.h1 - 1, self.h1 + 1):  # vertical, horizontal, two diagonals
            m = p & (p >> s)
            if m & (m >> 2 * s):
                return True
        return False

    def winning_cells(self, p: int, mask: int) -> int:
        """Empty cells (bits) where a disc would complete four for the player holding ``p``."""
        r = (p << 1) & (p << 2) & (p << 3)
        for s in (self.h1, self.h1 - 1, self.h1 + 1):
            q = (p << s) & (p << 2 * s)
            r |= (q & (p << 3 * s)) | (q & (p >> s))
            q = (p >> s) & (p >> 2 * s)
            r |= (q & (p << s)) | (q & (p >> 3 * s))
        return r & (self.full ^ mask)

    def playable(self, mask: int) -> int:
        """The lowest empty cell of every column that is not full."""
        return (mask + self.bottom) & self.full

    def columns_of(self, bits: int) -> list[int]:
        return [c for c in range(self.cols) if bits & self.column[c]]


def tactical_moves(bb: Bitboard, me: int, you: int) -> list[int]:
    """The columns a two-ply search prefers for the player holding ``me``: win now; else block the
    other's immediate win; else never play right under a cell that wins for the other, and among
    the rest take the cell on the most lines of four (ties: all of them)."""
    mask = me | you
    playable = bb.playable(mask)
    win = bb.winning_cells(me, mask) & playable
    if win:
        return bb.columns_of(win)
    threats = bb.winning_cells(you, mask)
    if threats & playable:
        return bb.columns_of(threats & playable)
    safe = playable & ~(threats >> 1) or playable
    best, best_score = [], -1
    for c, column in enumerate(bb.column):
        move = safe & column
        if move:
            score = bb.lines[move]
            if score > best_score:
                best, best_score = [c], score
            elif score == best_score:
                best.append(c)
    return best


class ConnectFour(VersusTask):
    title = "Connect Four"
    rules = ("You ({you}) and the opponent ({them}) take turns dropping a disc into one of the "
             "{cols} columns of a {rows}-row board; it falls to the lowest empty cell. Four of your "
             "discs in a row (across, up or diagonally) win. You move first; the opponent answers "
             "every move. With probability {strength:g} the opponent plays the move of a two-ply "
             "search (win, block, never set up your win, else the cell on the most lines of four), "
             "otherwise a random legal move. Dropping into a full column wastes your turn.")
    rewards = OUTCOME_REWARDS
    ends = "when someone connects four or the board is full"
    Params = ConnectFourParams
    glyphs = {FLOOR: "empty", YOU: "your disc", THEM: "opponent disc"}
    axes = True
    default_max_turns = 50

    def prompt_fields(self) -> dict:
        return super().prompt_fields() | {"you": YOU, "them": THEM}

    def _make_actions(self) -> ActionSet:
        return ActionSet(groups=[("drop your disc into that column",
                                  [chr(65 + c) for c in range(self.params.cols)])])

    def _init(self) -> None:
        self.bb = Bitboard(self.params.rows, self.params.cols)

    def _setup(self, rng: np.random.Generator) -> None:
        self.rng = rng
        self.mine = self.theirs = 0
        self.cells = [[FLOOR] * self.params.cols for _ in range(self.params.rows)]  # top row first

    def drop(self, col: int, glyph: str) -> int:
        """The bit where a disc dropped in ``col`` lands (the column must not be full)."""
        bit = self.bb.playable(self.mine | self.theirs) & self.bb.column[col]
        self.cells[self.params.rows - bit.bit_length() + col * self.bb.h1][col] = glyph
        return bit

    def legal_columns(self) -> list[int]:
        return self.bb.columns_of(self.bb.playable(self.mine | self.theirs))

    def _agent_move(self, action: int) -> str | None:
        if not self.bb.playable(self.mine | self.theirs) & self.bb.column[action]:
            return f"Column {chr(65 + action)} is full."
        self.mine |= self.drop(action, YOU)
        return None

    def _opponent_move(self) -> None:
        col = choose(self.rng, self.params.strength,
                     lambda: tactical_moves(self.bb, self.theirs, self.mine), self.legal_columns())
        self.theirs |= self.drop(col, THEM)
        self.say(f"Opponent dropped in {chr(65 + col)}.")

    def _result(self) -> str | None:
        if self.bb.has_four(self.mine):
            return WIN
        if self.bb.has_four(self.theirs):
            return LOSS
        if (self.mine | self.theirs) == self.bb.full:
            return DRAW
        return None

    def _grid(self) -> list[str]:
        return ["".join(row) for row in self.cells]


register_variants(ConnectFour, "Classics", {
    "glyphbench/classics-connectfour-v0": dict(rows=6, cols=7, strength=0.9, max_turns=50),
})
