"""The Craftax state packed into flat numpy arrays, views of one buffer, for the compiled step
(``kernel``).

``State`` (``state.py``) is upstream's ``EnvState`` field for field, with Python numbers and
lists where the rules read and write single values. A compiled function cannot take that
object, so ``Packed`` holds the same values in arrays a compiled function can:

- the four maps (``map``, ``item_map``, ``mob_map``, ``light_map``), shared with the state
  (``pack`` makes the state's maps the packed state's);
- ``ints`` (int64): every integer and boolean field and small array, at the offsets below;
- ``floats`` (float64): the seven float fields (``HEALTH`` ... ``LIGHT``);
- ``mobs`` (int64, ``(GROUPS, levels, SLOTS, MOB_FIELDS)``) and ``health`` (float64,
  ``(GROUPS, levels, SLOTS)``): the five slot kinds, passive, melee and ranged mobs (upstream's
  class order) then the mobs' and the player's projectiles; a kind with fewer slots than
  ``SLOTS`` (ranged mobs: 2) leaves the rest empty; a projectile's flight direction is its
  ``DROW`` / ``DCOL``;
- ``kills`` (int64, ``(3, KILL_TYPES)``): mobs killed so far by class and type (the task's
  tally reads it; the state has no such field);
- ``draws`` (float64) and ``ints[DRAW_AT]``: the uniform floats the step draws, in the order
  ``common.lanes.Draws`` gives them from the same stream (``KernelDraws`` keeps it filled);
- ``ints[STEP_FLAGS]``: what the last compiled step changed (``kernel``'s flags);
- ``ints[FREE]``: which mob classes have a free slot on the player's floor (kept by ``pack`` and
  the step); ``ints[STEPS]``, ``ints[NIGHTS]``: the steps played, and those that ended on the
  surface at night (counted by the step, for the task's tally);
- ``settings`` (int64): ``Settings`` at the ``SET_*`` offsets;
- ``codes``, ``lines``, ``words``: the window the step draws (``kernel_view``);
- ``before``: the step's copy of ``ints`` as they were before it (scratch).

All of them are views of one byte buffer, ``arena`` (``ARRAYS``, ``SPANS``): the compiled step
takes that one argument.

``pack(state, settings)`` makes one, ``unpack(packed, state)`` writes the values back into a
``State`` (in place: a reference to it sees them).
"""

from __future__ import annotations

from dataclasses import fields

import numpy as np

from .state import (MAP_SIZE, MAX_GROWING_PLANTS, MAX_MELEE, MAX_PASSIVE, MAX_RANGED, NUM_LEVELS,
                    OBS_DIM, Inventory, Mobs, Settings, State)

# ---- ints: scalar fields
_SCALARS = ("player_level", "player_direction", "player_food", "player_drink", "player_energy",
            "player_mana", "is_sleeping", "is_resting", "player_xp", "player_dexterity",
            "player_strength", "player_intelligence", "sword_enchantment", "bow_enchantment",
            "boss_progress", "boss_timesteps_to_spawn_this_round", "timestep")
(LEVEL, DIRECTION, FOOD, DRINK, ENERGY, MANA, SLEEPING, RESTING, XP, DEX, STR, INT, SWORD_ENCH,
 BOW_ENCH, BOSS_PROGRESS, BOSS_WAVE, TIMESTEP) = range(len(_SCALARS))
ROW, COL = len(_SCALARS), len(_SCALARS) + 1          # player_position
# the inventory's counts (``Inventory`` field order, less the two arrays)
INVENTORY = tuple(f.name for f in fields(Inventory) if f.name not in ("armour", "potions"))
INV = COL + 1
(WOOD, STONE, COAL, IRON, DIAMOND, SAPLING, PICKAXE, SWORD, BOW, ARROWS, TORCHES, RUBY, SAPPHIRE,
 BOOKS) = range(INV, INV + len(INVENTORY))
assert INVENTORY == ("wood", "stone", "coal", "iron", "diamond", "sapling", "pickaxe", "sword",
                     "bow", "arrows", "torches", "ruby", "sapphire", "books")

