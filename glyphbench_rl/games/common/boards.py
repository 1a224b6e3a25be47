"""Board-puzzle helpers for games whose actions name cells.

- ``cell_actions``: one action per board cell (optionally several families, e.g. fill and mark),
  described in one prompt line per family.
- ``Bits``: a board's cells as bits of a Python int (row-major), so regions, flood fills and
  neighbourhoods cost a few big-int operations instead of set walks.
- ``runs`` / ``clue_margins``: run-length clues of a line of cells and their layout around the
  board, as a printed nonogram has them (nonograms).
"""

from __future__ import annotations

from typing import Iterator, Sequence

from ...core.actions import ActionSet, cell_names


def cell_actions(rows: int, cols: int, families: Sequence[tuple[str, str]]) -> ActionSet:
    """Actions named ``prefix + cell`` (``A1``, ``XA1`` ...) for each ``(prefix, description)``
    family, family-major and row-major inside a family: action ``k * rows * cols + r * cols + c``
    is family ``k`` at cell (r, c)."""
    names = cell_names(rows, cols)
    return ActionSet(groups=[(description, [prefix + n for n in names]) for prefix, description in families])


def cell_of(action: int, cols: int, cells: int) -> tuple[int, int, int]:
    """(family, row, col) of a ``cell_actions`` index."""
    family, i = divmod(action, cells)
    return family, i // cols, i % cols


class Bits:
    """Geometry of an ``height`` x ``width`` board whose cell (r, c) is bit ``r * width + c``."""

    __slots__ = ("height", "width", "full", "_no_first_col", "_no_last_col")

    def __init__(self, height: int, width: int) -> None:
        self.height, self.width = height, width
        self.full = (1 << height * width) - 1
        first = sum(1 << r * width for r in range(height))
        self._no_first_col = self.full & ~first
        self._no_last_col = self.full & ~(first << width - 1)

    def bit(self, r: int, c: int) -> int:
        return 1 << r * self.width + c

    def grow(self, mask: int) -> int:
        """``mask`` plus its orthogonal neighbours (no wrap between rows)."""
        w = self.width
        return (mask | (mask << 1 & self._no_first_col) | (mask >> 1 & self._no_last_col)
                | mask << w | mask >> w) & self.full

    def grow8(self, mask: int) -> int:
        """``mask`` plus its orthogonal and diagonal neighbours."""
        row = mask | (mask << 1 & self._no_first_col) | (mask >> 1 & self._no_last_col)
        return (row | row << self.width | row >> self.width) & self.full

    def flood(self, seed: int, allowed: int, diagonal: bool = False) -> int:
        """The cells of ``allowed`` 4-connected (8-connected with ``diagonal``) to ``seed``
        (seed cells outside it are dropped)."""
        grow = self.grow8 if diagonal else self.grow
        region = seed & allowed
        while True:
            grown = grow(region) & allowed
            if grown == region:
                return region
            region = grown

    def flood8(self, seed: int, allowed: int) -> int:
        """The cells of ``allowed`` 8-connected (diagonals too) to ``seed``."""
        return self.flood(seed, allowed, diagonal=True)

    def regions(self, mask: int) -> Iterator[int]:
        """The 4-connected components of ``mask``, lowest cell first."""
        while mask:
            part = self.flood(mask & -mask, mask)
            mask &= ~part
            yield part

    def cells(self, mask: int) -> list[tuple[int, int]]:
        out = []
        while mask:
            low = mask & -mask
            out.append(divmod(low.bit_length() - 1, self.width))
            mask ^= low
        return out

    def row_bits(self, mask: int, r: int) -> int:
        """Row ``r`` of ``mask`` as a ``width``-bit int (bit c = column c)."""
        return mask >> r * self.width & (1 << self.width) - 1

    def col_bits(self, mask: int, c: int) -> int:
        """Column ``c`` of ``mask`` as a ``height``-bit int (bit r = row r)."""
        return sum(1 << r for r in range(self.height) if mask >> r * self.width + c & 1)


def runs(line: int, length: int) -> tuple[int, ...]:
    """Lengths of the runs of set bits of ``line`` (bit 0 first): the nonogram clue of a line."""
    out, count = [], 0
    for i in range(length):
        if line >> i & 1:
            count += 1
        elif count:
            out.append(count)
            count = 0
    if count:
        out.append(count)
    return tuple(out)


def clue_char(n: int) -> str:
    """One character for a clue number: its digit below 10, else its circled number (⑩ is 10,
    up to ⑳)."""
    return str(n) if n < 10 else chr(0x2460 + n - 1)


def clue_margins(row_clues: Sequence[Sequence[int]],
                 col_clues: Sequence[Sequence[int]]) -> tuple[tuple[str, ...], tuple[str, ...]]:
    """The clues laid out as a printed nonogram has them, as ``Frame.above`` and ``Frame.beside``:
    each column's numbers stacked over the column, one character each (``clue_char``), the last
    run nearest the board; each row's numbers right of the row, separated by spaces. An empty
    line's clue is 0."""
    stacks = [[clue_char(n) for n in clue] or ["0"] for clue in col_clues]
    depth = max(map(len, stacks), default=0)
    stacks = [[" "] * (depth - len(stack)) + stack for stack in stacks]
    above = tuple("".join(stack[i] for stack in stacks).rstrip() for i in range(depth))
    beside = tuple(" ".join(map(str, clue)) if clue else "0" for clue in row_clues)
    return above, beside
