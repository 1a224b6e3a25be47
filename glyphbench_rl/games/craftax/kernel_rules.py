"""``rules`` and ``upkeep`` compiled: the player's sub-rules and the end-of-step upkeep, in the
same order, on the packed state (``packed``).

``act(...)`` is everything ``rules.step`` does before ``mobs.update``: a sleeping or resting
player's action becomes NOOP, ``change_floor``, the action's own rule, the boss rule, then
``move`` / ``level_up``; it returns the action played. ``upkeep(...)`` is ``grow_plants``,
``update_intrinsics``, ``clip_vitals`` and ``inventory_achievements``; the caller adds the
reward, the timestep and its light level (``upkeep.daylight``).

Each function here is its namesake of ``rules`` / ``upkeep`` (see there for the rules), written
for numba on ``packed``'s arrays; the tables (recipes, placing, mining, chests, potions, spells,
enchanting) are numpy arrays built from ``tables`` below. Floats are Python's (float64) at every
operation, the light map's float32 where ``rules.add_torch_light`` works in float32, so the two
give the same bits. ``upkeep``'s memos (``_FACTS``, ``_LAST``, ``_EARNED``) only skip work: here
the plain rule runs every step. ``tests/games/craftax/test_craftax_kernel_rules.py`` plays both
from the same states and draws.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from .kernel_mobs import attack_mob, boss_logic, damage_necromancer, max_food, random
from .packed import (ACH, ALIVE, ARMOUR, ARMOUR_ENCH, ARROWS, BOOKS, BOSS_PROGRESS, BOW,
                     BOW_ENCH, CHESTS, COL, DCOL, DEX, DIRECTION, DOWN_LADDERS, DRINK, DROW,
                     ENERGY, FATIGUE, FOOD, HEALTH, HUNGER, INT, INV, INVENTORY, KILLED, LEVEL,
                     MANA, MOB_COL, MOB_ROW, PICKAXE, PLANT_AGE, PLANT_MASK, PLANT_POS,
                     PLAYER_SHOTS, POTION_MAP, POTIONS, RECOVER, RECOVER_MANA, RESTING, ROW,
                     SAPLING, SET_GOD_MODE, SET_INTRINSICS, SET_MAX_ATTRIBUTE, SLEEPING, SPELLS,
                     STR, SWORD, SWORD_ENCH, THIRST, TORCHES, TYPE, UP_LADDERS, XP)
from .state import MAX_GROWING_PLANTS, MAX_PLAYER_PROJECTILES
from .tables import (
    BOOK_CHEST_LEVELS, BOSS_LEVEL, BOW_CHEST_LEVEL, CAN_PLACE_ITEM, CHEST_ARROWS, CHEST_ORES,
    CHEST_ORE_CHANCE, CHEST_POTION, CHEST_TOOL_CHANCE, CHEST_TOOL_TIER_WEIGHTS, CHEST_TORCH,
    DERECOVER_LIMIT, DERECOVER_RATE, DEXTERITY_DECAY, DIRECTIONS, DRINK_BLOCKS,
    ENCHANT_DAMAGE_FRACTION, ENCHANT_MANA_COST, ENCHANT_TABLES, FATIGUE_LIMIT, FATIGUE_RESTED,
    GOD_MODE_MIN_HEALTH, HUNGER_LIMIT, INTELLIGENCE_ENCHANT_BONUS, INTELLIGENCE_MANA_BONUS,
    INVENTORY_ACHIEVEMENTS, IS_SOLID, LEARN_SPELL_ACHIEVEMENT, LEVEL_ACHIEVEMENT, MANA_LIMIT,
    MANA_RATE, MINING_BY_BLOCK, MONSTERS_KILLED_TO_CLEAR_LEVEL, MOVES, NUM_LEVELS, PLACING,
    PLANT_RIPE_AGE, PLAYER_ARROW, POTION_ACTIONS, POTION_EFFECTS, RECIPE_BY_ACTION,
    RECOVER_LIMIT, RECOVER_RATE, RIPE_PLANT_FOOD, SAPLING_CHANCE, SLEEP_INTRINSIC_RATE,
    SPELL_MANA_COST, STACK_LIMIT, STRENGTH_DAMAGE_BONUS, SWORD_DAMAGE, THIRST_LIMIT,
    TORCH_LIGHT_HALF, TORCH_LIGHT_MAP, XP_PER_NEW_LEVEL, Achievement, Action, BlockType,
    ItemType,
)
from . import packed, rules, tables
from .tables import SPELLS as SPELL_TABLE     # (``packed.SPELLS`` is the learned spells' offset)

# ---------------------------------------------------------------------------------------------
# Tables (from ``tables``; indexed by action, block, level ...)

_ACTIONS = len(Action)
_BLOCKS = len(BlockType)
_OFFSET = {name: INV + i for i, name in enumerate(INVENTORY)}   # inventory field -> ints offset

_NOOP, _DO, _SLEEP, _REST = (int(a) for a in (Action.NOOP, Action.DO, Action.SLEEP, Action.REST))
_DESCEND, _ASCEND = int(Action.DESCEND), int(Action.ASCEND)
_PLACE_TORCH, _PLACE_PLANT, _PLACE_STONE = (int(a) for a in (
    Action.PLACE_TORCH, Action.PLACE_PLANT, Action.PLACE_STONE))
_ENCHANT_SWORD, _ENCHANT_BOW = int(Action.ENCHANT_SWORD), int(Action.ENCHANT_BOW)
_GRASS, _PATH, _WATER, _LAVA = (int(b) for b in (BlockType.GRASS, BlockType.PATH,
                                                 BlockType.WATER, BlockType.LAVA))
_CHEST, _RIPE, _PLANT, _NECRO = (int(b) for b in (BlockType.CHEST, BlockType.RIPE_PLANT,
                                                  BlockType.PLANT, BlockType.NECROMANCER))
_TABLE, _FURNACE = int(BlockType.CRAFTING_TABLE), int(BlockType.FURNACE)
_NO_ITEM, _TORCH = int(ItemType.NONE), int(ItemType.TORCH)
_LADDER_DOWN, _LADDER_UP = int(ItemType.LADDER_DOWN), int(ItemType.LADDER_UP)
_COLLECT_DRINK, _EAT_PLANT, _OPEN_CHEST, _FIRE_BOW, _DRINK_POTION, _WAKE_UP = (int(a) for a in (
    Achievement.COLLECT_DRINK, Achievement.EAT_PLANT, Achievement.OPEN_CHEST,
    Achievement.FIRE_BOW, Achievement.DRINK_POTION, Achievement.WAKE_UP))
_ENCHANT_SWORD_ACH, _ENCHANT_ARMOUR_ACH = (int(Achievement.ENCHANT_SWORD),
                                           int(Achievement.ENCHANT_ARMOUR))
_PLAYER_ARROW = int(PLAYER_ARROW)

_IS_SOLID = np.array(IS_SOLID, np.bool_)                     # [block]
_CAN_PLACE_ITEM = np.array(CAN_PLACE_ITEM, np.bool_)         # [block]
_DRINK_BLOCK = np.zeros(_BLOCKS, np.bool_)                   # [block]
_DRINK_BLOCK[[int(b) for b in DRINK_BLOCKS]] = True
# [level] -> the level's entry achievement, -1 for none (the overworld)
_LEVEL_ACHIEVEMENT = np.array([-1 if a is None else int(a) for a in LEVEL_ACHIEVEMENT], np.int64)
_BOOK_CHEST = np.zeros(NUM_LEVELS, np.bool_)                 # [level]
_BOOK_CHEST[list(BOOK_CHEST_LEVELS)] = True

# [direction] -> the facing step (``DIRECTIONS``: (0, 0) for every other action); [action] ->
# a move's step
_DIR = np.zeros((_ACTIONS, 2), np.int64)
for _a, _d in DIRECTIONS.items():
    _DIR[int(_a)] = _d
_MOVE = np.zeros((_ACTIONS, 2), np.int64)
for _a, _d in MOVES.items():
    _MOVE[_a] = _d

# recipes, by action: the cost per inventory field (``INVENTORY`` order), the result (a field's
# offset, or -1: armour), its kind, tier and amount, the furnace flag and the achievement (-1)
_TOOL, _STACK, _ARMOUR = 1, 2, 3
_RECIPE_COST = np.zeros((_ACTIONS, len(INVENTORY)), np.int64)
_RECIPE_RESULT = np.full(_ACTIONS, -1, np.int64)
_RECIPE_KIND = np.zeros(_ACTIONS, np.int64)
_RECIPE_TIER = np.zeros(_ACTIONS, np.int64)
_RECIPE_AMOUNT = np.zeros(_ACTIONS, np.int64)
_RECIPE_FURNACE = np.zeros(_ACTIONS, np.bool_)
_RECIPE_ACHIEVEMENT = np.full(_ACTIONS, -1, np.int64)
for _a, _r in RECIPE_BY_ACTION.items():
    for _item, _n in _r.cost.items():
        _RECIPE_COST[_a, INVENTORY.index(_item)] = _n
    _RECIPE_KIND[_a] = {"armour": _ARMOUR, "pickaxe": _TOOL, "sword": _TOOL}.get(_r.result, _STACK)
    _RECIPE_RESULT[_a] = -1 if _r.result == "armour" else _OFFSET[_r.result]
    _RECIPE_TIER[_a], _RECIPE_AMOUNT[_a], _RECIPE_FURNACE[_a] = _r.tier, _r.amount, _r.furnace
    _RECIPE_ACHIEVEMENT[_a] = -1 if _r.achievement is None else int(_r.achievement)

# placing, by action: the item's offset, its cost, the block placed (-1: none), the achievement
_PLACE_ITEM = np.zeros(_ACTIONS, np.int64)
_PLACE_COST = np.zeros(_ACTIONS, np.int64)
_PLACE_BLOCK = np.full(_ACTIONS, -1, np.int64)
_PLACE_ACHIEVEMENT = np.zeros(_ACTIONS, np.int64)
for _a, (_item, _cost, _block, _ach) in PLACING.items():
    _PLACE_ITEM[_a], _PLACE_COST[_a], _PLACE_ACHIEVEMENT[_a] = _OFFSET[_item], _cost, int(_ach)
    _PLACE_BLOCK[_a] = -1 if _block is None else int(_block)

# mining, by block: the pickaxe tier needed (-1: not mined), the item's offset (-1: none), the
# block left
_MINE_TIER = np.full(_BLOCKS, -1, np.int64)
_MINE_ITEM = np.full(_BLOCKS, -1, np.int64)
_MINE_LEFT = np.zeros(_BLOCKS, np.int64)
for _b, (_tier, _item, _left) in MINING_BY_BLOCK.items():
    _MINE_TIER[_b], _MINE_LEFT[_b] = _tier, _left
    _MINE_ITEM[_b] = -1 if _item is None else _OFFSET[_item]

# chests: the ores (offset, weight, least, most), the tools' tier weights
_ORE_ITEM = np.array([_OFFSET[o[0]] for o in CHEST_ORES], np.int64)
_ORE_WEIGHT = np.array([o[1] for o in CHEST_ORES], np.float64)
_ORE_LOW = np.array([o[2] for o in CHEST_ORES], np.int64)
_ORE_HIGH = np.array([o[3] for o in CHEST_ORES], np.int64)
_TOOL_TIER_WEIGHT = np.array(CHEST_TOOL_TIER_WEIGHTS, np.float64)
_CHEST_TOOLS = np.array([PICKAXE, SWORD], np.int64)
_COLOURS = len(POTION_ACTIONS)

# potions: [action] -> colour (-1); [effect] -> the vital (an offset of ``floats`` for health,
# else of ``ints``), whether it is in ``floats``, the change
_POTION_COLOUR = np.full(_ACTIONS, -1, np.int64)
for _i, _a in enumerate(POTION_ACTIONS):
    _POTION_COLOUR[int(_a)] = _i
_POTION_IN_FLOATS = np.array([f"player_{v}" in packed._FLOATS for v, _ in POTION_EFFECTS],
                             np.bool_)
_POTION_VITAL = np.array([packed._FLOATS.index(f"player_{v}") if f"player_{v}" in packed._FLOATS
                          else packed._SCALARS.index(f"player_{v}") for v, _ in POTION_EFFECTS],
                         np.int64)
_POTION_CHANGE = np.array([c for _, c in POTION_EFFECTS], np.int64)

# spells: [action] -> (spell index, projectile kind, achievement); [spell] -> its learning's
_SPELL_INDEX = np.full(_ACTIONS, -1, np.int64)
_SPELL_KIND = np.zeros(_ACTIONS, np.int64)
_SPELL_ACHIEVEMENT = np.zeros(_ACTIONS, np.int64)
for _a, (_i, _kind, _ach) in SPELL_TABLE.items():
    _SPELL_INDEX[int(_a)], _SPELL_KIND[int(_a)], _SPELL_ACHIEVEMENT[int(_a)] = _i, int(_kind), int(_ach)
_LEARN_ACHIEVEMENT = np.array([int(a) for a in LEARN_SPELL_ACHIEVEMENT], np.int64)
_NUM_SPELLS = len(LEARN_SPELL_ACHIEVEMENT)

# enchantment tables: [block] -> element (0: not a table) and the gem's offset
_ENCHANT_ELEMENT = np.zeros(_BLOCKS, np.int64)
_ENCHANT_GEM = np.zeros(_BLOCKS, np.int64)
for _b, (_element, _gem) in ENCHANT_TABLES.items():
    _ENCHANT_ELEMENT[int(_b)], _ENCHANT_GEM[int(_b)] = _element, _OFFSET[_gem]

# level-ups: [action] -> the attribute's offset
_ATTRIBUTE = np.zeros(_ACTIONS, np.int64)
for _a, _name in rules._ATTRIBUTES.items():
    _ATTRIBUTE[_a] = packed._SCALARS.index(_name)

_SWORD_DAMAGE = np.array(SWORD_DAMAGE, np.int64)             # [sword tier]
_TORCH_LIGHT = np.ascontiguousarray(TORCH_LIGHT_MAP)          # float32, (9, 9)
assert _TORCH_LIGHT.dtype == np.float32

# upkeep: rates by asleep (0, 1); the inventory achievements (offset, at least, achievement)
_RECOVER_RATE = np.array(RECOVER_RATE, np.float64)
_DERECOVER_RATE = np.array(DERECOVER_RATE, np.float64)
_MANA_RATE = np.array(MANA_RATE, np.int64)
assert all(isinstance(x, int) for x in MANA_RATE)
_HELD_OFFSET = np.array([_OFFSET[n] for n, _, _ in INVENTORY_ACHIEVEMENTS], np.int64)
_HELD_LEAST = np.array([least for _, least, _ in INVENTORY_ACHIEVEMENTS], np.int64)
_HELD_ACHIEVEMENT = np.array([int(a) for _, _, a in INVENTORY_ACHIEVEMENTS], np.int64)

# [action] -> its own rule (``rules._RULE``, 0: none); moves and level-ups come after the boss
# rule
(_DO_RULE, _CRAFT_RULE, _PLACE_RULE, _SHOOT_RULE, _CAST_RULE, _POTION_RULE, _READ_RULE,
 _ENCHANT_RULE, _LEVEL_UP_RULE, _MOVE_RULE) = (
    rules._DO_RULE, rules._CRAFT_RULE, rules._PLACE_RULE, rules._SHOOT_RULE, rules._CAST_RULE,
    rules._POTION_RULE, rules._READ_RULE, rules._ENCHANT_RULE, rules._LEVEL_UP_RULE,
    rules._MOVE_RULE)
_RULE = np.zeros(_ACTIONS, np.int64)
for _a, _rule in rules._RULE.items():
    _RULE[_a] = _rule


# ---------------------------------------------------------------------------------------------
# helpers shared with the other modules


@njit(cache=True)
def max_health(strength):
    return 8 + strength


@njit(cache=True)
def max_mana(intelligence):
    return 6 + 3 * intelligence


assert all(max_health.py_func(a) == tables.max_health(a)
           and max_mana.py_func(a) == tables.max_mana(a) for a in range(1, 20))


@njit(cache=True)
def in_bounds(map, r, c):
    return 0 <= r < map.shape[1] and 0 <= c < map.shape[2]


@njit(cache=True)
def is_in_mob(mob_map, ints, level, r, c):
    """A mob stands at (r, c) of ``level``, or the player does."""
    if mob_map[level, r, c]:
        return True
    return level == ints[LEVEL] and r == ints[ROW] and c == ints[COL]


@njit(cache=True)
def is_free(map, mob_map, ints, level, r, c):
    """(r, c) of ``level`` is in bounds, not solid, and nobody stands there."""
    return (in_bounds(map, r, c) and not _IS_SOLID[map[level, r, c]]
            and not is_in_mob(mob_map, ints, level, r, c))


@njit(cache=True)
def player_can_enter(map, mob_map, ints, r, c):
    """Free, and neither water nor lava."""
    level = ints[LEVEL]
    return is_free(map, mob_map, ints, level, r, c) and not (
        map[level, r, c] == _WATER or map[level, r, c] == _LAVA)


@njit(cache=True)
def player_damage_vector(ints):
    """(physical, fire, ice) of the player's melee hit."""
    base = _SWORD_DAMAGE[ints[SWORD]]
    element = base * ENCHANT_DAMAGE_FRACTION * (
        1 + INTELLIGENCE_ENCHANT_BONUS * (ints[INT] - 1))
    physical = base * (1 + STRENGTH_DAMAGE_BONUS * (ints[STR] - 1))
    ench = ints[SWORD_ENCH]
    return physical, element if ench == 1 else 0.0, element if ench == 2 else 0.0


