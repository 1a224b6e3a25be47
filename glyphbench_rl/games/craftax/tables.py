"""Craftax's rules as data: upstream ``craftax`` 1.6.1's enumerations and constant tables.

The enumerations keep upstream's names and values (``craftax/craftax/constants.py``), so a state
or a table converts without renaming; ``tests/games/craftax`` checks every table here against the
package. Mob tables are in ``bestiary``.
"""

from __future__ import annotations

import math
from enum import IntEnum



class BlockType(IntEnum):
    INVALID = 0
    OUT_OF_BOUNDS = 1
    GRASS = 2
    WATER = 3
    STONE = 4
    TREE = 5
    WOOD = 6
    PATH = 7
    COAL = 8
    IRON = 9
    DIAMOND = 10
    CRAFTING_TABLE = 11
    FURNACE = 12
    SAND = 13
    LAVA = 14
    PLANT = 15
    RIPE_PLANT = 16
    WALL = 17
    DARKNESS = 18
    WALL_MOSS = 19
    STALAGMITE = 20
    SAPPHIRE = 21
    RUBY = 22
    CHEST = 23
    FOUNTAIN = 24
    FIRE_GRASS = 25
    ICE_GRASS = 26
    GRAVEL = 27
    FIRE_TREE = 28
    ICE_SHRUB = 29
    ENCHANTMENT_TABLE_FIRE = 30
    ENCHANTMENT_TABLE_ICE = 31
    NECROMANCER = 32
    GRAVE = 33
    GRAVE2 = 34
    GRAVE3 = 35
    NECROMANCER_VULNERABLE = 36


class ItemType(IntEnum):
    NONE = 0
    TORCH = 1
    LADDER_DOWN = 2
    LADDER_UP = 3
    LADDER_DOWN_BLOCKED = 4


class Action(IntEnum):
    NOOP = 0
    LEFT = 1
    RIGHT = 2
    UP = 3
    DOWN = 4
    DO = 5
    SLEEP = 6
    PLACE_STONE = 7
    PLACE_TABLE = 8
    PLACE_FURNACE = 9
    PLACE_PLANT = 10
    MAKE_WOOD_PICKAXE = 11
    MAKE_STONE_PICKAXE = 12
    MAKE_IRON_PICKAXE = 13
    MAKE_WOOD_SWORD = 14
    MAKE_STONE_SWORD = 15
    MAKE_IRON_SWORD = 16
    REST = 17
    DESCEND = 18
    ASCEND = 19
    MAKE_DIAMOND_PICKAXE = 20
    MAKE_DIAMOND_SWORD = 21
    MAKE_IRON_ARMOUR = 22
    MAKE_DIAMOND_ARMOUR = 23
    SHOOT_ARROW = 24
    MAKE_ARROW = 25
    CAST_FIREBALL = 26
    CAST_ICEBALL = 27
    PLACE_TORCH = 28
    DRINK_POTION_RED = 29
    DRINK_POTION_GREEN = 30
    DRINK_POTION_BLUE = 31
    DRINK_POTION_PINK = 32
    DRINK_POTION_CYAN = 33
    DRINK_POTION_YELLOW = 34
    READ_BOOK = 35
    ENCHANT_SWORD = 36
    ENCHANT_ARMOUR = 37
    MAKE_TORCH = 38
    LEVEL_UP_DEXTERITY = 39
    LEVEL_UP_STRENGTH = 40
    LEVEL_UP_INTELLIGENCE = 41
    ENCHANT_BOW = 42


class MobType(IntEnum):
    PASSIVE = 0
    MELEE = 1
    RANGED = 2
    PROJECTILE = 3


class ProjectileType(IntEnum):
    ARROW = 0
    DAGGER = 1
    FIREBALL = 2
    ICEBALL = 3
    ARROW2 = 4
    SLIMEBALL = 5
    FIREBALL2 = 6
    ICEBALL2 = 7