# ---- ints: array fields, flattened, in this order (name, length, where: the State field, or
# ``inventory.X``)
_ARRAYS = (("armour", 4, "inventory.armour"), ("potions", 6, "inventory.potions"),
           ("armour_ench", 4, "armour_enchantments"), ("potion_map", 6, "potion_mapping"),
           ("spells", 2, "learned_spells"), ("down_ladders", 2 * NUM_LEVELS, "down_ladders"),
           ("up_ladders", 2 * NUM_LEVELS, "up_ladders"), ("chests", NUM_LEVELS, "chests_opened"),
           ("killed", NUM_LEVELS, "monsters_killed"), ("ach", 67, "achievements"),
           ("plant_pos", 2 * MAX_GROWING_PLANTS, "growing_plants_positions"),
           ("plant_age", MAX_GROWING_PLANTS, "growing_plants_age"),
           ("plant_mask", MAX_GROWING_PLANTS, "growing_plants_mask"))
_OFFSET = {}
_at = BOOKS + 1
for _name, _length, _ in _ARRAYS:
    _OFFSET[_name] = _at
    _at += _length
ARMOUR, POTIONS, ARMOUR_ENCH, POTION_MAP, SPELLS = (_OFFSET[n] for n in (
    "armour", "potions", "armour_ench", "potion_map", "spells"))
DOWN_LADDERS, UP_LADDERS, CHESTS, KILLED, ACH = (_OFFSET[n] for n in (
    "down_ladders", "up_ladders", "chests", "killed", "ach"))
PLANT_POS, PLANT_AGE, PLANT_MASK = (_OFFSET[n] for n in ("plant_pos", "plant_age", "plant_mask"))
DRAW_AT = _at          # the next float of ``draws``
STEP_FLAGS = _at + 1   # what the last step changed (``kernel``'s flags)
FREE = _at + 2         # the mob classes with a free slot on the player's floor (bit k: class k)
STEPS = _at + 3        # the steps played since the state was packed first
NIGHTS = _at + 4       # those of them that ended on the surface at night (``kernel``)
NUM_INTS = _at + 5
# the ints the HUD line reads besides the position (``hud``), as (start, stop) ranges: the
# scalars up to the enchantments, the inventory's counts up to the spells, the floors' kills
HUD_RANGES = ((0, BOW_ENCH + 1), (INV, SPELLS + 2), (KILLED, KILLED + NUM_LEVELS))

# ---- floats
_FLOATS = ("player_health", "player_recover", "player_hunger", "player_thirst", "player_fatigue",
           "player_recover_mana", "light_level")
HEALTH, RECOVER, HUNGER, THIRST, FATIGUE, RECOVER_MANA, LIGHT = range(len(_FLOATS))
NUM_FLOATS = len(_FLOATS)

# ---- mobs
GROUP_FIELDS = ("passive_mobs", "melee_mobs", "ranged_mobs", "mob_projectiles", "player_projectiles")
PASSIVE, MELEE, RANGED, MOB_SHOTS, PLAYER_SHOTS = range(len(GROUP_FIELDS))
GROUPS = len(GROUP_FIELDS)
SLOTS = 3
MOB_ROW, MOB_COL, ALIVE, COOLDOWN, TYPE, DROW, DCOL = range(7)
MOB_FIELDS = 7
KILL_TYPES = 8
CLASS_SLOTS = (MAX_PASSIVE, MAX_MELEE, MAX_RANGED)     # the mob classes' slots in use
_DIRECTIONS = {MOB_SHOTS: "mob_projectile_directions", PLAYER_SHOTS: "player_projectile_directions"}

# ---- settings
(SET_DAY_LENGTH, SET_DESPAWN, SET_MAX_ATTRIBUTE, SET_GOD_MODE, SET_INTRINSICS, SET_DAYLIGHT,
 SET_SPAWNING) = range(7)
_SETTINGS = ("day_length", "mob_despawn_distance", "max_attribute", "god_mode", "intrinsics",
             "daylight", "spawning")


def settings_vector(settings: Settings) -> np.ndarray:
    return np.array([int(getattr(settings, name)) for name in _SETTINGS], np.int64)


