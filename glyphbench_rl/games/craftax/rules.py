"""Craftax's step: upstream ``craftax_step`` (craftax 1.6.1, ``game_logic.py``) as a chain of
small sub-rules on the numpy ``State``, in upstream's order.

``step(state, action, settings, draws)`` mutates ``state`` and returns upstream's reward (the
weights of the achievements unlocked this step plus 0.1 x the change in health). The order:

1. a sleeping or resting player's action becomes NOOP;
2. ``change_floor`` (DESCEND / ASCEND, and the first-entry achievement and XP of a level);
3. the action's own rule: ``craft``, ``do`` (attack, mine, drink, eat, open chests, hit the
   necromancer), ``place``, ``shoot_arrow``, ``cast_spell``, ``drink_potion``, ``read_book``,
   ``enchant``; then the boss rule (``mobs.boss_logic``, every step) and ``level_up``;
4. ``move`` (the move actions only);
5. ``mobs.update`` and ``mobs.spawn`` (``settings.spawning`` off skips the spawn);
6. the upkeep (``upkeep``): ``grow_plants``, ``update_intrinsics``, ``clip_vitals``,
   ``inventory_achievements``;
7. the reward, ``timestep`` + 1 and the light level of the new timestep (``upkeep.daylight``).

Randomness is explicit: ``draws`` (``games.common.lanes.Draws``) gives the uniform draws for
the sapling found on grass, chest loot, the spell a book teaches and the armour piece an
enchantment lands on, one draw per upstream random choice, taken only when the choice matters.

Helpers other modules use: ``in_bounds``, ``is_in_mob``, ``is_free``, ``player_can_enter`` and
``player_damage_vector`` (the player's melee damage). The combat and boss rules the player's
actions share with the mobs live once, in ``mobs``: ``mobs.attack_mob`` (a hit on a mob, with the
kill bookkeeping), ``mobs.hurt_player`` / ``mobs.damage_to_player`` (a mob's damage to the
player), ``mobs.damage_necromancer`` and ``mobs.boss_logic``; the mob tables are ``bestiary``'s.
"""

from __future__ import annotations

import numpy as np

from . import mobs
from .state import MAX_PLAYER_PROJECTILES, State
from .tables import (
    ACHIEVEMENT_REWARD, BOOK_CHEST_LEVELS, BOSS_LEVEL, BOW_CHEST_LEVEL, CAN_PLACE_ITEM,
    CHEST_ARROWS, CHEST_ORES, CHEST_ORE_CHANCE, CHEST_POTION, CHEST_TOOL_CHANCE,
    CHEST_TOOL_TIER_WEIGHTS, CHEST_TORCH, CLOSE_BLOCKS, DIRECTIONS, DRINK_BLOCKS,
    ENCHANT_DAMAGE_FRACTION, ENCHANT_MANA_COST, ENCHANT_TABLES, INTELLIGENCE_ENCHANT_BONUS,
    IS_SOLID, LEARN_SPELL_ACHIEVEMENT, LEVEL_ACHIEVEMENT, MINING_BY_BLOCK,
    MONSTERS_KILLED_TO_CLEAR_LEVEL, MOVES, NUM_LEVELS, PLACING, PLAYER_ARROW, POTION_ACTIONS,
    POTION_EFFECTS, RECIPE_BY_ACTION, RIPE_PLANT_FOOD, SAPLING_CHANCE, SPELLS, SPELL_MANA_COST,
    STACK_LIMIT, STRENGTH_DAMAGE_BONUS, SWORD_DAMAGE, TORCH_LIGHT_HALF, TORCH_LIGHT_MAP,
    XP_PER_NEW_LEVEL, Achievement, Action, BlockType, ItemType, max_drink, max_food,
)
from .upkeep import clip_vitals, daylight, grow_plants, inventory_achievements, update_intrinsics

_WEIGHTS = np.array(ACHIEVEMENT_REWARD, np.float64)
_DIR = {int(a): d for a, d in DIRECTIONS.items()}
_POTION_INDEX = {int(a): i for i, a in enumerate(POTION_ACTIONS)}
_SPELLS = {int(a): (i, int(p), int(ach)) for a, (i, p, ach) in SPELLS.items()}
_PLACING = {int(a): (item, cost, None if block is None else int(block), int(ach))
            for a, (item, cost, block, ach) in PLACING.items()}