class Achievement(IntEnum):
    COLLECT_WOOD = 0
    PLACE_TABLE = 1
    EAT_COW = 2
    COLLECT_SAPLING = 3
    COLLECT_DRINK = 4
    MAKE_WOOD_PICKAXE = 5
    MAKE_WOOD_SWORD = 6
    PLACE_PLANT = 7
    DEFEAT_ZOMBIE = 8
    COLLECT_STONE = 9
    PLACE_STONE = 10
    EAT_PLANT = 11
    DEFEAT_SKELETON = 12
    MAKE_STONE_PICKAXE = 13
    MAKE_STONE_SWORD = 14
    WAKE_UP = 15
    PLACE_FURNACE = 16
    COLLECT_COAL = 17
    COLLECT_IRON = 18
    COLLECT_DIAMOND = 19
    MAKE_IRON_PICKAXE = 20
    MAKE_IRON_SWORD = 21
    MAKE_ARROW = 22
    MAKE_TORCH = 23
    PLACE_TORCH = 24
    COLLECT_SAPPHIRE = 54
    COLLECT_RUBY = 59
    MAKE_DIAMOND_PICKAXE = 60
    MAKE_DIAMOND_SWORD = 25
    MAKE_IRON_ARMOUR = 26
    MAKE_DIAMOND_ARMOUR = 27
    ENTER_GNOMISH_MINES = 28
    ENTER_DUNGEON = 29
    ENTER_SEWERS = 30
    ENTER_VAULT = 31
    ENTER_TROLL_MINES = 32
    ENTER_FIRE_REALM = 33
    ENTER_ICE_REALM = 34
    ENTER_GRAVEYARD = 35
    DEFEAT_GNOME_WARRIOR = 36
    DEFEAT_GNOME_ARCHER = 37
    DEFEAT_ORC_SOLIDER = 38
    DEFEAT_ORC_MAGE = 39
    DEFEAT_LIZARD = 40
    DEFEAT_KOBOLD = 41
    DEFEAT_KNIGHT = 65
    DEFEAT_ARCHER = 66
    DEFEAT_TROLL = 42
    DEFEAT_DEEP_THING = 43
    DEFEAT_PIGMAN = 44
    DEFEAT_FIRE_ELEMENTAL = 45
    DEFEAT_FROST_TROLL = 46
    DEFEAT_ICE_ELEMENTAL = 47
    DAMAGE_NECROMANCER = 48
    DEFEAT_NECROMANCER = 49
    EAT_BAT = 50
    EAT_SNAIL = 51
    FIND_BOW = 52
    FIRE_BOW = 53
    LEARN_FIREBALL = 55
    CAST_FIREBALL = 56
    LEARN_ICEBALL = 57
    CAST_ICEBALL = 58
    OPEN_CHEST = 61
    DRINK_POTION = 62
    ENCHANT_SWORD = 63
    ENCHANT_ARMOUR = 64


# --------------------------------------------------------------------------------------------
# Rule tables (upstream ``constants.py``, and the numbers ``game_logic.py`` writes inline, named
# here; the inline ones are checked by the lockstep test against the package's step).
# --------------------------------------------------------------------------------------------

NUM_BLOCK_TYPES = len(BlockType)
NUM_ACHIEVEMENTS = len(Achievement)

# Blocks nothing walks through (upstream SOLID_BLOCKS); ``IS_SOLID[block]`` is the fast lookup.
SOLID_BLOCKS = frozenset({
    BlockType.STONE, BlockType.TREE, BlockType.COAL, BlockType.IRON, BlockType.DIAMOND,
    BlockType.CRAFTING_TABLE, BlockType.FURNACE, BlockType.PLANT, BlockType.RIPE_PLANT,
    BlockType.WALL, BlockType.WALL_MOSS, BlockType.STALAGMITE, BlockType.RUBY, BlockType.SAPPHIRE,
    BlockType.CHEST, BlockType.FOUNTAIN, BlockType.FIRE_TREE, BlockType.ENCHANTMENT_TABLE_FIRE,
    BlockType.ENCHANTMENT_TABLE_ICE, BlockType.GRAVE, BlockType.GRAVE2, BlockType.GRAVE3,
    BlockType.NECROMANCER,
})
IS_SOLID = tuple(b in SOLID_BLOCKS for b in BlockType)

# Blocks a torch (an item) may be placed on (upstream CAN_PLACE_ITEM_BLOCKS).
CAN_PLACE_ITEM_BLOCKS = frozenset({BlockType.GRASS, BlockType.SAND, BlockType.PATH,
                                   BlockType.FIRE_GRASS, BlockType.ICE_GRASS})
CAN_PLACE_ITEM = tuple(b in CAN_PLACE_ITEM_BLOCKS for b in BlockType)

# Action -> (drow, dcol); every other action is (0, 0) (upstream DIRECTIONS, 16 rows).
DIRECTIONS = {Action.NOOP: (0, 0), Action.LEFT: (0, -1), Action.RIGHT: (0, 1),
              Action.UP: (-1, 0), Action.DOWN: (1, 0)}