@njit(cache=True)
def facing(ints):
    d = ints[DIRECTION]
    if 0 <= d < _ACTIONS:
        return ints[ROW] + _DIR[d, 0], ints[COL] + _DIR[d, 1]
    return ints[ROW], ints[COL]


@njit(cache=True)
def is_near_block(map, ints, block):
    """``block`` in one of the eight cells around the player (cut at the map's edge)."""
    level, r, c = ints[LEVEL], ints[ROW], ints[COL]
    for i in range(max(r - 1, 0), min(r + 2, map.shape[1])):
        for j in range(max(c - 1, 0), min(c + 2, map.shape[2])):
            if (i != r or j != c) and map[level, i, j] == block:
                return True
    return False


# ---------------------------------------------------------------------------------------------
# the sub-rules, in upstream's order


@njit(cache=True)
def change_floor(item_map, ints, settings, action):
    """DESCEND on a down ladder with the level's kills (or god mode), ASCEND on an up ladder;
    a level's first entry: its achievement and 1 XP."""
    level = ints[LEVEL]
    if action == _DESCEND or action == _ASCEND:
        item = item_map[level, ints[ROW], ints[COL]]
        if action == _DESCEND and level < NUM_LEVELS - 1 and (settings[SET_GOD_MODE] or (
                item == _LADDER_DOWN
                and ints[KILLED + level] >= MONSTERS_KILLED_TO_CLEAR_LEVEL)):
            level += 1
            ints[ROW], ints[COL] = ints[UP_LADDERS + 2 * level], ints[UP_LADDERS + 2 * level + 1]
        elif action == _ASCEND and level > 0 and (settings[SET_GOD_MODE] or item == _LADDER_UP):
            level -= 1
            ints[ROW] = ints[DOWN_LADDERS + 2 * level]
            ints[COL] = ints[DOWN_LADDERS + 2 * level + 1]
        ints[LEVEL] = level
    achievement = _LEVEL_ACHIEVEMENT[level]
    if achievement >= 0 and not ints[ACH + achievement]:
        ints[ACH + achievement] = 1
        ints[XP] += XP_PER_NEW_LEVEL


