"""Climbing and descending: a vertical world taller than the field, seen a screen or a window at
a time (H.E.R.O.'s mine shaft, Crazy Climber's building).

- ``Tower``: the world's rows (top first, changeable cell by cell: a ``scroller.Strip`` never
  scrolled) and ``top``, the first world row shown: ``page(r)`` flips screen by screen (a mine
  shaft), ``follow(r, below)`` scrolls so the player stays ``below`` rows above the field's
  bottom (a building facade); ``clear_run`` clears a column of wall cells (a blast),
  ``beam`` traces a shot along a row to the first mover or cell not air;
- ``ClimbTask``: an ``ArcadeTask`` whose field is the tower's window: ``_world_rows(top)`` gives
  the rows shown (the tower's, or a game's own rows such as windows that open and shut) and
  ``_movers()`` the movers in world rows, shifted into the field;
- ``Fallers``: things dropping a row a tick (flowerpots, rocks) that hit what they reach;
- ``shaft`` and ``ledges``: a mine shaft's cells and its bands, each a rock floor with a gap
  and the way across to it (``ClimbTask.screens`` and ``paged``: its screens, a ``RoomMap``);
- ``crawl``: critters that pace a ledge or climb a thread, turning back at anything solid;
- ``thrust``: a helicopter pack or a jump against gravity: up a row when lifted, else down
  ``fall`` rows, never through a blocked cell (``physics.move_vertical``).
"""

from __future__ import annotations

from typing import Callable, Iterable, Iterator, NamedTuple

from ..common.physics import move_vertical
from .engine import ArcadeTask
from .rooms import RoomMap
from .scroller import Strip


class Tower(Strip):
    """A tall ``Strip`` that is never scrolled but seen ``view`` rows at a time from ``top``."""
    __slots__ = ("view", "top")

    def __init__(self, rows: list[str], view: int) -> None:
        if len(rows) < view:
            raise ValueError("a tower needs at least a field's height of rows")
        super().__init__(rows)
        self.view, self.top = view, 0

    def __len__(self) -> int:
        return len(self.rows)

    def clear_run(self, r: int, c: int, ch: str, empty: str) -> bool:
        """Clear the column of ``ch`` cells running up and down through (r, c) (a wall blown);
        False when (r, c) holds no ``ch``."""
        if self.get(r, c) != ch:
            return False
        while self.get(r - 1, c) == ch:
            r -= 1
        while self.get(r, c) == ch:
            self.put(r, c, empty)
            r += 1
        return True

    def beam(self, r: int, c: int, d: int, reach: int, empty: str, movers: list) -> tuple:
        """A shot along row ``r`` from (r, c) toward ``d`` (+1 right, -1 left), ``reach`` cells:
        the air cells it crosses, and what stops it: ``(mover, None)`` (a mover ``[r, c, ...]``
        in its way), ``(None, column)`` (a cell other than air) or ``(None, None)``."""
        cells = []
        for k in range(1, reach + 1):
            x = c + d * k
            for m in movers:
                if m[0] == r and m[1] == x:
                    return cells, m, None
            if self.get(r, x) != empty:
                return cells, None, x
            cells.append(x)
        return cells, None, None

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


class Ledge(NamedTuple):
    """One band of a shaft: rows ``top`` to ``floor - 1`` of air over the rock ``floor``, which
    has a two-cell gap at ``gap`` and ``gap + 1`` (none on the ``last`` band: something waits
    there); you drop in through ``entry`` and ``entry + 1`` and head ``step`` (+1 right, -1
    left) to ``near``, the gap cell you reach first (``far`` the other); ``between`` the columns
    strictly between where you land and ``near``."""
    top: int
    floor: int
    entry: int
    gap: int
    step: int
    near: int
    far: int
    between: list
    last: bool


def ledges(draws, width: int, height: int, screens: int, bands: int, entry: int,
           run: int = 4) -> Iterator[Ledge]:
    """The bands of a shaft ``screens`` screens deep, ``bands`` floors a screen (the lowest on a
    screen's bottom row), top first: each band's gap is drawn at least ``run`` columns clear of
    where you drop in, and the next band is entered through it."""
    rise = (height - 1) // bands
    floors = [height - 1 - rise * j for j in range(bands)][::-1]
    for s in range(screens):
        for j, f in enumerate(floors):
            gaps = [b for b in range(1, width - 2) if b >= entry + run + 2 or b <= entry - run - 2]
            b = gaps[draws.below(len(gaps))]
            step = 1 if b > entry else -1
            near, far = (b, b + 1) if step > 0 else (b + 1, b)
            between = list(range(entry + 2 if step > 0 else entry - 1, near, step))
            yield Ledge(s * height + (floors[j - 1] + 1 if j else 0), s * height + f, entry, b,
                        step, near, far, between, s == screens - 1 and j == bands - 1)
            entry = b


def shaft(draws, width: int, height: int, screens: int, bands: int, entry: int, rock: str,
          empty: str) -> tuple[list[list[str]], list[Ledge]]:
    """A shaft's cells (rows of one-character lists, rock at both sides, the floors cut with
    their gaps) and its ``ledges``, for a game to furnish before making its ``Tower``."""
    rows = [list(rock + empty * (width - 2) + rock) for _ in range(screens * height)]
    bands_ = list(ledges(draws, width, height, screens, bands, entry))
    for band in bands_:
        rows[band.floor] = list(rock * width)
        if not band.last:
            rows[band.floor][band.gap] = rows[band.floor][band.gap + 1] = empty
    return rows, bands_


def crawl(tower: Tower, movers: list, lo: int, hi: int, empty: str) -> None:
    """Movers ``[r, c, dr, dc, ...]`` between world rows ``lo`` and ``hi`` (a screen) step a
    cell along their heading, turning back at anything but air (a bat along its ledge, a
    spider up and down its thread); a mover with no heading stays."""
    for m in movers:
        if lo <= m[0] < hi and (m[2] or m[3]):
            if tower.get(m[0] + m[2], m[1] + m[3]) != empty:
                m[2], m[3] = -m[2], -m[3]
            if tower.get(m[0] + m[2], m[1] + m[3]) == empty:
                m[0] += m[2]
                m[1] += m[3]


def thrust(r: int, lifted: bool, fall: int, blocked: Callable[[int], bool]) -> int:
    """The row after a tick: one up when ``lifted`` (unless blocked), else ``fall`` rows down
    (stopping on the first blocked row)."""
    if lifted:
        return r if blocked(r - 1) else r - 1
    return move_vertical(r, fall, blocked)[0] if fall else r


class ClimbTask(ArcadeTask):
    """An arcade task whose field is a ``Tower``'s window (``self.tower``, made in
    ``_setup`` after ``start``)."""

    def _still(self) -> list[str]:
        return []

    def screens(self, rows: list[str]) -> None:
        """A world seen a screen at a time: ``self.tower`` over ``rows``, ``self.map`` a
        ``RoomMap`` of its screens (one a row, the first entered), ``self.entry`` where the
        player (``self.r``, ``self.c``) first came into each screen."""
        view = self.params.height
        self.tower = Tower(rows, view)
        self.map = RoomMap(["#"] * (len(rows) // view))
        self.map.enter(0, 0)
        self.entry = {0: (self.r, self.c)}

    def paged(self) -> None:
        """After a move: flip to the player's screen, a first visit marked on the map and its
        way in remembered (where a life lost there starts again)."""
        tower = self.tower
        if tower.page(self.r):
            screen = tower.top // tower.view
            self.map.enter(screen, 0)
            self.entry.setdefault(screen, (self.r, self.c))

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
