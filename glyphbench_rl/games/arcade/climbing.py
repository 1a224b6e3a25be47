"""Climbing and descending: a vertical world taller than the field, seen a screen or a window at
a time (H.E.R.O.'s mine shaft, Crazy Climber's building).

- ``Tower``: the world's rows (top first, changeable cell by cell) and ``top``, the first world
  row shown: ``page(r)`` flips screen by screen (a mine shaft), ``follow(r, below)`` scrolls so
  the player stays ``below`` rows above the field's bottom (a building facade);
- ``ClimbTask``: an ``ArcadeTask`` whose field is the tower's window: ``_world_rows(top)`` gives
  the rows shown (the tower's, or a game's own rows such as windows that open and shut) and
  ``_movers()`` the movers in world rows, shifted into the field;
- ``Purse``: pattern D's tally plus native points that count toward no unit (a critter shot, a
  wall blown, a floor climbed), each paid as reward when scored;
- ``Fallers``: things dropping a row a tick (flowerpots, rocks) that hit what they reach;
- ``thrust``: a helicopter pack or a jump against gravity: up a row when lifted, else down
  ``fall`` rows, never through a blocked cell (``physics.move_vertical``).
"""

from __future__ import annotations

from typing import Callable, Iterable

from ..common.physics import move_vertical
from .engine import ArcadeTask, Tally


class Purse(Tally):
    __slots__ = ()

    def bonus(self, points: float) -> None:
        """Native points that count toward no unit; paid at once."""
        if points > 0 and not self.task.done:
            self.shown = None
            self.points += points
            self.task.reward(points)


class Tower:
    __slots__ = ("rows", "view", "top")

    def __init__(self, rows: list[str], view: int) -> None:
        if len(rows) < view:
            raise ValueError("a tower needs at least a field's height of rows")
        self.rows, self.view, self.top = rows, view, 0

    def __len__(self) -> int:
        return len(self.rows)

    def get(self, r: int, c: int) -> str:
        """The cell at world (r, c); "" outside the tower."""
        if 0 <= r < len(self.rows):
            row = self.rows[r]
            if 0 <= c < len(row):
                return row[c]
        return ""

    def put(self, r: int, c: int, ch: str) -> None:
        row = self.rows[r]
        self.rows[r] = row[:c] + ch + row[c + 1:]

    def page(self, r: int) -> bool:
        """Show the screen holding world row ``r``; True when the screen changed."""
        top = min(r // self.view * self.view, len(self.rows) - self.view)
        changed, self.top = top != self.top, top
        return changed

    def follow(self, r: int, below: int) -> None:
        """Scroll so that world row ``r`` is ``below`` rows above the field's bottom row."""
        self.top = max(0, min(r - (self.view - 1 - below), len(self.rows) - self.view))

    def window(self) -> list[str]:
        return self.rows[self.top:self.top + self.view]


class Fallers:
    """Things falling a row a tick, in world rows; ``hits(r, c)`` takes the one at (r, c)."""
    __slots__ = ("cells",)

    def __init__(self) -> None:
        self.cells: list[tuple[int, int]] = []

    def drop(self, r: int, c: int) -> None:
        self.cells.append((r, c))

    def advance(self, bottom: int) -> None:
        """Every faller down a row; those past world row ``bottom`` are gone."""
        self.cells = [(r + 1, c) for r, c in self.cells if r < bottom]

    def hits(self, r: int, c: int) -> bool:
        if (r, c) in self.cells:
            self.cells.remove((r, c))
            return True
        return False


def thrust(r: int, lifted: bool, fall: int, blocked: Callable[[int], bool]) -> int:
    """The row after a tick: one up when ``lifted`` (unless blocked), else ``fall`` rows down
    (stopping on the first blocked row)."""
    if lifted:
        return r if blocked(r - 1) else r - 1
    return move_vertical(r, fall, blocked)[0] if fall else r


class ClimbTask(ArcadeTask):
    """An arcade task whose field is a ``Tower``'s window (``self.tower``, made in
    ``_setup`` after ``climb_start``)."""

    def climb_start(self, rng) -> None:
        """``start`` with pattern D's tally able to pay native points (``self.score.bonus``)."""
        self.start(rng)
        p = self.params
        self.score = Purse(self, p.goal, p.unit)

    def _still(self) -> list[str]:
        return []

    def _world_rows(self, top: int) -> list[str]:
        """The field's rows, world rows ``top`` onward (the tower's own by default)."""
        return self.tower.window()

    def _movers(self) -> Iterable[tuple[int, int, str]]:
        """(world row, col, glyph) of every mover, drawn in order."""
        return ()

    def _rows(self) -> list[str]:
        return self._world_rows(self.tower.top)

    def _sprites(self):
        top = self.tower.top
        return [(r - top, c, g) for r, c, g in self._movers()]