@njit(cache=True)
def craft(map, ints, action):
    """A recipe: its cost paid, at a crafting table (and furnace)."""
    for k in range(_RECIPE_COST.shape[1]):
        if ints[INV + k] < _RECIPE_COST[action, k]:
            return
    if not is_near_block(map, ints, _TABLE) or (
            _RECIPE_FURNACE[action] and not is_near_block(map, ints, _FURNACE)):
        return
    kind, tier, result = _RECIPE_KIND[action], _RECIPE_TIER[action], _RECIPE_RESULT[action]
    if kind == _ARMOUR:
        below = -1
        for i in range(4):
            if ints[ARMOUR + i] < tier:
                below = i
                break
        if below < 0:
            return
        ints[ARMOUR + below] = tier
        ints[ACH + _RECIPE_ACHIEVEMENT[action]] = 1
    elif kind == _TOOL:
        if ints[result] >= tier:
            return
        ints[result] = tier
    else:   # arrows, torches
        if ints[result] >= STACK_LIMIT:
            return
        ints[result] += _RECIPE_AMOUNT[action]
    for k in range(_RECIPE_COST.shape[1]):
        ints[INV + k] -= _RECIPE_COST[action, k]


@njit(cache=True)
def do(map, mob_map, ints, floats, mobs, health, kills, draws):
    """DO on the facing cell: attack a mob there; else mine, find a sapling, drink, eat a ripe
    plant, open a chest or hit the necromancer."""
    r, c = facing(ints)
    if not in_bounds(map, r, c):
        return
    level = ints[LEVEL]
    if mob_map[level, r, c]:
        physical, fire, ice = player_damage_vector(ints)
        hit, _ = attack_mob(ints, floats, mobs, health, mob_map, kills, r, c, physical, fire,
                            ice, True)
        if hit:
            return
    block = map[level, r, c]
    tier = _MINE_TIER[block]
    if tier >= 0:
        if ints[PICKAXE] >= tier:
            map[level, r, c] = _MINE_LEFT[block]
            if _MINE_ITEM[block] >= 0:
                ints[_MINE_ITEM[block]] += 1
    elif block == _GRASS:
        if random(ints, draws) < SAPLING_CHANCE:
            ints[SAPLING] += 1
    elif _DRINK_BLOCK[block]:
        ints[DRINK] = min(max_food(ints[DEX]), ints[DRINK] + 1)
        floats[THIRST] = 0.0
        ints[ACH + _COLLECT_DRINK] = 1
    elif block == _RIPE:
        eat_plant(map, ints, floats, r, c)
    elif block == _CHEST:
        open_chest(map, ints, draws, r, c)
    elif block == _NECRO:
        damage_necromancer(ints, mobs)


