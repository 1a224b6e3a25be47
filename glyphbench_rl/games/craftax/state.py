"""The Craftax game state: upstream Craftax 1.6.1's ``EnvState``, field for field, in numpy.

Every field keeps upstream's name, shape and meaning (``craftax/craftax/craftax_state.py``), so a
state converts either way without a table of renames (``State.from_upstream`` reads any object
with upstream's attribute names: the package's own state in the fidelity tests). Arrays are
numpy; scalar fields are plain Python numbers (the rules read and write them often, and a
Python ``int`` is several times faster than a numpy scalar), and so are the mob slots
(``Mobs``: lists per level, for the same reason). Per-level arrays lead with the level
axis, as upstream: ``map[level, row, col]``; positions are ``(row, col)``.

Two upstream fields are not kept: ``state_rng`` (our randomness is explicit numpy streams, see
``rules``) and ``fractal_noise_angles`` (world generation parameters, not state).
"""

from __future__ import annotations

import copy
from dataclasses import dataclass, field, fields

import numpy as np

NUM_LEVELS = 9
MAP_SIZE = (48, 48)
OBS_DIM = (9, 11)      # upstream's OBS_DIM: the rows and columns of the player's view
MAX_MELEE, MAX_PASSIVE, MAX_RANGED = 3, 3, 2
MAX_MOB_PROJECTILES, MAX_PLAYER_PROJECTILES, MAX_GROWING_PLANTS = 3, 3, 10
# the State fields of the three mob classes, in upstream's class order (MobType 0, 1, 2)
MOB_GROUPS = ("passive_mobs", "melee_mobs", "ranged_mobs")


@dataclass
class Inventory:
    wood: int = 0
    stone: int = 0
    coal: int = 0
    iron: int = 0
    diamond: int = 0
    sapling: int = 0
    pickaxe: int = 0
    sword: int = 0
    bow: int = 0
    arrows: int = 0
    armour: np.ndarray = field(default_factory=lambda: np.zeros(4, np.int32))
    torches: int = 0
    ruby: int = 0
    sapphire: int = 0
    potions: np.ndarray = field(default_factory=lambda: np.zeros(6, np.int32))
    books: int = 0


@dataclass
class Mobs:
    """One kind of mob (or projectile) on every level, as Python lists indexed ``[level][slot]``:
    slot ``i`` of level ``l`` is live when ``mask[l][i]``; its cell is ``position[l][i]``, a
    ``(row, col)`` tuple. Upstream keeps jax arrays; the rules read and write a few slots a
    turn, and a list item costs a fraction of a numpy scalar read or write. ``from_arrays`` and
    ``arrays`` convert from and to upstream's arrays (shapes and dtypes), for the conversion
    from upstream's state and for comparisons. Health is float32 upstream: every value kept
    here is one a float32 holds (``float32`` rounds a new one), so the lists hold exactly what
    upstream's arrays would."""
    position: list        # [level][slot] -> (row, col)
    health: list          # [level][slot] -> float (a float32 value)
    mask: list            # [level][slot] -> bool
    attack_cooldown: list  # [level][slot] -> int
    type_id: list         # [level][slot] -> int

    @classmethod
    def empty(cls, slots: int, levels: int = NUM_LEVELS) -> "Mobs":
        return cls([[(0, 0)] * slots for _ in range(levels)],
                   [[1.0] * slots for _ in range(levels)],
                   [[False] * slots for _ in range(levels)],
                   [[0] * slots for _ in range(levels)],
                   [[0] * slots for _ in range(levels)])

    @classmethod
    def from_arrays(cls, position, health, mask, attack_cooldown, type_id) -> "Mobs":
        """From upstream's arrays (anything numpy reads): position (levels, slots, 2), health,
        mask, attack_cooldown and type_id (levels, slots)."""
        return cls([[(int(r), int(c)) for r, c in level] for level in np.asarray(position).tolist()],
                   np.asarray(health, np.float32).tolist(), np.asarray(mask, bool).tolist(),
                   np.asarray(attack_cooldown, np.int32).tolist(),
                   np.asarray(type_id, np.int32).tolist())

    def arrays(self) -> dict[str, np.ndarray]:
        """Upstream's arrays of this kind, by field name (new arrays: editing them changes
        nothing here)."""
        return {"position": np.array(self.position, np.int32).reshape(len(self.mask), -1, 2),
                "health": np.array(self.health, np.float32),
                "mask": np.array(self.mask, bool),
                "attack_cooldown": np.array(self.attack_cooldown, np.int32),
                "type_id": np.array(self.type_id, np.int32)}

    def __deepcopy__(self, memo) -> "Mobs":
        # (the items are immutable: copying the per-level lists is a deep copy, and much
        # quicker than deepcopy's walk over every item)
        copied = memo[id(self)] = Mobs(*([list(level) for level in getattr(self, f.name)]
                                         for f in fields(Mobs)))
        return copied