MOVES = {int(a): d for a, d in DIRECTIONS.items() if d != (0, 0)}

# The eight cells around the player where a crafting table / furnace counts as "near".
CLOSE_BLOCKS = ((0, -1), (0, 1), (-1, 0), (1, 0), (-1, -1), (-1, 1), (1, -1), (1, 1))

# ---- achievements and their reward weights
INTERMEDIATE_ACHIEVEMENTS = frozenset({
    Achievement.COLLECT_SAPPHIRE, Achievement.COLLECT_RUBY, Achievement.MAKE_DIAMOND_PICKAXE,
    Achievement.MAKE_DIAMOND_SWORD, Achievement.MAKE_IRON_ARMOUR, Achievement.MAKE_DIAMOND_ARMOUR,
    Achievement.ENTER_GNOMISH_MINES, Achievement.ENTER_DUNGEON, Achievement.DEFEAT_GNOME_WARRIOR,
    Achievement.DEFEAT_GNOME_ARCHER, Achievement.DEFEAT_ORC_SOLIDER, Achievement.DEFEAT_ORC_MAGE,
    Achievement.EAT_BAT, Achievement.EAT_SNAIL, Achievement.FIND_BOW, Achievement.FIRE_BOW,
    Achievement.OPEN_CHEST, Achievement.DRINK_POTION,
})
VERY_ADVANCED_ACHIEVEMENTS = frozenset({
    Achievement.ENTER_FIRE_REALM, Achievement.ENTER_ICE_REALM, Achievement.ENTER_GRAVEYARD,
    Achievement.DEFEAT_PIGMAN, Achievement.DEFEAT_FIRE_ELEMENTAL, Achievement.DEFEAT_FROST_TROLL,
    Achievement.DEFEAT_ICE_ELEMENTAL, Achievement.DAMAGE_NECROMANCER,
    Achievement.DEFEAT_NECROMANCER,
})
BASIC_WEIGHT, INTERMEDIATE_WEIGHT, ADVANCED_WEIGHT, VERY_ADVANCED_WEIGHT = 1, 3, 5, 8


def achievement_weight(achievement: int) -> int:
    """Upstream's reward for unlocking ``achievement``: the 25 Crafter-style ones (values <= 24)
    are basic, then intermediate, very advanced, and everything else advanced."""
    if achievement <= 24:
        return BASIC_WEIGHT
    if achievement in INTERMEDIATE_ACHIEVEMENTS:
        return INTERMEDIATE_WEIGHT
    if achievement in VERY_ADVANCED_ACHIEVEMENTS:
        return VERY_ADVANCED_WEIGHT
    return ADVANCED_WEIGHT


ACHIEVEMENT_REWARD = tuple(achievement_weight(a) for a in range(NUM_ACHIEVEMENTS))

# ---- levels
NUM_LEVELS = 9
LEVEL_NAMES = ("Overworld", "Dungeon", "Gnomish Mines", "Sewers", "Vaults", "Troll Mines",
               "Fire Realm", "Ice Realm", "Graveyard")
# First entry into a level (never the overworld) unlocks its achievement and gives 1 XP.
LEVEL_ACHIEVEMENT = (None, Achievement.ENTER_DUNGEON, Achievement.ENTER_GNOMISH_MINES,
                     Achievement.ENTER_SEWERS, Achievement.ENTER_VAULT,
                     Achievement.ENTER_TROLL_MINES, Achievement.ENTER_FIRE_REALM,
                     Achievement.ENTER_ICE_REALM, Achievement.ENTER_GRAVEYARD)
# Ambient light of each level's light map (world_gen_configs ``default_light``; the dungeon
# levels 1, 3, 4 are fully lit): levels at 0 are dark, seen only by torches, lava and ladders.
LEVEL_DEFAULT_LIGHT = (1.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0, 0.0, 0.0)
DARK_LEVELS = frozenset(i for i, light in enumerate(LEVEL_DEFAULT_LIGHT) if light == 0.0)
BOSS_LEVEL = NUM_LEVELS - 1          # the graveyard: the necromancer fight
MONSTERS_KILLED_TO_CLEAR_LEVEL = 8   # kills on a level before its down ladder opens
BOSS_FIGHT_EXTRA_DAMAGE = 0.5        # damage to the player x1.5 on the boss level
BOSS_FIGHT_SPAWN_TURNS = 7           # turns of a spawn wave after each necromancer hit
LIGHT_VISIBLE = 0.05                 # a cell is seen when its light exceeds this (renderer)