@njit(cache=True)
def eat_plant(map, ints, floats, r, c):
    """A ripe plant becomes a plant: food +4, hunger 0; the age of the growing-plant slot at
    (r, c), or slot 0, is reset."""
    map[ints[LEVEL], r, c] = _PLANT
    ints[FOOD] = min(max_food(ints[DEX]), ints[FOOD] + RIPE_PLANT_FOOD)
    floats[HUNGER] = 0.0
    ints[ACH + _EAT_PLANT] = 1
    at = 0
    for i in range(MAX_GROWING_PLANTS):
        if ints[PLANT_POS + 2 * i] == r and ints[PLANT_POS + 2 * i + 1] == c:
            at = i
            break
    ints[PLANT_AGE + at] = 0


@njit(cache=True)
def _amount(ints, draws, low, high):
    return low + int(random(ints, draws) * (high - low + 1))


@njit(cache=True)
def _weighted(ints, draws, weights):
    x, total = random(ints, draws), 0.0
    for i in range(len(weights)):
        total += weights[i]
        if x < total:
            return i
    return len(weights) - 1


@njit(cache=True)
def open_chest(map, ints, draws, r, c):
    """The chest becomes path and gives its loot; the first chest of the dungeon holds the bow,
    the first of the sewers or vaults a book."""
    level = ints[LEVEL]
    map[level, r, c] = _PATH
    if random(ints, draws) < CHEST_TORCH[0]:
        ints[TORCHES] += _amount(ints, draws, CHEST_TORCH[1], CHEST_TORCH[2])
    if random(ints, draws) < CHEST_ORE_CHANCE:
        i = _weighted(ints, draws, _ORE_WEIGHT)
        ints[_ORE_ITEM[i]] += _amount(ints, draws, _ORE_LOW[i], _ORE_HIGH[i])
    if random(ints, draws) < CHEST_POTION[0]:
        colour = int(random(ints, draws) * _COLOURS)
        ints[POTIONS + colour] += _amount(ints, draws, CHEST_POTION[1], CHEST_POTION[2])
    if random(ints, draws) < CHEST_ARROWS[0]:
        ints[ARROWS] += _amount(ints, draws, CHEST_ARROWS[1], CHEST_ARROWS[2])
    if random(ints, draws) < CHEST_TOOL_CHANCE:
        tool = _CHEST_TOOLS[int(random(ints, draws) * len(_CHEST_TOOLS))]
        tier = 1 + _weighted(ints, draws, _TOOL_TIER_WEIGHT)
        ints[tool] = max(tier, ints[tool])
    first = not ints[CHESTS + level]
    if first and level == BOW_CHEST_LEVEL:
        ints[BOW] = 1
    if first and _BOOK_CHEST[level]:
        ints[BOOKS] += 1
    for i in range(_COLOURS):
        ints[POTIONS + i] = min(ints[POTIONS + i], STACK_LIMIT)
    ints[CHESTS + level] = 1
    ints[ACH + _OPEN_CHEST] = 1