_ENCHANT_TABLES = {int(b): v for b, v in ENCHANT_TABLES.items()}
_RECIPE_COST = {a: tuple(r.cost.items()) for a, r in RECIPE_BY_ACTION.items()}
_DRINK_BLOCKS = frozenset(int(b) for b in DRINK_BLOCKS)
_GRASS, _PATH, _WATER = int(BlockType.GRASS), int(BlockType.PATH), int(BlockType.WATER)
_LAVA, _CHEST, _RIPE = int(BlockType.LAVA), int(BlockType.CHEST), int(BlockType.RIPE_PLANT)
_PLANT, _NECRO = int(BlockType.PLANT), int(BlockType.NECROMANCER)
_TABLE, _FURNACE = int(BlockType.CRAFTING_TABLE), int(BlockType.FURNACE)
_NOOP, _DO = int(Action.NOOP), int(Action.DO)
_DESCEND, _ASCEND = int(Action.DESCEND), int(Action.ASCEND)

# ------------------------------------------------------------------------------------------
# helpers shared with the other modules


def in_bounds(state: State, r: int, c: int) -> bool:
    rows, cols = state.map.shape[1:]
    return 0 <= r < rows and 0 <= c < cols


def is_in_mob(state: State, level: int, r: int, c: int) -> bool:
    """A mob stands at (r, c) of ``level``, or the player does (upstream is_in_mob)."""
    if state.mob_map.item(level, r, c):
        return True
    p_row, p_col = state.player_position.tolist()
    return level == state.player_level and r == p_row and c == p_col


def is_free(state: State, level: int, pos) -> bool:
    """``pos`` (row, col) of ``level`` is in bounds, not solid, and nobody (mob or player)
    stands there: where a mob may walk, before its own collision rules (water, lava)."""
    r, c = int(pos[0]), int(pos[1])
    return (in_bounds(state, r, c) and not IS_SOLID[state.map.item(level, r, c)]
            and not is_in_mob(state, level, r, c))


def player_can_enter(state: State, r: int, c: int) -> bool:
    """Upstream's land-creature collision for the player: free, and neither water nor lava."""
    level = state.player_level
    return is_free(state, level, (r, c)) and state.map.item(level, r, c) not in (_WATER, _LAVA)


def player_damage_vector(state: State) -> tuple[float, float, float]:
    """(physical, fire, ice) damage of the player's melee hit: the sword tier's damage scaled by
    strength; an enchanted sword adds half the unscaled damage as its element, scaled by
    intelligence."""
    base = SWORD_DAMAGE[state.inventory.sword]
    element = base * ENCHANT_DAMAGE_FRACTION * (
        1 + INTELLIGENCE_ENCHANT_BONUS * (state.player_intelligence - 1))
    physical = base * (1 + STRENGTH_DAMAGE_BONUS * (state.player_strength - 1))
    ench = state.sword_enchantment
    return physical, element if ench == 1 else 0.0, element if ench == 2 else 0.0


def unlock(state: State, achievement: int) -> None:
    state.achievements[achievement] = True


def facing(state: State) -> tuple[int, int]:
    dr, dc = _DIR.get(state.player_direction, (0, 0))
    row, col = state.player_position.tolist()
    return row + dr, col + dc


def is_near_block(state: State, block: int) -> bool:
    """``block`` is in one of the eight cells around the player (``CLOSE_BLOCKS``: crafting
    stations), read as the 3 x 3 window around the player (cut at the map's edge) less its
    centre."""
    level, (r, c) = state.player_level, state.player_position.tolist()
    r0, c0 = max(r - 1, 0), max(c - 1, 0)
    window = state.map[level, r0:r + 2, c0:c + 2].tolist()
    window[r - r0][c - c0] = -1          # (the player's own cell is not near)
    return any(block in row for row in window)


assert len(CLOSE_BLOCKS) == 8 and set(CLOSE_BLOCKS) == {
    (dr, dc) for dr in (-1, 0, 1) for dc in (-1, 0, 1) if dr or dc}


# ------------------------------------------------------------------------------------------
# the sub-rules, in upstream's order


