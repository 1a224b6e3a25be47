"""The free-flying / shooter engine: bodies that move by a velocity each turn, swept collisions,
guns with cooldown and range, and spawners (starpilot, bossfight, plunder, caveflyer, bigfish,
dodgeball).

A game is thin: it builds a ``World`` from its level rows in ``_setup`` (``self.start``), adds
``Body`` objects, spawns and steers them in ``_think`` and applies its rules in ``_hit``.

**Bodies** (``Body``): a glyph, a cell (``r``, ``c``), a velocity (``vr``, ``vc``: rows and
columns per move; rows grow downward), ``hp`` (hit points, or a fish's size), ``side`` (one bit:
``PLAYER``, ``SHOT``, ``FOE``, ``FOE_SHOT``, ``ITEM``, ``FRIEND``, or a game's own bit) and
``hits`` (the sides it collides with; a pair collides when either one's ``hits`` names the
other's side), ``reach`` (cells it may still travel: a shot's range), ``period``/``phase`` (it
moves on turns where ``turn % period == phase``: slow bodies), ``edge`` (what the world's edge
does: ``GONE`` removes it, ``WRAP`` wraps columns, ``STOP`` blocks like a wall) and ``data`` (the
game's own). ``alive`` false (a game's verdict) or ``spent`` (its flight ended: off the world
or out of reach; its events this turn still count) removes it at the end of the turn.

**Movement is swept** (``World.step``): a body moving ``n`` cells a turn visits every cell on
its way, one cell per ``1/n`` of the turn. Two colliding bodies meet when they share a cell at the
same moment of the turn, or swap cells at the same moment (crossing heads-on); still bodies hold
their cell the whole turn. So a shot moving 2 cells cannot jump over an enemy, and two bodies
that cross in one turn collide; a body following another at the same speed does not. A body
whose next cell is solid (a ``World.solid`` character of the rows) stops before it, with
``bump`` set to that cell. ``World.step`` returns the turn's events in time order: ``(a, b)``
for a collision (in the order the two were added: ``pair(a, b, side)`` sorts them),
``(a, None)`` for ``a`` bumping into a wall (or a ``STOP`` edge).

**Shooter tasks** (``ShooterTask``): the five Procgen actions plus ``FIRE`` (``FIRE_ACTIONS``,
or ``with_fire(description)``; a game without a gun sets ``ACTIONS`` to the engine's five, and
one with fewer moves uses ``only(...)`` with an ``action_map`` back to these indices);
the player is a ``Body`` (``self.player``) whose velocity is the move of this turn; it is drawn
as the Procgen arrow (``self.pos`` follows it). One turn (``_act``) is: the player's move or
shot, ``_think()`` (spawn, steer, enemy fire), the world's swept step, ``_hit(a, b)`` for each
event whose bodies still live (in time order, stopping when the episode ends), ``_left(body)``
for each body that left the world, and ``_after()``. The HUD reports the player's velocity and
the moving bodies (``shows_motion``).

**Spawners** (``Spawner``): a period with per-spawn jitter drawn from a named stream
(``self.stream("name")``), and lane picks from it; the level generator (``_setup``'s rng)
chooses the periods per seed.

A sketch (the four games here are full examples)::

    class Game(ShooterTask):
        solid = "#"                  # still characters that stop bodies
        fire_dir = (0, 1)            # or None: the way the player last moved (start_dir at first)
        player_hits = FOE | ITEM     # what touching the player means something
        def _setup(self, rng):
            self.start(rows, (r, c), Gun("-", speed=2, reach=8, cooldown=2))
            self.world.add(Body("E", r, 19, 0, -1, side=FOE, hits=PLAYER))
            self.waves = Spawner(self.stream("waves"), period=int(rng.integers(3, 6)), jitter=1)
        def _think(self):
            if self.waves.due(self.turn): ...     # add bodies in self.waves.pick(lanes)
        def _hit(self, a, b):
            if (shot := pair(a, b, SHOT)): ...    # shot[0] the shot, shot[1] what it hit
            elif pair(a, b, PLAYER): ...          # something touched the player
"""

