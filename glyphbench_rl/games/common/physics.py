"""Falling and flying bodies.

- ``fall`` / ``move_vertical``: integer gravity on a grid and a cell-by-cell vertical sweep, so
  a body moving several cells in one tick never tunnels through a solid cell (Flappy, the
  Platformer, Tetris).
- ``launch_velocity`` / ``flight``: projectile flight over a height map, for games that lob
  shells (Artillery) or throw things.

Flight coordinates are continuous: ``x`` grows to the right in cell widths (column ``c`` spans
``[c, c + 1)``), ``y`` grows upward in cell heights from the bottom of the field (row ``r`` from
the bottom spans ``[r, r + 1)``). Ground fills rows ``0 .. heights[c] - 1`` of column ``c``.
"""

from __future__ import annotations

import math
from typing import Callable, Collection, Sequence

Cell = tuple[int, int]   # (column, row from the bottom)

CELL_FRACTION = 0.5      # a tick moves a shell about this many cells at its launch speed


def fall(vy: int, gravity: int, max_fall: int) -> int:
    """Vertical speed after one tick of gravity (rows per tick, positive = down), capped."""
    return min(vy + gravity, max_fall)


def move_vertical(y: int, dy: int, blocked: Callable[[int], bool]) -> tuple[int, bool]:
    """Move ``dy`` rows one row at a time, stopping before the first blocked row.

    Returns the new row and whether something stopped the move.
    """
    step = 1 if dy > 0 else -1
    for _ in range(abs(dy)):
        if blocked(y + step):
            return y, True
        y += step
    return y, False


def launch_velocity(angle_deg: float, speed: float, leftward: bool = False) -> tuple[float, float]:
    """Velocity of a shell fired ``angle_deg`` above the horizontal, to the right unless ``leftward``."""
    a = math.radians(angle_deg)
    vx = speed * math.cos(a)
    return (-vx if leftward else vx), speed * math.sin(a)


def flight(x: float, y: float, vx: float, vy: float, ax: float, ay: float,
           heights: Sequence[int], targets: Collection[Cell] = (), max_ticks: int = 5000
           ) -> tuple[list[Cell], Cell | None]:
    """Fly a point mass with constant acceleration (wind ``ax``, gravity ``ay`` < 0).

    Returns the cells it passed through in order (only those inside the field's columns; the
    field has no ceiling) and its impact cell: the first ground cell or cell in ``targets`` it
    enters, or None when it leaves the field through a side or ``max_ticks`` run out. Integration
    is semi-implicit Euler with a step sized so one tick moves about half a cell.
    """
    width = len(heights)
    dt = CELL_FRACTION / max(1.0, math.hypot(vx, vy))
    # Per-tick displacement and its per-tick change: two additions per tick and per axis.
    dx, dy, ddx, ddy = vx * dt, vy * dt, ax * dt * dt, ay * dt * dt
    path: list[Cell] = []
    col, row = int(x), int(y)
    for _ in range(max_ticks):
        dx += ddx
        dy += ddy
        x += dx
        y += dy
        if not 0 <= x < width:
            return path, None
        c, r = int(x), (int(y) if y >= 0 else -1)
        if c == col and r == row:
            continue
        col, row = c, r
        if r < heights[c]:
            return path, (c, max(r, 0))
        if (c, r) in targets:
            return path, (c, r)
        path.append((c, r))
    return path, None
