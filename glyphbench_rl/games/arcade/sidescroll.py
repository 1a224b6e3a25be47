"""Side-scrolling worlds longer than the screen, driven or run along a ground line (James Bond
007, Road Runner, Private Eye).

A ``Course`` is the whole stage as row strings (scenery, holes, water, buildings, things that
stay where they were put); the view is a window ``width`` columns wide that follows the player,
cut from those rows only when it moves or the course changes. A course may run backward: the
player heads left on the screen, world column 0 at the view's right edge (Road Runner)::

    course = Course(lay(("." , ".", "#"), 200), width=30)
    course.follow(x, lead=20)            # 20 view columns ahead of the player
    rows = course.view()                 # a copy of the window's rows (movers go on top)
    c = course.screen(x)                 # a world column's view column, -1 off the view
    if course.get(r, x) == SEED: course.put(r, x, EMPTY)

``Leap`` is a jump off the ground line (an arc of rows above it, one a tick); ``fall`` drops
bombs and flowerpots a row a turn; ``ScrollTask`` the ``ArcadeTask`` whose field is a course's
view with the movers drawn in (a HUD note remade only when its key changes).
"""

from __future__ import annotations

from typing import Sequence

from .engine import ArcadeTask


def lay(fills: Sequence[str], length: int) -> list[list[str]]:
    """A course's rows as lists of cells ``length`` long, row i filled with ``fills[i]``, for a
    game to carve into before ``Course(carve(...))`` joins them."""
    return [[ch] * length for ch in fills]


class Course:
    """A stage's rows (strings, or lists of cells that are joined) and the view on them."""
    __slots__ = ("rows", "width", "length", "left", "backward", "version", "_cut", "_cut_key")

    def __init__(self, rows, width: int, backward: bool = False) -> None:
        self.rows = [row if isinstance(row, str) else "".join(row) for row in rows]
        self.length = len(self.rows[0])
        if self.length < width:
            raise ValueError(f"a course of {self.length} columns is narrower than its {width}-column view")
        self.width, self.backward, self.left, self.version = width, backward, 0, 0
        self._cut, self._cut_key = None, None

    def follow(self, x: int, lead: int) -> None:
        """Move the view so that ``lead`` of its columns lie ahead of world column ``x`` (the way
        the course runs), stopping at the course's ends."""
        left = x - (self.width - 1 - lead)
        hi = self.length - self.width
        self.left = 0 if left < 0 else (hi if left > hi else left)

    def screen(self, x: int) -> int:
        c = x - self.left
        if c < 0 or c >= self.width:
            return -1
        return self.width - 1 - c if self.backward else c

    def view(self) -> list[str]:
        key = (self.left, self.version)
        if key != self._cut_key:
            a, b = self.left, self.left + self.width
            self._cut = ([row[a:b][::-1] for row in self.rows] if self.backward
                         else [row[a:b] for row in self.rows])
            self._cut_key = key
        return self._cut[:]

    def get(self, r: int, x: int) -> str:
        if 0 <= x < self.length and 0 <= r < len(self.rows):
            return self.rows[r][x]
        return ""

    def put(self, r: int, x: int, ch: str) -> None:
        row = self.rows[r]
        self.rows[r] = row[:x] + ch + row[x + 1:]
        self.version += 1

    def seen(self, x: int) -> bool:
        """World column ``x`` is in the view."""
        return 0 <= x - self.left < self.width


ARC = (1, 2, 2, 1)   # a jump's rows above the ground, turn by turn


def jump_text(arc: Sequence[int] = ARC) -> str:
    """A jump as the prompt says it."""
    return f"up to {max(arc)} rows high for {len(arc)} turns"


class Leap:
    """A jump off the ground line: ``start(tick)`` (only from the ground) lifts the jumper by
    ``arc[i]`` rows on the i-th tick after, then lands it; ``lift(tick)`` is the rows above the
    ground now (0: on it)."""
    __slots__ = ("arc", "since")

    def __init__(self, arc: Sequence[int] = ARC) -> None:
        self.arc, self.since = tuple(arc), -len(arc) - 1

    def start(self, tick: int) -> bool:
        if self.lift(tick):
            return False
        self.since = tick
        return True

    def lift(self, tick: int) -> int:
        i = tick - self.since
        return self.arc[i] if 0 <= i < len(self.arc) else 0

    def land(self) -> None:
        self.since = -len(self.arc) - 1


def fall(things: list, r: int, c: int, floor: int) -> tuple[bool, list]:
    """Drop each thing (``.r``, ``.c``) a row: True when one comes down on (``r``, ``c``) (the
    player's cell), and the things that reached row ``floor``; ``things`` keeps the rest."""
    hit, landed, kept = False, [], []
    for t in things:
        t.r += 1
        if t.r == r and t.c == c:
            hit = True
        elif t.r >= floor:
            landed.append(t)
        else:
            kept.append(t)
    things[:] = kept
    return hit, landed


class ScrollTask(ArcadeTask):
    """An ``ArcadeTask`` on ``self.course`` (made in ``_setup``): the field is the course's view
    with the movers drawn in: each group of ``_movers()`` (things with ``.r`` and ``.c``, a world
    column, and the group's glyph), then ``_marks()`` (row, world column, glyph), the later on
    top; the HUD's extra text is ``note_text()``, remade only when ``note_key()`` changes."""
    _key = None

    def _movers(self):
        return ()

    def _marks(self):
        return ()

    def _grid(self) -> list[str]:
        course = self.course
        rows = course.view()
        left, w, back, h = course.left, course.width, course.backward, len(rows)
        for things, glyph in self._movers():
            for t in things:
                c, r = t.c - left, t.r
                if 0 <= c < w and 0 <= r < h:
                    if back:
                        c = w - 1 - c
                    line = rows[r]
                    rows[r] = line[:c] + glyph + line[c + 1:]
        for r, x, glyph in self._marks():
            c = x - left
            if 0 <= c < w and 0 <= r < h:
                if back:
                    c = w - 1 - c
                line = rows[r]
                rows[r] = line[:c] + glyph + line[c + 1:]
        return rows

    def lost(self, why: str) -> bool:
        """``lose_life(why)``, then True: the turn stops here whether or not lives remain."""
        self.lose_life(why)
        return True

    def note_key(self):
        raise NotImplementedError

    def note_text(self) -> str:
        raise NotImplementedError

    def _extra_hud(self) -> str:
        key = self.note_key()
        if key != self._key:
            self._key, self._note = key, self.note_text()
        return self._note