from __future__ import annotations

from math import lcm
from typing import Any, ClassVar, Iterable, Sequence

import numpy as np

from ...core.actions import ActionSet
from .engine import ACTIONS, ARROWS, DELTAS, MAX_MOVERS, ProcgenTask, velocity_text

Cell = tuple[int, int]

# sides: one bit each (games may define more bits above FRIEND)
PLAYER, SHOT, FOE, FOE_SHOT, ITEM, FRIEND = 1, 2, 4, 8, 16, 32
# what the world's edge does to a body
GONE, WRAP, STOP = 0, 1, 2
FAR = 1 << 30   # the reach of a body that flies forever
_KEY = 1 << 16  # a cell's int key is r * _KEY + c (World.step)
_NO_TRACK: tuple[tuple[int, ...], int] = ((), 1)   # a dead body's track
FIRE = len(ACTIONS)   # the FIRE action's index

FIRE_ACTIONS = ActionSet([(a.name, a.description) for a in ACTIONS] + [("FIRE", "shoot")],
                         noop="NOOP")


_VELOCITY_TEXT: dict[tuple[int, int], str] = {}


def _velocity_text(vr: int, vc: int) -> str:
    text = _VELOCITY_TEXT.get((vr, vc))
    if text is None:
        text = _VELOCITY_TEXT[vr, vc] = velocity_text(vr, vc)
    return text


# HUD words of movers, remembered by their (distance, dr, dc, glyph, vr, vc) entry
_WORDS: dict[tuple[int, int, int, str, int, int], str] = {}


def with_fire(description: str) -> ActionSet:
    """The five Procgen actions plus FIRE described as ``description``."""
    return ActionSet([(a.name, a.description) for a in ACTIONS] + [("FIRE", description)], noop="NOOP")


def only(actions: ActionSet, names: Sequence[str], **described: str) -> ActionSet:
    """``actions`` restricted to ``names`` (new descriptions by name in ``described``). The
    game maps the smaller set's indices back (``ShooterTask.action_map``)."""
    kept = [(a.name, described.get(a.name, a.description)) for a in actions if a.name in names]
    return ActionSet(kept, noop="NOOP" if "NOOP" in names else None)


class Body:
    """A moving (or still) thing of the world; see the module notes for the fields."""

    __slots__ = ("glyph", "r", "c", "vr", "vc", "hp", "side", "hits", "reach", "period",
                 "phase", "edge", "alive", "spent", "bump", "data")

    def __init__(self, glyph: str, r: int, c: int, vr: int = 0, vc: int = 0, *, side: int = FOE,
                 hits: int = 0, hp: int = 1, reach: int = FAR, period: int = 1, phase: int = 0,
                 edge: int = GONE, data: Any = None) -> None:
        self.glyph, self.r, self.c, self.vr, self.vc = glyph, r, c, vr, vc
        self.side, self.hits, self.hp, self.reach = side, hits, hp, reach
        self.period, self.phase, self.edge, self.data = period, phase, edge, data
        self.alive = True
        self.spent = False   # its flight ends this turn (off a GONE edge, or out of reach)
        self.bump: Cell | None = None

    @property
    def cell(self) -> Cell:
        return self.r, self.c

    def moves_on(self, turn: int) -> bool:
        return bool(self.vr or self.vc) and (self.period == 1 or turn % self.period == self.phase)

    def meets(self, other: "Body") -> bool:
        return bool(self.hits & other.side or other.hits & self.side)

    def __repr__(self) -> str:
        return f"Body({self.glyph!r}, {self.r}, {self.c}, v={self.vr},{self.vc}, hp={self.hp})"