# ---- light
TORCH_LIGHT_RADIUS = 5.0             # torch light = clip(1 - distance / radius, 0, 1)
TORCH_LIGHT_HALF = 4                 # it is added over the 9x9 square around the torch


def _torch_light_map():
    import numpy as np
    r = np.arange(-TORCH_LIGHT_HALF, TORCH_LIGHT_HALF + 1, dtype=np.float32)
    distance = np.sqrt(r[:, None] ** 2 + r[None, :] ** 2)
    # (x 1/radius, not / radius: what the package's jitted ``/ 5.0`` computes, to the bit)
    light = 1.0 - distance * np.float32(1 / TORCH_LIGHT_RADIUS)
    return np.clip(light, 0.0, 1.0).astype(np.float32)


TORCH_LIGHT_MAP = _torch_light_map()


NIGHT_LIGHT = 0.5   # the surface is in night below this light level (the HUD's Day/Night)


def light_level(timestep: int, day_length: int) -> float:
    """The daylight at ``timestep`` (upstream calculate_light_level): 1 at noon, 0 at night."""
    progress = (timestep / day_length) % 1 + 0.3
    return 1.0 - abs(math.cos(math.pi * progress)) ** 3


# ---- crafting: action -> recipe


class Recipe:
    """``cost`` (inventory field -> amount) buys ``result``: a tool tier (``pickaxe``/``sword``
    set to ``tier``, allowed while below it), an armour piece (the first slot below ``tier``), or
    ``amount`` more ``arrows``/``torches`` (allowed while below ``STACK_LIMIT``). A crafting
    table must be among the eight cells around the player, and a furnace too if ``furnace``."""

    __slots__ = ("cost", "furnace", "result", "tier", "amount", "achievement")

    def __init__(self, cost, result, tier=0, amount=0, furnace=False, achievement=None):
        self.cost, self.result, self.tier, self.amount = dict(cost), result, tier, amount
        self.furnace, self.achievement = furnace, achievement

    def __repr__(self) -> str:
        return (f"Recipe({self.cost}, {self.result!r}, tier={self.tier}, amount={self.amount}, "
                f"furnace={self.furnace})")


STACK_LIMIT = 99    # arrows/torches are crafted only below it; every count is clipped to it
RECIPES = {
    Action.MAKE_WOOD_PICKAXE: Recipe({"wood": 1}, "pickaxe", tier=1),
    Action.MAKE_STONE_PICKAXE: Recipe({"wood": 1, "stone": 1}, "pickaxe", tier=2),
    Action.MAKE_IRON_PICKAXE: Recipe({"wood": 1, "stone": 1, "iron": 1, "coal": 1}, "pickaxe",
                                     tier=3, furnace=True),
    Action.MAKE_DIAMOND_PICKAXE: Recipe({"wood": 1, "diamond": 3}, "pickaxe", tier=4),
    Action.MAKE_WOOD_SWORD: Recipe({"wood": 1}, "sword", tier=1),
    Action.MAKE_STONE_SWORD: Recipe({"wood": 1, "stone": 1}, "sword", tier=2),
    Action.MAKE_IRON_SWORD: Recipe({"wood": 1, "stone": 1, "iron": 1, "coal": 1}, "sword",
                                   tier=3, furnace=True),
    Action.MAKE_DIAMOND_SWORD: Recipe({"wood": 1, "diamond": 2}, "sword", tier=4),
    Action.MAKE_IRON_ARMOUR: Recipe({"iron": 3, "coal": 3}, "armour", tier=1, furnace=True,
                                    achievement=Achievement.MAKE_IRON_ARMOUR),
    Action.MAKE_DIAMOND_ARMOUR: Recipe({"diamond": 3}, "armour", tier=2,
                                       achievement=Achievement.MAKE_DIAMOND_ARMOUR),
    Action.MAKE_ARROW: Recipe({"wood": 1, "stone": 1}, "arrows", amount=2),
    Action.MAKE_TORCH: Recipe({"wood": 1, "coal": 1}, "torches", amount=4),
}
RECIPE_BY_ACTION = {int(a): r for a, r in RECIPES.items()}