def float32(value: float) -> float:
    """``value`` rounded to the nearest float32, as a Python float: what storing it in
    upstream's float32 health array keeps."""
    return np.float32(value).item()


@dataclass
class State:
    map: np.ndarray               # (levels, rows, cols) int32: BlockType values
    item_map: np.ndarray          # (levels, rows, cols) int32: ItemType values (torches, ladders)
    mob_map: np.ndarray           # (levels, rows, cols) bool: a mob stands there
    light_map: np.ndarray         # (levels, rows, cols) float32
    down_ladders: np.ndarray      # (levels, 2) int32
    up_ladders: np.ndarray        # (levels, 2) int32
    chests_opened: np.ndarray     # (levels,) bool: the level's first chest was opened
    monsters_killed: np.ndarray   # (levels,) int32

    player_position: np.ndarray   # (2,) int32: row, col
    player_level: int
    player_direction: int         # an Action value: LEFT 1, RIGHT 2, UP 3, DOWN 4

    player_health: float
    player_food: int
    player_drink: int
    player_energy: int
    player_mana: int
    is_sleeping: bool
    is_resting: bool

    player_recover: float
    player_hunger: float
    player_thirst: float
    player_fatigue: float
    player_recover_mana: float

    player_xp: int
    player_dexterity: int
    player_strength: int
    player_intelligence: int

    inventory: Inventory

    melee_mobs: Mobs
    passive_mobs: Mobs
    ranged_mobs: Mobs

    mob_projectiles: Mobs
    mob_projectile_directions: np.ndarray      # (levels, slots, 2) int32
    player_projectiles: Mobs
    player_projectile_directions: np.ndarray   # (levels, slots, 2) int32

    growing_plants_positions: np.ndarray  # (plants, 2) int32 (level 0 only, as upstream)
    growing_plants_age: np.ndarray        # (plants,) int32
    growing_plants_mask: np.ndarray       # (plants,) bool

    potion_mapping: np.ndarray    # (6,) int32: colour index -> effect index
    learned_spells: np.ndarray    # (2,) bool: fireball, iceball

    sword_enchantment: int        # 0 none, 1 fire, 2 ice
    bow_enchantment: int
    armour_enchantments: np.ndarray  # (4,) int32

    boss_progress: int
    boss_timesteps_to_spawn_this_round: int

    light_level: float
    achievements: np.ndarray      # (67,) bool, indexed by Achievement value
    timestep: int

    def copy(self) -> "State":
        return copy.deepcopy(self)

    @classmethod
    def from_upstream(cls, other) -> "State":
        """Our state from any object with upstream ``EnvState``'s attribute names (the
        ``craftax`` package's own state, whose jax arrays numpy reads as arrays)."""
        return cls(**{f.name: _convert(getattr(other, f.name), f.name) for f in fields(cls)})


_SCALAR_FLOATS = {"player_health", "player_recover", "player_hunger", "player_thirst",
                  "player_fatigue", "player_recover_mana", "light_level"}
_SCALAR_BOOLS = {"is_sleeping", "is_resting"}


def _convert(value, name: str):
    if hasattr(value, "mask") and hasattr(value, "type_id"):
        return Mobs.from_arrays(*(np.array(getattr(value, f.name)) for f in fields(Mobs)))
    if hasattr(value, "wood") and hasattr(value, "potions"):
        return Inventory(**{f.name: (np.array(getattr(value, f.name)) if f.name in ("armour", "potions")
                                     else int(getattr(value, f.name))) for f in fields(Inventory)})
    array = np.array(value)
    if array.ndim:
        return array
    if name in _SCALAR_FLOATS:
        return float(array)
    if name in _SCALAR_BOOLS:
        return bool(array)
    return int(array)


@dataclass(frozen=True)
class Settings:
    """Upstream's ``EnvParams`` (the values are upstream's defaults), plus switches a scenario
    may turn off; upstream always has them on. A switch never changes a rule, it leaves a
    sub-rule out of the step."""
    day_length: int = 300
    mob_despawn_distance: int = 14
    max_attribute: int = 5
    god_mode: bool = False
    intrinsics: bool = True    # hunger, thirst, fatigue and their effects on the vitals
    daylight: bool = True      # the day-night cycle (off: the light level stays at full day)
    spawning: bool = True      # mobs spawn and despawn