def pair(a: Body, b: Body | None, side: int) -> tuple[Body, Body] | None:
    """A collision event's bodies as (the one on ``side``, the other), or None when neither
    is on ``side`` (or ``b`` is None: a bump). Events list bodies in the order they were added,
    so a game's ``_hit`` asks ``pair(a, b, SHOT)`` rather than trusting the order."""
    if b is None:
        return None
    if a.side & side:
        return a, b
    if b.side & side:
        return b, a
    return None


class World:
    """Still rows (strings; ``solid`` characters stop bodies) and the bodies moving over them."""

    def __init__(self, rows: Sequence[str], solid: str) -> None:
        self.rows = list(rows)
        self.height, self.width = len(self.rows), len(self.rows[0])
        self.solid = frozenset(solid)
        self.bodies: list[Body] = []

    # -- cells ------------------------------------------------------------------------------------
    def inside(self, r: int, c: int) -> bool:
        return 0 <= r < self.height and 0 <= c < self.width

    def is_solid(self, r: int, c: int) -> bool:
        return self.rows[r][c] in self.solid

    def put(self, r: int, c: int, ch: str) -> None:
        """Change one still cell (a wall shot away, a door)."""
        row = self.rows[r]
        self.rows[r] = row[:c] + ch + row[c + 1:]

    def at(self, r: int, c: int) -> list[Body]:
        return [b for b in self.bodies if b.alive and b.r == r and b.c == c]

    def free(self, r: int, c: int) -> bool:
        """Inside, not solid and holding no live body."""
        return self.inside(r, c) and not self.is_solid(r, c) and not self.at(r, c)

    # -- bodies -----------------------------------------------------------------------------------
    def add(self, body: Body) -> Body:
        self.bodies.append(body)
        return body

    def count(self, side: int) -> int:
        return sum(1 for b in self.bodies if b.alive and b.side & side)

    def cull(self) -> list[Body]:
        """Drop dead and spent bodies (after the turn's events: a shot that flies off the
        world still hits what it met on the way); returns the live ones that left over a
        ``GONE`` edge this turn."""
        for b in self.bodies:
            if b.spent or not b.alive:
                break
        else:
            return []          # (most turns end none: keep the list)
        gone = [b for b in self.bodies if b.spent and b.alive and not self.inside(b.r, b.c)]
        self.bodies = [b for b in self.bodies if b.alive and not b.spent]
        return gone

    def track(self, body: Body) -> tuple[list[Cell], int]:
        """The cells a moving ``body`` visits this turn (its own first) and the step (1-based)
        at which it bumped into something solid or a ``STOP`` edge (0 if none); sets ``bump``
        and ``spent`` (off a ``GONE`` edge, or out of reach) and uses up ``reach``."""
        r, c = body.r, body.c
        path = [(r, c)]
        vr, vc = body.vr, body.vc
        n = max(abs(vr), abs(vc))
        rows, solid, width, height = self.rows, self.solid, self.width, self.height
        straight = vr in (0, n, -n) and vc in (0, n, -n)    # along an axis or a diagonal
        ur, uc = vr // n, vc // n
        for k in range(1, min(n, body.reach) + 1):
            if straight:
                nr, nc = r + ur * k, c + uc * k
            else:
                nr, nc = r + int(vr * k / n), c + int(vc * k / n)
            if not 0 <= nc < width:
                if body.edge == WRAP:
                    nc %= width
                elif body.edge == GONE:
                    body.spent = True
                    path.append((nr, nc))
                    break
                else:
                    body.bump = (nr, nc)
                    return path, k
            if not 0 <= nr < height:
                if body.edge == STOP:
                    body.bump = (nr, nc)
                    return path, k
                body.spent = True
                path.append((nr, nc))
                break
            if rows[nr][nc] in solid:
                body.bump = (nr, nc)
                return path, k
            path.append((nr, nc))
        body.reach -= len(path) - 1
        if body.reach <= 0:
            body.spent = True
        return path, 0

    def step(self, turn: int) -> list[tuple[Body, Body | None]]:
        """Move every live body by its velocity, swept; returns the turn's collisions and
        bumps in time order (see the module notes)."""
        # Cells are keyed as one int (``r * _KEY + c``): cheaper to build and hash than a
        # (row, column) tuple, and unique for any cell a body can reach (one step off the world
        # at most). Only cells visited by two bodies lead to the exact (slower) meeting test.
        timed: list[tuple[float, int, int, Body, Body | None]] = []
        where: dict[int, int] = {}            # cell -> the first body on it this turn
        crowd: dict[int, list[int]] = {}      # cells more than one body visits
        bodies = self.bodies
        # per body: (its cell keys this turn, cells a turn), or just its start key when it
        # moves at most one cell (built only for the few pairs that share a cell)
        tracks: list[tuple[Sequence[int], int] | int] = []
        add = tracks.append
        setdefault = where.setdefault
        rows, solid, height, width = self.rows, self.solid, self.height, self.width
        for i, b in enumerate(bodies):
            if not b.alive or b.spent:
                add(_NO_TRACK)
                continue
            b.bump = None
            r, c, vr, vc = b.r, b.c, b.vr, b.vc
            here = r * _KEY + c
            if (vr or vc) and (b.period == 1 or turn % b.period == b.phase):
                nr, nc = r + vr, c + vc
                if (vr == 0 or vc == 0) and -1 <= vr + vc <= 1 and b.reach > 1 \
                        and 0 <= nr < height and 0 <= nc < width and rows[nr][nc] not in solid:
                    b.r, b.c = nr, nc                        # the usual one-cell move
                    b.reach -= 1
                    there = nr * _KEY + nc
                    add(here)
                    j = setdefault(here, i)
                    if j != i:
                        crowd.setdefault(here, [j]).append(i)
                    j = setdefault(there, i)
                    if j != i:
                        crowd.setdefault(there, [j]).append(i)
                    continue
                n = max(abs(vr), abs(vc))
                keys = None
                if vr in (0, n, -n) and vc in (0, n, -n) and b.reach > n \
                        and 0 <= nr < height and 0 <= nc < width and 0 <= r < height and 0 <= c < width:
                    # a straight move of n cells (a fast shot) from and to cells inside the
                    # world (so all between are inside): its cells, unless one on the way is
                    # solid (then ``track`` finds the bump)
                    ur, uc = vr // n, vc // n
                    keys = [here]
                    for k in range(1, n + 1):
                        if rows[r + ur * k][c + uc * k] in solid:
                            keys = None
                            break
                        keys.append(here + (ur * k) * _KEY + uc * k)
                if keys is not None:
                    b.r, b.c = nr, nc
                    b.reach -= n
                else:
                    path, bumped = self.track(b)
                    if bumped:
                        timed.append((bumped / n, i, i, b, None))
                    b.r, b.c = path[-1]
                    keys = [pr * _KEY + pc for pr, pc in path]
                add((keys, n))
                for key in keys:
                    j = setdefault(key, i)
                    if j != i:
                        crowd.setdefault(key, [j]).append(i)
            else:
                add(here)
                j = setdefault(here, i)
                if j != i:
                    crowd.setdefault(here, [j]).append(i)
        if crowd:
            pairs = set()
            for here in crowd.values():
                for k, i in enumerate(here):
                    for j in here[k + 1:]:
                        if bodies[i].meets(bodies[j]):
                            pairs.add((i, j))
            for i, j in pairs:
                ti, tj = tracks[i], tracks[j]
                # (a one-cell or still body's track is its start key: it ends where it is now)
                if type(ti) is int:
                    ti = (ti, bodies[i].r * _KEY + bodies[i].c), 1
                if type(tj) is int:
                    tj = (tj, bodies[j].r * _KEY + bodies[j].c), 1
                moment = _meeting(*ti, *tj)
                if moment is not None:
                    timed.append((moment, i, j, bodies[i], bodies[j]))
        if not timed:
            return []
        if len(timed) > 1:
            timed.sort(key=lambda e: e[:3])   # by moment, then by the order bodies were added
        return [(a, b) for *_, a, b in timed]

    def sprites(self, skip: Body | None = None) -> list[tuple[int, int, str]]:
        return [(b.r, b.c, b.glyph) for b in self.bodies if b.alive and b is not skip]

    def movers(self, skip: Body | None = None) -> list[tuple[str, int, int, int, int]]:
        return [(b.glyph, b.r, b.c, b.vr, b.vc) for b in self.bodies
                if b.alive and b is not skip and (b.vr or b.vc)]