def change_floor(state: State, action: int, settings) -> None:
    """DESCEND on a down ladder once the level has ``MONSTERS_KILLED_TO_CLEAR_LEVEL`` kills
    (or in god mode) moves to the next level's up ladder; ASCEND on an up ladder moves to the
    previous level's down ladder. Being on a level other than the overworld whose entry
    achievement is missing unlocks it and gives 1 XP (whatever the action)."""
    level = state.player_level
    if action == _DESCEND or action == _ASCEND:
        r, c = state.player_position.tolist()
        item = state.item_map.item(level, r, c)
        if action == _DESCEND and level < NUM_LEVELS - 1 and (settings.god_mode or (
                item == ItemType.LADDER_DOWN
                and state.monsters_killed[level] >= MONSTERS_KILLED_TO_CLEAR_LEVEL)):
            level += 1
            state.player_position[:] = state.up_ladders[level]
        elif action == _ASCEND and level > 0 and (settings.god_mode or item == ItemType.LADDER_UP):
            level -= 1
            state.player_position[:] = state.down_ladders[level]
        state.player_level = level
    achievement = LEVEL_ACHIEVEMENT[level]
    if achievement is not None and not state.achievements.item(achievement):
        unlock(state, achievement)
        state.player_xp += XP_PER_NEW_LEVEL


def craft(state: State, action: int) -> None:
    """A recipe of ``tables.RECIPES``: its cost paid, at a crafting table (and furnace)."""
    recipe = RECIPE_BY_ACTION[action]
    inv = state.inventory
    for item, n in _RECIPE_COST[action]:    # (the cheaper test first: both only return)
        if getattr(inv, item) < n:
            return
    if not is_near_block(state, _TABLE) or (recipe.furnace and not is_near_block(state, _FURNACE)):
        return
    result = recipe.result
    if result == "armour":
        below = np.flatnonzero(inv.armour < recipe.tier)
        if not below.size:
            return
        inv.armour[below[0]] = recipe.tier
        unlock(state, recipe.achievement)
    elif result in ("pickaxe", "sword"):
        if getattr(inv, result) >= recipe.tier:
            return
        setattr(inv, result, recipe.tier)
    else:   # arrows, torches
        if getattr(inv, result) >= STACK_LIMIT:
            return
        setattr(inv, result, getattr(inv, result) + recipe.amount)
    for item, n in recipe.cost.items():
        setattr(inv, item, getattr(inv, item) - n)


def do(state: State, settings, draws) -> None:
    """DO on the facing cell: attack a mob there (then nothing else happens); otherwise mine it
    (``tables.MINING``, with the pickaxe tier), find a sapling on grass, drink water, eat a ripe
    plant, open a chest, or hit the vulnerable necromancer."""
    r, c = facing(state)
    if not in_bounds(state, r, c):
        return
    level, inv = state.player_level, state.inventory
    if state.mob_map.item(level, r, c):     # (the mob map is exact: no mob there, no lookup)
        hit, _ = mobs.attack_mob(state, r, c, player_damage_vector(state), True)
        if hit:
            return
    block = state.map.item(level, r, c)
    mined = MINING_BY_BLOCK.get(block)
    if mined is not None:
        tier, item, left = mined
        if inv.pickaxe >= tier:
            state.map[level, r, c] = left
            if item is not None:
                setattr(inv, item, getattr(inv, item) + 1)
    elif block == _GRASS:
        if draws.random() < SAPLING_CHANCE:
            inv.sapling += 1
    elif block in _DRINK_BLOCKS:
        state.player_drink = min(max_drink(state.player_dexterity), state.player_drink + 1)
        state.player_thirst = 0.0
        unlock(state, Achievement.COLLECT_DRINK)
    elif block == _RIPE:
        eat_plant(state, r, c)
    elif block == _CHEST:
        open_chest(state, r, c, draws)
    elif block == _NECRO:
        mobs.damage_necromancer(state)


def eat_plant(state: State, r: int, c: int) -> None:
    """A ripe plant becomes a (growing) plant again: food +4, hunger 0. Upstream resets the age
    of the growing-plant slot at that position, or slot 0 when none is there."""
    state.map[state.player_level, r, c] = _PLANT
    state.player_food = min(max_food(state.player_dexterity), state.player_food + RIPE_PLANT_FOOD)
    state.player_hunger = 0.0
    unlock(state, Achievement.EAT_PLANT)
    at = np.flatnonzero((state.growing_plants_positions[:, 0] == r)
                        & (state.growing_plants_positions[:, 1] == c))
    state.growing_plants_age[at[0] if at.size else 0] = 0


def _amount(draws, low: int, high: int) -> int:
    return low + draws.below(high - low + 1)


def _weighted(draws, weights) -> int:
    x, total = draws.random(), 0.0
    for i, w in enumerate(weights):
        total += w
        if x < total:
            return i
    return len(weights) - 1


