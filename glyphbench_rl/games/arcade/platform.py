"""Side-view platform rooms (Montezuma's Revenge, Pitfall!): a player who stands on floors, falls
under gravity, jumps in an arc, climbs ladders and ropes and swings on vines, seen one room or
screen at a time.

``Platformer`` (an ``ArcadeTask``) moves the player one tick for an intent (``STAY``, ``LEFT``,
``RIGHT``, ``UP``, ``DOWN``, ``JUMP``, ``JUMP_LEFT``, ``JUMP_RIGHT``) over the current room's
still rows (``self.still``; a game keeps one list of rows per room and points ``still`` at it):
- cells in ``SOLID`` hold you up and block you; walking into one calls ``_bump`` (a door that a
  key opens answers True and you pass);
- ``LADDER`` and ``ROPE`` cells hold you; UP and DOWN climb along them (up a ladder onto the
  floor at its top), sideways steps off;
- with nothing under you you fall a row a tick; landing after more than ``safe_fall`` rows costs
  a life (``lose_life``), as in both originals;
- a jump follows ``ARC_UP`` or ``ARC_SIDE`` (up a row, across, down a row), stopping on what it
  meets; a rope met mid-jump is grabbed, and a vine whose tip comes within a column;
- a ``Swing`` (a vine) carries the one who holds its tip; DOWN lets go;
- leaving the rows (an edge, or a ladder through the top or the bottom) calls ``_leave(dr, dc)``
  for the game to change rooms; a cell in ``HAZARD`` under you costs a life.
A world of rooms keeps one list of rows per room, made by ``_build(room)`` on the first visit
(``show(room)``; ``room_grid`` and ``paint`` help draw one; ``cross`` finds the next room of a
grid of rooms); ``spanning_tree`` links a world's rooms at random from the start, and ``locks``
puts doors on some links with each key in a room reachable before its door (so there is always
a way through); ``meet`` steps the monsters and finds the one the player met.
``Walker``: a monster pacing a floor between two columns (or rolling round a screen, or closing
on the player). ``Blink``: cells that switch between two glyphs on a cycle (lasers, jaws,
quicksand), written into the still rows when they switch.
"""

from __future__ import annotations

from typing import ClassVar, Hashable, Iterable

from .engine import EMPTY, ArcadeTask

STAY, LEFT, RIGHT, UP, DOWN, JUMP, JUMP_LEFT, JUMP_RIGHT = range(8)
LADDER, ROPE = "H", "|"
ARC_UP = ((-1, 0), (0, 0), (1, 0))
ARC_SIDE = ((-1, 1), (0, 1), (0, 1), (1, 1))
JUMP_TEXT = ("A jump rises one row, and a sideways jump carries you four columns (up one row, "
             "across, down one row)")


Room = Hashable
Link = tuple[Room, Room]


def spanning_tree(near: dict, start: Room, rng) -> list[Link]:
    """A random spanning tree of the rooms from ``start`` (``near``: room -> its neighbours),
    as (room, room it was reached from... to) links in the order they were made."""
    tree, seen, edge = [], {start}, [(start, b) for b in near[start]]
    while edge:
        a, b = edge.pop(int(rng.integers(len(edge))))
        if b not in seen:
            seen.add(b)
            tree.append((a, b))
            edge += [(b, n) for n in near[b] if n not in seen]
    return tree


def reachable(rooms: Iterable[Room], tree: list[Link], shut: Iterable[Link]) -> set:
    """The rooms reachable from ``rooms`` over the tree's links, not through the ``shut`` ones."""
    closed = {frozenset(e) for e in shut}
    links: dict = {}
    for a, b in tree:
        if frozenset((a, b)) not in closed:
            links.setdefault(a, []).append(b)
            links.setdefault(b, []).append(a)
    out, todo = set(rooms), list(rooms)
    while todo:
        for b in links.get(todo.pop(), ()):
            if b not in out:
                out.add(b)
                todo.append(b)
    return out


def locks(tree: list[Link], start: Room, doors: list[Link], rng) -> list[tuple[Room, Room, Room]]:
    """Doors on the links ``doors``, in an order they can be opened: (room before the door,
    room behind it, room its key lies in), each key in a room reachable before its door."""
    shut, out = list(doors), []
    reach = reachable([start], tree, shut)
    while shut:
        a, b = next(e for e in shut if (e[0] in reach) != (e[1] in reach))
        pool = sorted(reach)
        out.append((a, b, pool[int(rng.integers(len(pool)))]) if a in reach else
                   (b, a, pool[int(rng.integers(len(pool)))]))
        shut.remove((a, b))
        reach = reachable(reach, tree, shut)
    return out


def paint(grid: list[list[str]], ch: str, rows: Iterable[int], cols: Iterable[int]) -> None:
    """Set every cell of ``rows`` x ``cols`` of a room being built (lists of cells) to ``ch``."""
    cols = tuple(cols)
    for r in rows:
        line = grid[r]
        for c in cols:
            line[c] = ch


