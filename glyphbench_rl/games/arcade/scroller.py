"""Scrolling worlds for arcade games (river raid, skiing, enduro, side-scrolling shooters).

The visible window is a ``Strip``: row strings that hold the scenery and everything that rides
with it (banks, obstacles, gates, parked cars). Each scroll drops one edge line and brings in a
fresh one at the opposite edge from a ``make`` callback (the game's spawner), so the world moves
while the player stays put on its axis; drawing is the strip's rows plus a few movers::

    strip = Strip(rows, axis="down")        # or "up", "left" (rows enter top/bottom/right)
    gone = strip.scroll(self._new_row())    # the line that left the window (what was passed)
    if strip.get(r, c) == OBSTACLE: ...     # things are read and cleared in place
    strip.put(r, c, EMPTY)

``Channel`` is a river or road whose two banks wander a column at a time between a narrowest
and a widest width (``Channel.next()`` gives the next line's banks); ``Pacer`` times scrolls and
spawns by tick (``every`` ticks, or a variable ``period`` for a speed).
"""

from __future__ import annotations

from ...core.actions import ActionSet
from ...core.params import require
from .bodies import Gun
from .engine import EMPTY


class Strip:
    """The window on a scrolling world: ``rows`` of equal width. ``scroll(line)`` moves the world
    one cell: "down" inserts ``line`` (a row) at the top and drops the bottom row, "up" appends
    it at the bottom and drops the top row, "left" appends ``line`` (one char per row, a string)
    at the right edge and drops the left column. It returns what left the window; ``push(line)``
    is the same move for a caller that does not need that."""
    __slots__ = ("rows", "axis", "shifts")

    def __init__(self, rows: list[str], axis: str = "down") -> None:
        if axis not in ("down", "up", "left"):
            raise ValueError(f"axis {axis!r}")
        self.rows, self.axis, self.shifts = list(rows), axis, 0

    def scroll(self, line: str) -> str:
        self.shifts += 1
        rows = self.rows
        if self.axis == "down":
            rows.insert(0, line)
            return rows.pop()
        if self.axis == "up":
            rows.append(line)
            return rows.pop(0)
        gone = "".join([row[0] for row in rows])      # (a list joins faster than a generator)
        self.rows = [row[1:] + ch for row, ch in zip(rows, line)]
        return gone

    def push(self, line: str) -> None:
        """``scroll`` for a caller that does not need what left (sideways, that is a cost)."""
        if self.axis == "left":
            self.shifts += 1
            self.rows = [row[1:] + ch for row, ch in zip(self.rows, line)]
        else:
            self.scroll(line)

    def preroll(self, n: int, make) -> None:
        """Scroll ``n`` fresh lines in before play starts (what leaves is not counted)."""
        for _ in range(n):
            self.scroll(make())

    def get(self, r: int, c: int) -> str:
        if 0 <= r < len(self.rows):
            row = self.rows[r]
            if 0 <= c < len(row):
                return row[c]
        return ""

    def put(self, r: int, c: int, ch: str) -> None:
        row = self.rows[r]
        self.rows[r] = row[:c] + ch + row[c + 1:]


