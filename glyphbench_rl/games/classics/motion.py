"""Movement and search helpers shared by the Classics puzzles that are more than walking.

Sliding until blocked (ice), breadth-first search over any hashable state (sliding
puzzles, Rush Hour, time-expanded patrol maps) and a guard's line-of-sight cone. Plain 4-way
walking and its search live in ``grid.py``; the directions here are its ``MOVES``/``DELTAS``.
"""

from __future__ import annotations

from collections import deque
from fractions import Fraction
from functools import lru_cache
from typing import Callable, Hashable, Iterable, TypeVar

from .grid import DELTAS

Cell = tuple[int, int]
S = TypeVar("S", bound=Hashable)
Neighbours = Callable[[S], Iterable[tuple[object, S]]]


def slide(start: Cell, delta: Cell, blocked: Callable[[int, int], bool],
          stops: Callable[[int, int], bool] | None = None) -> Cell:
    """Where something moving from ``start`` by ``delta`` comes to rest: the last cell before a
    blocked one, or the first cell where ``stops`` holds (an exit, a hole). ``blocked`` must hold
    outside the board, so a slide always ends."""
    r, c = start
    dr, dc = delta
    while not blocked(r + dr, c + dc):
        r, c = r + dr, c + dc
        if stops is not None and stops(r, c):
            break
    return r, c


def bfs_search(start: S, neighbours: Neighbours, is_goal: Callable[[S], bool],
               limit: int | None = None) -> list | None:
    """The actions of one shortest path from ``start`` to a goal state, or None when no goal is
    reachable (or more than ``limit`` states were seen). ``neighbours(state)`` yields
    ``(action, next state)``, the action being a name or an index; states that lose simply have
    no neighbours and are no goal."""
    if is_goal(start):
        return []
    prev: dict = {start: None}
    queue = deque([start])
    while queue:
        state = queue.popleft()
        for name, nxt in neighbours(state):
            if nxt in prev:
                continue
            prev[nxt] = (state, name)
            if is_goal(nxt):
                path = []
                while prev[nxt] is not None:
                    nxt, step = prev[nxt]
                    path.append(step)
                return path[::-1]
            if limit is not None and len(prev) > limit:
                return None
            queue.append(nxt)
    return None


def bfs_layers(sources: Iterable[S], neighbours: Callable[[S], Iterable[S]],
               limit: int | None = None) -> dict[S, int] | None:
    """Distance (in steps) from the nearest source to every reachable state, or None when more
    than ``limit`` states are reachable. ``neighbours`` yields bare states here."""
    dist = {s: 0 for s in sources}
    queue = deque(dist)
    while queue:
        state = queue.popleft()
        d = dist[state] + 1
        for nxt in neighbours(state):
            if nxt not in dist:
                dist[nxt] = d
                queue.append(nxt)
                if limit is not None and len(dist) > limit:
                    return None
    return dist


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