def room_grid(h: int, w: int, wall: str, floor: str, exits: Iterable[int] = (), gap: int = 4,
              top: int | None = None, bottom: int | None = None) -> list[list[str]]:
    """A room's cells (lists, for ``paint``): walls round it, a floor along the bottom, a gap
    ``gap`` rows high above the floor in the side wall for each exit (-1 left, 1 right), a
    ladder from the ceiling down to the floor at column ``top`` and one through the floor at
    column ``bottom``."""
    g = [[EMPTY] * w for _ in range(h)]
    paint(g, wall, range(h), (0, w - 1))
    paint(g, wall, (0,), range(w))
    paint(g, floor, (h - 1,), range(1, w - 1))
    for dc in exits:
        paint(g, EMPTY, range(h - 1 - gap, h - 1), (0 if dc < 0 else w - 1,))
    if top is not None:
        paint(g, LADDER, range(h - 1), (top,))
    if bottom is not None:
        g[h - 1][bottom] = LADDER
    return g


class Walker:
    """A monster on row ``r`` stepping every ``every`` ticks (0: never): between columns ``lo``
    and ``hi``, turning at the ends; round a screen ``wrap`` columns wide; or, with ``chase``,
    toward the column it is given (standing still when given none)."""
    __slots__ = ("r", "c", "d", "lo", "hi", "every", "glyph", "wrap", "chase")

    def __init__(self, r: int, c: int, lo: int, hi: int, every: int, glyph: str, d: int = 1,
                 wrap: int = 0, chase: bool = False) -> None:
        self.r, self.c, self.lo, self.hi, self.every, self.glyph = r, c, lo, hi, every, glyph
        self.d, self.wrap, self.chase = d, wrap, chase

    def step(self, tick: int, target: int | None = None) -> None:
        if not self.every or tick % self.every or (self.chase and target is None):
            return
        if self.wrap:
            self.c = (self.c + self.d) % self.wrap
            return
        if self.chase:
            self.d = 1 if target > self.c else -1 if target < self.c else 0
        elif not self.lo <= self.c + self.d <= self.hi:
            self.d = -self.d
        self.c = min(self.hi, max(self.lo, self.c + self.d))


class Blink:
    """``cells`` that show ``on`` for ``lit`` ticks, then ``off`` for ``dark`` ticks, from
    ``phase``."""
    __slots__ = ("cells", "on", "off", "lit", "dark", "phase", "state")

    def __init__(self, cells: list[tuple[int, int]], on: str, off: str, lit: int, dark: int,
                 phase: int = 0) -> None:
        self.cells, self.on, self.off, self.lit, self.dark, self.phase = cells, on, off, lit, dark, phase
        self.state = None

    def lit_at(self, tick: int) -> bool:
        return (tick + self.phase) % (self.lit + self.dark) < self.lit


