"""Craftax's mobs as data: upstream ``craftax`` 1.6.1's mob and projectile tables
(``craftax/craftax/constants.py``) as plain Python tuples, which the step reads with ints.

Mob classes are ``MobType`` (passive 0, melee 1, ranged 2, projectile 3). A mob's kind within its
class is its ``type_id``; upstream's per-type tables lead with the type id (upstream's comments
call that axis "floor", since floor ``f`` spawns mostly type ``f``; the lookups index it with the
type id, and so do we). ``tests/games/craftax/test_craftax_bestiary.py`` checks every table here
against the package.
"""

from __future__ import annotations

from .state import MAX_MELEE, MAX_MOB_PROJECTILES, MAX_PASSIVE, MAX_PLAYER_PROJECTILES, MAX_RANGED
from .tables import Achievement as A
from .tables import IS_SOLID, BlockType, MobType, ProjectileType

# The type id spawned on each level, per class: (passive, melee, ranged). On the boss level
# (8) the waves use the row of the boss's progress instead.
FLOOR_MOB_MAPPING = (
    (0, 0, 0),  # 0 overworld: cow, zombie, skeleton
    (2, 2, 2),  # 1 dungeon: snail, orc soldier, orc mage
    (1, 1, 1),  # 2 gnomish mines: bat, gnome warrior, gnome archer
    (2, 3, 3),  # 3 sewers: snail, lizard, kobold
    (2, 4, 4),  # 4 vaults: snail, knight, archer
    (1, 5, 5),  # 5 troll mines: bat, troll, deep thing
    (1, 6, 6),  # 6 fire realm: bat, pigman, fire elemental
    (1, 7, 7),  # 7 ice realm: bat, frost troll, ice elemental
    (0, 0, 0),  # 8 graveyard (boss)
)

# Per level: (passive, melee, ranged, extra melee at night); the night term is scaled by
# (1 - light level)^2.
FLOOR_MOB_SPAWN_CHANCE = (
    (0.1, 0.02, 0.05, 0.1),
    (0.1, 0.06, 0.05, 0.0),
    (0.1, 0.06, 0.05, 0.0),
    (0.1, 0.06, 0.05, 0.0),
    (0.1, 0.06, 0.05, 0.0),
    (0.1, 0.06, 0.05, 0.0),
    (0.1, 0.06, 0.05, 0.0),
    (0.0, 0.06, 0.05, 0.0),
    (0.1, 0.06, 0.05, 0.0),
)

# What a mob may not enter besides solid blocks and other mobs: (ground, water, lava).
# "Ground" is any block that is neither solid, water nor lava.
COLLISION_LAND_CREATURE = (False, True, True)
COLLISION_FLYING = (False, False, False)
COLLISION_AQUATIC = (True, False, True)
COLLISION_AMPHIBIAN = (False, False, True)

_L, _F, _Q, _M = COLLISION_LAND_CREATURE, COLLISION_FLYING, COLLISION_AQUATIC, COLLISION_AMPHIBIAN
# [type_id][class] -> collision triple (class: passive, melee, ranged, projectile)
MOB_TYPE_COLLISION_MAPPING = (
    (_L, _L, _L, _F),  # cow, zombie, skeleton
    (_F, _L, _L, _F),  # bat (flies), gnome warrior, gnome archer
    (_L, _L, _L, _F),  # snail, orc soldier, orc mage
    (_L, _M, _L, _F),  # -, lizard (swims), kobold
    (_L, _L, _L, _F),  # -, knight, archer
    (_L, _L, _Q, _F),  # -, troll, deep thing (water only)
    (_L, _L, _F, _F),  # -, pigman, fire elemental (flies)
    (_L, _L, _F, _F),  # -, frost troll, ice elemental (flies)
    (_L, _L, _L, _F),
)


