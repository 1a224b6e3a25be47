"""The Craftax tasks as data: one ``Scenario`` per task, on the one engine with Craftax's rules.

A scenario says how the world is made (a generated world, started on the surface or on a floor's
up-ladder; or a blank grass world for the drills), the edits made to it (cleared squares, blocks
scattered or stamped, mobs placed), the start kit and vitals, the engine switches (``Settings``),
the events that happen during play (a wave at a turn, a knight once strength reaches 3), the
reward terms and the success test. Tests and terms are read from the task's ``Tally`` counters
(``task.Tally``), written as ``"got.wood"`` (a count) or ``"holds.iron >= 1 and holds.coal >= 1"``
(a test).

Where a task needs something Craftax lacks, it is an edit of the state, never a rule change: a
floor's ladder gate of 8 kills becomes a gate of k by starting the floor's kill count at 8 - k;
a fight with more mobs than Craftax keeps at once (3 melee, 3 passive, 2 ranged per floor) sends
the rest in as slots free up.
"""

from __future__ import annotations

import operator
import re
import sys
from dataclasses import dataclass, field, replace
from typing import Callable

import numpy as np

from .mobs import MOB_BY_NAME, add_mob
from .state import MOB_GROUPS, Settings
from .tables import LEVEL_NAMES, BlockType

# ------------------------------------------------------------------------------------------------
# tests over the tally


_CLAUSE = re.compile(r"^\s*([a-z_.]+)\s*(>=|<=|==|>|<)\s*(-?[0-9.]+)\s*$")
# (a counter is compared as it is, int or float: exact for the small counts a test reads)
_OPS = {">=": operator.ge, "<=": operator.le, "==": operator.eq, ">": operator.gt, "<": operator.lt}


def parse_test(text: str, tally) -> Callable:
    """``"a.b >= 3 and c < 2"`` -> a function of the tally giving True or False; a bare counter
    name (``"got.wood"``) -> a function giving that counter. Counters are compiled once by
    ``tally.getter`` (an unknown one is a KeyError naming it)."""
    if not re.search(r"[<>=]", text):
        return tally.getter(text.strip())
    clauses = []
    for part in text.split(" and "):
        m = _CLAUSE.match(part)
        if not m:
            raise ValueError(f"bad scenario test {text!r}: each clause is 'counter op number'")
        clauses.append((tally.getter(m.group(1)), _OPS[m.group(2)], float(m.group(3))))
    if len(clauses) == 1:
        (get, op, n), = clauses
        return lambda t: op(get(t), n)
    if len(clauses) == 2:       # (written out: a term's test may be asked every step)
        (get, op, n), (get2, op2, n2) = clauses
        return lambda t: op(get(t), n) and op2(get2(t), n2)
    return lambda t: all(op(get(t), n) for get, op, n in clauses)


