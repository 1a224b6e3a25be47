"""CraftaxTask: one task class that plays any scenario of ``scenarios`` on the engine.

A scenario is data (``scenarios.Scenario``): how the world is made and edited, the start kit, the
engine switches, the objective and the reward terms. The task builds the world at reset, steps
the compiled engine (``kernel``: ``rules.step`` on the packed state, one call a step), keeps the ``Tally`` of what happened (``Tally.counters``: items got
and held, kills by mob, blocks placed, floors reached, achievements ...), pays the scenario's
reward terms from it and ends the episode on the scenario's success test or on death. Nothing here
changes a rule of the game: upstream's native reward is not paid; the scenario's terms are.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np

from ...core import GlyphTask
from ...core.actions import ActionSet
from ...core.params import param
from . import hud, kernel, kernel_view, view
from .bestiary import MOB_NAMES
from .scenarios import SCENARIOS, Scenario, parse_test
from .packed import (ACH, ARMOUR, BOSS_PROGRESS, COL, DEX, DIRECTION, FREE, HEALTH, INT, INV,
                     INVENTORY, KILLED, LEVEL, NIGHTS, POTION_MAP, ROW, SPELLS, STEP_FLAGS, STEPS,
                     STR, SWORD_ENCH, XP, KernelDraws, Packed, pack, unpack)
from .state import MAP_SIZE, State
from .tables import DIRECTIONS, Achievement, Action, BlockType
from .upkeep import COUNTS

SINGLE = [
    ("NOOP", "do nothing"),
    ("DO", "act on the faced cell"),
    ("SLEEP", "sleep until energy is full (a sleeper is hit harder)"),
    ("REST", "rest until health is full"),
    ("DESCEND", "take the ladder down you stand on"), ("ASCEND", "take the ladder up you stand on"),
    ("SHOOT_ARROW", "shoot an arrow ahead (needs a bow)"),
    ("READ_BOOK", "learn a spell from a book"),
]
GROUPS = [
    ("step that way, or turn to face it when blocked", ("LEFT", "RIGHT", "UP", "DOWN")),
    ("place on the faced cell", ("PLACE_STONE", "PLACE_TABLE", "PLACE_FURNACE", "PLACE_PLANT", "PLACE_TORCH")),
    ("craft it", tuple(a.name for a in Action if a.name.startswith("MAKE_"))),
    ("cast ahead (2 mana)", ("CAST_FIREBALL", "CAST_ICEBALL")),
    ("drink a potion of that colour", tuple(a.name for a in Action if a.name.startswith("DRINK_POTION_"))),
    ("at a faced enchantment table: 9 mana and a ruby (fire) or sapphire (ice)",
     ("ENCHANT_SWORD", "ENCHANT_ARMOUR", "ENCHANT_BOW")),
    ("spend 1 XP on it", ("LEVEL_UP_DEXTERITY", "LEVEL_UP_STRENGTH", "LEVEL_UP_INTELLIGENCE")),
]
# numbered as upstream's Action (index i is Action(i)); the prompt groups similar actions
ACTIONS = ActionSet(SINGLE, groups=GROUPS, noop="NOOP", order=[a.name for a in Action])

# inventory fields the tally follows (counts; tools are tiers), in ``held_counts``' order
ITEMS = COUNTS
PLACED = {Action.PLACE_STONE: BlockType.STONE, Action.PLACE_TABLE: BlockType.CRAFTING_TABLE,
          Action.PLACE_FURNACE: BlockType.FURNACE, Action.PLACE_PLANT: BlockType.PLANT}
CASTS = frozenset(int(a) for a in (Action.CAST_FIREBALL, Action.CAST_ICEBALL))
DRINKS = frozenset(range(Action.DRINK_POTION_RED, Action.DRINK_POTION_YELLOW + 1))
_PLACE_TORCH, _RED = int(Action.PLACE_TORCH), int(Action.DRINK_POTION_RED)   # (ints: read each step)
# the actions whose effect the tally finds by a difference (one look-up a step): a placement
# (the block placed and its counter name), a torch, a potion, a spell
_PLACING, _TORCH, _DRINKING, _CASTING = range(1, 5)
_WATCHED = ({int(a): _PLACING for a in PLACED} | {_PLACE_TORCH: _TORCH}
            | dict.fromkeys(DRINKS, _DRINKING) | dict.fromkeys(CASTS, _CASTING))
_PLACED = {int(a): (int(b), b.name.lower()) for a, b in PLACED.items()}
POTION_EFFECTS = ("heal", "harm", "mana", "drain", "energy", "tire")   # upstream's effect order
_HELD_AT = tuple(INV + INVENTORY.index(name) for name in ITEMS)    # (packed offsets, ITEMS order)
_FACING = {int(a): d for a, d in DIRECTIONS.items()}
# the step's flags (``kernel``) the tally counts from; a step with none costs a turn's count
_COUNTED = (kernel.CHANGED_INVENTORY | kernel.ATE | kernel.DRANK | kernel.SPENT_MANA
            | kernel.USED_TORCH | kernel.DRANK_POTION | kernel.KILLED_MOB | kernel.CHANGED_LEVEL
            | kernel.CHANGED_ACHIEVEMENTS)
# what an edit of the state between steps may have changed that the tally compares with what it
# saw last (its holdings, level, achievements): the next step looks at them whatever it changed
_EDITED = kernel.CHANGED_INVENTORY | kernel.CHANGED_LEVEL | kernel.CHANGED_ACHIEVEMENTS
# what the next frame makes anew (``CraftaxTask._stale``): the window (the step draws it; an
# edit or a reset does not), the HUD line's text (``CHANGED_HUD``), its position (``MOVED``)
# and whether the step changed the window it drew (``CHANGED_WINDOW``: its rows decoded anew)
_WINDOW = 1 << 20
_HUD_STALE = kernel.CHANGED_HUD | kernel.MOVED
_SHOWN = _HUD_STALE | kernel.CHANGED_WINDOW | kernel.CHANGED_LEGEND   # (the step's flags for what is on show)
_ALL_STALE = _WINDOW | _SHOWN
# (the step's bits read every step, as module ints)
_REFILL, _DEAD, _CHANGED_HUD, _MOVED, _CHANGED_WINDOW, _CHANGED_LEGEND = (
    kernel.REFILL, kernel.DEAD, kernel.CHANGED_HUD, kernel.MOVED, kernel.CHANGED_WINDOW,
    kernel.CHANGED_LEGEND)
_WINDOW_STALE = _WINDOW | _CHANGED_WINDOW | _CHANGED_LEGEND


class Tally:
    """What happened so far in an episode, as named counters a scenario's tests read:
    ``holds.X`` (inventory now), ``got.X`` (units gained in total), ``kills.NAME`` (by mob name,
    ``kills.monsters`` = melee and ranged, ``kills.all``), ``placed.X`` (blocks placed: stone,
    crafting_table, furnace, plant, torch), ``level``, ``deepest``, ``turn``, ``night`` (turns
    lived on the surface at night), ``ate``, ``drank``, ``cast``, ``potion.EFFECT`` (potions drunk
    by effect), ``health``, ``done.X`` (an achievement, 0 or 1), ``str``/``dex``/``int``, ``xp``,
    ``enchant.sword``, ``spells``, ``gate`` (the level's kill count toward its ladder), ``boss``.

    It reads the packed state the kernel plays (``packed``): ``getter(key)`` compiles a counter
    to a function of the tally, once; a step only updates the few running counts (items got,
    kills, placements), so a test costs a few reads.

    ``changes`` counts the steps after which a *steady* counter (``steady``) differed from what it
    was after the step before: the counts the tally keeps (``kept``: all but ``turn`` and
    ``night``), and ``holds.X`` (not armour), ``level`` and ``done.X``, read off the state (which
    scenario events do not edit). A test asked right after a step that reads only steady
    counters gives what it gave when ``changes`` was last the same, so it need not be asked
    again (``CraftaxTask._score``, ``run_events``); the HUD's progress, made whenever asked, may
    do so only for kept counts (the state may have been edited since the step)."""

    def __init__(self, p: Packed) -> None:
        self.p = p
        self.ints, self.floats, self.kill_counts = p.ints, p.floats, p.kills
        self.got = dict.fromkeys(ITEMS, 0)
        self.kills: dict[str, int] = {"monsters": 0, "all": 0}
        self.placed = {b.name.lower(): 0 for b in PLACED.values()} | {"torch": 0}
        # (``turn`` and ``night`` are the step's counts: ``STEPS``, ``NIGHTS``)
        self.counts = {"ate": 0, "drank": 0, "cast": 0, "deepest": self.ints.item(LEVEL)}
        self.potions = dict.fromkeys(POTION_EFFECTS, 0)
        self._held = self._holdings()
        self._killed = self.kill_counts.copy()       # the kill counts counted
        self._getters: dict = {}       # key -> getter, compiled once (``value``)
        self.changes = 0
        self._last_level = self.ints.item(LEVEL)     # after the last step
        self._achieved = None     # not None: a test reads an achievement (a change is steady)

    def _holdings(self) -> tuple:
        return tuple(map(self.ints.item, _HELD_AT))

    def getter(self, key: str):
        head, _, tail = key.partition(".")
        simple = {"level": lambda t: t.ints.item(LEVEL), "health": lambda t: t.floats.item(HEALTH),
                  "str": lambda t: t.ints.item(STR), "dex": lambda t: t.ints.item(DEX),
                  "int": lambda t: t.ints.item(INT), "xp": lambda t: t.ints.item(XP),
                  "spells": lambda t: t.ints.item(SPELLS) + t.ints.item(SPELLS + 1),
                  "gate": lambda t: t.ints.item(KILLED + t.ints.item(LEVEL)),
                  "boss": lambda t: t.ints.item(BOSS_PROGRESS),
                  "turn": lambda t: t.ints.item(STEPS), "night": lambda t: t.ints.item(NIGHTS)}
        if key in simple:
            return simple[key]
        if key in self.counts:
            return lambda t: t.counts[key]
        if head == "holds" and tail in ITEMS:
            at = INV + INVENTORY.index(tail)
            return lambda t: t.ints.item(at)
        if key == "holds.armour":
            return lambda t: int(np.count_nonzero(t.ints[ARMOUR:ARMOUR + 4]))
        if head == "got" and tail in ITEMS:
            return lambda t: t.got[tail]
        if head == "kills":      # mob names have spaces; a test writes them with _ (kills.fire_elemental)
            name = tail.replace("_", " ")
            return lambda t: t.kills.get(name, 0)
        if head == "placed" and tail in self.placed:
            return lambda t: t.placed[tail]
        if head == "potion" and tail in self.potions:
            return lambda t: t.potions[tail]
        if head == "done" and tail.upper() in Achievement.__members__:
            at = ACH + Achievement[tail.upper()].value
            self._achieved = True      # (a test reads achievements: a change counts)
            return lambda t: t.ints.item(at)
        if key == "enchant.sword":
            return lambda t: t.ints.item(SWORD_ENCH)
        raise KeyError(f"unknown Craftax counter {key!r} (see task.Tally)")

    @staticmethod
    def kept(key: str) -> bool:
        """``key`` is a count the tally keeps that only a step bumping ``changes`` changes."""
        return (key.partition(".")[0] in ("got", "kills", "placed", "potion")
                or key in ("ate", "drank", "cast", "deepest"))

    @classmethod
    def steady(cls, key: str) -> bool:
        """``key`` is kept, or read off the state and followed by ``changes`` (see the class)."""
        head, _, tail = key.partition(".")
        return (cls.kept(key) or head == "done" or (head == "holds" and tail in ITEMS)
                or key == "level")

    def steady_test(self, text: str) -> bool:
        """A scenario test (``"got.wood >= 3 and level >= 1"``) or bare counter reads only steady
        counters: its value changes only in a step that bumps ``changes``."""
        return all(self.steady(key) for key in re.findall(r"[a-z_][a-z0-9_.]*", text)
                   if key != "and")

    def value(self, key: str) -> float:
        get = self._getters.get(key)
        if get is None:
            get = self._getters[key] = self.getter(key)
        return get(self)

    def facing_block(self) -> int:
        """The block the player faces (-1 off the map)."""
        ints = self.ints
        dr, dc = _FACING.get(ints.item(DIRECTION), (0, 0))
        r, c = ints.item(ROW) + dr, ints.item(COL) + dc
        if not (0 <= r < MAP_SIZE[0] and 0 <= c < MAP_SIZE[1]):
            return -1
        return self.p.map.item(ints.item(LEVEL), r, c)

    def _count_kills(self) -> None:
        """The kills since the last look, by class and type, from the kernel's kill counts."""
        now, old = self.kill_counts, self._killed
        for kind, type_id in zip(*np.nonzero(now != old)):
            n = int(now[kind, type_id] - old[kind, type_id])
            name = MOB_NAMES[kind][type_id]
            self.kills[name] = self.kills.get(name, 0) + n
            self.kills["all"] += n
            if kind:
                self.kills["monsters"] += n
        self._killed = now.copy()

    def after_step(self, action: int, flags: int, ahead: int | None) -> None:
        """Count the step the kernel just played, called when ``flags`` (what it changed:
        ``kernel``'s bits) has one of ``_COUNTED`` (the step counts the turns and the nights
        itself); ``ahead``, the block the player faced before it, for a placing action."""
        counts = self.counts
        changed = False          # a steady counter changed (``changes``)
        ints = self.ints
        if flags & kernel.CHANGED_INVENTORY:
            held = self._holdings()
            if held != self._held:
                for k, old, new in zip(ITEMS, self._held, held):
                    if new > old:
                        self.got[k] += new - old
                self._held = held
                changed = True
        if flags & kernel.ATE:
            counts["ate"] += 1
            changed = True
        if flags & kernel.DRANK:
            counts["drank"] += 1
            changed = True
        watched = _WATCHED.get(action)
        if watched is None:
            pass
        elif watched == _CASTING:
            if flags & kernel.SPENT_MANA:
                counts["cast"] += 1
                changed = True
        elif watched == _PLACING:
            block, name = _PLACED[action]
            if ahead != block and self.facing_block() == block:
                self.placed[name] += 1
                changed = True
        elif watched == _TORCH:
            if flags & kernel.USED_TORCH:
                self.placed["torch"] += 1
                changed = True
        elif flags & kernel.DRANK_POTION:    # (only drinking lowers a potion count)
            self.potions[POTION_EFFECTS[ints.item(POTION_MAP + action - _RED)]] += 1
            changed = True
        if flags & kernel.KILLED_MOB:
            self._count_kills()
            changed = True
        if flags & kernel.CHANGED_LEVEL:
            level = ints.item(LEVEL)
            if level != self._last_level:
                self._last_level = level
                changed = True
            if level > counts["deepest"]:
                counts["deepest"] = level
                changed = True
        if flags & kernel.CHANGED_ACHIEVEMENTS and self._achieved is not None:
            changed = True
        if changed:
            self.changes += 1


@dataclass(frozen=True)
class CraftaxParams:
    scenario: str = param("firstday", choices=tuple(SCENARIOS))


class CraftaxTask(GlyphTask):
    title = "Craftax"
    Params = CraftaxParams
    ACTIONS = ACTIONS
    glyphs = view.VOCAB
    default_max_turns = 200
    rules = "{intro}{objective} {game_rules}"
    rewards = "{reward_text}"
    ends = "{ends_text}"

    scenario: Scenario

    def _init(self) -> None:
        self.scenario = SCENARIOS[self.params.scenario]
        self.settings = self.scenario.settings


    def prompt_fields(self) -> dict:
        s = self.scenario
        intro = s.intro()
        return {"intro": intro + " " if intro else "", "objective": s.objective, "game_rules": view.rules_text(topics=s.topics, drains=self.settings.intrinsics),
                "reward_text": s.reward_text(), "ends_text": s.ends_text()}

    def _setup(self, rng: np.random.Generator) -> None:
        self._state, self.ctx = self.scenario.build(rng)
        self.packed = pack(self._state, self.settings)
        self.kernel_draws = KernelDraws(self.stream("craftax"))
        self.kernel_draws.top_up(self.packed)
        self._lent = False      # the State was handed out (``state``): it is kept in step
        self._edited = 0        # what edits between steps may have changed (``_EDITED``)
        self.window = kernel_view.Window(self.packed)     # (the window the step draws)
        self.line = hud.Line()
        self._play, self._arena = kernel.entry(), self.packed.arena
        self._stale = _ALL_STALE
        self.play_rng = self.stream("scenario")
        self.tally = Tally(self.packed)
        tally, scenario = self.tally, self.scenario
        # (term, its units as a function of the tally, units paid); a term drops out once it
        # can pay no more. ``_live``: those that read a counter that is not steady (Tally)
        self._open = [[term, term.counter(parse_test(term.test, tally)), 0]
                      for term in scenario.terms]
        self._live = [e for e in self._open if not tally.steady_test(e[0].test)]
        self._success = parse_test(scenario.success, tally) if scenario.success else None
        self._success_live = bool(scenario.success) and not tally.steady_test(scenario.success)
        self.events = [(e, parse_test(e.when, tally), tally.steady_test(e.when))
                       for e in scenario.events]
        self.fired: set[int] = set()             # scenario events already run
        self._scored_at = self.events_at = None  # ``tally.changes`` when last scored, events run
        # the HUD's progress and the ``tally.changes`` it was made at, when its keys are steady
        self._goal: tuple | None = None
        self._goal_steady = all(tally.kept(k) for k in scenario.progress_keys)

    @property
    def state(self) -> State:
        """The game as a ``State`` (``state.py``, upstream's fields), for planners, tests and
        edits. The task plays the packed state (``packed``, ``kernel``); once the State has been
        asked for, the two are kept in step at every step, so an edit to it is played and a
        reference to it sees each step."""
        if not self._lent:
            unpack(self.packed, self._state)
            self._lent = True
        return self._state

    def edit(self, change) -> None:
        """Run ``change(state)`` on the State and play on from what it leaves (scenario events,
        waiting mobs)."""
        state = self._state
        if not self._lent:
            unpack(self.packed, state)
        change(state)
        if not self._lent:
            self._repack()
        self._edited = _EDITED

    def _take_edits(self) -> None:
        """The State handed out may have been edited since: play (and show) what it holds."""
        if self._lent:
            self._repack()
            self._edited = _EDITED

    def _repack(self) -> None:
        """The State into the packed state; everything on show is made anew."""
        pack(self._state, self.settings, into=self.packed)
        self._stale = _ALL_STALE

    def _act(self, action: int) -> None:
        p, tally = self.packed, self.tally
        if self._lent:
            self._take_edits()
        ahead = tally.facing_block() if action in _PLACED else None
        native = self._play(self._arena, action)
        self._flags = flags = p.ints.item(STEP_FLAGS)
        if self._edited:
            flags |= self._edited
            self._edited = 0
            self._stale = _SHOWN      # (the frame was made before the edits: all of it anew)
        else:
            self._stale = flags & _SHOWN       # (the step drew the window it leaves)
        if flags & _REFILL:
            self.kernel_draws.top_up(p)
        if self._lent:
            unpack(p, self._state)
        if flags & _COUNTED:
            tally.after_step(action, flags, ahead)
        if self.events:     # (most scenarios have no events and no waiting mobs)
            self.scenario.run_events(self, tally)
        elif self.ctx.reserve:      # (all run_events does without events)
            self.admit()
        self._score(tally, native)

    def admit(self) -> None:
        """Waiting mobs take free slots (``scenarios.Context.admit``); nothing to do while every
        class they wait for is full, as the last call left them."""
        ctx = self.ctx
        waited, classes = ctx.waited
        if ctx.reserve == waited and classes:
            if classes != self._admit_classes:
                self._admit_classes, self._admit_bits = classes, sum(1 << k for k in classes)
            if not self.packed.ints.item(FREE) & self._admit_bits:   # (the step keeps FREE)
                return
        self.edit(lambda state: ctx.admit(state, self.play_rng))

    _flags = 0      # the last step's flags (``kernel``)
    _admit_classes, _admit_bits = None, 0     # the classes ``admit`` last waited for, as bits

    def _score(self, tally: Tally, native: float) -> None:
        """Pay the scenario's terms (``native``, upstream's reward for the step, is not paid
        here) and end the episode on death or success. Unless a steady counter changed since
        the last step (``tally.changes``), only the terms and success test that read other
        counters are asked: the others give what they gave."""
        changes = tally.changes
        fresh = changes != self._scored_at
        if fresh:
            self._scored_at = changes
        entries = self._open if fresh else self._live
        if entries:
            finished = False
            for entry in entries:
                term, count, paid = entry
                units = count(tally)
                if units > paid:
                    entry[2] = units
                    self.reward(term.unit * (units - paid))
                    finished = finished or units >= term.cap
            if finished:
                self._open = [e for e in self._open if e[2] < e[0].cap]
                self._live = [e for e in self._live if e[2] < e[0].cap]
        # (the step flags a death; an edit after it, a scenario event, may have changed it)
        if (self.packed.floats.item(HEALTH) <= 0 if self._edited else self._flags & _DEAD):
            self.reward(self.scenario.death)
            self.say("You died.")
            self.finish(won=False)
        elif self._success is not None and (fresh or self._success_live) and self._success(tally):
            self.say(self.scenario.success_message)
            self.finish(won=True)

    def _grid(self) -> tuple[str, ...]:
        if self._lent:
            self._take_edits()
        stale = self._stale
        if stale & _WINDOW:
            self._stale = stale & ~_WINDOW_STALE
            return self.window.rows(self.packed)
        if stale & _CHANGED_WINDOW:
            self._stale = stale & ~_WINDOW_STALE
            return self.window.shown(stale & _CHANGED_LEGEND)
        return self.window.last      # (the window shown last, drawn again the same)

    _legends = None     # the Legends whose entries were found to be the window's

    def _glyph_bits(self, legends) -> int | None:
        # (the window's codes, collected as it was drawn; a legend of other entries reads rows)
        if legends is not self._legends:
            if legends.entries != kernel_view.ENTRIES:
                return None
            self._legends = legends
        return self.window.bits

    def _hud(self) -> str:
        tally, goal = self.tally, self._goal
        if goal is None or goal[0] != tally.changes or not self._goal_steady:
            goal = self._goal = (tally.changes, self.scenario.progress(tally))  # (a few counters)
        goal = goal[1]
        line = self._line()
        if line is not self._hud_parts[0] or goal != self._hud_parts[1]:
            self._hud_parts = (line, goal, f"{line} | {goal}" if goal else line)
        return self._hud_parts[2]

    _hud_parts = (None, None, "")     # the line, the goal and the HUD made of them, last made

    def _line(self) -> str:
        """The HUD line of the packed state (``hud.Line``), made anew as far as ``_stale`` says."""
        if self._lent:
            self._take_edits()
        stale = self._stale
        if stale & _CHANGED_HUD:
            line = self.line.update(self.packed)
        elif stale & _MOVED:
            line = self.line.moved(self.packed)
        else:
            return self.line.line
        self._stale = stale & ~_HUD_STALE
        return line
