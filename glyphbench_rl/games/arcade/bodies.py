"""Moving things for arcade games: bodies with a velocity, swept motion, wrapping, shots with a
range and a cooldown, formations that sweep and descend, scripted opponents and countdowns.

Everything is plain Python on ints (no numpy per turn)::

    ball = Body(5, 8, dr=1, dc=-1)
    hit = sweep(ball, lambda r, c: (r, c) in paddle)   # cell by cell, stops at the first hit
    gun = Gun(cooldown=1, speed=2, reach=12, limit=1)
    if action == FIRE: gun.fire(turn, row - 1, col, dr=-1, dc=0)
    for shot, cell in gun.advance(lambda r, c: (r, c) in targets): ...
    wave = Formation(rows=2, cols=4, top=1, left=2, gap=2, width=14, sweep=5, advance=24)
    wave.tick(turn)                                     # sweep, step down at an edge or on time
    step = track(paddle_r, ball.r, chance, draws)       # -1, 0 or +1 toward a target
"""

from __future__ import annotations

from typing import Callable, Iterator

Hit = Callable[[int, int], bool]


class Body:
    """A thing at (r, c) moving (dr, dc) cells a turn."""
    __slots__ = ("r", "c", "dr", "dc", "glyph", "alive", "data")

    def __init__(self, r: int, c: int, dr: int = 0, dc: int = 0, glyph: str = "*", data=None) -> None:
        self.r, self.c, self.dr, self.dc, self.glyph, self.alive, self.data = r, c, dr, dc, glyph, True, data