@dataclass(frozen=True)
class Term:
    """A reward term: ``unit`` per unit of ``test`` (a counter, ``per`` of it making one unit,
    capped at ``cap`` units), or ``unit`` once when ``test`` (a test) first holds. ``says`` names
    it in the prompt ("each wood collected")."""
    name: str
    test: str
    unit: float
    says: str
    cap: int = 1
    per: int = 1

    def units(self, tally, fn) -> int:
        """The units ``fn`` (the test compiled by ``parse_test``) gives now."""
        return self.counter(fn)(tally)

    def counter(self, fn) -> Callable:
        """``units`` as one function of the tally, made once (the task pays every step)."""
        per, cap = self.per, self.cap
        if not self.counts:         # a test (its function gives a bool): one unit while it holds
            return lambda tally: 1 if fn(tally) else 0

        def units(tally) -> int:    # (a counter: a number, never a bool)
            return min(int(fn(tally)) // per, cap)
        return units

    @property
    def counts(self) -> bool:
        return not re.search(r"[<>=]", self.test)


# ------------------------------------------------------------------------------------------------
# edits of the start state


def _floor_block(state) -> int:
    r, c = state.player_position
    return int(state.map[state.player_level, r, c])


def _cells(state, dmin: int, dmax: int, metric: str = "manhattan"):
    """Cells of the player's level at distance dmin..dmax from the player, in bounds."""
    pr, pc = (int(v) for v in state.player_position)
    rows, cols = state.map.shape[1:]
    out = []
    for r in range(max(0, pr - dmax), min(rows, pr + dmax + 1)):
        for c in range(max(0, pc - dmax), min(cols, pc + dmax + 1)):
            d = abs(r - pr) + abs(c - pc) if metric == "manhattan" else max(abs(r - pr), abs(c - pc))
            if dmin <= d <= dmax:
                out.append((r, c))
    return out


def _free(state, r: int, c: int, floor: int) -> bool:
    level = state.player_level
    return (int(state.map[level, r, c]) == floor and not state.mob_map[level, r, c]
            and int(state.item_map[level, r, c]) == 0
            and (r, c) != tuple(int(v) for v in state.player_position))


@dataclass(frozen=True)
class Clear:
    """Make the square of ``radius`` (Chebyshev) around the player plain floor, mobs removed."""
    radius: int

    def apply(self, state, rng, ctx) -> None:
        floor, level = ctx.floor, state.player_level
        for r, c in _cells(state, 0, self.radius, "chebyshev"):
            if int(state.item_map[level, r, c]) == 0:
                state.map[level, r, c] = floor
        _remove_mobs(state, lambda r, c: max(abs(r - ctx.r0), abs(c - ctx.c0)) <= self.radius)


@dataclass(frozen=True)
class Scatter:
    """``count`` cells of ``block`` at Manhattan distance dmin..dmax, on free floor (or on
    cells of block ``on``: ore into stone, say)."""
    block: BlockType
    count: int
    dmin: int
    dmax: int
    on: int | None = None

    def apply(self, state, rng, ctx) -> None:
        if self.on is None:
            spots = [p for p in _cells(state, self.dmin, self.dmax) if _free(state, *p, ctx.floor)]
        else:
            level = state.player_level
            spots = [p for p in _cells(state, self.dmin, self.dmax) if int(state.map[level, p[0], p[1]]) == self.on]
        for i in rng.permutation(len(spots))[:self.count]:
            r, c = spots[i]
            state.map[state.player_level, r, c] = self.block


@dataclass(frozen=True)
class Stamp:
    """``block`` at offsets (row, col) from the player."""
    block: BlockType
    offsets: tuple

    def apply(self, state, rng, ctx) -> None:
        for dr, dc in self.offsets:
            r, c = ctx.r0 + dr, ctx.c0 + dc
            if 0 <= r < state.map.shape[1] and 0 <= c < state.map.shape[2]:
                state.map[state.player_level, r, c] = self.block


@dataclass(frozen=True)
class Remove:
    """Every ``block`` within ``radius`` (Chebyshev) of the player becomes ``into``."""
    block: BlockType
    radius: int
    into: BlockType = BlockType.GRASS

    def apply(self, state, rng, ctx) -> None:
        level = state.player_level
        for r, c in _cells(state, 0, self.radius, "chebyshev"):
            if int(state.map[level, r, c]) == self.block:
                state.map[level, r, c] = self.into


@dataclass(frozen=True)
class Mobs:
    """``count`` mobs called ``name`` on free floor at Manhattan distance dmin..dmax; those that
    do not fit Craftax's per-floor slots come in later, as slots free up."""
    name: str
    count: int
    dmin: int
    dmax: int

    def apply(self, state, rng, ctx) -> None:
        for _ in range(self.count):
            ctx.reserve.append((self.name, self.dmin, self.dmax))
        ctx.admit(state, rng)


@dataclass(frozen=True)
class NoMobs:
    """Remove every mob of the player's level."""

    def apply(self, state, rng, ctx) -> None:
        _remove_mobs(state, lambda r, c: True)


@dataclass(frozen=True)
class Gate:
    """The ladder of the player's level opens after ``k`` kills (the count starts at 8 - k)."""
    k: int

    def apply(self, state, rng, ctx) -> None:
        state.monsters_killed[state.player_level] = max(0, 8 - self.k)


@dataclass(frozen=True)
class GateAt:
    """The ladder of ``level`` opens after ``k`` kills there."""
    levels: tuple
    k: int

    def apply(self, state, rng, ctx) -> None:
        for level in self.levels:
            state.monsters_killed[level] = max(0, 8 - self.k)


@dataclass(frozen=True)
class Potions:
    """One potion of each colour whose (hidden, per-episode) effect is in ``effects``: 0 heal,
    1 harm, 2 mana, 3 mana loss, 4 energy, 5 energy loss."""
    effects: tuple

    def apply(self, state, rng, ctx) -> None:
        for colour, effect in enumerate(state.potion_mapping):
            state.inventory.potions[colour] = int(int(effect) in self.effects)


@dataclass(frozen=True)
class MoveLadder:
    """The surface's down-ladder moves to (row, col) offset from the player, on cleared floor."""
    offset: tuple

    def apply(self, state, rng, ctx) -> None:
        from .tables import ItemType
        r0, c0 = (int(v) for v in state.down_ladders[0])
        state.item_map[0, r0, c0] = ItemType.NONE
        r, c = ctx.r0 + self.offset[0], ctx.c0 + self.offset[1]
        state.map[0, r, c] = ctx.floor
        state.item_map[0, r, c] = ItemType.LADDER_DOWN
        state.down_ladders[0] = (r, c)


@dataclass(frozen=True)
class NearLadder:
    """The player starts at a walkable cell dmin..dmax steps (Chebyshev) from the level's
    down-ladder, one it can walk to."""
    dmin: int
    dmax: int

    def apply(self, state, rng, ctx) -> None:
        from .rules import player_can_enter
        level = state.player_level
        target = tuple(int(v) for v in state.down_ladders[level])
        seen, frontier, found = {target}, [target], []
        while frontier:
            nxt = []
            for r, c in frontier:
                for dr, dc in ((1, 0), (-1, 0), (0, 1), (0, -1)):
                    p = (r + dr, c + dc)
                    if p not in seen and 0 <= p[0] < state.map.shape[1] and 0 <= p[1] < state.map.shape[2] \
                            and player_can_enter(state, *p):
                        seen.add(p)
                        nxt.append(p)
                        if self.dmin <= max(abs(p[0] - target[0]), abs(p[1] - target[1])) <= self.dmax \
                                and not state.mob_map[level, p[0], p[1]]:
                            found.append(p)
            frontier = nxt
        if found:
            state.player_position[:] = found[int(rng.integers(len(found)))]
            ctx.r0, ctx.c0 = (int(v) for v in state.player_position)


def _remove_mobs(state, where) -> None:
    level = state.player_level
    for kind in MOB_GROUPS:
        mobs = getattr(state, kind)
        for i, alive in enumerate(mobs.mask[level]):
            r, c = mobs.position[level][i]
            if alive and where(r, c):
                mobs.mask[level][i] = False
                state.mob_map[level, r, c] = False


# ------------------------------------------------------------------------------------------------
# the scenario


class Context:
    """What building and playing a scenario keeps beside the state: the spawn point, the level's
    floor block, mobs waiting for a free slot."""

    def __init__(self, state) -> None:
        self.r0, self.c0 = (int(v) for v in state.player_position)
        self.floor = _floor_block(state)
        self.reserve: list[tuple[str, int, int]] = []
        # the waiting list ``admit`` left and the classes of its mobs (all of known names), to
        # tell at once that every one of them still waits (see ``admit``)
        self.waited: tuple[list, tuple[int, ...]] = ([], ())

    def admit(self, state, rng) -> None:
        """Each waiting mob, in turn, whose class has a free slot takes a random free cell in
        its ring (one draw, when the ring has a free cell); the others wait, drawing nothing.
        A ring's free cells are found once and found again only after a mob was placed.

        While the list is the one the last call left and none of its mobs' classes has a free
        slot, every mob waits and nothing is drawn: the list stays as it is, without the walk
        over it (a fight scenario's step, its mobs all out, asks this every turn)."""
        groups = (state.passive_mobs, state.melee_mobs, state.ranged_mobs)
        level = state.player_level
        waited, classes = self.waited
        if self.reserve == waited:
            for k in classes:
                if False in groups[k].mask[level]:
                    break
            else:
                return
        waiting = []
        rings: dict[tuple[int, int], tuple] = {}
        for name, dmin, dmax in self.reserve:
            known = MOB_BY_NAME.get(name)
            if known is not None and False not in groups[known[0]].mask[level]:
                waiting.append((name, dmin, dmax))      # (no free slot: add_mob would refuse)
                continue
            ring = rings.get((dmin, dmax))
            if ring is None:
                ring = rings[dmin, dmax] = _free_cells(state, dmin, dmax, self.floor)
            ok, count, r0, c0, width = ring
            if not count:
                waiting.append((name, dmin, dmax))
                continue
            k = int(np.flatnonzero(np.frombuffer(ok, np.uint8))[rng.integers(count)])
            if add_mob(state, name, (r0 + k // width, c0 + k % width)):
                rings.clear()
            else:
                waiting.append((name, dmin, dmax))
        self.reserve = waiting
        known = [MOB_BY_NAME.get(name) for name, _, _ in waiting]
        self.waited = ((list(waiting), tuple({k[0] for k in known})) if None not in known
                        else ([None], ()))       # (a list no reserve equals: never skipped)


def _free_ring(state, dmin: int, dmax: int, floor: int):
    """``[p for p in _cells(state, dmin, dmax) if _free(state, *p, floor)]`` as a mask over the
    box ``rows r0.., cols c0.., width`` columns wide (its true cells in row-major order are
    that list) and their count: ``(mask, count, r0, c0, width)``."""
    level = state.player_level
    pr, pc = state.player_position.tolist()
    rows, cols = state.map.shape[1:]
    r0, r1 = max(0, pr - dmax), min(rows, pr + dmax + 1)
    c0, c1 = max(0, pc - dmax), min(cols, pc + dmax + 1)
    ok = state.map[level, r0:r1, c0:c1] == floor
    ok &= _ring(dmin, dmax)[r0 - pr + dmax:r1 - pr + dmax, c0 - pc + dmax:c1 - pc + dmax]
    np.greater(ok, state.mob_map[level, r0:r1, c0:c1], out=ok)      # (ok and no mob)
    items = state.item_map[level, r0:r1, c0:c1]
    if np.count_nonzero(items):
        ok &= items == 0
    return ok, np.count_nonzero(ok), r0, c0, c1 - c0


def _free_cells(state, dmin: int, dmax: int, floor: int):
    """``_free_ring`` with the mask as bytes (1: a free cell), found by byte operations on the
    box's blocks, items and mob map (one copy of each, no numpy arithmetic):
    ``(mask bytes, count, r0, c0, width)``."""
    level = state.player_level
    pr, pc = state.player_position.tolist()
    rows, cols = state.map.shape[1:]
    r0, r1 = max(0, pr - dmax), min(rows, pr + dmax + 1)
    c0, c1 = max(0, pc - dmax), min(cols, pc + dmax + 1)
    window = (level, slice(r0, r1), slice(c0, c1))
    blocks, items, mobs = state.map[window], state.item_map[window], state.mob_map[window]
    if not (blocks.dtype == _INT32 and items.dtype == _INT32 and mobs.dtype == np.bool_
            and 0 <= floor < 256):
        ok, count, r0, c0, width = _free_ring(state, dmin, dmax, floor)
        return ok.astype(np.uint8).tobytes(), count, r0, c0, width
    # each a byte per cell, 1 where: the floor block, no item, no mob, in the ring
    parts = (blocks.tobytes()[_LOW::4].translate(_IS[floor]),
             items.tobytes()[_LOW::4].translate(_IS[0]), mobs.tobytes().translate(_IS[0]),
             _ring_bytes(dmin, dmax, r0 - pr + dmax, r1 - pr + dmax, c0 - pc + dmax,
                         c1 - pc + dmax))
    free = -1
    for part in parts:
        free &= int.from_bytes(part, "little")
    size = len(parts[0])
    return free.to_bytes(size, "little"), free.bit_count(), r0, c0, c1 - c0


_INT32 = np.dtype(np.int32)
_LOW = 0 if sys.byteorder == "little" else 3      # (where an int32's low byte is)
# _IS[v]: a translation table giving 1 for the byte v, 0 for any other
_IS = tuple(bytes(int(i == v) for i in range(256)) for v in range(256))
_RING_BYTES: dict[tuple, bytes] = {}


def _ring_bytes(dmin: int, dmax: int, a: int, b: int, c: int, d: int) -> bytes:
    """``_ring(dmin, dmax)[a:b, c:d]`` as bytes (1 in the ring)."""
    key = (dmin, dmax, a, b, c, d)
    ring = _RING_BYTES.get(key)
    if ring is None:
        ring = _RING_BYTES[key] = _ring(dmin, dmax)[a:b, c:d].astype(np.uint8).tobytes()
    return ring


_RINGS: dict[tuple[int, int], np.ndarray] = {}


def _ring(dmin: int, dmax: int) -> np.ndarray:
    """The cells at Manhattan distance dmin..dmax from the centre of a (2 dmax + 1) square,
    the centre (the player's cell) left out."""
    ring = _RINGS.get((dmin, dmax))
    if ring is None:
        d = np.abs(np.arange(-dmax, dmax + 1))
        d = d[:, None] + d[None, :]
        ring = _RINGS[dmin, dmax] = (d >= dmin) & (d <= dmax)
        ring[dmax, dmax] = False
    return ring


@dataclass(frozen=True)
class Event:
    """Once ``when`` (a test) holds, ``edits`` run (mobs arrive, say)."""
    when: str
    edits: tuple
    says: str = ""


@dataclass(frozen=True)
class Scenario:
    name: str
    objective: str                      # one or two sentences for the prompt
    success: str                        # a test; "" for tasks that run to the horizon
    terms: tuple                        # Term, ...
    horizon: int
    world: str = "overworld"            # "overworld" (generated) or "blank" (grass everywhere)
    floor: int = 0                      # the level the player starts on (at its up-ladder)
    settings: Settings = Settings()
    kit: dict = field(default_factory=dict)      # inventory fields
    player: dict = field(default_factory=dict)   # other State fields (vitals, attributes ...)
    edits: tuple = ()
    events: tuple = ()
    death: float = -1.0                 # added on the step the player dies
    time: int = 0                       # the starting timestep (day length 300)
    topics: tuple = ("craft",)          # rule sections the prompt includes (view.rules_text)
    progress_keys: tuple = ()           # counters shown in the HUD
    success_message: str = "Objective complete."

    # -- building ---------------------------------------------------------------------------------
    def build(self, rng: np.random.Generator):
        """The start state and its Context."""
        from . import worldgen
        state = (worldgen.generate(rng, self.settings) if self.world == "overworld"
                 else worldgen.blank(self.settings))
        if self.floor:
            from .tables import LEVEL_ACHIEVEMENT
            state.player_level = self.floor
            state.player_position = state.up_ladders[self.floor].copy()
            # the player came down the ladders: the floors' first-entry achievements are had
            # (else Craftax's step would grant the start floor's, and its XP, on the first turn)
            for level in range(1, self.floor + 1):
                state.achievements[LEVEL_ACHIEVEMENT[level]] = True
        state.timestep = self.time
        for k, v in self.kit.items():
            if k in ("armour", "potions"):
                getattr(state.inventory, k)[:] = v
            else:
                setattr(state.inventory, k, v)
        for k, v in self.player.items():
            if isinstance(getattr(state, k), np.ndarray):
                getattr(state, k)[:] = v
            else:
                setattr(state, k, v)
        from .rules import daylight
        state.light_level = daylight(state.timestep, self.settings)
        ctx = Context(state)
        for edit in self.edits:
            edit.apply(state, rng, ctx)
        return state, ctx

    def run_events(self, task, tally) -> None:
        """After each step: waiting mobs take free slots (``task.admit``); events whose test
        holds run once (the ``task`` keeps them) on its state (``task.edit``); a steady test only
        when ``tally.changes`` moved (``task.Tally``)."""
        ctx, rng = task.ctx, task.play_rng
        if ctx.reserve:
            task.admit()
        fresh, task.events_at = tally.changes != task.events_at, tally.changes
        for i, (event, when, steady) in enumerate(task.events):
            if (fresh or not steady) and i not in task.fired and when(tally):
                task.fired.add(i)

                def run(state, event=event) -> None:
                    ctx.r0, ctx.c0 = (int(v) for v in state.player_position)
                    for edit in event.edits:
                        edit.apply(state, rng, ctx)
                task.edit(run)
                if event.says:
                    task.say(event.says)

    # -- text ---------------------------------------------------------------------------------------
    def intro(self) -> str:
        return f"You start on floor {self.floor} ({LEVEL_NAMES[self.floor]})." if self.floor else ""

    def reward_text(self) -> str:
        """The terms in order; milestones of one size said together ("+1/6 each: ...")."""
        parts, i, terms = [], 0, self.terms
        while i < len(terms):
            t = terms[i]
            if t.counts and t.cap > 1:
                parts.append(f"+{_amount(t.unit)} for {t.says} (up to {t.cap})")
                i += 1
                continue
            same = [t]
            while i + len(same) < len(terms) and not (terms[i + len(same)].counts and terms[i + len(same)].cap > 1) \
                    and abs(terms[i + len(same)].unit - t.unit) < 1e-12:
                same.append(terms[i + len(same)])
            if len(same) == 1:
                parts.append(f"+{_amount(t.unit)} {t.says}")
            else:
                parts.append(f"+{_amount(t.unit)} each: " + ", ".join(x.says.removeprefix("for ") for x in same))
            i += len(same)
        if self.death:
            parts.append(f"{self.death:+g} if you die")
        return "; ".join(parts) + "."

    def ends_text(self) -> str:
        return "when the objective is complete or you die" if self.success else "when you die"

    def progress(self, tally) -> str:
        """The HUD's progress: each progress key's label and value (remembered by the values:
        they change on few turns)."""
        keys = self.progress_keys
        if not keys:
            return ""
        values = tuple([tally.value(k) for k in keys])
        key = (keys, values, tuple(map(type, values)))    # (1 and 1.0 and True print apart)
        text = _PROGRESS.get(key)
        if text is None:
            labels = [k.split('.')[-1].capitalize() for k in keys]
            if len(_PROGRESS) >= 10_000:
                _PROGRESS.clear()
            text = _PROGRESS[key] = " ".join([f"{label} {_fmt(v)}" for label, v in zip(labels, values)])
        return text

    def check(self, tally) -> None:
        """Compile every test and counter of the scenario (a KeyError names a bad one)."""
        for text in [t.test for t in self.terms] + [e.when for e in self.events] + \
                [self.success] * bool(self.success):
            parse_test(text, tally)
        for key in self.progress_keys:
            tally.getter(key)


_PROGRESS: dict[tuple, str] = {}     # progress keys, values, their types -> the text


def _amount(x: float) -> str:
    """A reward size as written in the prompt: 0.25, or 1/6 where the decimal would run on."""
    text = f"{x:g}"
    n = round(1 / x) if x else 0
    if len(text) > 5 and n and abs(1 / n - x) < 1e-9:
        return f"1/{n}"
    return text


def _fmt(v) -> str:
    return f"{v:g}" if isinstance(v, float) else str(v)


SCENARIOS: dict[str, Scenario] = {}


def scenario(**kw) -> Scenario:
    s = Scenario(**kw)
    if s.name in SCENARIOS:
        raise ValueError(f"scenario {s.name} defined twice")
    SCENARIOS[s.name] = s
    return s


def variant(base: Scenario, **kw) -> Scenario:
    s = replace(base, **kw)
    SCENARIOS[s.name] = s
    return s