def open_chest(state: State, r: int, c: int, draws) -> None:
    """The chest becomes path and gives upstream's loot (``tables.CHEST_*``); the first chest of
    the dungeon also holds the bow, the first of the sewers or vaults a book."""
    level, inv = state.player_level, state.inventory
    state.map[level, r, c] = _PATH
    chance, low, high = CHEST_TORCH
    if draws.random() < chance:
        inv.torches += _amount(draws, low, high)
    if draws.random() < CHEST_ORE_CHANCE:
        item, _, low, high = CHEST_ORES[_weighted(draws, [w for _, w, _, _ in CHEST_ORES])]
        setattr(inv, item, getattr(inv, item) + _amount(draws, low, high))
    chance, low, high = CHEST_POTION
    if draws.random() < chance:
        inv.potions[draws.below(len(inv.potions))] += _amount(draws, low, high)
    chance, low, high = CHEST_ARROWS
    if draws.random() < chance:
        inv.arrows += _amount(draws, low, high)
    if draws.random() < CHEST_TOOL_CHANCE:
        tool = ("pickaxe", "sword")[draws.below(2)]
        tier = 1 + _weighted(draws, CHEST_TOOL_TIER_WEIGHTS)
        setattr(inv, tool, max(tier, getattr(inv, tool)))
    first = not state.chests_opened[level]
    if first and level == BOW_CHEST_LEVEL:
        inv.bow = 1
    if first and level in BOOK_CHEST_LEVELS:
        inv.books += 1
    np.minimum(inv.potions, STACK_LIMIT, out=inv.potions)
    state.chests_opened[level] = True
    unlock(state, Achievement.OPEN_CHEST)


def add_growing_plant(state: State, r: int, c: int) -> None:
    free = np.flatnonzero(~state.growing_plants_mask)
    if free.size:
        i = free[0]
        state.growing_plants_positions[i] = (r, c)
        state.growing_plants_age[i] = 0
        state.growing_plants_mask[i] = True


def place(state: State, action: int) -> None:
    """Place a table (2 wood), furnace (1 stone), stone (1 stone; also onto water), plant (a
    sapling, onto grass) or torch (onto ``CAN_PLACE_ITEM`` blocks) on the facing cell, which
    must be in bounds, without a mob, and (but for those exceptions) neither solid nor holding
    an item. A torch adds its light to the level's light map."""
    level, inv = state.player_level, state.inventory
    item_name, cost, block, achievement = _PLACING[action]
    if getattr(inv, item_name) < cost:      # (the cheaper test first: both only return)
        return
    r, c = facing(state)
    if not in_bounds(state, r, c) or is_in_mob(state, level, r, c):
        return
    here = state.map.item(level, r, c)
    has_item = state.item_map.item(level, r, c) != ItemType.NONE
    if action == Action.PLACE_TORCH:
        if not CAN_PLACE_ITEM[here] or has_item:
            return
        state.item_map[level, r, c] = ItemType.TORCH
        add_torch_light(state, level, r, c)
    elif action == Action.PLACE_PLANT:
        if here != _GRASS or has_item:
            return
        add_growing_plant(state, r, c)
    elif action == Action.PLACE_STONE:
        if here != _WATER and (IS_SOLID[here] or has_item):
            return
    elif IS_SOLID[here] or has_item:
        return
    if block is not None:
        state.map[level, r, c] = block
    setattr(inv, item_name, getattr(inv, item_name) - cost)
    unlock(state, achievement)


def add_torch_light(state: State, level: int, r: int, c: int) -> None:
    """Add the torch's 9x9 light (1 - distance / 5) around (r, c), clipped to [0, 1]."""
    h = TORCH_LIGHT_HALF
    rows, cols = state.map.shape[1:]
    r0, r1, c0, c1 = max(r - h, 0), min(r + h + 1, rows), max(c - h, 0), min(c + h + 1, cols)
    patch = TORCH_LIGHT_MAP[r0 - (r - h):r1 - (r - h), c0 - (c - h):c1 - (c - h)]
    area = state.light_map[level, r0:r1, c0:c1]
    np.clip(area + patch, 0.0, 1.0, out=area)


def _spawn_player_projectile(state: State, kind: int) -> None:
    level = state.player_level
    p = state.player_projectiles
    live = p.mask[level]
    i = live.index(False) if False in live else 0      # (numpy's argmin of the mask)
    p.position[level][i] = tuple(state.player_position.tolist())
    live[i] = True
    p.type_id[level][i] = int(kind)
    state.player_projectile_directions[level, i] = _DIR[state.player_direction]


