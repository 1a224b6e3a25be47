"""Sectors: space games flown over a map of places to enter (gravitar's solar system and planets,
solaris's sector chart), with a ship that keeps its velocity and falls under gravity.

``Ship``: a position and a velocity in sub-cells (``SCALE`` a cell, so a speed of one sub-cell a
turn is a drift of a cell every ``SCALE`` turns), one of 8 headings (drawn as the arrow it points,
``SHIPS``), ``rotate``, ``push`` (thrust along the heading), ``pull`` (gravity); speeds are capped
at a cell a turn, so the ship never jumps a cell.

``FlightTask`` (an ``ArenaTask``): the arena's shots, foe shells, foes and fuel, flown by
``FLIGHT`` actions (NOOP, LEFT/RIGHT rotate, THRUST, FIRE along the heading). Each tick: the
action, gravity (``_gravity()``: a (row, col) pull in sub-cells, or None), the flight cell by
cell (a solid cell or a foe is a crash: ``_crash``; leaving the field: ``_edge``), shots, shells,
fuel (``_fuel_out`` when it runs dry), ``_turn()``. ``Sectors`` keeps the places of a map (what
each holds, which are gone) beside a ``RoomMap`` for the HUD.
"""

from __future__ import annotations

from typing import ClassVar

from ...core.actions import ActionSet
from .arena import ArenaTask
from .rooms import RoomMap

SCALE = 4
HEADINGS = ((-1, 0), (-1, 1), (0, 1), (1, 1), (1, 0), (1, -1), (0, -1), (-1, -1))   # clockwise from up
SHIPS = "↑↗→↘↓↙←↖"
COMPASS = ("N", "NE", "E", "SE", "S", "SW", "W", "NW")
FLIGHT = ActionSet([("NOOP", "coast a turn"), ("LEFT", "rotate the ship 45 degrees anticlockwise"),
                    ("RIGHT", "rotate the ship 45 degrees clockwise"),
                    ("THRUST", "fire the engine: speed up the way the ship points (costs fuel)"),
                    ("FIRE", "shoot the way the ship points")], noop="NOOP")
ROT_LEFT, ROT_RIGHT, THRUST, SHOOT = 1, 2, 3, 4


def ship_glyphs() -> dict[str, str]:
    return {g: f"your ship (pointing {w})" for g, w in zip(SHIPS, COMPASS)}


def heading_to(dr: int, dc: int) -> int:
    """The heading (0..7) nearest the direction (dr, dc) (by signs)."""
    return HEADINGS.index(((dr > 0) - (dr < 0), (dc > 0) - (dc < 0)))


class Ship:
    """Position (y, x) and velocity (vy, vx) in sub-cells; (r, c) the cell it is in."""
    __slots__ = ("y", "x", "vy", "vx", "head", "power")

    def __init__(self, r: int, c: int, head: int = 0, power: int = 2) -> None:
        self.y, self.x, self.vy, self.vx, self.head, self.power = r * SCALE + SCALE // 2, c * SCALE + SCALE // 2, 0, 0, head, power

    def place(self, r: int, c: int) -> None:
        self.y, self.x, self.vy, self.vx = r * SCALE + SCALE // 2, c * SCALE + SCALE // 2, 0, 0

    def rotate(self, k: int) -> None:
        self.head = (self.head + k) % 8

    def push(self) -> None:
        dr, dc = HEADINGS[self.head]
        self.pull(dr * self.power, dc * self.power)

    def pull(self, ay: int, ax: int) -> None:
        self.vy = max(-SCALE, min(SCALE, self.vy + ay))
        self.vx = max(-SCALE, min(SCALE, self.vx + ax))