def sweep(body: Body, hit: Hit, steps: int = 1) -> tuple[int, int] | None:
    """Move ``body`` by its velocity ``steps`` times, one cell at a time along the dominant axis
    (so a fast body cannot jump over a thin thing); stop on the first cell where ``hit`` is true
    and return it (the body stays on the last free cell), else None."""
    dr, dc = body.dr, body.dc
    if not dr or not dc:                         # the usual case: straight along an axis (or still)
        if dc:
            sr, sc, n = 0, (1 if dc > 0 else -1), (dc if dc > 0 else -dc)
        else:
            sr, sc, n = (1 if dr > 0 else -1), 0, (dr if dr > 0 else -dr)
        r, c = body.r, body.c
        for _ in range(n * steps):
            r += sr
            c += sc
            if hit(r, c):
                return r, c
            body.r, body.c = r, c
        return None
    n = max(abs(dr), abs(dc)) * steps
    if n == 1:                                   # one diagonal cell
        r, c = body.r + dr, body.c + dc
        if hit(r, c):
            return r, c
        body.r, body.c = r, c
        return None
    r0, c0, tr, tc = body.r, body.c, dr * steps, dc * steps
    for i in range(1, n + 1):
        r = r0 + (tr * i // n if tr >= 0 else -(-tr * i // n))
        c = c0 + (tc * i // n if tc >= 0 else -(-tc * i // n))
        if hit(r, c):
            return r, c
        body.r, body.c = r, c
    return None


def wrap(value: int, size: int) -> int:
    """A coordinate on a wrapping field (asteroids, scrolling worlds)."""
    return value % size


class Gun:
    """Shots fired along (dr, dc) at ``speed`` cells a turn for ``reach`` cells, at most
    ``limit`` in flight and one every ``cooldown`` turns."""
    __slots__ = ("cooldown", "speed", "reach", "limit", "shots", "ready")

    def __init__(self, cooldown: int = 1, speed: int = 1, reach: int = 99, limit: int = 1) -> None:
        self.cooldown, self.speed, self.reach, self.limit = cooldown, speed, reach, limit
        self.shots: list[Body] = []
        self.ready = 0

    def ready_at(self, turn: int) -> bool:
        return turn >= self.ready and len(self.shots) < self.limit

    def fire(self, turn: int, r: int, c: int, dr: int, dc: int, glyph: str = "|") -> Body | None:
        if turn < self.ready or len(self.shots) >= self.limit:
            return None
        self.ready = turn + self.cooldown
        shot = Body(r, c, dr, dc, glyph, data=self.reach)
        self.shots.append(shot)
        return shot

    def advance(self, hit: Hit) -> Iterator[tuple[Body, tuple[int, int] | None]]:
        """Move every shot; yield (shot, cell) for each that hit something (the shot is gone)
        and (shot, None) for each that ran out of reach. ``hit`` decides what stops a shot; the
        caller removes walls and the field's edges through it too."""
        kept, speed = [], self.speed
        for shot in self.shots:
            cell = sweep(shot, hit, speed) if (shot.dr or shot.dc) else None
            shot.data -= speed
            if cell is not None:
                shot.alive = False
                yield shot, cell
            elif shot.data <= 0:
                shot.alive = False
                yield shot, None
            else:
                kept.append(shot)
        self.shots = kept


class Formation:
    """A block of ``rows`` x ``cols`` members ``gap`` columns apart that slides one column every
    ``sweep`` turns within a field ``width`` wide (a 1-cell margin), steps down a row when it
    meets an edge, and also every ``advance`` turns (0: only at edges). What depends only on
    who is alive is cached relative to the block's corner (rebuilt on ``kill``), so a move
    costs nothing; ``version`` counts moves and kills, for callers caching what they draw."""
    __slots__ = ("top", "left", "gap", "width", "sweep", "advance", "dx", "alive", "rows", "cols",
                 "version", "_shape", "_drawn")

    def __init__(self, rows: int, cols: int, top: int, left: int, gap: int, width: int,
                 sweep: int, advance: int = 0) -> None:
        self.rows, self.cols, self.top, self.left, self.gap = rows, cols, top, left, gap
        self.width, self.sweep, self.advance, self.dx = width, sweep, advance, 1
        self.alive = {(i, j) for i in range(rows) for j in range(cols)}
        self.version, self._shape, self._drawn = 0, None, None

    def kill(self, member: tuple[int, int]) -> None:
        self.alive.discard(member)
        self.version += 1
        self._shape = self._drawn = None

    def shape(self):
        """(pattern per member row, lowest member row per column, lowest and highest column,
        lowest row), relative to the corner."""
        if self._shape is None:
            low: dict[int, int] = {}
            for i, j in self.alive:
                if low.get(j, -1) < i:
                    low[j] = i
            span = (self.cols - 1) * self.gap + 1
            pats = {}
            for i in {i for i, _ in self.alive}:
                line = ["."] * span
                for j in range(self.cols):
                    if (i, j) in self.alive:
                        line[j * self.gap] = "\0"
                pats[i] = "".join(line).rstrip(".")
            cols = sorted(low)
            self._shape = (pats, [(low[j], j) for j in cols], cols[0] if cols else 0,
                           cols[-1] if cols else 0, max(low.values(), default=-1))
        return self._shape

    def member_at(self, r: int, c: int) -> tuple[int, int] | None:
        j, rem = divmod(c - self.left, self.gap)
        m = (r - self.top, j)
        return m if not rem and m in self.alive else None

    def cells(self) -> dict[tuple[int, int], tuple[int, int]]:
        """Field cell -> member (row, column) for every live member."""
        t, l, g = self.top, self.left, self.gap
        return {(t + i, l + j * g): (i, j) for i, j in self.alive}

    def lines(self, glyph: str, empty: str) -> dict[int, str]:
        """Field row -> the row's text with the members drawn on ``empty``."""
        drawn = self._drawn   # (glyph, empty, each member row's pattern drawn), until a kill
        if drawn is None or drawn[0] != glyph or drawn[1] != empty:
            drawn = self._drawn = (glyph, empty, {i: pat.replace(".", empty).replace("\0", glyph)
                                                  for i, pat in self.shape()[0].items()})
        t, w, pad = self.top, self.width, empty * self.left
        return {t + i: (pad + line).ljust(w, empty)[:w] for i, line in drawn[2].items()}

    def front(self) -> list[tuple[int, int]]:
        """The lowest live member's cell in each column, left to right (who drops bombs)."""
        t, l, g = self.top, self.left, self.gap
        return [(t + i, l + j * g) for i, j in self.shape()[1]]

    def bottom(self) -> int:
        if not self.alive:
            return -1
        return self.top + (self._shape or self.shape())[4]   # (no call while the shape stands)

    def tick(self, turn: int) -> None:
        down = self.advance and turn % self.advance == 0
        if turn % self.sweep == 0 and self.alive:
            _, _, lo, hi, _ = self.shape()
            lo, hi = self.left + lo * self.gap, self.left + hi * self.gap
            if (hi + self.dx > self.width - 2) or (lo + self.dx < 1):
                self.dx = -self.dx
                down = True
            else:
                self.left += self.dx
                self.version += 1
        if down:
            self.top += 1
            self.version += 1


def track(pos: int, target: int, chance: float, draws) -> int:
    """A scripted opponent's step on one axis: toward ``target`` with probability ``chance``
    (one uniform draw from ``draws``), else stay."""
    if pos == target or draws.random() >= chance:
        return 0
    return 1 if target > pos else -1


def chase(r: int, c: int, tr: int, tc: int) -> tuple[int, int]:
    """One step closing on (tr, tc) along the dominant axis (rows on a tie)."""
    dr, dc = tr - r, tc - c
    if abs(dr) >= abs(dc) and dr:
        return (1 if dr > 0 else -1), 0
    if dc:
        return 0, (1 if dc > 0 else -1)
    return 0, 0


class Countdown:
    """Fuel, oxygen or a clock: ``tick()`` takes one and says True when it runs out;
    ``refill()`` tops it up."""
    __slots__ = ("full", "left")

    def __init__(self, full: int) -> None:
        self.full = self.left = full

    def tick(self, amount: int = 1) -> bool:
        left = self.left - amount
        self.left = left if left > 0 else 0   # (max written out: this runs every turn)
        return self.left == 0

    def refill(self) -> None:
        self.left = self.full