def _projectile_slot_free(state: State) -> bool:
    return state.player_projectiles.mask[state.player_level].count(True) < MAX_PLAYER_PROJECTILES


def shoot_arrow(state: State) -> None:
    """With a bow, an arrow and a free projectile slot: an arrow starts at the player's cell,
    flying the way the player faces (``mobs.update`` moves it)."""
    inv = state.inventory
    if inv.bow >= 1 and inv.arrows >= 1 and _projectile_slot_free(state):
        _spawn_player_projectile(state, int(PLAYER_ARROW))
        inv.arrows -= 1
        unlock(state, Achievement.FIRE_BOW)


def cast_spell(state: State, action: int) -> None:
    """A learned spell with 2 mana and a free projectile slot: a fireball / iceball starts at
    the player's cell."""
    index, kind, achievement = _SPELLS[action]
    if (state.learned_spells.item(index) and state.player_mana >= SPELL_MANA_COST
            and _projectile_slot_free(state)):
        _spawn_player_projectile(state, kind)
        state.player_mana -= SPELL_MANA_COST
        unlock(state, achievement)


def drink_potion(state: State, action: int) -> None:
    """A potion of the action's colour has the effect ``potion_mapping`` gives that colour
    (``tables.POTION_EFFECTS``); vitals are clipped at the end of the step."""
    colour = _POTION_INDEX[action]
    potions = state.inventory.potions
    if potions.item(colour) <= 0:      # (a Python number: a numpy scalar's test costs more)
        return
    potions[colour] -= 1
    vital, change = POTION_EFFECTS[int(state.potion_mapping[colour])]
    name = "player_" + vital
    setattr(state, name, getattr(state, name) + change)
    unlock(state, Achievement.DRINK_POTION)


def read_book(state: State, draws) -> None:
    """A book teaches a spell not yet learned, drawn evenly (upstream draws among both when
    both are known; the book is spent either way)."""
    if state.inventory.books <= 0:
        return
    unknown = np.flatnonzero(~state.learned_spells)
    if unknown.size == 0:
        unknown = np.arange(len(state.learned_spells))
    spell = int(unknown[draws.below(unknown.size)]) if unknown.size > 1 else int(unknown[0])
    state.inventory.books -= 1
    state.learned_spells[spell] = True
    unlock(state, LEARN_SPELL_ACHIEVEMENT[spell])


def enchant(state: State, action: int, draws) -> None:
    """Facing an enchantment table, with 9 mana and its gem (ruby: fire, sapphire: ice), the
    sword / bow / armour (a piece drawn among the unenchanted ones, or if none among those of
    the other element) takes the table's element."""
    r, c = facing(state)
    table = _ENCHANT_TABLES.get(state.map.item(state.player_level, r, c)) if in_bounds(
        state, r, c) else None
    if table is None:
        return
    element, gem = table
    inv = state.inventory
    if state.player_mana < ENCHANT_MANA_COST or getattr(inv, gem) < 1:
        return
    if action == Action.ENCHANT_SWORD:
        if inv.sword <= 0:
            return
        state.sword_enchantment = element
        unlock(state, Achievement.ENCHANT_SWORD)
    elif action == Action.ENCHANT_BOW:
        if inv.bow <= 0:
            return
        state.bow_enchantment = element
    else:
        if inv.armour.sum() <= 0:
            return
        ench = state.armour_enchantments
        targets = np.flatnonzero(ench == 0)
        if not targets.size:
            targets = np.flatnonzero(ench != element)
        if targets.size:   # (all pieces already of this element: upstream changes nothing)
            ench[targets[draws.below(targets.size)] if targets.size > 1 else targets[0]] = element
        unlock(state, Achievement.ENCHANT_ARMOUR)
    setattr(inv, gem, getattr(inv, gem) - 1)
    state.player_mana -= ENCHANT_MANA_COST


_ATTRIBUTES = {int(Action.LEVEL_UP_DEXTERITY): "player_dexterity",
               int(Action.LEVEL_UP_STRENGTH): "player_strength",
               int(Action.LEVEL_UP_INTELLIGENCE): "player_intelligence"}


def level_up(state: State, action: int, settings) -> None:
    """One XP raises an attribute below ``settings.max_attribute`` by one."""
    name = _ATTRIBUTES[action]
    if state.player_xp >= 1 and getattr(state, name) < settings.max_attribute:
        setattr(state, name, getattr(state, name) + 1)
        state.player_xp -= 1