class Channel:
    """A river or road between two banks inside a field ``width`` wide: the water (or tarmac)
    spans columns ``left..right``; ``next(draws)`` lets each bank wander by at most one column
    (with probability ``wander``) while the span stays within [narrow, wide] cells and a
    one-cell bank remains on each side."""
    __slots__ = ("width", "narrow", "wide", "wander", "left", "right", "texts")

    def __init__(self, width: int, narrow: int, wide: int, wander: float = 0.3) -> None:
        self.width, self.narrow, self.wide, self.wander = width, narrow, min(wide, width - 2), wander
        span = self.wide
        self.left = (width - span) // 2
        self.right = self.left + span - 1
        self.texts: dict = {}             # (bank, water, left, right) -> the line's text

    def next(self, draws) -> tuple[int, int]:
        if self.narrow < self.wide and draws.random() < self.wander:
            side = draws.random()
            step = 1 if draws.random() < 0.5 else -1
            if side < 0.5:
                left = self.left + step
                if 1 <= left and self.narrow <= self.right - left + 1 <= self.wide:
                    self.left = left
            else:
                right = self.right + step
                if right <= self.width - 2 and self.narrow <= right - self.left + 1 <= self.wide:
                    self.right = right
        return self.left, self.right

    def step(self, draws, bank: str) -> tuple[int, int, str]:
        """The next line: its banks (``next``) and its text (``line``)."""
        left, right = self.next(draws)
        return left, right, self.line(bank)

    def line(self, bank: str, water: str = EMPTY) -> str:
        """This line as text: banks outside the span, water inside (made once per span)."""
        key = (bank, water, self.left, self.right)
        text = self.texts.get(key)
        if text is None:
            left, right = self.left, self.right
            text = self.texts[key] = (bank * left + water * (right - left + 1)
                                      + bank * (self.width - 1 - right))
        return text


class Pacer:
    """When things happen by tick: ``due(tick)`` is true every ``period`` ticks (0 never);
    ``period`` may change (a speed) and counts from the last time it was due."""
    __slots__ = ("period", "last")

    def __init__(self, period: int) -> None:
        self.period, self.last = period, 0

    def due(self, tick: int) -> bool:
        if self.period > 0 and tick - self.last >= self.period:
            self.last = tick
            return True
        return False


def put_one(line: str, c: int, ch: str) -> str:
    """``line`` with ``ch`` at column ``c``."""
    return line[:c] + ch + line[c + 1:]


def fly_shots(gun: Gun, hit, strike, rows: list[str] | None = None, clear: str = "") -> None:
    """``gun.advance(hit)`` for shots that move, at most one cell a step on each axis (every
    shot here), without a generator: each shot steps cell by cell, ``speed`` cells, and stops
    at the first cell where ``hit(r, c)`` is true; ``strike(r, c)`` then hears of it at once (as
    a caller looping over ``advance`` would) and returns True to stop the volley (the episode
    ended: like a caller leaving the loop, the gun keeps its shots as they stand). With ``hit``
    None, a shot stops off the ``rows`` (above or below them: shots fly inside their columns)
    or on a glyph not in ``clear``, found in the loop (no call per cell)."""
    kept, speed, h = [], gun.speed, len(rows) if rows is not None else 0
    for shot in gun.shots:
        dr, dc, r, c = shot.dr, shot.dc, shot.r, shot.c
        struck = False
        for _ in range(speed):
            r += dr
            c += dc
            if (not 0 <= r < h or rows[r][c] not in clear) if hit is None else hit(r, c):
                struck = True
                break
            shot.r, shot.c = r, c
        shot.data -= speed
        if struck:
            shot.alive = False
            if strike(r, c):
                return
        elif shot.data <= 0:
            shot.alive = False
        else:
            kept.append(shot)
    gun.shots = kept


def stamp(rows: list[str], things, glyph: str) -> None:
    """Draw ``glyph`` on ``rows`` at each thing's (``.r``, ``.c``), skipping cells off the rows
    (cheaper than a (row, col, glyph) per mover through ``_sprites``)."""
    h, w = len(rows), len(rows[0])
    for t in things:
        r, c = t.r, t.c
        if 0 <= c < w and 0 <= r < h:
            line = rows[r]
            rows[r] = line[:c] + glyph + line[c + 1:]


class Camera:
    """A view ``view`` columns wide on a world ``world`` columns around (it wraps; with
    ``wrap=False`` a corridor whose ends stop the view), kept centred on a followed column:
    ``follow(x)`` moves the view, ``screen(x)`` is a world column's place in the view (-1 when
    out of it). A world no wider than the view never moves."""
    __slots__ = ("world", "view", "left", "wrap")

    def __init__(self, world: int, view: int, wrap: bool = True) -> None:
        self.world, self.view, self.left, self.wrap = world, view, 0, wrap

    def follow(self, x: int) -> None:
        if self.world > self.view:
            left = x - self.view // 2
            self.left = left % self.world if self.wrap else min(max(0, left), self.world - self.view)

    def screen(self, x: int) -> int:
        c = (x - self.left) % self.world
        return c if c < self.view else -1


