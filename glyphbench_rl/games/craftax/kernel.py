"""``rules.step`` compiled: the whole Craftax step on the packed state (``packed``).

``step(p, action)`` is ``rules.step(state, action, settings, draws)`` for the state ``p`` packs:
the action's rules (``kernel_rules.act``), the mobs (``kernel_mobs.update``, ``spawn``), the
upkeep (``kernel_rules.upkeep``), the reward, the timestep and its light level, in upstream's
order, with the same draws. Each compiled module is its reference module's sub-rules one for one
(``kernel_rules``: ``rules`` and ``upkeep``; ``kernel_mobs``: ``mobs``);
``tests/games/craftax/test_craftax_kernel*.py`` play the reference and the kernel side by side and
find the same state after every step. The task plays the kernel (``task.CraftaxTask``); the
reference stays the readable rules, the one the fidelity tests hold against upstream Craftax.

The step also writes ``ints[STEP_FLAGS]``: which of the things the task's tally counts changed
(the ``CHANGED_*`` bits, so that a step that changed none costs the tally nothing), and
``REFILL`` when fewer than ``DRAWS_RESERVE`` draws are left for the next step.

The compiled step is called through its entry point for the packed arrays' types (``_entry``):
numba's dispatcher works out the types of a call's twelve arguments every time, which costs more
than the step itself; ``pack`` checks that the maps have those types.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, typeof

from . import kernel_mobs, kernel_rules
from .packed import (ACH, BOOKS, DRAW_AT, DRAWS_RESERVE, DRINK, FOOD, HEALTH, INV, LEVEL, LIGHT,
                     MANA, POTIONS, SET_DAY_LENGTH, SET_DAYLIGHT, SET_SPAWNING, STEP_FLAGS,
                     TIMESTEP, TORCHES, Packed)
from .tables import ACHIEVEMENT_REWARD, NIGHT_LIGHT

_WEIGHTS = np.array(ACHIEVEMENT_REWARD, np.float64)
_ACHIEVEMENTS = len(ACHIEVEMENT_REWARD)

# ``ints[STEP_FLAGS]``'s bits: what the step changed
(CHANGED_INVENTORY, ATE, DRANK, SPENT_MANA, USED_TORCH, DRANK_POTION, KILLED_MOB, CHANGED_LEVEL,
 CHANGED_ACHIEVEMENTS, NIGHT_ON_SURFACE, REFILL) = (1 << i for i in range(11))


@njit(cache=True)
def light_level(timestep, day_length):
    """``tables.light_level`` (the same bits: ``x ** 3.0`` is libm's pow, as Python's)."""
    progress = (timestep / day_length) % 1 + 0.3
    return 1.0 - abs(math.cos(math.pi * progress)) ** 3.0


@njit(cache=True)
def _changed(before, ints, start, stop):
    for i in range(start, stop):
        if ints[i] != before[i]:
            return True
    return False


@njit(cache=True)
def _flags(before, ints, floats, kills_before, kills, draws):
    flags = 0
    if _changed(before, ints, INV, BOOKS + 1):
        flags |= CHANGED_INVENTORY
    if ints[FOOD] > before[FOOD]:
        flags |= ATE
    if ints[DRINK] > before[DRINK]:
        flags |= DRANK
    if ints[MANA] < before[MANA]:
        flags |= SPENT_MANA
    if ints[TORCHES] < before[TORCHES]:
        flags |= USED_TORCH
    for i in range(POTIONS, POTIONS + 6):
        if ints[i] < before[i]:
            flags |= DRANK_POTION
    if kills.sum() != kills_before:
        flags |= KILLED_MOB
    if ints[LEVEL] != before[LEVEL]:
        flags |= CHANGED_LEVEL
    if _changed(before, ints, ACH, ACH + _ACHIEVEMENTS):
        flags |= CHANGED_ACHIEVEMENTS
    if ints[LEVEL] == 0 and floats[LIGHT] < NIGHT_LIGHT:
        flags |= NIGHT_ON_SURFACE
    if len(draws) - ints[DRAW_AT] < DRAWS_RESERVE:
        flags |= REFILL
    return flags


@njit(cache=True)
def _step(map, item_map, mob_map, light_map, ints, floats, mobs, health, kills, draws, settings,
          action):
    before = ints.copy()
    kills_before = kills.sum()
    start_health = floats[HEALTH]
    played = kernel_rules.act(map, item_map, mob_map, light_map, ints, floats, mobs, health,
                              kills, draws, settings, action)
    kernel_mobs.update(map, mob_map, ints, floats, mobs, health, kills, draws, settings)
    if settings[SET_SPAWNING]:
        kernel_mobs.spawn(map, mob_map, ints, floats, mobs, health, draws, settings)
    kernel_rules.upkeep(map, ints, floats, settings, played)
    reward = 0.0
    for i in range(_ACHIEVEMENTS):
        if ints[ACH + i] and not before[ACH + i]:
            reward += _WEIGHTS[i]
    reward += (floats[HEALTH] - start_health) * 0.1
    ints[TIMESTEP] += 1
    floats[LIGHT] = light_level(ints[TIMESTEP], settings[SET_DAY_LENGTH]) \
        if settings[SET_DAYLIGHT] else 1.0
    ints[STEP_FLAGS] = _flags(before, ints, floats, kills_before, kills, draws)
    return reward


_entry = None       # the compiled step's entry point for the packed arrays' types


def step(p: Packed, action: int) -> float:
    """One step of the packed state; returns upstream's reward. ``p.draws`` must hold enough
    floats (``packed.KernelDraws.top_up``; the step sets ``REFILL`` when it no longer does)."""
    global _entry
    if _entry is None:
        _entry = _step.compile(tuple(typeof(a) for a in (
            p.map, p.item_map, p.mob_map, p.light_map, p.ints, p.floats, p.mobs, p.health,
            p.kills, p.draws, p.settings, 0)))
    return _entry(p.map, p.item_map, p.mob_map, p.light_map, p.ints, p.floats, p.mobs, p.health,
                  p.kills, p.draws, p.settings, action)
