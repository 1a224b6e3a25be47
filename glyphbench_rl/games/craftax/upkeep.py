"""The upkeep at the end of each Craftax step (upstream ``craftax_step``'s last sub-rules, in
its order, called by ``rules.step``): ``grow_plants``, ``update_intrinsics``, ``clip_vitals``,
``inventory_achievements``, and ``daylight``, the light level of the new timestep.

They run every step whatever the action, so each reads its fields once into locals and returns
early in the common case (no plant growing, vitals in range, an inventory seen before).
"""

from __future__ import annotations

import numpy as np

from .state import MAX_GROWING_PLANTS, State
from .tables import (
    BOSS_LEVEL, DERECOVER_LIMIT, DERECOVER_RATE, DEXTERITY_DECAY, FATIGUE_LIMIT, FATIGUE_RESTED,
    GOD_MODE_MIN_HEALTH, HUNGER_LIMIT, INTELLIGENCE_MANA_BONUS, INVENTORY_ACHIEVEMENTS,
    MANA_LIMIT, MANA_RATE, PLANT_RIPE_AGE, RECOVER_LIMIT, RECOVER_RATE, SLEEP_INTRINSIC_RATE,
    STACK_LIMIT, THIRST_LIMIT, Achievement, Action, BlockType, light_level, max_drink, max_energy,
    max_food, max_health, max_mana,
)

_RIPE = int(BlockType.RIPE_PLANT)
_SLEEP, _REST = int(Action.SLEEP), int(Action.REST)
_WAKE_UP = int(Achievement.WAKE_UP)


# the plant slots' bytes with no plant growing and every age 0 (as the state keeps them: a bool
# and an int32 a slot; slots kept otherwise take the rule's path, which changes nothing then)
_NO_PLANTS, _NO_AGES = bytes(MAX_GROWING_PLANTS), bytes(4 * MAX_GROWING_PLANTS)


def grow_plants(state: State) -> None:
    """Growing plants (level 0) age by one (a free slot's age stays 0); at ``PLANT_RIPE_AGE``
    their block is a ripe plant."""
    mask = state.growing_plants_mask
    age = state.growing_plants_age
    if mask.tobytes() == _NO_PLANTS and age.tobytes() == _NO_AGES:
        return          # (no plant growing and every age 0, the common case: nothing changes)
    age += 1
    age *= mask
    if age.max() >= PLANT_RIPE_AGE:
        for i in np.flatnonzero(age >= PLANT_RIPE_AGE):
            r, c = state.growing_plants_positions[i]
            state.map[0, r, c] = _RIPE


