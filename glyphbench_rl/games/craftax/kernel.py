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
player's position (``MOVED``), the window (``CHANGED_WINDOW``) or the glyphs on it
(``CHANGED_LEGEND``) changed, whether the player died
(``DEAD``), and ``REFILL`` when fewer than ``DRAWS_RESERVE`` draws are
left for the next step; ``ints[FREE]``, the mob classes with a free slot on the player's floor;
it counts the steps and those that ended on the surface at night (``STEPS``, ``NIGHTS``, the
task's ``turn`` and ``night``); and it draws the window of the state it leaves (``kernel_view``: the codes, the rows' bytes and
the legend's bits), so that a task's step is one call.

That call takes one argument, the packed state's ``arena`` (``packed``: every array is a view of
it, and the step makes the same views, as plain pointers into it: ``_at``): each array argument
would cost the call an allocation and about 0.1 us. It is made through the entry point for the arena's type (``entry``): numba's
dispatcher works out the types of a call's arguments every time, which costs more than the step.
"""

from __future__ import annotations

import math

import numpy as np
from numba import carray, njit, typeof, types
from numba.extending import intrinsic

from . import kernel_mobs, kernel_rules, kernel_view
from .packed import (ACH, ALIVE, ARRAYS, BOOKS, CLASS_SLOTS, COL, DRAW_AT, DRAWS_RESERVE, DRINK,
                     FOOD, FREE, HEALTH, HUD_RANGES, INV, LEVEL, LIGHT, MANA, NIGHTS, POTIONS, ROW,
                     SET_DAY_LENGTH, SET_DAYLIGHT, SET_SPAWNING, SPANS, STEP_FLAGS, STEPS, TIMESTEP,
                     TORCHES, Packed)
from .tables import ACHIEVEMENT_REWARD, NIGHT_LIGHT

_WEIGHTS = np.array(ACHIEVEMENT_REWARD, np.float64)
_ACHIEVEMENTS = len(ACHIEVEMENT_REWARD)

# ``ints[STEP_FLAGS]``'s bits: what the step changed
(CHANGED_INVENTORY, ATE, DRANK, SPENT_MANA, USED_TORCH, DRANK_POTION, KILLED_MOB, CHANGED_LEVEL,
 CHANGED_ACHIEVEMENTS, NIGHT_ON_SURFACE, REFILL, CHANGED_HUD, MOVED, CHANGED_WINDOW,
 DEAD, CHANGED_LEGEND) = (1 << i for i in range(16))
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


# the arena's views (``packed.ARRAYS``) as the compiled step makes them: (first byte, shape)
_SPAN = {name: (SPANS[name][0], shape) for name, _, shape in ARRAYS}
_MAP0, _MAP_SHAPE = _SPAN["map"]
_ITEM0, _ = _SPAN["item_map"]
_LIGHT0, _ = _SPAN["light_map"]
_MOB0, _ = _SPAN["mob_map"]
_INTS0, _INTS_SHAPE = _SPAN["ints"]
_FLOATS0, _FLOATS_SHAPE = _SPAN["floats"]
_MOBS0, _MOBS_SHAPE = _SPAN["mobs"]
_HEALTH0, _HEALTH_SHAPE = _SPAN["health"]
_KILLS0, _KILLS_SHAPE = _SPAN["kills"]
_SETTINGS0, _SETTINGS_SHAPE = _SPAN["settings"]
_DRAWS0, _DRAWS_SHAPE = _SPAN["draws"]
_CODES0, _CODES_SHAPE = _SPAN["codes"]
_LINES0, _LINES_SHAPE = _SPAN["lines"]
_WORDS0, _WORDS_SHAPE = _SPAN["words"]
_BEFORE0, _ = _SPAN["before"]
assert all(start % 8 == 0 for start, _ in _SPAN.values())    # (every view aligned)


@intrinsic
def _at(typingctx, arena, offset, dtype):
    """A pointer to ``dtype`` values at byte ``offset`` of ``arena`` (uint8, C): with
    ``numba.carray`` it makes a view of the arena that, unlike ``arena[a:b].view(...)``, is not
    reference-counted (the step's fifteen views cost it about 1 us that way; ``arena``, the
    step's argument, outlives them)."""
    sig = types.CPointer(dtype.dtype)(arena, offset, dtype)

    def codegen(context, builder, signature, args):
        data = context.make_array(signature.args[0])(context, builder, args[0]).data
        return builder.bitcast(builder.gep(data, [args[1]]),
                               context.get_value_type(signature.return_type))
    return sig, codegen
assert [name for name, _, _ in ARRAYS] == ["map", "item_map", "light_map", "mob_map", "ints",
                                           "floats", "mobs", "health", "kills", "settings",
                                           "draws", "codes", "lines", "words", "before"]


@njit(cache=True)
def _step(arena, action):
    map = carray(_at(arena, _MAP0, np.int32), _MAP_SHAPE)
    item_map = carray(_at(arena, _ITEM0, np.int32), _MAP_SHAPE)
    light_map = carray(_at(arena, _LIGHT0, np.float32), _MAP_SHAPE)
    mob_map = carray(_at(arena, _MOB0, np.bool_), _MAP_SHAPE)
    ints = carray(_at(arena, _INTS0, np.int64), _INTS_SHAPE)
    floats = carray(_at(arena, _FLOATS0, np.float64), _FLOATS_SHAPE)
    mobs = carray(_at(arena, _MOBS0, np.int64), _MOBS_SHAPE)
    health = carray(_at(arena, _HEALTH0, np.float64), _HEALTH_SHAPE)
    kills = carray(_at(arena, _KILLS0, np.int64), _KILLS_SHAPE)
    settings = carray(_at(arena, _SETTINGS0, np.int64), _SETTINGS_SHAPE)
    draws = carray(_at(arena, _DRAWS0, np.float64), _DRAWS_SHAPE)
    codes = carray(_at(arena, _CODES0, np.uint8), _CODES_SHAPE)
    lines = carray(_at(arena, _LINES0, np.uint8), _LINES_SHAPE)
    words = carray(_at(arena, _WORDS0, np.uint64), _WORDS_SHAPE)
    before = carray(_at(arena, _BEFORE0, np.int64), _INTS_SHAPE)

    before[:] = ints
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
    ints[STEPS] += 1
    flags = ints[STEP_FLAGS]
    if flags & NIGHT_ON_SURFACE:
        ints[NIGHTS] += 1
    if floats[HEALTH] <= 0:
        flags |= DEAD
    drawn = kernel_view.draw_window(map, item_map, light_map, ints, mobs, codes, lines, words)
    if drawn & kernel_view.LINES_CHANGED:
        flags |= CHANGED_WINDOW
    if drawn & kernel_view.WORDS_CHANGED:
        flags |= CHANGED_LEGEND
    ints[STEP_FLAGS] = flags
    return reward


_entry = None       # the compiled step's entry point for the arena's type


def entry():
    """The compiled step, called as ``entry()(p.arena, action)``: it plays the action on the
    state ``p`` packs, draws the window it leaves into ``p.codes``, ``p.lines`` and ``p.words``
    and returns upstream's reward (``p.draws`` must hold enough floats:
    ``packed.KernelDraws.top_up``; the step sets ``REFILL`` when it no longer does)."""
    global _entry
    if _entry is None:
        _entry = _step.compile((typeof(np.zeros(8, np.uint8)), typeof(0)))
    return _entry


def step(p: Packed, action: int) -> float:
    """One step of the packed state; returns upstream's reward."""
    if not p.in_arena():
        raise ValueError("Craftax kernel: an array of the packed state was replaced; the "
                         "compiled step plays the arena's (write into the arrays instead)")
    return entry()(p.arena, action)