@njit(cache=True)
def add_growing_plant(ints, r, c):
    for i in range(MAX_GROWING_PLANTS):
        if not ints[PLANT_MASK + i]:
            ints[PLANT_POS + 2 * i], ints[PLANT_POS + 2 * i + 1] = r, c
            ints[PLANT_AGE + i] = 0
            ints[PLANT_MASK + i] = 1
            return


@njit(cache=True)
def place(map, item_map, mob_map, light_map, ints, action):
    """Place a table, furnace, stone (also onto water), plant (onto grass) or torch (onto
    ``CAN_PLACE_ITEM`` blocks, with its light) on the facing cell: in bounds, no mob, neither
    solid nor holding an item."""
    level = ints[LEVEL]
    item, cost = _PLACE_ITEM[action], _PLACE_COST[action]
    if ints[item] < cost:
        return
    r, c = facing(ints)
    if not in_bounds(map, r, c) or is_in_mob(mob_map, ints, level, r, c):
        return
    here = map[level, r, c]
    has_item = item_map[level, r, c] != _NO_ITEM
    if action == _PLACE_TORCH:
        if not _CAN_PLACE_ITEM[here] or has_item:
            return
        item_map[level, r, c] = _TORCH
        add_torch_light(light_map, level, r, c)
    elif action == _PLACE_PLANT:
        if here != _GRASS or has_item:
            return
        add_growing_plant(ints, r, c)
    elif action == _PLACE_STONE:
        if here != _WATER and (_IS_SOLID[here] or has_item):
            return
    elif _IS_SOLID[here] or has_item:
        return
    if _PLACE_BLOCK[action] >= 0:
        map[level, r, c] = _PLACE_BLOCK[action]
    ints[item] -= cost
    ints[ACH + _PLACE_ACHIEVEMENT[action]] = 1