def _enterable(collision: tuple) -> tuple:
    """For each block: a mob whose collision triple is ``collision`` may step onto it (it is
    not solid, and the triple lets the mob onto its kind of ground)."""
    water, lava = BlockType.WATER, BlockType.LAVA
    return tuple(not IS_SOLID[block]
                 and not collision[1 if block == water else 2 if block == lava else 0]
                 for block in range(len(BlockType)))


# [type_id][class] -> [block] -> the mob may enter it (free of mobs and the player): the
# collision triples applied to every block once, for the movers' one look-up a step
MOB_TYPE_ENTERABLE = tuple(tuple(_enterable(collision) for collision in row)
                           for row in MOB_TYPE_COLLISION_MAPPING)

# Damage vectors are (physical, fire, ice).
NO_DAMAGE = (0.0, 0.0, 0.0)
# [type_id][class] -> damage; only melee (class 1) and projectile (class 3) columns are non-zero.
# The projectile column is indexed by ProjectileType.
MOB_TYPE_DAMAGE_MAPPING = (
    (NO_DAMAGE, (2.0, 0.0, 0.0), NO_DAMAGE, (2.0, 0.0, 0.0)),  # zombie; arrow
    (NO_DAMAGE, (4.0, 0.0, 0.0), NO_DAMAGE, (4.0, 0.0, 0.0)),  # gnome warrior; dagger
    (NO_DAMAGE, (3.0, 0.0, 0.0), NO_DAMAGE, (0.0, 3.0, 0.0)),  # orc soldier; fireball
    (NO_DAMAGE, (5.0, 0.0, 0.0), NO_DAMAGE, (0.0, 0.0, 3.0)),  # lizard; iceball
    (NO_DAMAGE, (6.0, 0.0, 0.0), NO_DAMAGE, (5.0, 0.0, 0.0)),  # knight; arrow2
    (NO_DAMAGE, (6.0, 1.0, 1.0), NO_DAMAGE, (4.0, 3.0, 3.0)),  # troll; slimeball
    (NO_DAMAGE, (3.0, 5.0, 0.0), NO_DAMAGE, (3.0, 5.0, 0.0)),  # pigman; fireball2
    (NO_DAMAGE, (4.0, 0.0, 5.0), NO_DAMAGE, (4.0, 0.0, 5.0)),  # frost troll; iceball2
)

# [type_id][class] -> starting health (class: passive, melee, ranged, -)
MOB_TYPE_HEALTH_MAPPING = (
    (3.0, 5.0, 3.0, 0.0),
    (4.0, 7.0, 5.0, 0.0),
    (6.0, 9.0, 6.0, 0.0),
    (8.0, 11.0, 8.0, 0.0),
    (0.0, 12.0, 12.0, 0.0),
    (0.0, 20.0, 4.0, 0.0),
    (0.0, 20.0, 14.0, 0.0),
    (0.0, 24.0, 16.0, 0.0),
    (0.0, 0.0, 0.0, 0.0),
)

NO_DEFENCE = (0.0, 0.0, 0.0)
# [type_id][class] -> defence vector (physical, fire, ice): the fraction of each damage blocked.
MOB_TYPE_DEFENCE_MAPPING = (
    (NO_DEFENCE,) * 4,
    (NO_DEFENCE,) * 4,
    (NO_DEFENCE,) * 4,
    (NO_DEFENCE,) * 4,
    (NO_DEFENCE, (0.5, 0.0, 0.0), (0.5, 0.0, 0.0), NO_DEFENCE),   # knight, archer
    (NO_DEFENCE, (0.2, 0.0, 0.0), (0.0, 0.0, 0.0), NO_DEFENCE),   # troll
    (NO_DEFENCE, (0.9, 1.0, 0.0), (0.9, 1.0, 0.0), NO_DEFENCE),   # pigman, fire elemental
    (NO_DEFENCE, (0.9, 0.0, 1.0), (0.9, 0.0, 1.0), NO_DEFENCE),   # frost troll, ice elemental
    (NO_DEFENCE,) * 4,
)

