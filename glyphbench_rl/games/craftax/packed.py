"""The Craftax state packed into a few flat numpy arrays, for the compiled step (``kernel``).

``State`` (``state.py``) is upstream's ``EnvState`` field for field, with Python numbers and
lists where the rules read and write single values. A compiled function cannot take that
object, so ``Packed`` holds the same values in arrays a compiled function can:

- the four maps (``map``, ``item_map``, ``mob_map``, ``light_map``): the state's own arrays,
  shared, not copied;
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
  the step);
- ``settings`` (int64): ``Settings`` at the ``SET_*`` offsets.

``pack(state, settings)`` makes one, ``unpack(packed, state)`` writes the values back into a
``State`` (in place: a reference to it sees them).
"""

from __future__ import annotations

from dataclasses import fields

import numpy as np

from .state import (MAP_SIZE, MAX_GROWING_PLANTS, MAX_MELEE, MAX_PASSIVE, MAX_RANGED, NUM_LEVELS,
                    Inventory, Mobs, Settings, State)

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
NUM_INTS = _at + 3
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


class Packed:
    """The arrays of one state (see the module docstring)."""

    __slots__ = ("map", "item_map", "mob_map", "light_map", "ints", "floats", "mobs", "health",
                 "kills", "draws", "settings")

    def __init__(self, settings: Settings) -> None:
        self.ints = np.zeros(NUM_INTS, np.int64)
        self.floats = np.zeros(NUM_FLOATS, np.float64)
        self.mobs = np.zeros((GROUPS, NUM_LEVELS, SLOTS, MOB_FIELDS), np.int64)
        self.health = np.zeros((GROUPS, NUM_LEVELS, SLOTS), np.float64)
        self.kills = np.zeros((3, KILL_TYPES), np.int64)
        self.draws = np.zeros(0, np.float64)
        self.settings = settings_vector(settings)


# the maps the packed state shares with the State, and their types (the compiled step is
# called for these types only: ``kernel``)
_MAPS = (("map", np.int32), ("item_map", np.int32), ("mob_map", np.bool_), ("light_map", np.float32))


def _get(state: State, where: str):
    obj = state
    for part in where.split("."):
        obj = getattr(obj, part)
    return obj


def pack(state: State, settings: Settings, into: Packed | None = None) -> Packed:
    """The state's values in arrays (``into``'s, when given: its kills and draws are kept)."""
    p = into if into is not None else Packed(settings)
    for name, dtype in _MAPS:
        array = getattr(state, name)
        if array.dtype != dtype or array.shape != (NUM_LEVELS, *MAP_SIZE) or not array.flags.c_contiguous:
            order = "C-contiguous" if array.flags.c_contiguous else "not C-contiguous"
            raise ValueError(f"Craftax state's {name} must be a C-contiguous {np.dtype(dtype)} "
                             f"array of shape {(NUM_LEVELS, *MAP_SIZE)}, not a {order} "
                             f"{array.dtype} array of shape {array.shape}")
        setattr(p, name, array)
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


DRAWS_RESERVE = 128     # floats kept ahead of a step: more than one step draws (about 40 at most)
DRAWS_BLOCK = 256


class KernelDraws:
    """The uniform floats of a numpy stream, in ``common.lanes.Draws``' order, kept in
    ``packed.draws`` from ``packed.ints[DRAW_AT]`` on: ``top_up`` (before a step, or when the
    step flags ``REFILL``) makes sure at least ``reserve`` are there, more than a step draws.

    ``packed.draws`` is one buffer of ``reserve + block`` floats, made by the first ``top_up``
    and refilled in place (the compiled step is bound to the array): the floats not yet taken
    move to its front and the stream's next ones fill the rest. Every float of the buffer is
    the stream's next one in turn, as ``Draws`` gives them (``Draws`` draws ``block`` at a time,
    which leaves the stream at another place between refills but gives the same sequence)."""

    __slots__ = ("stream", "block", "reserve")

    def __init__(self, stream: np.random.Generator, block: int = DRAWS_BLOCK,
                 reserve: int = DRAWS_RESERVE) -> None:
        self.stream, self.block, self.reserve = stream, block, reserve

    def top_up(self, p: Packed) -> None:
        buffer, at = p.draws, p.ints.item(DRAW_AT)
        size = self.reserve + self.block
        if len(buffer) != size:
            left = buffer[at:]
            p.draws = buffer = np.empty(size, np.float64)
            buffer[:len(left)] = left
        else:
            left = buffer[at:]
            if len(left) >= self.reserve:
                return
            buffer[:len(left)] = left.copy()
        buffer[len(left):] = self.stream.random(size - len(left))
        p.ints[DRAW_AT] = 0