@njit(cache=True)
def add_torch_light(light_map, level, r, c):
    """Add the torch's 9x9 light around (r, c), clipped to [0, 1] (float32)."""
    h = TORCH_LIGHT_HALF
    for i in range(max(r - h, 0), min(r + h + 1, light_map.shape[1])):
        for j in range(max(c - h, 0), min(c + h + 1, light_map.shape[2])):
            v = np.float32(light_map[level, i, j] + _TORCH_LIGHT[i - (r - h), j - (c - h)])
            light_map[level, i, j] = min(max(v, np.float32(0.0)), np.float32(1.0))


@njit(cache=True)
def _spawn_player_projectile(ints, mobs, kind):
    level = ints[LEVEL]
    i = 0
    for slot in range(MAX_PLAYER_PROJECTILES):
        if not mobs[PLAYER_SHOTS, level, slot, ALIVE]:
            i = slot
            break
    shot = mobs[PLAYER_SHOTS, level, i]
    shot[MOB_ROW], shot[MOB_COL] = ints[ROW], ints[COL]
    shot[ALIVE] = 1
    shot[TYPE] = kind
    shot[DROW], shot[DCOL] = _DIR[ints[DIRECTION], 0], _DIR[ints[DIRECTION], 1]


@njit(cache=True)
def _projectile_slot_free(ints, mobs):
    live = 0
    for slot in range(MAX_PLAYER_PROJECTILES):
        live += mobs[PLAYER_SHOTS, ints[LEVEL], slot, ALIVE] != 0
    return live < MAX_PLAYER_PROJECTILES


@njit(cache=True)
def shoot_arrow(ints, mobs):
    """With a bow, an arrow and a free slot: an arrow leaves the player's cell."""
    if ints[BOW] >= 1 and ints[ARROWS] >= 1 and _projectile_slot_free(ints, mobs):
        _spawn_player_projectile(ints, mobs, _PLAYER_ARROW)
        ints[ARROWS] -= 1
        ints[ACH + _FIRE_BOW] = 1


@njit(cache=True)
def cast_spell(ints, mobs, action):
    """A learned spell, 2 mana and a free slot: a fireball / iceball leaves the player's cell."""
    index = _SPELL_INDEX[action]
    if (ints[SPELLS + index] and ints[MANA] >= SPELL_MANA_COST
            and _projectile_slot_free(ints, mobs)):
        _spawn_player_projectile(ints, mobs, _SPELL_KIND[action])
        ints[MANA] -= SPELL_MANA_COST
        ints[ACH + _SPELL_ACHIEVEMENT[action]] = 1


@njit(cache=True)
def drink_potion(ints, floats, action):
    """A potion of the action's colour: the effect ``potion_mapping`` gives it."""
    colour = _POTION_COLOUR[action]
    if ints[POTIONS + colour] <= 0:
        return
    ints[POTIONS + colour] -= 1
    effect = ints[POTION_MAP + colour]
    if _POTION_IN_FLOATS[effect]:
        floats[_POTION_VITAL[effect]] += _POTION_CHANGE[effect]
    else:
        ints[_POTION_VITAL[effect]] += _POTION_CHANGE[effect]
    ints[ACH + _DRINK_POTION] = 1


