"""CraftaxTask: one task class that plays any scenario of ``scenarios`` on the engine.

A scenario is data (``scenarios.Scenario``): how the world is made and edited, the start kit, the
engine switches, the objective and the reward terms. The task builds the world at reset, steps
the engine (``rules.step``), keeps the ``Tally`` of what happened (``Tally.counters``: items got
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
from ..common.lanes import Draws
from . import hud, rules, view
from .bestiary import MOB_NAMES
from .scenarios import SCENARIOS, Scenario, parse_test
from .tables import NIGHT_LIGHT, Achievement, Action, BlockType
from .upkeep import COUNTS, held_counts

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


class Tally:
    """What happened so far in an episode, as named counters a scenario's tests read:
    ``holds.X`` (inventory now), ``got.X`` (units gained in total), ``kills.NAME`` (by mob name,
    ``kills.monsters`` = melee and ranged, ``kills.all``), ``placed.X`` (blocks placed: stone,
    crafting_table, furnace, plant, torch), ``level``, ``deepest``, ``turn``, ``night`` (turns
    lived on the surface at night), ``ate``, ``drank``, ``cast``, ``potion.EFFECT`` (potions drunk
    by effect), ``health``, ``done.X`` (an achievement, 0 or 1), ``str``/``dex``/``int``, ``xp``,
    ``enchant.sword``, ``spells``, ``gate`` (the level's kill count toward its ladder), ``boss``.

    ``getter(key)`` compiles a counter to a function of the tally, once; a step only updates the
    few running counts (items got, kills, placements), so a test costs a few attribute reads.

    ``changes`` counts the steps after which a *steady* counter (``steady``) differed from what it
    was after the step before: the counts the tally keeps (``kept``: all but ``turn`` and
    ``night``), and ``holds.X`` (not armour), ``level`` and ``done.X``, read off the state (which
    scenario events do not edit). A test asked right after a step that reads only steady
    counters gives what it gave when ``changes`` was last the same, so it need not be asked
    again (``CraftaxTask._score``, ``run_events``); the HUD's progress, made whenever asked, may
    do so only for kept counts (the state may have been edited since the step)."""

    def __init__(self, state) -> None:
        self.state = state
        self.got = dict.fromkeys(ITEMS, 0)
        self.kills: dict[str, int] = {"monsters": 0, "all": 0}
        self.placed = {b.name.lower(): 0 for b in PLACED.values()} | {"torch": 0}
        self.counts = {"turn": 0, "night": 0, "ate": 0, "drank": 0, "cast": 0,
                       "deepest": state.player_level}
        self.potions = dict.fromkeys(POTION_EFFECTS, 0)
        self._held = self._holdings(state)
        self._getters: dict = {}       # key -> getter, compiled once (``value``)
        self.changes = 0
        self._last_level, self._last_kills = state.player_level, 0     # after the last step
        self._achieved = None     # the achievements' bytes after the last step (a test reads one)
        # ``rules.step``'s ``ended``: the step sets the held counts and achievements' bytes it
        # ended with, ``after_step`` takes them (and reads them itself when no step set them)
        self.step_ended: list = [None, None]

    @staticmethod
    def _holdings(state) -> tuple:
        return held_counts(state.inventory)

    def getter(self, key: str):
        head, _, tail = key.partition(".")
        simple = {"level": lambda t: t.state.player_level, "health": lambda t: t.state.player_health,
                  "str": lambda t: t.state.player_strength, "dex": lambda t: t.state.player_dexterity,
                  "int": lambda t: t.state.player_intelligence, "xp": lambda t: t.state.player_xp,
                  "spells": lambda t: int(t.state.learned_spells.sum()),
                  "gate": lambda t: int(t.state.monsters_killed[t.state.player_level]),
                  "boss": lambda t: t.state.boss_progress}
        if key in simple:
            return simple[key]
        if key in self.counts:
            return lambda t: t.counts[key]
        if head == "holds" and tail in ITEMS:
            return lambda t: getattr(t.state.inventory, tail)
        if key == "holds.armour":
            return lambda t: int(np.count_nonzero(t.state.inventory.armour))
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
            index = Achievement[tail.upper()].value
            if self._achieved is None:      # (a test reads achievements: each step compares them)
                self._achieved = b""
            return lambda t: int(t.state.achievements.item(index))
        if key == "enchant.sword":
            return lambda t: t.state.sword_enchantment
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

    def before_step(self, state, action: int) -> None:
        """Remember what a step can change that the tally counts by difference. (The level's
        mob masks, the three classes' slots in one list: ``after_mobs`` looks at slots only
        when one changed, which few turns do.)"""
        self._vitals = (state.player_food, state.player_drink, state.player_mana)
        self._level = level = state.player_level
        self._masks = [*state.passive_mobs.mask[level], *state.melee_mobs.mask[level],
                       *state.ranged_mobs.mask[level]]
        watched = _WATCHED.get(action)
        if watched == _PLACING:
            self._ahead = self._facing_block(state)
        elif watched == _TORCH:
            self._torches = state.inventory.torches
        elif watched == _DRINKING:
            self._potions = state.inventory.potions.copy()

    @staticmethod
    def _facing_block(state) -> int:
        r, c = rules.facing(state)
        if not rules.in_bounds(state, r, c):
            return -1
        return state.map.item(state.player_level, r, c)

    def after_mobs(self, state) -> None:
        """Called by the step after the mobs moved and before any spawn: a slot live before the
        step whose mob is now gone with no health left was a kill (a despawned mob keeps its
        health; spawning could reuse the slot, which is why this runs before it). Until the
        spawn no slot comes alive and no type changes, so the slots to look at are those whose
        mask went from live to dead, and the type read now is the one before."""
        level = self._level
        groups = (state.passive_mobs, state.melee_mobs, state.ranged_mobs)
        if [*groups[0].mask[level], *groups[1].mask[level], *groups[2].mask[level]] == self._masks:
            return
        first = 0       # where the class's slots start in the remembered list
        for k, mobs in enumerate(groups):
            now = mobs.mask[level]
            for i, alive in enumerate(now):
                if self._masks[first + i] and not alive and mobs.health[level][i] <= 0:
                    self._kill(k, mobs.type_id[level][i])
            first += len(now)

    def _kill(self, kind: int, type_id: int) -> None:
        name = MOB_NAMES[kind][type_id]
        self.kills[name] = self.kills.get(name, 0) + 1
        self.kills["all"] += 1
        if kind:
            self.kills["monsters"] += 1

    def after_step(self, state, action: int) -> None:
        counts = self.counts
        counts["turn"] += 1
        changed = False          # a steady counter changed (``changes``)
        ended = self.step_ended
        held, achieved = ended
        ended[0] = ended[1] = None
        if held is None:
            held = held_counts(state.inventory)
        if held != self._held:
            for k, old, new in zip(ITEMS, self._held, held):
                if new > old:
                    self.got[k] += new - old
            self._held = held
            changed = True
        food, drink, mana = self._vitals
        if state.player_food > food:
            counts["ate"] += 1
            changed = True
        if state.player_drink > drink:
            counts["drank"] += 1
            changed = True
        watched = _WATCHED.get(action)
        if watched is None:
            pass
        elif watched == _CASTING:
            if state.player_mana < mana:
                counts["cast"] += 1
                changed = True
        elif watched == _PLACING:
            block, name = _PLACED[action]
            if self._ahead != block and self._facing_block(state) == block:
                self.placed[name] += 1
                changed = True
        elif watched == _TORCH:
            if state.inventory.torches < self._torches:
                self.placed["torch"] += 1
                changed = True
        else:
            colour = action - _RED
            if state.inventory.potions[colour] < self._potions[colour]:
                self.potions[POTION_EFFECTS[int(state.potion_mapping[colour])]] += 1
                changed = True
        if self.kills["all"] != self._last_kills:      # (every kill counts in "all")
            self._last_kills = self.kills["all"]
            changed = True
        level = state.player_level
        if level == 0 and state.light_level < NIGHT_LIGHT:
            counts["night"] += 1
        if level != self._last_level:
            self._last_level = level
            changed = True
        if level > counts["deepest"]:
            counts["deepest"] = level
            changed = True
        if self._achieved is not None:
            if achieved is None:
                achieved = state.achievements.tobytes()
            if achieved != self._achieved:
                self._achieved = achieved
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
        self.draws = Draws(self.stream("craftax"))
        self.state, self.ctx = self.scenario.build(rng)
        self.play_rng = self.stream("scenario")
        self.tally = Tally(self.state)
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

    def _act(self, action: int) -> None:
        state, tally = self.state, self.tally
        tally.before_step(state, action)
        native = rules.step(state, action, self.settings, self.draws, after_mobs=tally.after_mobs,
                            ended=tally.step_ended)
        tally.after_step(state, action)
        if self.events:     # (most scenarios have no events and no waiting mobs)
            self.scenario.run_events(self, state, tally)
        elif self.ctx.reserve:      # (all run_events does without events)
            self.ctx.admit(state, self.play_rng)
        self._score(state, tally, native)

    def _score(self, state, tally: Tally, native: float) -> None:
        """Pay the scenario's terms (``native``, upstream's reward for the step, is not paid
        here) and end the episode on death or success. Unless a steady counter changed since
        the last step (``tally.changes``), only the terms and success test that read other
        counters are asked: the others give what they gave."""
        fresh = tally.changes != self._scored_at
        self._scored_at = tally.changes
        finished = False
        for entry in self._open if fresh else self._live:
            term, count, paid = entry
            units = count(tally)
            if units > paid:
                entry[2] = units
                self.reward(term.unit * (units - paid))
                finished = finished or units >= term.cap
        if finished:
            self._open = [e for e in self._open if e[2] < e[0].cap]
            self._live = [e for e in self._live if e[2] < e[0].cap]
        if state.player_health <= 0:
            self.reward(self.scenario.death)
            self.say("You died.")
            self.finish(won=False)
        elif self._success is not None and (fresh or self._success_live) and self._success(tally):
            self.say(self.scenario.success_message)
            self.finish(won=True)

    def _grid(self) -> tuple[str, ...]:
        return view.rows(self.state)

    def _hud(self) -> str:
        tally, goal = self.tally, self._goal
        if goal is None or goal[0] != tally.changes or not self._goal_steady:
            goal = self._goal = (tally.changes, self.scenario.progress(tally))  # (a few counters)
        goal = goal[1]
        line = hud.hud(self.state, self.settings)
        return f"{line} | {goal}" if goal else line