# Ranged type_id -> the ProjectileType it shoots.
RANGED_MOB_TYPE_TO_PROJECTILE_TYPE_MAPPING = (
    ProjectileType.ARROW,      # skeleton
    ProjectileType.ARROW,      # gnome archer
    ProjectileType.FIREBALL,   # orc mage
    ProjectileType.DAGGER,     # kobold
    ProjectileType.ARROW2,     # archer
    ProjectileType.SLIMEBALL,  # deep thing
    ProjectileType.FIREBALL2,  # fire elemental
    ProjectileType.ICEBALL2,   # ice elemental
)

# ProjectileType -> damage vector (the projectile column of MOB_TYPE_DAMAGE_MAPPING).
PROJECTILE_DAMAGE = tuple(row[MobType.PROJECTILE] for row in MOB_TYPE_DAMAGE_MAPPING)

# [class][type_id] -> the Achievement for killing it (passive: for eating it); 0 where none.
MOB_ACHIEVEMENT_MAP = (
    (A.EAT_COW, A.EAT_BAT, A.EAT_SNAIL, 0, 0, 0, 0, 0),
    (A.DEFEAT_ZOMBIE, A.DEFEAT_GNOME_WARRIOR, A.DEFEAT_ORC_SOLIDER, A.DEFEAT_LIZARD,
     A.DEFEAT_KNIGHT, A.DEFEAT_TROLL, A.DEFEAT_PIGMAN, A.DEFEAT_FROST_TROLL),
    (A.DEFEAT_SKELETON, A.DEFEAT_GNOME_ARCHER, A.DEFEAT_ORC_MAGE, A.DEFEAT_KOBOLD,
     A.DEFEAT_ARCHER, A.DEFEAT_DEEP_THING, A.DEFEAT_FIRE_ELEMENTAL, A.DEFEAT_ICE_ELEMENTAL),
)
MOB_ACHIEVEMENT_MAP = tuple(tuple(int(a) for a in row) for row in MOB_ACHIEVEMENT_MAP)

# Game mechanics of mobs. (The level constants the mobs read, BOSS_LEVEL,
# MONSTERS_KILLED_TO_CLEAR_LEVEL and the boss fight's, and the player's side of combat, the
# sleeping factor, armour defence and the food of an eaten mob, are in ``tables``; the despawn
# distance is ``Settings.mob_despawn_distance``.)
MELEE_ATTACK_COOLDOWN = 5            # turns a melee mob waits after an attack
RANGED_ATTACK_COOLDOWN = 4           # turns a ranged mob waits after a shot

# Slots per level (upstream StaticEnvParams).
MAX_MOBS = {MobType.PASSIVE: MAX_PASSIVE, MobType.MELEE: MAX_MELEE, MobType.RANGED: MAX_RANGED}
MAX_MOB_PROJECTILE_SLOTS = MAX_MOB_PROJECTILES
MAX_PLAYER_PROJECTILE_SLOTS = MAX_PLAYER_PROJECTILES

# Names for the HUD and messages, [class][type_id].
MOB_NAMES = (
    ("cow", "bat", "snail"),
    ("zombie", "gnome warrior", "orc soldier", "lizard", "knight", "troll", "pigman",
     "frost troll"),
    ("skeleton", "gnome archer", "orc mage", "kobold", "archer", "deep thing",
     "fire elemental", "ice elemental"),
)
PROJECTILE_NAMES = ("arrow", "dagger", "fireball", "iceball", "arrow", "slimeball", "fireball",
                    "iceball")


def mob_name(kind: int, level: int, type_id: int) -> str:
    """The name of a mob of class ``kind`` (a MobType; PROJECTILE names projectiles) and kind
    ``type_id``. Names depend on the type only (upstream's textures do too); ``level`` is taken
    so a caller can pass what it has, and names an unknown type by its level's usual mob."""
    if kind == MobType.PROJECTILE:
        return PROJECTILE_NAMES[type_id]
    names = MOB_NAMES[kind]
    if 0 <= type_id < len(names):
        return names[type_id]
    return names[FLOOR_MOB_MAPPING[level][kind] % len(names)]