@njit(cache=True)
def read_book(ints, draws):
    """A book teaches a spell not yet learned, drawn evenly (among both when both are known)."""
    if ints[BOOKS] <= 0:
        return
    unknown = np.empty(_NUM_SPELLS, np.int64)
    n = 0
    for i in range(_NUM_SPELLS):
        if not ints[SPELLS + i]:
            unknown[n] = i
            n += 1
    if n == 0:
        for i in range(_NUM_SPELLS):
            unknown[i] = i
        n = _NUM_SPELLS
    spell = unknown[int(random(ints, draws) * n)] if n > 1 else unknown[0]
    ints[BOOKS] -= 1
    ints[SPELLS + spell] = 1
    ints[ACH + _LEARN_ACHIEVEMENT[spell]] = 1


@njit(cache=True)
def enchant(map, ints, draws, action):
    """Facing an enchantment table, with 9 mana and its gem: the sword / bow / an armour piece
    (drawn among the unenchanted, else among those of the other element) takes its element."""
    r, c = facing(ints)
    if not in_bounds(map, r, c):
        return
    block = map[ints[LEVEL], r, c]
    element, gem = _ENCHANT_ELEMENT[block], _ENCHANT_GEM[block]
    if element == 0:
        return
    if ints[MANA] < ENCHANT_MANA_COST or ints[gem] < 1:
        return
    if action == _ENCHANT_SWORD:
        if ints[SWORD] <= 0:
            return
        ints[SWORD_ENCH] = element
        ints[ACH + _ENCHANT_SWORD_ACH] = 1
    elif action == _ENCHANT_BOW:
        if ints[BOW] <= 0:
            return
        ints[BOW_ENCH] = element
    else:
        if ints[ARMOUR] + ints[ARMOUR + 1] + ints[ARMOUR + 2] + ints[ARMOUR + 3] <= 0:
            return
        targets = np.empty(4, np.int64)
        n = 0
        for i in range(4):
            if ints[ARMOUR_ENCH + i] == 0:
                targets[n] = i
                n += 1
        if n == 0:
            for i in range(4):
                if ints[ARMOUR_ENCH + i] != element:
                    targets[n] = i
                    n += 1
        if n:
            target = targets[int(random(ints, draws) * n)] if n > 1 else targets[0]
            ints[ARMOUR_ENCH + target] = element
        ints[ACH + _ENCHANT_ARMOUR_ACH] = 1
    ints[gem] -= 1
    ints[MANA] -= ENCHANT_MANA_COST


@njit(cache=True)
def level_up(ints, settings, action):
    """One XP raises an attribute below ``max_attribute`` by one."""
    attribute = _ATTRIBUTE[action]
    if ints[XP] >= 1 and ints[attribute] < settings[SET_MAX_ATTRIBUTE]:
        ints[attribute] += 1
        ints[XP] -= 1


@njit(cache=True)
def move(map, mob_map, ints, settings, action):
    """Face the move's direction; step there if the player can enter (always in god mode)."""
    r, c = ints[ROW] + _MOVE[action, 0], ints[COL] + _MOVE[action, 1]
    if settings[SET_GOD_MODE] or player_can_enter(map, mob_map, ints, r, c):
        ints[ROW], ints[COL] = r, c
    ints[DIRECTION] = action


@njit(cache=True)
def act(map, item_map, mob_map, light_map, ints, floats, mobs, health, kills, draws, settings,
        action):
    """``rules.step`` up to the mobs: returns the action played (NOOP asleep or resting)."""
    if ints[SLEEPING] or ints[RESTING]:
        action = _NOOP
    if ints[LEVEL] or action == _DESCEND or action == _ASCEND:
        change_floor(item_map, ints, settings, action)
    rule = _RULE[action]
    if rule == _DO_RULE:
        do(map, mob_map, ints, floats, mobs, health, kills, draws)
    elif rule == _CRAFT_RULE:
        craft(map, ints, action)
    elif rule == _PLACE_RULE:
        place(map, item_map, mob_map, light_map, ints, action)
    elif rule == _SHOOT_RULE:
        shoot_arrow(ints, mobs)
    elif rule == _CAST_RULE:
        cast_spell(ints, mobs, action)
    elif rule == _POTION_RULE:
        drink_potion(ints, floats, action)
    elif rule == _READ_RULE:
        read_book(ints, draws)
    elif rule == _ENCHANT_RULE:
        enchant(map, ints, draws, action)
    if ints[LEVEL] == BOSS_LEVEL or ints[BOSS_PROGRESS] >= BOSS_LEVEL:
        boss_logic(ints)
    if rule == _MOVE_RULE:
        move(map, mob_map, ints, settings, action)
    elif rule == _LEVEL_UP_RULE:
        level_up(ints, settings, action)
    return action


# ---------------------------------------------------------------------------------------------
# the upkeep (``upkeep``), in upstream's order