# ---- the arena: every array of a packed state is a view of one byte buffer, so that the
# compiled step takes one argument (each array a compiled function takes costs its call an
# allocation and about 0.1 us). (name, dtype, shape), laid out in this order, each at a
# multiple of 8 bytes; ``kernel`` makes the same views inside the compiled step.
DRAWS_RESERVE = 128     # floats kept ahead of a step: more than one step draws (about 40 at most)
DRAWS_SIZE = 384        # the draws' buffer (``KernelDraws``)
LINE_BYTES = OBS_DIM[0] * (OBS_DIM[1] + 1) - 1      # the window's rows, each but the last ended
_MAP_SHAPE = (NUM_LEVELS, *MAP_SIZE)
ARRAYS = (("map", np.int32, _MAP_SHAPE), ("item_map", np.int32, _MAP_SHAPE),
          ("light_map", np.float32, _MAP_SHAPE), ("mob_map", np.bool_, _MAP_SHAPE),
          ("ints", np.int64, (NUM_INTS,)), ("floats", np.float64, (NUM_FLOATS,)),
          ("mobs", np.int64, (GROUPS, NUM_LEVELS, SLOTS, MOB_FIELDS)),
          ("health", np.float64, (GROUPS, NUM_LEVELS, SLOTS)), ("kills", np.int64, (3, KILL_TYPES)),
          ("settings", np.int64, (len(_SETTINGS),)), ("draws", np.float64, (DRAWS_SIZE,)),
          ("codes", np.uint8, OBS_DIM), ("lines", np.uint8, (LINE_BYTES,)),
          ("words", np.uint64, (3,)), ("before", np.int64, (NUM_INTS,)))


