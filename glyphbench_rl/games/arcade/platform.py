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
``Walker``: a monster pacing a floor between two columns (or rolling round a screen, or closing
on the player). ``Blink``: cells that switch between two glyphs on a cycle (lasers, jaws,
quicksand), written into the still rows when they switch.
"""

from __future__ import annotations

from typing import ClassVar

from .engine import EMPTY, ArcadeTask

STAY, LEFT, RIGHT, UP, DOWN, JUMP, JUMP_LEFT, JUMP_RIGHT = range(8)
LADDER, ROPE = "H", "|"
ARC_UP = ((-1, 0), (0, 0), (1, 0))
ARC_SIDE = ((-1, 1), (0, 1), (0, 1), (1, 1))
JUMP_TEXT = ("A jump rises one row, and a sideways jump carries you four columns (up one row, "
             "across, down one row)")


class Walker:
    """A monster on row ``r`` stepping every ``every`` ticks (0: never): between columns ``lo``
    and ``hi``, turning at the ends; round a screen ``wrap`` columns wide; or, with ``chase``,
    toward the column it is given."""
    __slots__ = ("r", "c", "d", "lo", "hi", "every", "glyph", "wrap", "chase")

    def __init__(self, r: int, c: int, lo: int, hi: int, every: int, glyph: str, d: int = 1,
                 wrap: int = 0, chase: bool = False) -> None:
        self.r, self.c, self.lo, self.hi, self.every, self.glyph = r, c, lo, hi, every, glyph
        self.d, self.wrap, self.chase = d, wrap, chase

    def step(self, tick: int, target: int = 0) -> None:
        if not self.every or tick % self.every:
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

    def place(self, r: int, c: int) -> None:
        """Put the player at (r, c), still (facing as before: set ``face``, 1 or -1, in
        ``_setup``)."""
        self.r, self.c, self.arc, self.ai, self.jd, self.fallen, self.held = r, c, None, 0, 0, 0, None
        self.swings: list[Swing] = getattr(self, "swings", [])

    def pay(self, points: float) -> None:
        """Native points outside the score rule's unit (treasures of several values, a log's
        penalty): shown in the HUD score and paid as reward."""
        score = self.score
        score.points += points
        score.shown = None
        self.reward(points)

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