def update_intrinsics(state: State, action: int, settings) -> None:
    """Sleep and rest start and end; hunger, thirst and fatigue accumulate (slower with
    dexterity, hunger and thirst at half speed asleep) and cost food, drink, energy at their
    limits; sleep restores energy; health recovers while food, drink and energy (or sleep) last
    and is lost otherwise; mana recovers (faster with intelligence, double asleep). In the boss
    fight the needs do not fall and health is not lost. ``settings.intrinsics`` off stops the
    drains: hunger, thirst and an awake player's fatigue no longer grow, so food, drink and
    energy never fall; sleep still restores energy (and so ends), health and mana still
    recover."""
    # (this runs every step: the fields are read once into locals and written once, and the
    # maxima and health are read only where needed, which an awake, not resting turn with no
    # need at its limit never does. Nothing here writes health before it is read.)
    dex, energy = state.player_dexterity, state.player_energy
    asleep = state.is_sleeping
    if asleep or action == _SLEEP:
        top_energy = max_energy(dex)
        if action == _SLEEP and energy < top_energy:
            asleep = state.is_sleeping = True
        if asleep and energy >= top_energy:
            asleep = state.is_sleeping = False
            state.achievements[_WAKE_UP] = True
    food, drink = state.player_food, state.player_drink
    if action == _REST or state.is_resting:
        health, top_health = state.player_health, max_health(state.player_strength)
        if action == _REST and health < top_health:
            state.is_resting = True
        if state.is_resting and (health >= top_health or food <= 0 or drink <= 0):
            state.is_resting = False

    fall = 0 if state.player_level == BOSS_LEVEL else 1
    decay = 1.0 - DEXTERITY_DECAY * (dex - 1)
    intrinsics = settings.intrinsics
    if intrinsics:
        rate = (SLEEP_INTRINSIC_RATE if asleep else 1.0) * decay
        hunger = state.player_hunger + rate
        if hunger > HUNGER_LIMIT:
            food = state.player_food = max(food - fall, 0)
            hunger = 0.0
        state.player_hunger = hunger
        thirst = state.player_thirst + rate
        if thirst > THIRST_LIMIT:
            drink = state.player_drink = max(drink - fall, 0)
            thirst = 0.0
        state.player_thirst = thirst
    if intrinsics or asleep:      # (asleep, fatigue only falls: energy only grows)
        fatigue = min(state.player_fatigue - 1, 0) if asleep else state.player_fatigue + decay
        if fatigue > FATIGUE_LIMIT:
            energy = state.player_energy = max(energy - fall, 0)
            fatigue = 0.0
        elif fatigue < FATIGUE_RESTED:
            energy = state.player_energy = min(energy + 1, max_energy(dex))
            fatigue = 0.0
        state.player_fatigue = float(fatigue)

    if food > 0 and drink > 0 and (energy > 0 or asleep):   # the needs are met
        recover = state.player_recover + RECOVER_RATE[asleep]
    else:
        recover = state.player_recover + DERECOVER_RATE[asleep] * fall
    if recover > RECOVER_LIMIT:
        state.player_health = min(state.player_health + 1, max_health(state.player_strength))
        recover = 0.0
    elif recover < DERECOVER_LIMIT:
        state.player_health -= 1
        recover = 0.0
    state.player_recover = recover

    mana = (state.player_recover_mana + MANA_RATE[asleep]) * (
        1 + INTELLIGENCE_MANA_BONUS * (state.player_intelligence - 1))
    if mana > MANA_LIMIT:
        state.player_mana += 1
        mana = 0.0
    state.player_recover_mana = float(mana)


# the inventory's counts (every one at most STACK_LIMIT), those ``INVENTORY_ACHIEVEMENTS``
# reads first, in its order; ``held_counts`` reads them (the tally too)
_INVENTORY_NAMES = tuple(dict.fromkeys(name for name, _, _ in INVENTORY_ACHIEVEMENTS))
COUNTS = _INVENTORY_NAMES + ("books",)
# (index into the held counts, at least, achievement)
_INVENTORY_ACHIEVEMENTS = tuple((_INVENTORY_NAMES.index(name), least, int(a))
                                for name, least, a in INVENTORY_ACHIEVEMENTS)


def held_counts(inv) -> tuple:
    """The inventory's ``COUNTS``, in that order. (Written out: it runs several times a step,
    and attribute reads cost half of ``operator.attrgetter``'s.)"""
    return (inv.wood, inv.stone, inv.coal, inv.iron, inv.diamond, inv.ruby, inv.sapphire,
            inv.sapling, inv.bow, inv.arrows, inv.torches, inv.pickaxe, inv.sword, inv.books)


assert COUNTS == ("wood", "stone", "coal", "iron", "diamond", "ruby", "sapphire", "sapling", "bow",
                  "arrows", "torches", "pickaxe", "sword", "books")


# held counts (``COUNTS`` order) -> (some count is over STACK_LIMIT, the achievements they
# earn, those as a mask of the bits ``int.from_bytes(achievements.tobytes(), "little")`` has).
# The inventory changes on few turns, so ``clip_vitals`` and ``inventory_achievements`` mostly
# find the counts they looked up last (``_LAST``: no hash of the 14 counts), else look them up
# here.
_FACTS: dict[tuple, tuple[bool, tuple[int, ...], int]] = {}
# the held counts looked up last and their facts; the held counts and achievements' bytes
# ``inventory_achievements`` last found every earned achievement in. Each is one pair, read and
# replaced whole (process-wide memos of pure functions: a pair is never seen half written)
_LAST: list = [(None, None)]
_EARNED: list = [(None, None)]


def _facts(held: tuple) -> tuple[bool, tuple[int, ...], int]:
    """``_FACTS[held]`` (made the first time), remembered in ``_LAST``."""
    facts = _FACTS.get(held)
    if facts is None:
        if len(_FACTS) >= 4096:
            _FACTS.clear()
        earned = tuple(a for i, least, a in _INVENTORY_ACHIEVEMENTS if held[i] >= least)
        facts = _FACTS[held] = (max(held) > STACK_LIMIT, earned, sum(1 << 8 * a for a in earned))
    _LAST[0] = held, facts
    return facts


