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
(the ``CHANGED_*`` bits, so that a step that changed none costs the tally nothing), whether the
HUD line's values (``CHANGED_HUD``: ``packed.HUD_RANGES``, the health, day or night) or the
player's position (``MOVED``) changed, and ``REFILL`` when fewer than ``DRAWS_RESERVE`` draws are
left for the next step; ``ints[FREE]``, the mob classes with a free slot on the player's floor;
and it draws the window of the state it leaves (``kernel_view``: the codes, the rows' bytes and
the legend's bits, into a ``kernel_view.Window``'s buffers), so that a task's step is one call.

The compiled step is called through its entry point for the arrays' types (``entry``): numba's
dispatcher works out the types of a call's arguments every time, which costs more than the step
itself; ``pack`` checks that the maps have those types. A task binds the arguments once
(``arguments``: the arrays are refilled in place, never replaced, while it plays).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, typeof

from . import kernel_mobs, kernel_rules, kernel_view
from .packed import (ACH, ALIVE, BOOKS, CLASS_SLOTS, COL, DRAW_AT, DRAWS_RESERVE, DRINK, FOOD,
                     FREE, HEALTH, HUD_RANGES, INV, LEVEL, LIGHT, MANA, POTIONS, ROW,
                     SET_DAY_LENGTH, SET_DAYLIGHT, SET_SPAWNING, STEP_FLAGS, TIMESTEP, TORCHES,
                     Packed)
from .state import Settings
from .tables import ACHIEVEMENT_REWARD, NIGHT_LIGHT

_WEIGHTS = np.array(ACHIEVEMENT_REWARD, np.float64)
_ACHIEVEMENTS = len(ACHIEVEMENT_REWARD)

# ``ints[STEP_FLAGS]``'s bits: what the step changed
(CHANGED_INVENTORY, ATE, DRANK, SPENT_MANA, USED_TORCH, DRANK_POTION, KILLED_MOB, CHANGED_LEVEL,
 CHANGED_ACHIEVEMENTS, NIGHT_ON_SURFACE, REFILL, CHANGED_HUD, MOVED) = (1 << i for i in range(13))
_HUD_RANGES = np.array(HUD_RANGES, np.int64)
_CLASS_SLOTS = np.array(CLASS_SLOTS, np.int64)


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
def _flags(before, ints, floats, health_before, light_before, kills_before, kills, draws):
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
    if ints[ROW] != before[ROW] or ints[COL] != before[COL]:
        flags |= MOVED
    hud = (floats[HEALTH] != health_before
           or (floats[LIGHT] >= NIGHT_LIGHT) != (light_before >= NIGHT_LIGHT))
    for k in range(len(_HUD_RANGES)):
        if hud:
            break
        hud = _changed(before, ints, _HUD_RANGES[k, 0], _HUD_RANGES[k, 1])
    if hud:
        flags |= CHANGED_HUD
    return flags


@njit(cache=True)
def _free(ints, mobs):
    """``packed.free_classes``: bit k, class k has a free slot on the player's floor."""
    level, bits = ints[LEVEL], 0
    for k in range(len(_CLASS_SLOTS)):
        for slot in range(_CLASS_SLOTS[k]):
            if not mobs[k, level, slot, ALIVE]:
                bits |= 1 << k
                break
    return bits


@njit(cache=True)
def _step(map, item_map, mob_map, light_map, ints, floats, mobs, health, kills, draws, settings,
          codes, lines, words, action):
    before = ints.copy()
    kills_before = kills.sum()
    start_health, light_before = floats[HEALTH], floats[LIGHT]
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
    ints[STEP_FLAGS] = _flags(before, ints, floats, start_health, light_before, kills_before,
                              kills, draws)
    ints[FREE] = _free(ints, mobs)
    kernel_view.draw_window(map, item_map, light_map, ints, mobs, codes, lines, words)
    return reward


def arguments(p: Packed, window: kernel_view.Window) -> tuple:
    """The compiled step's arguments but the action, for ``p`` and ``window``: to be made again
    whenever one of ``p``'s arrays is replaced (``pack`` into it sets its maps)."""
    return (p.map, p.item_map, p.mob_map, p.light_map, p.ints, p.floats, p.mobs, p.health,
            p.kills, p.draws, p.settings, window.codes, window.lines, window.words)


_entry = None       # the compiled step's entry point for the packed arrays' types


def entry():
    """The compiled step, called as ``entry()(*arguments(p, window), action)``: it plays the
    action on the state ``p`` packs and returns upstream's reward (``p.draws`` must hold enough
    floats: ``packed.KernelDraws.top_up``; the step sets ``REFILL`` when it no longer does)."""
    global _entry
    if _entry is None:
        _entry = _step.compile(_SIGNATURE)
    return _entry


_SCRATCH = kernel_view.Window()


def step(p: Packed, action: int, window: kernel_view.Window | None = None) -> float:
    """One step of the packed state (its window drawn into ``window``, or a scratch one);
    returns upstream's reward."""
    return entry()(*arguments(p, window or _SCRATCH), action)


def _signature():
    p = Packed(Settings())
    p.map = p.item_map = np.zeros((1, 1, 1), np.int32)
    p.mob_map, p.light_map = np.zeros((1, 1, 1), np.bool_), np.zeros((1, 1, 1), np.float32)
    return tuple(typeof(a) for a in arguments(p, _SCRATCH)) + (typeof(0),)


_SIGNATURE = _signature()