class Swing:
    """A vine hanging from (``top``, ``col``) whose tip, ``length`` rows down, swings ``reach``
    columns either side, a column a tick."""
    __slots__ = ("top", "col", "length", "reach", "phase", "_cells")

    def __init__(self, top: int, col: int, length: int, reach: int, phase: int = 0) -> None:
        self.top, self.col, self.length, self.reach, self.phase = top, col, length, reach, phase
        self._cells: dict[int, list[tuple[int, int, str]]] = {}

    def offset(self, tick: int) -> int:
        k = self.reach
        t = (tick + self.phase) % (4 * k)
        return t - k if t < 2 * k else 3 * k - t

    def tip(self, tick: int) -> tuple[int, int]:
        return self.top + self.length, self.col + self.offset(tick)

    def cells(self, tick: int) -> list[tuple[int, int, str]]:
        off = self.offset(tick)
        cells = self._cells.get(off)
        if cells is None:
            n = self.length
            cells = self._cells[off] = [(self.top + i, self.col + (off * i + (n // 2 if off > 0 else -(n // 2))) // n
                                         if i else self.col, ROPE) for i in range(n + 1)]
        return cells


class Platformer(ArcadeTask):
    SOLID: ClassVar[frozenset] = frozenset("#=")
    HAZARD: ClassVar[frozenset] = frozenset()
    safe_fall: ClassVar[int] = 3

    def show(self, room) -> None:
        """Make ``room``'s rows the still rows (built by ``_build`` on the first visit, then
        kept, changes and all, in ``rows_of``)."""
        rows_of = self.__dict__.setdefault("rows_of", {})
        rows = rows_of.get(room)
        if rows is None:
            rows = rows_of[room] = self._build(room)
        self.still = rows
        self.still_version += 1

    def _build(self, room) -> list[str]:
        raise NotImplementedError

    def cross(self, room: tuple[int, int], dr: int, dc: int) -> tuple[tuple[int, int], int, int]:
        """For rooms on a grid: the room the player reaches leaving ``room`` by (dr, dc), and
        the cell there (the opposite edge, the same row or column)."""
        h, w = len(self.still), len(self.still[0])
        return ((room[0] + dr, room[1] + dc), self.r if not dr else (h - 1 if dr < 0 else 0),
                self.c if not dc else (w - 1 if dc < 0 else 0))

    def start(self, rng) -> None:
        self.rows_of: dict = {}
        super().start(rng)
        self.face = 1

    def place(self, r: int, c: int) -> None:
        """Put the player at (r, c), still (facing as before)."""
        self.r, self.c, self.arc, self.ai, self.jd, self.fallen, self.held = r, c, None, 0, 0, 0, None
        self.swings: list[Swing] = getattr(self, "swings", [])

    def _bump(self, r: int, c: int, ch: str) -> bool:
        """Walking into solid ``ch`` at (r, c): True when it gave way (a door opened)."""
        return False

    def _leave(self, dr: int, dc: int) -> None:
        """The player left the rows by (dr, dc): change rooms (place the player)."""
        raise NotImplementedError

    def _open(self, r: int, c: int) -> bool:
        """Whether the player may move into (r, c) (off the rows: the game's ``_leave``)."""
        ch = self.still[r][c]
        return ch not in self.SOLID or self._bump(r, c, ch)

    def _shift(self, dr: int, dc: int) -> bool:
        """Move by (dr, dc), or by as much of it as is open; False when it left the room."""
        rows, h, w = self.still, len(self.still), len(self.still[0])
        for mr, mc in ((dr, dc), (dr, 0), (0, dc)) if dr and dc else ((dr, dc),):
            r, c = self.r + mr, self.c + mc
            if not (0 <= r < h and 0 <= c < w):
                if mr and mc:
                    continue
                self.arc = None
                self._leave(mr, mc)
                return False
            if (mr or mc) and self._open(r, c):
                self.r, self.c = r, c
                if rows[r][c] == ROPE:
                    self.arc = None
                return True
        self.arc = None if dr else self.arc
        return True

    def _grab(self) -> None:
        for s in self.swings:
            r, c = s.tip(self.tick)
            if r == self.r and -1 <= c - self.c <= 1:
                self.held, self.arc = s, None

    def walk(self, intent: int) -> bool:
        """One tick of the player's body for ``intent``; False when a life was lost (a fall too
        far or a hazard) or the room changed, True when the player is still in play here."""
        if self.held is not None:
            if intent != DOWN:
                self.r, self.c = self.held.tip(self.tick)
                return self._safe()
            self.held = None
        if self.arc is not None:
            dr, dc = self.arc[self.ai]
            self.ai += 1
            if self.ai == len(self.arc):
                self.arc = None
            if not self._shift(dr, dc * self.jd):
                return False
            if self.swings:
                self._grab()
            return self._safe()
        rows, r, c = self.still, self.r, self.c
        here = rows[r][c]
        below = rows[r + 1][c] if r + 1 < len(rows) else here
        hold = here == LADDER or here == ROPE
        if not (hold or below in self.SOLID or below == LADDER):
            self.fallen += 1
            if not self._shift(1, 0):
                return False
            r = self.r
            below = rows[r + 1][c] if r + 1 < len(rows) else EMPTY
            if self.fallen > self.safe_fall and (below in self.SOLID or below == LADDER):
                self.lose_life("You fell too far.")
                return False
            return self._safe()
        self.fallen = 0
        if intent == LEFT or intent == RIGHT:
            self.face = -1 if intent == LEFT else 1
            if not self._shift(0, self.face):
                return False
        elif intent == UP:
            above = rows[r - 1][c] if r else here
            if (here == LADDER and above not in self.SOLID) or (here == ROPE and above == ROPE):
                if not self._shift(-1, 0):
                    return False
        elif intent == DOWN:
            if below == LADDER or (hold and below == here):
                if not self._shift(1, 0):
                    return False
        elif intent >= JUMP:
            self.jd = 0 if intent == JUMP else -1 if intent == JUMP_LEFT else 1
            if self.jd:
                self.face = self.jd
            self.arc, self.ai = (ARC_UP if intent == JUMP else ARC_SIDE), 0
            return self.walk(STAY)
        return self._safe()

    def _safe(self) -> bool:
        if self.still[self.r][self.c] in self.HAZARD:
            self.lose_life(self._hazard_text())
            return False
        return True

    def _hazard_text(self) -> str:
        return "You touched a hazard."

    def blink(self, blinks: list[Blink]) -> None:
        """Write the blinking cells that switched this tick into the still rows."""
        for b in blinks:
            state = b.lit_at(self.tick)
            if state is not b.state:
                b.state = state
                g = b.on if state else b.off
                for r, c in b.cells:
                    self.set_still(r, c, g)

    def touching(self, walkers: list[Walker]) -> Walker | None:
        r, c = self.r, self.c
        for w in walkers:
            if w.r == r and w.c == c:
                return w
        return None

    def meet(self, walkers: list[Walker], target: int | None = None) -> Walker | None:
        """Step the walkers (chasers toward column ``target``) and return one the player met:
        walked into, or that walked into the player (so the two cannot pass through each other)."""
        met = self.touching(walkers)
        tick = self.tick
        for w in walkers:
            w.step(tick, target)
        return met or self.touching(walkers)
