"""Lane hopping: rows of hazards or footholds, progress by reaching rows, diagonal pyramid hops.

- ``Drift``: rows that slide (ice floes, logs) built on ``common.lanes.Lane``: ``solid(r, c,
  tick)`` says whether a cell of a drifting row holds you at the end of ``tick``, and
  ``carry(r, tick)`` how far that row moved during the tick (a rider moves with it);
- ``Pyramid``: a stack of cubes, row k holding k + 1 of them, drawn as a triangle with cubes two
  columns apart; ``hop(cube, action)`` is the cube a diagonal hop lands on, or None off the edge;
- ``Ladders``: floors on given rows joined by ladders at given columns: ``climb(r, c, dr)`` says
  whether a step up or down the ladder from (r, c) is allowed;
- ``DIAGONALS``: the diagonal hop action set (NOOP, UP_LEFT, UP_RIGHT, DOWN_LEFT, DOWN_RIGHT).
"""

from __future__ import annotations

from ...core.actions import ActionSet
from ..common.lanes import Lane

DIAGONALS = ActionSet([("NOOP", "stay on your cube"), ("UP_LEFT", "hop up and to the left"),
                       ("UP_RIGHT", "hop up and to the right"), ("DOWN_LEFT", "hop down and to the left"),
                       ("DOWN_RIGHT", "hop down and to the right")], noop="NOOP")
HOPS = ((0, 0), (-1, -1), (-1, 0), (1, 0), (1, 1))   # (row, index) change of a pyramid hop


class Drift:
    """Drifting rows: ``lanes`` maps a grid row to its ``Lane``; a cell is solid where the lane
    shows something other than ``water``. A lane's row repeats every ``period x length`` ticks:
    ``cycles`` holds, per grid row, its row at each tick of that cycle (made once, with the
    lanes), so a turn looks its rows up instead of working out each shift."""
    __slots__ = ("lanes", "water", "cycles")

    def __init__(self, lanes: dict[int, Lane], water: str) -> None:
        self.lanes, self.water = lanes, water
        self.cycles = {r: [lane.row(t) for t in range(lane.period * len(lane.pattern))]
                       for r, lane in lanes.items()}

    def line(self, r: int, tick: int) -> str:
        """The row of the lane on grid row ``r`` at the end of ``tick``."""
        cycle = self.cycles[r]
        return cycle[tick % len(cycle)]

    def solid(self, r: int, c: int, tick: int) -> bool:
        return r in self.lanes and self.line(r, tick)[c % len(self.lanes[r].pattern)] != self.water

    def carry(self, r: int, tick: int) -> int:
        lane = self.lanes.get(r)
        return 0 if lane is None else lane.moves_at(tick)

    def rows(self, tick: int) -> dict[int, str]:
        return {r: self.line(r, tick) for r in self.lanes}


class Pyramid:
    """``levels`` rows of cubes; cube (k, i), 0 <= i <= k, sits at grid row ``top + k`` and
    column ``apex - k + 2 i``."""
    __slots__ = ("levels", "top", "apex", "cubes")

    def __init__(self, levels: int, top: int, apex: int) -> None:
        self.levels, self.top, self.apex = levels, top, apex
        self.cubes = [(k, i) for k in range(levels) for i in range(k + 1)]

    def cell(self, cube: tuple[int, int]) -> tuple[int, int]:
        return self.top + cube[0], self.apex - cube[0] + 2 * cube[1]

    def hop(self, cube: tuple[int, int], action: int) -> tuple[int, int] | None:
        dk, di = HOPS[action]
        k, i = cube[0] + dk, cube[1] + di
        return (k, i) if 0 <= i <= k < self.levels else None


class Ladders:
    """Floors on ``floors`` (grid rows, bottom first) and ladders: ``ladders[j]`` the columns of
    the ladders from floor j up to floor j + 1; ladder cells are the rows between the two."""
    __slots__ = ("floors", "ladders", "cells", "levels")

    def __init__(self, floors: list[int], ladders: list[list[int]]) -> None:
        self.floors, self.ladders = floors, ladders
        self.cells = {(r, c) for j, cols in enumerate(ladders) for c in cols
                      for r in range(floors[j + 1], floors[j] + 1)}
        self.levels: dict[int, int] = {}            # grid row -> its floor (the first listed)
        for j, r in enumerate(floors):
            self.levels.setdefault(r, j)

    def climb(self, r: int, c: int, dr: int) -> bool:
        return (r, c) in self.cells and (r + dr, c) in self.cells

    def floor_of(self, r: int) -> int | None:
        return self.levels.get(r)