# ---- placing: action -> (inventory field, cost, block placed, achievement)
PLACING = {
    Action.PLACE_TABLE: ("wood", 2, BlockType.CRAFTING_TABLE, Achievement.PLACE_TABLE),
    Action.PLACE_FURNACE: ("stone", 1, BlockType.FURNACE, Achievement.PLACE_FURNACE),
    Action.PLACE_STONE: ("stone", 1, BlockType.STONE, Achievement.PLACE_STONE),
    Action.PLACE_PLANT: ("sapling", 1, BlockType.PLANT, Achievement.PLACE_PLANT),
    Action.PLACE_TORCH: ("torches", 1, None, Achievement.PLACE_TORCH),
}

# ---- mining (DO on a block): block -> (pickaxe tier needed, inventory field or None, the
# block left behind). Trees need no tool. Collecting is credited by INVENTORY_ACHIEVEMENTS.
MINING = {
    BlockType.TREE: (0, "wood", BlockType.GRASS),
    BlockType.FIRE_TREE: (0, "wood", BlockType.FIRE_GRASS),
    BlockType.ICE_SHRUB: (0, "wood", BlockType.ICE_GRASS),
    BlockType.STONE: (1, "stone", BlockType.PATH),
    BlockType.COAL: (1, "coal", BlockType.PATH),
    BlockType.IRON: (2, "iron", BlockType.PATH),
    BlockType.DIAMOND: (3, "diamond", BlockType.PATH),
    BlockType.SAPPHIRE: (4, "sapphire", BlockType.PATH),
    BlockType.RUBY: (4, "ruby", BlockType.PATH),
    BlockType.STALAGMITE: (1, "stone", BlockType.PATH),
    BlockType.FURNACE: (0, None, BlockType.PATH),
    BlockType.CRAFTING_TABLE: (0, None, BlockType.PATH),
}
MINING_BY_BLOCK = {int(b): (tier, item, int(left)) for b, (tier, item, left) in MINING.items()}
SAPLING_CHANCE = 0.1        # DO on grass finds a sapling
DRINK_BLOCKS = frozenset({BlockType.WATER, BlockType.FOUNTAIN})   # DO: drink +1, thirst 0
RIPE_PLANT_FOOD = 4         # DO on a ripe plant: food +4, hunger 0, the plant regrows
COW_FOOD = 6                # killing a passive mob in melee: food +6, hunger 0
PLANT_RIPE_AGE = 600        # a planted sapling ripens after this many steps (level 0 only)

# Achievements read off the inventory at the end of every step: (field, at least, achievement).
INVENTORY_ACHIEVEMENTS = (
    ("wood", 1, Achievement.COLLECT_WOOD), ("stone", 1, Achievement.COLLECT_STONE),
    ("coal", 1, Achievement.COLLECT_COAL), ("iron", 1, Achievement.COLLECT_IRON),
    ("diamond", 1, Achievement.COLLECT_DIAMOND), ("ruby", 1, Achievement.COLLECT_RUBY),
    ("sapphire", 1, Achievement.COLLECT_SAPPHIRE), ("sapling", 1, Achievement.COLLECT_SAPLING),
    ("bow", 1, Achievement.FIND_BOW), ("arrows", 1, Achievement.MAKE_ARROW),
    ("torches", 1, Achievement.MAKE_TORCH),
    ("pickaxe", 1, Achievement.MAKE_WOOD_PICKAXE), ("pickaxe", 2, Achievement.MAKE_STONE_PICKAXE),
    ("pickaxe", 3, Achievement.MAKE_IRON_PICKAXE),
    ("pickaxe", 4, Achievement.MAKE_DIAMOND_PICKAXE),
    ("sword", 1, Achievement.MAKE_WOOD_SWORD), ("sword", 2, Achievement.MAKE_STONE_SWORD),
    ("sword", 3, Achievement.MAKE_IRON_SWORD), ("sword", 4, Achievement.MAKE_DIAMOND_SWORD),
)

# ---- combat (the player's side)
SWORD_DAMAGE = (1, 2, 3, 5, 8)          # physical damage by sword tier (0 = bare hands)
STRENGTH_DAMAGE_BONUS = 0.25            # physical x (1 + 0.25 (strength - 1))
ENCHANT_DAMAGE_FRACTION = 0.5           # an enchanted sword adds half its base as fire/ice
INTELLIGENCE_ENCHANT_BONUS = 0.05       # ... x (1 + 0.05 (intelligence - 1))
ARMOUR_DEFENCE_PER_TIER = 0.1           # physical defence per armour tier per piece
ENCHANTED_ARMOUR_DEFENCE = 0.2          # fire (ice) defence per fire (ice) enchanted piece
SLEEPING_MELEE_FACTOR = 3.5             # melee damage x (1 + 2.5) on a sleeping player