@njit(cache=True)
def grow_plants(map, ints):
    """Growing plants age by one (a free slot's age stays 0); at ``PLANT_RIPE_AGE`` their
    block (level 0) is a ripe plant."""
    for i in range(MAX_GROWING_PLANTS):
        ints[PLANT_AGE + i] = (ints[PLANT_AGE + i] + 1) * ints[PLANT_MASK + i]
        if ints[PLANT_AGE + i] >= PLANT_RIPE_AGE:
            map[0, ints[PLANT_POS + 2 * i], ints[PLANT_POS + 2 * i + 1]] = _RIPE


@njit(cache=True)
def update_intrinsics(ints, floats, settings, action):
    """Sleep and rest start and end; hunger, thirst and fatigue accumulate and cost food, drink,
    energy; sleep restores energy; health recovers or is lost; mana recovers."""
    dex, energy = ints[DEX], ints[ENERGY]
    asleep = ints[SLEEPING] != 0
    if asleep or action == _SLEEP:
        top_energy = max_food(dex)
        if action == _SLEEP and energy < top_energy:
            asleep = True
            ints[SLEEPING] = 1
        if asleep and energy >= top_energy:
            asleep = False
            ints[SLEEPING] = 0
            ints[ACH + _WAKE_UP] = 1
    food, drink = ints[FOOD], ints[DRINK]
    if action == _REST or ints[RESTING]:
        health, top_health = floats[HEALTH], max_health(ints[STR])
        if action == _REST and health < top_health:
            ints[RESTING] = 1
        if ints[RESTING] and (health >= top_health or food <= 0 or drink <= 0):
            ints[RESTING] = 0

    fall = 0 if ints[LEVEL] == BOSS_LEVEL else 1
    decay = 1.0 - DEXTERITY_DECAY * (dex - 1)
    intrinsics = settings[SET_INTRINSICS] != 0
    if intrinsics:
        rate = (SLEEP_INTRINSIC_RATE if asleep else 1.0) * decay
        hunger = floats[HUNGER] + rate
        if hunger > HUNGER_LIMIT:
            food = max(food - fall, 0)
            ints[FOOD] = food
            hunger = 0.0
        floats[HUNGER] = hunger
        thirst = floats[THIRST] + rate
        if thirst > THIRST_LIMIT:
            drink = max(drink - fall, 0)
            ints[DRINK] = drink
            thirst = 0.0
        floats[THIRST] = thirst
    if intrinsics or asleep:
        fatigue = min(floats[FATIGUE] - 1, 0.0) if asleep else floats[FATIGUE] + decay
        if fatigue > FATIGUE_LIMIT:
            energy = max(energy - fall, 0)
            ints[ENERGY] = energy
            fatigue = 0.0
        elif fatigue < FATIGUE_RESTED:
            energy = min(energy + 1, max_food(dex))
            ints[ENERGY] = energy
            fatigue = 0.0
        floats[FATIGUE] = fatigue

    a = 1 if asleep else 0      # (the rates' index)
    if food > 0 and drink > 0 and (energy > 0 or asleep):
        recover = floats[RECOVER] + _RECOVER_RATE[a]
    else:
        recover = floats[RECOVER] + _DERECOVER_RATE[a] * fall
    if recover > RECOVER_LIMIT:
        floats[HEALTH] = min(floats[HEALTH] + 1, max_health(ints[STR]))
        recover = 0.0
    elif recover < DERECOVER_LIMIT:
        floats[HEALTH] -= 1
        recover = 0.0
    floats[RECOVER] = recover

    mana = (floats[RECOVER_MANA] + _MANA_RATE[a]) * (
        1 + INTELLIGENCE_MANA_BONUS * (ints[INT] - 1))
    if mana > MANA_LIMIT:
        ints[MANA] += 1
        mana = 0.0
    floats[RECOVER_MANA] = mana


@njit(cache=True)
def clip_vitals(ints, floats, settings):
    """Inventory counts at most 99; vitals within [0, maximum]; god mode keeps health at least
    9."""
    for k in range(len(INVENTORY)):
        if ints[INV + k] > STACK_LIMIT:
            ints[INV + k] = STACK_LIMIT
    low = GOD_MODE_MIN_HEALTH if settings[SET_GOD_MODE] else 0
    top = max_health(ints[STR])
    health = floats[HEALTH]
    if health < low or health > top:
        floats[HEALTH] = min(max(health, low), top)
    top = max_food(ints[DEX])               # = max_drink = max_energy
    for vital in (FOOD, DRINK, ENERGY):
        ints[vital] = min(max(ints[vital], 0), top)
    top = max_mana(ints[INT])
    ints[MANA] = min(max(ints[MANA], 0), top)


@njit(cache=True)
def inventory_achievements(ints):
    """Collecting and crafting achievements read off the inventory."""
    for i in range(len(_HELD_OFFSET)):
        if ints[_HELD_OFFSET[i]] >= _HELD_LEAST[i]:
            ints[ACH + _HELD_ACHIEVEMENT[i]] = 1


@njit(cache=True)
def upkeep(map, ints, floats, settings, action):
    """``grow_plants``, ``update_intrinsics``, ``clip_vitals``, ``inventory_achievements``
    (not the daylight, not the timestep)."""
    grow_plants(map, ints)
    update_intrinsics(ints, floats, settings, action)
    clip_vitals(ints, floats, settings)
    inventory_achievements(ints)