FLY_ACTIONS = ActionSet([("NOOP", "hover"), ("LEFT", "fly one cell left (face left)"),
                         ("RIGHT", "fly one cell right (face right)"), ("UP", "climb one row"),
                         ("DOWN", "descend one row"), ("FIRE", "shoot the way you face")], noop="NOOP")
FLY_MOVES = ((0, 0), (0, -1), (0, 1), (-1, 0), (1, 0), (0, 0))
FLY_FIRE, FLY_UP = 5, 3
RIGHT_ME, LEFT_ME, FLY_SHOT, GROUND = ">", "<", "-", "_"


class Flyer:
    """Mixin for an ``ArcadeTask`` whose ship flies over a ground row on a wrapping world the
    view follows (Chopper Command, Defender): its Params have ``world`` and ``reach``; it faces
    the way it last moved and FIRE (``FLY_ACTIONS``) shoots that way. ``fly_start(r)`` in
    ``_setup``; ``fly(action, lowest)`` moves and fires; in ``_grid``, ``fly_view()`` moves the
    camera and gives the rows to draw on, ``fly_draw(rows)`` draws the shots and the ship (a world
    column x is at view column ``(x - left) % world``, as ``Camera.screen`` has it)."""

    def fly_fields(self) -> dict:
        p = self.params
        return {"scroll_text": (f" (the {p.width}-column view follows you; it wraps around)"
                                if p.world > p.width else "")}

    def _still(self) -> list[str]:
        p = self.params
        return [EMPTY * p.width] * (p.height - 1) + [GROUND * p.width]

    def fly_start(self, r: int) -> None:
        p = self.params
        self.r, self.x, self.face = r, p.world // 2, 1
        self.camera = Camera(p.world, p.width)
        self.gun = Gun(cooldown=1, speed=2, reach=p.reach, limit=1)

    def fly(self, action: int, lowest: int) -> None:
        dr, dc = FLY_MOVES[action]
        if dc:
            self.face = dc
        r = self.r + dr
        self.r = 0 if r < 0 else r if r < lowest else lowest
        self.x = (self.x + dc) % self.params.world
        if action == FLY_FIRE:
            self.gun.fire(self.tick, self.r, self.x, 0, self.face, FLY_SHOT)

    def fly_view(self) -> tuple[list[str], int, int, int]:
        """The camera follows you; then the still rows to draw on (a copy), the view's first
        world column, the world's width and the view's width (the grid counted, for
        ``ArcadeTask._draw``)."""
        self._grids += 1
        cam = self.camera
        cam.follow(self.x)
        return self.still[:], cam.left, self.params.world, cam.view

    def fly_draw(self, rows: list[str]) -> list[str]:
        """Draw the shots (bar one still on your cell) and the ship on ``rows``, through
        ``self.camera`` (moved to follow you by the caller); all fly inside the rows, each row
        remembered (``ArcadeTask._draw``)."""
        left, w, x, view = self.camera.left, self.params.world, self.x, len(rows[0])
        drawn = self._drawn
        for s in self.gun.shots:
            if s.c != x:
                c = (s.c - left) % w
                if c < view:
                    key = (rows[s.r], c, FLY_SHOT)
                    rows[s.r] = drawn.get(key) or self._draw(key)
        c = (x - left) % w
        if c < view:
            key = (rows[self.r], c, RIGHT_ME if self.face > 0 else LEFT_ME)
            rows[self.r] = drawn.get(key) or self._draw(key)
        return rows


def banks_fit(p) -> None:
    """``check`` for Params with a ``Channel`` (``narrow``, ``wide``) inside ``width``."""
    require(p.narrow <= p.wide <= p.width - 2, "wide", "fit the field with banks", p.wide)
