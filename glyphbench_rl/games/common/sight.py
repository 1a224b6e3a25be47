"""Lines of sight on a grid of cells: the cells a segment between two cell centres crosses,
whether an opaque cell blocks it, and a watcher's widening view cone (guards, sentries). The
directions are ``grid.DELTAS``."""

from __future__ import annotations

from fractions import Fraction
from functools import lru_cache
from typing import Callable

from .grid import DELTAS

Cell = tuple[int, int]


def line_cells(a: Cell, b: Cell) -> list[Cell]:
    """The cells strictly between ``a`` and ``b`` whose inside the segment joining the two cell
    centres passes through (a cell it only touches at a corner does not count), nearest first.
    Exact: each cell's span of the segment is clipped with fractions."""
    (r0, c0), (r1, c1) = a, b
    dr, dc = r1 - r0, c1 - c0
    half = Fraction(1, 2)
    found = []
    for r in range(min(r0, r1), max(r0, r1) + 1):
        for c in range(min(c0, c1), max(c0, c1) + 1):
            if (r, c) in (a, b):
                continue
            lo, hi = Fraction(0), Fraction(1)
            for start, delta, centre in ((r0, dr, r), (c0, dc, c)):
                if delta == 0:   # the segment runs along this axis: inside only on the same line
                    if start != centre:
                        lo, hi = Fraction(1), Fraction(0)
                    continue
                t1, t2 = sorted(((centre - start - half) / delta, (centre - start + half) / delta))
                lo, hi = max(lo, t1), min(hi, t2)
            if lo < hi:
                found.append((lo, (r, c)))
    return [cell for _, cell in sorted(found)]


def sight_line(a: Cell, b: Cell, opaque: Callable[[int, int], bool]) -> bool:
    """Whether ``b`` can be seen from ``a``: no opaque cell strictly between them."""
    return not any(opaque(r, c) for r, c in line_cells(a, b))


@lru_cache(maxsize=64)
def _cone_template(facing: int, reach: int) -> tuple[tuple[Cell, tuple[Cell, ...]], ...]:
    """For a watcher at (0, 0): each cell of the cone with the cells its sight line crosses."""
    dr, dc = DELTAS[facing]
    out = []
    for ahead in range(1, reach + 1):
        half = ahead // 2
        for side in range(-half, half + 1):
            cell = (dr * ahead + dc * side, dc * ahead + dr * side)
            out.append((cell, tuple(line_cells((0, 0), cell))))
    return tuple(out)


def view_cone(origin: Cell, facing: int, reach: int, opaque: Callable[[int, int], bool]) -> frozenset[Cell]:
    """Cells a watcher at ``origin`` facing ``DELTAS[facing]`` sees: up to ``reach`` cells ahead,
    the cone widening by one cell to each side every two cells (1, 3, 3, 5, 5 ... wide), cut by
    opaque cells. The watcher's own cell is included; ``opaque`` must hold outside the board."""
    r0, c0 = origin
    seen = {origin}
    for (dr, dc), between in _cone_template(facing, reach):
        if not opaque(r0 + dr, c0 + dc) and not any(opaque(r0 + r, c0 + c) for r, c in between):
            seen.add((r0 + dr, c0 + dc))
    return frozenset(seen)