def _layout() -> tuple[dict[str, tuple[int, int]], int]:
    at, spans = 0, {}
    for name, dtype, shape in ARRAYS:
        size = int(np.prod(shape)) * np.dtype(dtype).itemsize
        spans[name] = (at, at + size)
        at += -(-size // 8) * 8
    return spans, at


SPANS, ARENA_BYTES = _layout()      # name -> (first byte, end); the arena's size


class Packed:
    """The arrays of one state (see the module docstring), views of one buffer (``arena``):
    ``map`` ... ``settings`` as above, ``draws`` (``KernelDraws``), and the window the step
    draws (``codes``, ``lines``, ``words``: ``kernel_view``). Write into them; an array put in
    place of one is not the arena's, and the compiled step (``kernel``) would not see it."""

    __slots__ = ("arena", *(name for name, _, _ in ARRAYS))

    def __init__(self, settings: Settings) -> None:
        self.arena = arena = np.zeros(ARENA_BYTES, np.uint8)
        for name, dtype, shape in ARRAYS:
            start, end = SPANS[name]
            setattr(self, name, arena[start:end].view(dtype).reshape(shape))
        self.settings[:] = settings_vector(settings)
        self.ints[DRAW_AT] = DRAWS_SIZE       # (none drawn yet: ``KernelDraws.top_up`` fills them)

    def in_arena(self) -> bool:
        """Every array is still the arena's."""
        return all(getattr(self, name).base is self.arena for name, _, _ in ARRAYS)


# the maps the packed state shares with the State, and their types
_MAPS = (("map", np.int32), ("item_map", np.int32), ("mob_map", np.bool_), ("light_map", np.float32))


def _get(state: State, where: str):
    obj = state
    for part in where.split("."):
        obj = getattr(obj, part)
    return obj


def pack(state: State, settings: Settings, into: Packed | None = None) -> Packed:
    """The state's values in arrays (``into``'s, when given: its kills, draws and window are
    kept). The state's maps become the packed state's (their values copied into the arena the
    first time): the two share them from then on."""
    p = into if into is not None else Packed(settings)
    for name, dtype in _MAPS:
        array, mine = getattr(state, name), getattr(p, name)
        if array is mine:
            continue
        if array.dtype != dtype or array.shape != (NUM_LEVELS, *MAP_SIZE) or not array.flags.c_contiguous:
            order = "C-contiguous" if array.flags.c_contiguous else "not C-contiguous"
            raise ValueError(f"Craftax state's {name} must be a C-contiguous {np.dtype(dtype)} "
                             f"array of shape {(NUM_LEVELS, *MAP_SIZE)}, not a {order} "
                             f"{array.dtype} array of shape {array.shape}")
        mine[...] = array
        setattr(state, name, mine)
    ints = p.ints
    for i, name in enumerate(_SCALARS):
        ints[i] = int(getattr(state, name))
    ints[ROW], ints[COL] = state.player_position.tolist()
    inv = state.inventory
    for i, name in enumerate(INVENTORY):
        ints[INV + i] = int(getattr(inv, name))
    for name, length, where in _ARRAYS:
        ints[_OFFSET[name]:_OFFSET[name] + length] = np.asarray(_get(state, where)).ravel()
    p.floats[:] = [float(getattr(state, name)) for name in _FLOATS]
    for g, name in enumerate(GROUP_FIELDS):
        group: Mobs = getattr(state, name)
        slots = len(group.mask[0])
        block = p.mobs[g]
        block[:] = 0
        block[:, :slots, MOB_ROW] = [[r for r, _ in level] for level in group.position]
        block[:, :slots, MOB_COL] = [[c for _, c in level] for level in group.position]
        block[:, :slots, ALIVE] = group.mask
        block[:, :slots, COOLDOWN] = group.attack_cooldown
        block[:, :slots, TYPE] = group.type_id
        if g in _DIRECTIONS:
            block[:, :slots, DROW:DCOL + 1] = getattr(state, _DIRECTIONS[g])
        p.health[g] = 0.0
        p.health[g, :, :slots] = group.health
    ints[FREE] = free_classes(p.mobs, ints.item(LEVEL))
    return p


def free_classes(mobs: np.ndarray, level: int) -> int:
    """Bit k set: mob class k (passive, melee, ranged) has a free slot on ``level``."""
    return sum(1 << k for k, slots in enumerate(CLASS_SLOTS) if not mobs[k, level, :slots, ALIVE].all())


def unpack(p: Packed, state: State) -> State:
    """Write ``p``'s values into ``state`` (its maps must be ``p``'s: they are not copied)."""
    ints = p.ints.tolist()
    for i, name in enumerate(_SCALARS):
        setattr(state, name, ints[i])
    state.is_sleeping, state.is_resting = bool(ints[SLEEPING]), bool(ints[RESTING])
    state.player_position[:] = ints[ROW], ints[COL]
    inv = state.inventory
    for i, name in enumerate(INVENTORY):
        setattr(inv, name, ints[INV + i])
    for name, length, where in _ARRAYS:
        target = _get(state, where)
        target[...] = np.asarray(ints[_OFFSET[name]:_OFFSET[name] + length]).reshape(target.shape)
    for name, value in zip(_FLOATS, p.floats.tolist()):
        setattr(state, name, value)
    for g, name in enumerate(GROUP_FIELDS):
        group: Mobs = getattr(state, name)
        slots = len(group.mask[0])
        block = p.mobs[g, :, :slots].tolist()
        group.position = [[(s[MOB_ROW], s[MOB_COL]) for s in level] for level in block]
        group.mask = [[bool(s[ALIVE]) for s in level] for level in block]
        group.attack_cooldown = [[s[COOLDOWN] for s in level] for level in block]
        group.type_id = [[s[TYPE] for s in level] for level in block]
        group.health = p.health[g, :, :slots].tolist()
        if g in _DIRECTIONS:
            getattr(state, _DIRECTIONS[g])[...] = p.mobs[g, :, :slots, DROW:DCOL + 1]
    state.map, state.item_map, state.mob_map, state.light_map = p.map, p.item_map, p.mob_map, p.light_map
    return state


class KernelDraws:
    """The uniform floats of a numpy stream, in ``common.lanes.Draws``' order, kept in
    ``packed.draws`` from ``packed.ints[DRAW_AT]`` on: ``top_up`` (before a step, or when the
    step flags ``REFILL``) makes sure at least ``reserve`` are there, more than a step draws.

    ``packed.draws`` is a buffer of the arena (``DRAWS_SIZE`` floats) refilled in place: the
    floats not yet taken move to its front and the stream's next ones fill the rest. Every float
    of the buffer is the stream's next one in turn, as ``Draws`` gives them (``Draws`` draws a
    block at a time, which leaves the stream at another place between refills but gives the
    same sequence)."""

    __slots__ = ("stream", "reserve")

    def __init__(self, stream: np.random.Generator, reserve: int = DRAWS_RESERVE) -> None:
        self.stream, self.reserve = stream, reserve

    def top_up(self, p: Packed) -> None:
        buffer, at = p.draws, p.ints.item(DRAW_AT)
        left = len(buffer) - at
        if left >= self.reserve:
            return
        buffer[:left] = buffer[at:].copy()
        buffer[left:] = self.stream.random(len(buffer) - left)
        p.ints[DRAW_AT] = 0