def _meeting(pa: Sequence[Cell], na: int, pb: Sequence[Cell], nb: int) -> float | None:
    """The first moment (a share of the turn) two tracks meet, or None: the same cell at the
    same moment, or swapped cells at the same moment. A track of ``n`` cells a turn is at its
    k-th cell from moment k/n (and stays at its last)."""
    sub = lcm(na, nb)
    la, lb = len(pa) - 1, len(pb) - 1
    a0, b0 = pa[0], pb[0]
    for s in range(1, sub + 1):
        a1, b1 = pa[min(s * na // sub, la)], pb[min(s * nb // sub, lb)]
        if a1 == b1 or (a1 == b0 and b1 == a0 and a1 != a0):
            return s / sub
        a0, b0 = a1, b1
    return None


class Gun:
    """Shots of ``glyph`` flying ``speed`` cells a turn for ``reach`` cells, one every
    ``cooldown`` turns at most."""

    __slots__ = ("glyph", "speed", "reach", "cooldown", "ready", "side", "hits")

    def __init__(self, glyph: str, speed: int, reach: int, cooldown: int, *, side: int = SHOT,
                 hits: int = FOE) -> None:
        self.glyph, self.speed, self.reach, self.cooldown = glyph, speed, reach, cooldown
        self.side, self.hits = side, hits
        self.ready = 0   # the first turn it may fire

    def fire(self, world: World, r: int, c: int, dr: int, dc: int, turn: int) -> Body | None:
        """A shot from (r, c) heading (dr, dc) (unit steps), or None while cooling down. The
        shot starts on the shooter's cell and moves this same turn."""
        if turn < self.ready:
            return None
        self.ready = turn + self.cooldown
        return world.add(Body(self.glyph, r, c, dr * self.speed, dc * self.speed, side=self.side,
                              hits=self.hits, reach=self.reach))


class Spawner:
    """Says when to spawn: every ``period`` turns, each gap shifted by up to ``jitter`` either
    way, from its own random stream (which it also lends for lane and kind picks)."""

    __slots__ = ("rng", "period", "jitter", "next")

    def __init__(self, rng: np.random.Generator, period: int, jitter: int = 0, first: int = 1) -> None:
        self.rng, self.period, self.jitter, self.next = rng, period, jitter, first

    def due(self, turn: int) -> bool:
        if turn < self.next:
            return False
        gap = self.period + (self.below(2 * self.jitter + 1) - self.jitter if self.jitter else 0)
        self.next = turn + max(1, gap)
        return True

    def pick(self, options: Sequence[Any]) -> Any:
        return options[self.below(len(options))]

    def below(self, n: int) -> int:
        """A uniform int in [0, n) (one float draw: cheaper than ``integers`` each turn)."""
        return int(self.rng.random() * n)

    def chance(self, p: float) -> bool:
        return bool(self.rng.random() < p)


class ShooterTask(ProcgenTask):
    """A Procgen game of free-moving bodies and shots (see the module notes)."""

    ACTIONS = FIRE_ACTIONS
    shows_motion = True
    solid: ClassVar[str] = ""              # still characters that stop bodies
    player_hits: ClassVar[int] = FOE | FOE_SHOT | ITEM | FRIEND
    player_edge: ClassVar[int] = STOP
    fire_dir: ClassVar[Cell | None] = None   # a fixed shot direction, or None: the facing one
    start_dir: ClassVar[Cell] = (-1, 0)      # the facing direction before any move
    action_map: ClassVar[tuple[int, ...] | None] = None   # own action index -> 0..4 or FIRE

    world: World
    player: Body
    gun: Gun | None

    def __init_subclass__(cls, **kwargs) -> None:
        if "shows_motion" not in cls.__dict__:   # every shooter game gets the motion sentence
            cls.shows_motion = cls.shows_motion
        super().__init_subclass__(**kwargs)

    def start(self, rows: Sequence[str], cell: Cell, gun: Gun | None = None) -> None:
        """Call from ``_setup``: the level's still rows, the player's cell and gun."""
        self.world = World(rows, self.solid)
        self.player = self.world.add(Body("@", *cell, side=PLAYER, hits=self.player_hits,
                                          edge=self.player_edge))
        self.place_player(cell)
        self.gun = gun
        self.aim = self.start_dir
        self.shots = 0

    # -- hooks ------------------------------------------------------------------------------------
    def _think(self) -> None:
        """Spawn, steer and let enemies fire (before the world moves)."""

    def _hit(self, a: Body, b: Body | None) -> None:
        """``a`` met ``b`` (or bumped into ``a.bump`` when ``b`` is None)."""

    def _left(self, body: Body) -> None:
        """``body`` left the world over a ``GONE`` edge."""

    def _after(self) -> None:
        """After the turn's events."""

    # -- the turn ----------------------------------------------------------------------------------
    def _act(self, action: int) -> None:
        if self.action_map is not None:
            action = self.action_map[action]
        p = self.player
        if action == FIRE:
            p.vr = p.vc = 0
            self.shoot()
        else:
            if action:
                self.facing = action
                self.aim = DELTAS[action]
            p.vr, p.vc = DELTAS[action]
        self._think()
        for a, b in self.world.step(self.turn):
            if a.alive and (b is None or b.alive):
                self._hit(a, b)
                if self._terminated:
                    break
        for body in self.world.cull():
            self._left(body)
        if p.bump:
            p.vr = p.vc = 0          # blocked: the HUD's Vel says you did not move
        self.pos = (p.r, p.c)
        if not self._terminated:
            self._after()

    def shoot(self) -> Body | None:
        """Fire the gun from the player's cell (in ``fire_dir`` or the facing direction)."""
        if self.gun is None:
            return None
        dr, dc = self.fire_dir or self.aim
        shot = self.gun.fire(self.world, self.player.r, self.player.c, dr, dc, self.turn)
        if shot is not None:
            self.shots += 1
        return shot

    # -- drawing -----------------------------------------------------------------------------------
    def _rows(self) -> Sequence[str]:
        return self.world.rows

    def _sprites(self) -> Iterable[tuple[int, int, str]]:
        return self.world.sprites(self.player)

    def _grid(self) -> list[str]:
        """The engine's view: the still rows' window, then the bodies in view, a row at a time
        (a row holding one body is two slices; one holding more is rebuilt once)."""
        memo, self._memo = self._memo, None
        top, left, marks, _ = memo if memo is not None else self._in_view()
        # the still rows' window, reused while the corner and the rows under it are unchanged
        # (the slice of the world's rows compares fast: the same string objects)
        still = self.world.rows[top:top + self.view_h]
        cache = self._still
        if cache is not None and cache[0] == top and cache[1] == left and cache[2] == still:
            view = list(cache[3])
        else:
            vw = self.view_w
            view = [row[left:left + vw] for row in still]
            self._still = (top, left, still, tuple(view))
        r, c = self.pos
        me = (c - left, ARROWS[self.facing])     # the player, drawn over everything
        if r - top in marks:
            marks[r - top].append(me)
        else:
            marks[r - top] = [me]
        for y, cells in marks.items():
            if len(cells) == 1:
                x, ch = cells[0]
                row = view[y]
                view[y] = row[:x] + ch + row[x + 1:]
            else:
                line = list(view[y])
                for x, ch in cells:
                    line[x] = ch
                view[y] = "".join(line)
        return view

    _still: tuple[int, int, list[str], tuple[str, ...]] | None = None

    def _velocity(self) -> Cell:
        return self.player.vr, self.player.vc

    # the frame's one pass over the bodies (``_in_view``), made by ``_motion`` for ``_grid``
    _memo: tuple[int, int, dict[int, list[tuple[int, str]]], list[tuple]] | None = None

    def _in_view(self) -> tuple[int, int, dict[int, list[tuple[int, str]]], list[tuple]]:
        """One pass over the live bodies inside the view, the player left out: the view's
        corner, the glyphs to draw per view row (``{row: [(column, glyph), ...]}``, in body
        order so later bodies draw over earlier ones) and the moving ones as HUD entries
        ``(distance, dr, dc, glyph, vr, vc)`` relative to the player."""
        top, left = self._corner()
        vh, vw, me = self.view_h, self.view_w, self.player
        pr, pc = self.pos
        marks: dict[int, list[tuple[int, str]]] = {}
        moving = []
        for b in self.world.bodies:
            y = b.r - top
            if 0 <= y < vh:
                x = b.c - left
                if 0 <= x < vw and b.alive and b is not me:
                    if y in marks:
                        marks[y].append((x, b.glyph))
                    else:
                        marks[y] = [(x, b.glyph)]
                    if b.vr or b.vc:
                        dr, dc = b.r - pr, b.c - pc
                        moving.append((abs(dr) + abs(dc), dr, dc, b.glyph, b.vr, b.vc))
        return top, left, marks, moving

    def _corner(self) -> Cell:
        """The view's top-left world cell (the engine's clamped window)."""
        r, c = self.pos
        span = self._span
        if span is None or span[0] is not self.world:   # (the world's size, once per level)
            w, vh, vw = self.world, self.view_h, self.view_w
            span = self._span = (w, vh // 2, max(w.height - vh, 0), vw // 2, max(w.width - vw, 0))
        _, half_h, low, half_w, right = span
        top, left = r - half_h, c - half_w
        return (0 if top < 0 else low if top > low else top,
                0 if left < 0 else right if left > right else left)

    _span: tuple[World, int, int, int, int] | None = None

    def _motion(self) -> str:
        """The engine's ``Vel ... | Moving: ...`` text, read from the bodies directly (the same
        text, faster; a game that overrides ``_movers`` gets the engine's own)."""
        if type(self)._movers is not ShooterTask._movers:
            return super()._motion()
        me = self.player
        memo = self._memo = self._in_view()     # (the frame's _grid, drawn next, reuses it)
        seen = memo[3]
        text = "Vel " + _velocity_text(me.vr, me.vc)
        if seen:
            seen.sort()
            words = []
            for entry in seen[:MAX_MOVERS]:
                word = _WORDS.get(entry)
                if word is None:
                    if len(_WORDS) > 8192:
                        _WORDS.clear()
                    _, dr, dc, ch, vr, vc = entry
                    word = _WORDS[entry] = f"{ch}@{dr:+d},{dc:+d}{velocity_text(vr, vc)}"
                words.append(word)
            text += " | Moving: " + " ".join(words)
        return text

    def _movers(self) -> Iterable[tuple[str, int, int, int, int]]:
        """The moving bodies in view (the HUD lists no others), the player left out."""
        top, left = self._corner()
        vh, vw, me = self.view_h, self.view_w, self.player
        return [(b.glyph, b.r, b.c, b.vr, b.vc) for b in self.world.bodies
                if (b.vr or b.vc) and 0 <= b.r - top < vh and 0 <= b.c - left < vw
                and b.alive and b is not me]

    def _extras(self) -> str:
        gun = self.gun
        if gun is None or gun.cooldown <= 1:
            return ""
        wait = gun.ready - self.turn - 1   # turns to wait before FIRE works again
        return f"Gun {'ready' if wait <= 0 else f'wait {wait}'}"
