"""Dungeon: worlds of rooms seen one at a time, with monsters that wander and chase, treasures,
and a bow or gun (venture, tutankham).

``DungeonTask`` is an ``ArenaTask`` (facing fire with a reach, one shot in flight) whose field is
one room of a world laid out on a ``RoomMap``: ``go(room, r, c)`` shows that room (its rows are
built once by the game's ``_room(room)`` and kept, so a treasure taken with ``set_still`` stays
taken) with the monsters it held when you left (or those ``_populate(room)`` adds on a first
visit), and the HUD carries the map of rooms. Monsters (``self.foes``) step every ``every``
ticks: down the shortest way toward you when within ``sense`` steps, else wandering (on along
their heading, turning at random or when blocked, back only at a dead end). Touching one, or
walking into one, costs a life. A slain monster may leave a corpse (``corpse`` ticks) that is as
deadly to touch. ``clock`` puts a countdown in the HUD (``_time_up()`` when it runs out);
``SIDEWAYS`` games shoot only left or right (the way last moved sideways); ``flash()`` slays
every monster in the room. ``linger``: after that many ticks in a room where ``_haunted(room)``,
a hunter (``HUNTER``, not to be harmed) comes in through the walls at the far corner and floats
a cell toward you every other tick.

Hooks, besides the arena's: ``_room``, ``_populate``, ``_cross(r, c)`` (you stepped on a
``LINKS`` cell: a door or passage to another room), ``_take(r, c, ch)`` (you stepped on any
other cell that is not floor: pick-ups), ``_armed()`` (whether FIRE shoots now), ``worth(foe)``
(native points for slaying it), ``_time_up()``. ``bonus(points)`` pays native points outside
the goal's units (kills, keys): shown in the HUD score, not counted toward ``goal``. Helpers for
laying rooms out: ``side_cell`` (a door in the middle of a box's side), ``free_near`` (the floor
cell nearest a spot), ``distinct`` (different random picks from block draws).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from ...core.params import param
from ..common.grid import bfs_layers
from ..common.lanes import Draws
from .arena import EMPTY, FIRE, ArenaParams, ArenaTask
from .bodies import Body, Countdown
from .rooms import LEGEND, RoomMap

CORPSE, HUNTER = "%", "H"
SIDES = {"top": (-1, 0), "bottom": (1, 0), "left": (0, -1), "right": (0, 1)}   # outward steps
TURNS = ((0, 1), (0, -1), (1, 0), (-1, 0))
WANDER = tuple(TURNS[k:] + TURNS[:k] for k in range(4))   # the four ways, from a random one


@dataclass(frozen=True)
class DungeonParams(ArenaParams):
    width: int = param(20, 12, 40)
    height: int = param(16, 10, 30)
    sense: int = param(6, 0, 60)       # a monster this many steps away (or nearer) chases you
    corpse: int = param(0, 0, 200)     # ticks a slain monster's corpse stays, deadly (0: none)
    clock: int = param(0, 0, 10000)    # ticks on the clock (0: no clock)
    linger: int = param(0, 0, 2000)    # ticks in a room before a hunter comes in (0: never)


class DungeonTask(ArenaTask):
    Params: ClassVar[type] = DungeonParams
    LINKS: ClassVar[str] = ""              # glyphs of cells that lead to another room
    IMMUNE: ClassVar[str] = ""             # monster glyphs that shots cannot harm
    SIDEWAYS: ClassVar[bool] = False       # FIRE only left or right

    def prompt_fields(self) -> dict:
        p = self.params
        return {**super().prompt_fields(), "map_text": f" {LEGEND}.", "unit": f"{p.unit:g}",
                "turn_text": " A move into a wall only turns you to face it.",
                "wander_text": (f"Monsters wander; one within {p.sense} steps of you comes for "
                                f"you by the shortest way, a step every {p.every} turns. Touching "
                                "a monster costs a life."),
                "corpse_text": (f" A slain monster leaves a corpse ({CORPSE}) for {p.corpse} "
                                "turns that is as deadly to touch.") if p.corpse else "",
                "linger_text": (f" After {p.linger} turns in a room a {self.hunter_name} ({HUNTER}) "
                                "comes in through the walls and floats a cell toward you every "
                                "other turn.") if p.linger else ""}

    hunter_name = "hunter"

    # -- the world -----------------------------------------------------------------------------------
    def start_dungeon(self, rng, layout, room, r: int, c: int) -> None:
        """Call first in ``_setup``: the arena start, the map of rooms, and you in ``room``."""
        self.start_arena(rng, r, c)
        self.new_world(layout)
        self.aim = (0, 1)
        self.clock = Countdown(self.params.clock) if self.params.clock else None
        self.go(room, r, c)

    def new_world(self, layout) -> None:
        """A fresh map of rooms (a new level or zone): every room unbuilt and unvisited."""
        self.map = RoomMap(layout)
        self.room = None
        self._built: dict = {}
        self.held: dict = {}
        self._nav: dict = {}                  # room -> (steps fields from your cells, walkways)
        self.corpses: list[Body] = []

    def go(self, room, r: int, c: int) -> None:
        """Show ``room`` with you at (r, c) (where you come back after a life lost there)."""
        if self.room is not None:
            self.held[self.room] = self.foes
        self.room = room
        self.still = self.rows_of(room)
        self.still_version += 1
        self.r, self.c = self.home = (r, c)
        self.corpses = []
        if room in self.held:
            self.foes = self.held.pop(room)
            for foe in self.foes:             # none waiting right at the door
                if abs(foe.r - r) + abs(foe.c - c) < 3:
                    foe.r, foe.c = self.spot(4)
        else:
            self.foes = []
            self._populate(room)
        self.gun.shots, self.shells.shots = [], []
        self.entered, self.prowler = self.tick, None
        self._fields, self._ways = self._nav.setdefault(room, ({}, []))
        self.map.enter(*room)

    def rows_of(self, room) -> list[str]:
        """The kept rows of ``room`` (built now if it was never shown): change one to change it."""
        rows = self._built.get(room)
        if rows is None:
            rows = self._built[room] = self._room(room)
        return rows

    # -- one tick ------------------------------------------------------------------------------------
    def _play(self, action: int) -> None:
        if action == FIRE and not self._armed():
            action = 0
        d = self.MOVES[action]
        if d is not None and d[1]:
            self.aim = d
        super()._play(action)
        if self.SIDEWAYS:
            self.face = self.aim               # (drawn as the way the gun points)
        if self.done:
            return
        if self.corpses:
            self.corpses = [b for b in self.corpses if b.data > self.tick]
        if self.clock is not None and self.clock.left and self.clock.tick():
            self._time_up()
        if self.params.linger and self._haunted(self.room):
            self._prowl()

    def _prowl(self) -> None:
        p, o = self.params, self.prowler
        if o is None:
            if self.tick - self.entered >= p.linger:
                self.prowler = [1 if self.r > p.height // 2 else p.height - 2,
                                1 if self.c > p.width // 2 else p.width - 2]
                self.say(f"A {self.hunter_name} is coming in!")
            return
        if self.tick % 2 == 0:
            o[0] += (self.r > o[0]) - (self.r < o[0])
            o[1] += (self.c > o[1]) - (self.c < o[1])
        if o[0] == self.r and o[1] == self.c:
            self._killed(f"The {self.hunter_name} got you.")

    def _enter(self, r: int, c: int) -> bool:
        if self.foe_at(r, c) is not None or self.corpse_at(r, c):
            self._killed(self.caught_text)
            return True
        ch = self.still[r][c]
        if ch in self.LINKS:
            self._cross(r, c)
            return True
        if ch != EMPTY and ch not in self.SOLID:
            self._take(r, c, ch)
        return False

    def corpse_at(self, r: int, c: int) -> bool:
        for b in self.corpses:
            if b.r == r and b.c == c:
                return True
        return False

    def _field(self) -> dict:
        """Steps from your cell to every cell a monster may walk (a breadth-first search over the
        room's walkways, kept per room and cell of yours)."""
        p = self.params
        w = p.width
        here = self.r * w + self.c
        dist = self._fields.get(here)
        if dist is not None:
            return dist
        ways = self._ways
        if not ways:                          # the room's walkways: each cell's open neighbours
            blocked, n = self.SOLID | set(self.LINKS), p.height * w
            open_ = [ch not in blocked for row in self.still for ch in row]
            for i in range(n):
                near = (i - w, i + w, i - 1 if i % w else -1, i + 1 if (i + 1) % w else -1)
                ways.append(tuple(j for j in near if 0 <= j < n and open_[j]))
        dist = bfs_layers((here,), ways.__getitem__)
        if len(self._fields) >= 512:
            self._fields.clear()
        self._fields[here] = dist
        return dist

    def _march(self) -> bool:
        """Every monster takes a step: within ``sense`` steps of you, one down the shortest way
        toward you; farther, wandering."""
        foes = self.foes
        if not foes:
            return False
        p = self.params
        h, w, still, solid, links = p.height, p.width, self.still, self.SOLID, self.LINKS
        pr, pc, sense, draws = self.r, self.c, p.sense, self.draws
        here = pr * w + pc
        taken = {f.r * w + f.c for f in foes}
        for b in self.corpses:
            taken.add(b.r * w + b.c)
        dist = ways = None
        for foe in foes:
            fr, fc, hr, hc = foe.r, foe.c, foe.dr, foe.dc
            at = fr * w + fc
            if (pr - fr if pr > fr else fr - pr) + (pc - fc if pc > fc else fc - pc) <= sense:
                if dist is None:
                    dist, ways = self._field(), self._ways
                d = dist.get(at, sense + 1)
                if d <= sense:                               # chasing: a step nearer, if one is free
                    for j in ways[at]:
                        if dist.get(j, d) < d and (j == here or j not in taken):
                            taken.discard(at)
                            taken.add(j)
                            foe.r, foe.c, foe.dr, foe.dc = j // w, j % w, j // w - fr, j % w - fc
                            break
                    continue
            u = draws.random()                               # wandering: on along its heading, mostly
            steps = ((hr, hc),) + WANDER[int(u * 20) & 3] if (hr or hc) and u < 0.8 else WANDER[int(u * 4)]
            back, last = (-hr, -hc), len(steps)
            for i, (sr, sc) in enumerate(steps + (back,)):     # turning back only at a dead end
                if not (sr or sc) or (i < last and sr == back[0] and sc == back[1]):
                    continue
                r, c = fr + sr, fc + sc
                if (r == pr and c == pc) or (0 <= r < h and 0 <= c < w and r * w + c not in taken
                                             and still[r][c] not in solid and still[r][c] not in links):
                    taken.discard(at)
                    taken.add(r * w + c)
                    foe.r, foe.c, foe.dr, foe.dc = r, c, sr, sc
                    break
        return self._caught()

    # -- slaying -------------------------------------------------------------------------------------
    def _hit(self, foe: Body) -> None:
        if foe.glyph in self.IMMUNE:
            return
        foe.data -= 1
        if foe.data <= 0:
            self.slay(foe)

    def slay(self, foe: Body) -> None:
        self.foes.remove(foe)
        self.kills += 1
        if self.params.corpse:
            self.corpses.append(Body(foe.r, foe.c, 0, 0, CORPSE, self.tick + self.params.corpse))
        self.say(f"You slew a {self.vocab().get(foe.glyph, self.foe_name)}.")
        self.score.bonus(self.worth(foe))

    def flash(self) -> int:
        """Slay every monster in the room that can be slain; how many."""
        doomed = [f for f in self.foes if f.glyph not in self.IMMUNE]
        for f in doomed:
            self.slay(f)
        return len(doomed)

    # -- hooks ---------------------------------------------------------------------------------------
    def _room(self, room) -> list[str]:
        raise NotImplementedError

    def _populate(self, room) -> None:
        """Place the monsters of a room shown for the first time (``add_foe``)."""

    def _cross(self, r: int, c: int) -> None:
        """You stepped on a ``LINKS`` cell at (r, c)."""

    def _take(self, r: int, c: int, ch: str) -> None:
        """You step on (r, c), which holds ``ch`` (a pick-up)."""

    def _armed(self) -> bool:
        return True

    def worth(self, foe: Body) -> float:
        return 0.0

    def _time_up(self) -> None:
        """The clock ran out."""

    def _haunted(self, room) -> bool:
        """Whether a hunter comes after you for lingering in ``room``."""
        return True

    def _respawn(self) -> None:
        super()._respawn()
        self.corpses = [b for b in self.corpses if abs(b.r - self.r) + abs(b.c - self.c) > 1]
        self.prowler, self.entered = None, self.tick

    def _below(self):
        return [(b.r, b.c, CORPSE) for b in self.corpses] if self.corpses else ()

    def _above(self):
        return () if self.prowler is None else ((self.prowler[0], self.prowler[1], HUNTER),)

    def _extra_hud(self) -> str:
        if self.clock is None:
            return self.map.hud()
        if self._shown_clock != (self.clock.left, self.map.hud()):
            self._shown_clock = (self.clock.left, self.map.hud())
            self._clock_text = f"{self.map.hud()} | Time {self.clock.left}"
        return self._clock_text

    _shown_clock = None


def side_cell(box: tuple[int, int, int, int], side: str) -> tuple[int, int]:
    """The middle cell of a side of the box (top, left, bottom, right): where its door is."""
    t, l, b, r = box
    return {"top": (t, (l + r) // 2), "bottom": (b, (l + r) // 2),
            "left": ((t + b) // 2, l), "right": ((t + b) // 2, r)}[side]


def free_near(grid, r: int, c: int) -> tuple[int, int]:
    """The floor cell of ``grid`` (rows of cells) nearest (r, c)."""
    cells = [(abs(i - r) + abs(j - c), i, j) for i, row in enumerate(grid)
             for j, ch in enumerate(row) if ch == EMPTY]
    return min(cells)[1:]


def distinct(draws: Draws, n: int, k: int) -> list[int]:
    """``k`` different numbers below ``n`` (all of them when ``k >= n``), at random."""
    picked: list[int] = []
    while len(picked) < min(k, n):
        x = draws.below(n)
        if x not in picked:
            picked.append(x)
    return picked


__all__ = ["CORPSE", "HUNTER", "SIDES", "DungeonParams", "DungeonTask", "distinct", "free_near",
           "side_cell"]