class FlightTask(ArenaTask):
    ACTIONS = FLIGHT
    arrows = False
    air_name = "Fuel"
    burn: ClassVar[int] = 3      # fuel a THRUST costs beyond the turn's own unit

    def start_flight(self, rng, r: int, c: int, head: int = 0, power: int = 2) -> None:
        self.start_arena(rng, r, c)
        self.ship = Ship(r, c, head, power)

    def _you(self) -> str:
        return SHIPS[self.ship.head]

    def _above(self):
        """The ship, drawn over the arena's plain player glyph."""
        return ((self.r, self.c, SHIPS[self.ship.head]),)

    def _play(self, action: int) -> None:
        ship = self.ship
        if action == ROT_LEFT or action == ROT_RIGHT:
            ship.rotate(-1 if action == ROT_LEFT else 1)
        elif action == THRUST:
            ship.push()
            if self.air is not None and self.air.tick(self.burn):
                self._fuel_out()
                return
        elif action == SHOOT:
            self.gun.fire(self.tick, self.r, self.c, *HEADINGS[ship.head])
        g = self._gravity()
        if g is not None:
            ship.pull(*g)
        if self._fly() or self.done:
            return
        if self.gun.shots:
            self._shots()
            if self.done:
                return
        if self.params.volley and self._volley():
            return
        if self.air is not None and self.air.tick():
            self._fuel_out()
            return
        self._turn()

    def _gravity(self):
        return None

    def _fly(self) -> bool:
        """Move the ship by its velocity; True when it crashed or left the field."""
        ship, p = self.ship, self.params
        y, x = ship.y + ship.vy, ship.x + ship.vx
        r, c = y // SCALE, x // SCALE
        if r == self.r and c == self.c:
            ship.y, ship.x = y, x
            return False
        if p.wrap:
            c %= p.width
            x %= p.width * SCALE
        if not (0 <= r < p.height and 0 <= c < p.width):
            return self._edge(r, c)
        if self.still[r][c] in self.SOLID or self.foe_at(r, c) is not None:
            self.r, self.c = r, c
            return self._crash(r, c)
        ship.y, ship.x, self.r, self.c = y, x, r, c
        return self._arrive(r, c)

    def _edge(self, r: int, c: int) -> bool:
        """The ship flew out of the field toward (r, c): by default it stops at the edge."""
        ship, p = self.ship, self.params
        if not 0 <= r < p.height:
            ship.vy, ship.y = 0, self.r * SCALE + SCALE // 2
        if not 0 <= c < p.width:
            ship.vx, ship.x = 0, self.c * SCALE + SCALE // 2
        return False

    def _crash(self, r: int, c: int) -> bool:
        return self._killed("You crashed.")

    def _arrive(self, r: int, c: int) -> bool:
        """The ship entered cell (r, c); True when that ended the tick."""
        return False

    def _fuel_out(self) -> None:
        self.say("Out of fuel: the game is over.")
        self.finish(won=False)

    def _respawn(self) -> None:
        self.shells.shots, self.gun.shots = [], []
        self.r, self.c = self.home
        self.ship.place(*self.home)

    def _extra_hud(self) -> str:
        ship = self.ship       # (its velocity in quarter cells a turn: rows + down, columns + right)
        return f"Fuel {self.air.left} | Head {COMPASS[ship.head]} | Vel {ship.vy:+d},{ship.vx:+d}{self._place_hud()}"

    def _place_hud(self) -> str:
        return ""


class Sectors:
    """The places of a map (``layout`` rows, ``#`` a place) and what each holds (``held``: place
    -> anything), with the ``RoomMap`` of those visited. ``chart(mark)`` is the HUD's picture of
    every place, ``mark(place)`` giving its character (``@`` for where you are), made again only
    after ``changed()``."""
    __slots__ = ("map", "held", "order", "_chart")

    def __init__(self, layout) -> None:
        self.map = RoomMap(layout)
        self.order = sorted(self.map.rooms)
        self.held: dict = {p: None for p in self.order}
        self._chart: str | None = None

    def changed(self) -> None:
        self._chart = None

    def go(self, place) -> bool:
        """Move to ``place``; True on a first visit."""
        self._chart = None
        return self.map.enter(*place)

    def chart(self, mark) -> str:
        if self._chart is None:
            m = self.map
            self._chart = "Chart " + "/".join(
                "".join("@" if (r, c) == m.here else mark((r, c)) if (r, c) in m.rooms else " "
                        for c in range(m.width)) for r in range(m.height))
        return self._chart

    def after(self, here, wanted) -> tuple[int, int] | None:
        """The next place in reading order after ``here`` (wrapping, ``here`` last) for which
        ``wanted(place)``."""
        i = self.order.index(here) if here in self.map.rooms else -1
        n = len(self.order)
        for k in range(1, n + 1):
            place = self.order[(i + k) % n]
            if wanted(place):
                return place
        return None