# ---- intrinsics (upstream update_player_intrinsics)
HUNGER_LIMIT = 25        # hunger above it: food -1
THIRST_LIMIT = 20        # thirst above it: drink -1
FATIGUE_LIMIT = 30       # fatigue above it: energy -1
FATIGUE_RESTED = -10     # fatigue below it (while asleep): energy +1
RECOVER_LIMIT = 25       # recover above it: health +1
DERECOVER_LIMIT = -15    # recover below it: health -1
MANA_LIMIT = 30          # mana recovery above it: mana +1
SLEEP_INTRINSIC_RATE = 0.5       # hunger/thirst grow at half speed while asleep
DEXTERITY_DECAY = 0.125          # hunger/thirst/fatigue rate x (1 - 0.125 (dexterity - 1))
RECOVER_RATE = (1.0, 2.0)        # (awake, asleep) with every need met
DERECOVER_RATE = (-1.0, -0.5)    # (awake, asleep) with a need unmet (not in the boss fight)
MANA_RATE = (1, 2)               # (awake, asleep), x (1 + 0.25 (intelligence - 1))
INTELLIGENCE_MANA_BONUS = 0.25


def max_health(strength: int) -> int:
    return 8 + strength


def max_food(dexterity: int) -> int:
    return 7 + 2 * dexterity


max_drink = max_energy = max_food


def max_mana(intelligence: int) -> int:
    return 6 + 3 * intelligence


GOD_MODE_MIN_HEALTH = 9

# ---- chests (upstream add_items_from_chest): each line is an independent chance
CHEST_TORCH = (0.6, 4, 7)           # (chance, min, max) torches
CHEST_ORE_CHANCE = 0.6
CHEST_ORES = (("coal", 0.3, 1, 3), ("iron", 0.3, 1, 2), ("diamond", 0.15, 1, 1),
              ("sapphire", 0.125, 1, 1), ("ruby", 0.125, 1, 1))   # (field, weight, min, max)
CHEST_POTION = (0.5, 1, 2)          # a random colour, (chance, min, max)
CHEST_ARROWS = (0.25, 1, 4)
CHEST_TOOL_CHANCE = 0.2             # then pickaxe or sword (even), of tier 1-4 with:
CHEST_TOOL_TIER_WEIGHTS = (0.4, 0.3, 0.2, 0.1)   # (a tool never downgrades)
BOW_CHEST_LEVEL = 1                 # the first chest opened on the dungeon holds the bow
BOOK_CHEST_LEVELS = frozenset({3, 4})   # the first chest on the sewers / vaults holds a book

# ---- potions: six colours, an episode's potion_mapping sends colour -> effect index
POTION_ACTIONS = (Action.DRINK_POTION_RED, Action.DRINK_POTION_GREEN, Action.DRINK_POTION_BLUE,
                  Action.DRINK_POTION_PINK, Action.DRINK_POTION_CYAN, Action.DRINK_POTION_YELLOW)
POTION_COLOURS = ("red", "green", "blue", "pink", "cyan", "yellow")
# effect index -> (vital, change)
POTION_EFFECTS = (("health", 8), ("health", -3), ("mana", 8), ("mana", -3), ("energy", 8),
                  ("energy", -3))

# ---- spells and enchanting
SPELL_MANA_COST = 2
SPELLS = {Action.CAST_FIREBALL: (0, ProjectileType.FIREBALL, Achievement.CAST_FIREBALL),
          Action.CAST_ICEBALL: (1, ProjectileType.ICEBALL, Achievement.CAST_ICEBALL)}
LEARN_SPELL_ACHIEVEMENT = (Achievement.LEARN_FIREBALL, Achievement.LEARN_ICEBALL)
PLAYER_ARROW = ProjectileType.ARROW2     # what SHOOT_ARROW fires
ENCHANT_MANA_COST = 9
# enchantment table -> (element: 1 fire / 2 ice, the gem it costs)
ENCHANT_TABLES = {BlockType.ENCHANTMENT_TABLE_FIRE: (1, "ruby"),
                  BlockType.ENCHANTMENT_TABLE_ICE: (2, "sapphire")}
XP_PER_NEW_LEVEL = 1