# the least maximum of any vital: each maximum grows with its attribute, which is at least 1
_LEAST_TOP = min(max_health(1), max_food(1), max_drink(1), max_energy(1), max_mana(1))
assert all(f(a + 1) > f(a) >= _LEAST_TOP for f in (max_health, max_food, max_drink, max_energy,
                                                    max_mana) for a in range(1, 20))


def clip_vitals(state: State, settings) -> tuple:
    """Inventory counts at most 99; vitals within [0, maximum] (the maxima grow with the
    attributes); god mode keeps health at least 9. Returns the held counts after the clip
    (``held_counts``: nothing else in the upkeep changes them; ``inventory_achievements`` reads
    them)."""
    inv = state.inventory
    held = held_counts(inv)
    last = _LAST[0]
    if (last[1] if held == last[0] else _facts(held))[0]:
        for name in COUNTS:
            if getattr(inv, name) > STACK_LIMIT:
                setattr(inv, name, STACK_LIMIT)
        held = held_counts(inv)
    # (armour is at most 2; potions only grow in chests, whose loot clips them)
    dex, strength, intelligence = (state.player_dexterity, state.player_strength,
                                   state.player_intelligence)
    low = GOD_MODE_MIN_HEALTH if settings.god_mode else 0
    health, food, drink, energy, mana = (state.player_health, state.player_food,
                                         state.player_drink, state.player_energy,
                                         state.player_mana)
    if (low <= health <= _LEAST_TOP and 0 <= food <= _LEAST_TOP and 0 <= drink <= _LEAST_TOP
            and 0 <= energy <= _LEAST_TOP and 0 <= mana <= _LEAST_TOP
            and strength >= 1 and dex >= 1 and intelligence >= 1):
        return held     # (within every maximum: the usual turn, no maximum worked out)
    top = max_health(strength)
    if health < low or health > top:
        state.player_health = float(min(max(health, low), top))
    top = max_food(dex)    # = max_drink(dex) = max_energy(dex)
    if not (0 <= food <= top and 0 <= drink <= top and 0 <= energy <= top):
        state.player_food = min(max(food, 0), top)
        state.player_drink = min(max(drink, 0), top)
        state.player_energy = min(max(energy, 0), top)
    top = max_mana(intelligence)
    if not (0 <= mana <= top):
        state.player_mana = min(max(mana, 0), top)
    return held


def inventory_achievements(state: State, held: tuple | None = None) -> bytes:
    """Collecting and crafting achievements read off the inventory (``INVENTORY_ACHIEVEMENTS``),
    so a tool found in a chest counts as made. ``held``: the inventory's ``held_counts``, if
    known. Returns the achievements' bytes after (the step's reward compares them).

    (What the counts earn is looked up, and written only when one of them is missing; the
    counts and achievements last found complete are remembered, so the usual turn, which
    changes neither, compares them and is done.)"""
    if held is None:
        held = held_counts(state.inventory)
    ach = state.achievements
    now = ach.tobytes()
    earned_in = _EARNED[0]
    if now == earned_in[1] and held == earned_in[0]:
        return now
    last = _LAST[0]
    _, earned, mask = last[1] if held == last[0] else _facts(held)
    if mask and mask & ~int.from_bytes(now, "little"):
        for achievement in earned:
            ach[achievement] = True
        now = ach.tobytes()
    _EARNED[0] = held, now
    return now


_DAYLIGHT: dict[int, dict[int, float]] = {}     # day length -> timestep -> light_level


def daylight(timestep: int, settings) -> float:
    """The light level at ``timestep``: upstream's daylight, or full day with the cycle off.
    (Remembered: a cosine and a cube each step otherwise.)"""
    if not settings.daylight:
        return 1.0
    day = _DAYLIGHT.get(settings.day_length)
    if day is None or len(day) >= 10_000:
        day = _DAYLIGHT[settings.day_length] = {}
    light = day.get(timestep)
    if light is None:
        light = day[timestep] = light_level(timestep, settings.day_length)
    return light