def move(state: State, action: int, settings) -> None:
    """Face the move's direction; step there if the player can enter the cell (not solid, no
    mob, not water or lava), or always in god mode."""
    dr, dc = MOVES[action]
    row, col = state.player_position.tolist()
    r, c = row + dr, col + dc
    if settings.god_mode or player_can_enter(state, r, c):
        state.player_position[0], state.player_position[1] = r, c
    state.player_direction = action


# each action's own rule (one dict look-up per step instead of a chain of set tests); moves
# and level-ups come after the boss rule, as upstream's
_DO_RULE, _CRAFT_RULE, _PLACE_RULE, _SHOOT_RULE, _CAST_RULE, _POTION_RULE, _READ_RULE, \
    _ENCHANT_RULE, _LEVEL_UP_RULE, _MOVE_RULE = range(1, 11)
_RULE = ({_DO: _DO_RULE, int(Action.SHOOT_ARROW): _SHOOT_RULE, int(Action.READ_BOOK): _READ_RULE}
         | dict.fromkeys(RECIPE_BY_ACTION, _CRAFT_RULE) | dict.fromkeys(_PLACING, _PLACE_RULE)
         | dict.fromkeys(_SPELLS, _CAST_RULE) | dict.fromkeys(_POTION_INDEX, _POTION_RULE)
         | dict.fromkeys((int(a) for a in (Action.ENCHANT_SWORD, Action.ENCHANT_ARMOUR,
                                           Action.ENCHANT_BOW)), _ENCHANT_RULE)
         | dict.fromkeys(_ATTRIBUTES, _LEVEL_UP_RULE) | dict.fromkeys(MOVES, _MOVE_RULE))
_LADDERS = (_DESCEND, _ASCEND)


def step(state: State, action: int, settings, draws, after_mobs=None, ended=None) -> float:
    """One upstream step (see the module docstring); returns upstream's reward. ``after_mobs``,
    if given, is called with the state after the mobs moved and before any spawn (a task
    counting kills looks at the mob slots then, before a spawn can reuse one). ``ended``, if
    given, a list of two: set to the inventory's ``held_counts`` and the achievements' bytes
    the step ended with (the upkeep read them; a task's tally takes them there)."""
    achievements = state.achievements
    before = achievements.tobytes()
    health = state.player_health
    action = int(action)
    if state.is_sleeping or state.is_resting:
        action = _NOOP

    if state.player_level or action in _LADDERS:     # (on the surface it has nothing else to do)
        change_floor(state, action, settings)
    rule = _RULE.get(action, 0)
    if not rule or rule >= _LEVEL_UP_RULE:
        pass        # (NOOP, SLEEP, REST, the ladders, or a rule that comes after the boss's)
    elif rule == _DO_RULE:
        do(state, settings, draws)
    elif rule == _CRAFT_RULE:
        craft(state, action)
    elif rule == _PLACE_RULE:
        place(state, action)
    elif rule == _SHOOT_RULE:
        shoot_arrow(state)
    elif rule == _CAST_RULE:
        cast_spell(state, action)
    elif rule == _POTION_RULE:
        drink_potion(state, action)
    elif rule == _READ_RULE:
        read_book(state, draws)
    elif rule == _ENCHANT_RULE:
        enchant(state, action, draws)
    if state.player_level == BOSS_LEVEL or state.boss_progress >= BOSS_LEVEL:
        mobs.boss_logic(state)      # (elsewhere, before the boss is beaten, it does nothing)
    if rule == _MOVE_RULE:
        move(state, action, settings)
    elif rule == _LEVEL_UP_RULE:
        level_up(state, action, settings)

    mobs.update(state, settings, draws)
    if after_mobs is not None:
        after_mobs(state)
    if settings.spawning:
        mobs.spawn(state, settings, draws)

    grow_plants(state)
    update_intrinsics(state, action, settings)
    counts = clip_vitals(state, settings)
    after = inventory_achievements(state, counts)    # (the achievements' bytes now)
    if ended is not None:
        ended[0], ended[1] = counts, after

    reward = 0.0
    if after != before:
        old = np.frombuffer(before, dtype=bool)
        reward = float(_WEIGHTS[achievements & ~old].sum())
    reward += (state.player_health - health) * 0.1
    state.timestep += 1
    state.light_level = daylight(state.timestep, settings)
    return reward
