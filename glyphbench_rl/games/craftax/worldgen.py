"""World generation: the nine levels of upstream Craftax 1.6.1 (``world_gen/world_gen.py`` and
``world_gen_configs.py``) in numpy.

Two generators make every level, each driven by a per-level configuration (upstream's facts):

* ``cave_level`` (upstream ``generate_smoothworld``): Perlin-noise terrain. A "water" noise
  makes seas and coasts, a "mountain" noise raises rock away from the centre (both pushed up with
  the distance from the centre), a stretched noise cuts tunnels through the rock, inner caves open
  where both noises are high, a fourth noise and a uniform draw scatter trees, then ores replace
  rock at fixed rates and lava fills the deepest rock. Levels 0 (overworld), 2 (gnomish mines),
  5 (troll mines), 6 (fire realm), 7 (ice realm) and 8 (graveyard: the necromancer stands at the
  centre, graves are its "trees").
* ``dungeon_level`` (upstream ``generate_dungeon``): eight rooms in a 3x3 grid of 16-cell chunks,
  each with torches in its corners, a chest and, half the time, a fountain; L-shaped corridors
  join every room to one joined before it; walls away from the floor turn to darkness. Levels 1
  (dungeon), 3 (sewers: water for fountains, a tenth of the floor flooded, the ice enchantment
  table) and 4 (vaults: the fire enchantment table).

One deliberate difference: upstream places ladders on any floor cell, so a ladder can sit in a
cave sealed by rock, across water, or (in the sewers) behind flooded corridor cells, reachable
only with a pickaxe or placed stone. Here every world is walkable: after a level is made,
``ensure_reachable`` carves the cheapest path (fewest blocking cells) from the level's arrival
point to its down ladder (and, on level 8, to the necromancer's side), turning the blocking cells
on that path into the level's floor. Chests, fountains, enchantment tables and the necromancer
are never carved. This changes a few cells per level (``tests/games/craftax`` measures it).
"""

from __future__ import annotations

from dataclasses import dataclass, fields
from functools import lru_cache

import numpy as np

from ...core.seeding import int_sampler
from .noise import fractal
from .state import (MAP_SIZE, MAX_MELEE, MAX_MOB_PROJECTILES, MAX_PASSIVE, MAX_PLAYER_PROJECTILES,
                    MAX_RANGED, MAX_GROWING_PLANTS, NUM_LEVELS, Inventory, Mobs, Settings, State)
from .tables import (BOSS_FIGHT_SPAWN_TURNS, SOLID_BLOCKS, TORCH_LIGHT_MAP, Achievement, Action,
                     BlockType as B, ItemType, light_level)

ROWS, COLS = MAP_SIZE
CENTRE = (ROWS // 2, COLS // 2)
# Never carved away to make a level walkable: the structures a level is made for.
PROTECTED = frozenset({B.CHEST, B.FOUNTAIN, B.ENCHANTMENT_TABLE_FIRE, B.ENCHANTMENT_TABLE_ICE,
                       B.NECROMANCER})

_WALKABLE = np.ones(len(B), bool)
# the player cannot walk into solid blocks (tables.SOLID_BLOCKS), water or lava
_WALKABLE[[int(b) for b in SOLID_BLOCKS | {B.WATER, B.LAVA}]] = False
_CARVABLE = np.ones(len(B), bool)
_CARVABLE[[int(b) for b in PROTECTED]] = False
# the blocks and items the generators write, as ints (an enum member is a slow look-up in a loop)
_PATH, _WALL, _WALL_MOSS, _DARKNESS, _CHEST, _STONE, _LAVA = (
    int(b) for b in (B.PATH, B.WALL, B.WALL_MOSS, B.DARKNESS, B.CHEST, B.STONE, B.LAVA))
_NO_ITEM, _TORCH, _LADDER_DOWN, _LADDER_UP = (
    int(i) for i in (ItemType.NONE, ItemType.TORCH, ItemType.LADDER_DOWN, ItemType.LADDER_UP))


# ---------------------------------------------------------------------------------------------
# Level configurations (upstream's SmoothGenConfig / DungeonConfig values)

def _plain_blocks(cfg) -> None:
    """Store a configuration's blocks (its ``int`` fields and ores) as plain ints: numpy takes
    an enum member in a comparison or a write far slower than an int."""
    for f in fields(cfg):
        if f.type in ("int", int):     # (the annotation, as a string under postponed evaluation)
            object.__setattr__(cfg, f.name, int(getattr(cfg, f.name)))
    if hasattr(cfg, "ores"):
        object.__setattr__(cfg, "ores", tuple((int(b), int(ore), p) for b, ore, p in cfg.ores))


@dataclass(frozen=True)
class CaveConfig:
    default: int            # the open ground
    sea: int                # where the water noise is high
    coast: int              # the band just below the sea threshold
    mountain: int           # where the mountain noise is high
    tunnel: int             # the stretched noise's lines through the mountains
    inner: int              # caves where both mountain and water noise are high
    ores: tuple             # (block it replaces, ore, chance per cell), applied in order
    tree_on: int
    tree: int
    lava: int               # fills the deepest rock where the tree noise is high
    spawn: int              # the block put at the centre (the player's cell on level 0)
    floor: int              # ladders stand on this block; carved paths are made of it
    ladder_up: bool
    ladder_down: bool
    water_strength: float   # the centre-distance push on the water noise: clip(d / s, 0, max)
    water_max: float
    mountain_strength: float
    mountain_max: float
    light: float            # the level's light where no torch or lava lights it
    water_threshold: float
    sand_threshold: float
    tree_uniform: float
    tree_perlin: float

    __post_init__ = _plain_blocks


_STONE_ORES = (B.COAL, B.IRON, B.DIAMOND, B.SAPPHIRE, B.RUBY)


def _stone_ores(*chances: float) -> tuple:
    return tuple((B.STONE, ore, p) for ore, p in zip(_STONE_ORES, chances))


OVERWORLD = CaveConfig(
    default=B.GRASS, sea=B.WATER, coast=B.SAND, mountain=B.STONE, tunnel=B.PATH, inner=B.PATH,
    ores=_stone_ores(0.03, 0.02, 0.001), tree_on=B.GRASS, tree=B.TREE, lava=B.LAVA,
    spawn=B.GRASS, floor=B.PATH, ladder_up=False, ladder_down=True,
    water_strength=5, water_max=1, mountain_strength=5, mountain_max=1, light=1.0,
    water_threshold=0.7, sand_threshold=0.6, tree_uniform=0.8, tree_perlin=0.5)
GNOMISH_MINES = CaveConfig(
    default=B.PATH, sea=B.WATER, coast=B.PATH, mountain=B.STONE, tunnel=B.STONE, inner=B.STONE,
    ores=_stone_ores(0.04, 0.02, 0.005, 0.0025, 0.0025), tree_on=B.PATH, tree=B.STALAGMITE,
    lava=B.LAVA, spawn=B.PATH, floor=B.PATH, ladder_up=True, ladder_down=True,
    water_strength=5, water_max=1, mountain_strength=17, mountain_max=1.5, light=0.0,
    water_threshold=0.7, sand_threshold=0.6, tree_uniform=0.8, tree_perlin=0.5)
TROLL_MINES = CaveConfig(
    default=B.PATH, sea=B.WATER, coast=B.PATH, mountain=B.STONE, tunnel=B.STONE, inner=B.STONE,
    ores=_stone_ores(0.04, 0.03, 0.01, 0.01, 0.01), tree_on=B.PATH, tree=B.STALAGMITE,
    lava=B.LAVA, spawn=B.PATH, floor=B.PATH, ladder_up=True, ladder_down=True,
    water_strength=5, water_max=1, mountain_strength=17, mountain_max=1.5, light=0.0,
    water_threshold=0.7, sand_threshold=0.6, tree_uniform=0.8, tree_perlin=0.5)
FIRE_REALM = CaveConfig(
    default=B.FIRE_GRASS, sea=B.LAVA, coast=B.SAND, mountain=B.STONE, tunnel=B.STONE,
    inner=B.STONE, ores=_stone_ores(0.05, 0.0, 0.0, 0.0, 0.025), tree_on=B.FIRE_GRASS,
    tree=B.FIRE_TREE, lava=B.LAVA, spawn=B.FIRE_GRASS, floor=B.FIRE_GRASS, ladder_up=True,
    ladder_down=True, water_strength=5, water_max=1, mountain_strength=5, mountain_max=1,
    light=1.0, water_threshold=0.5, sand_threshold=0.6, tree_uniform=0.8, tree_perlin=0.5)
ICE_REALM = CaveConfig(
    default=B.ICE_GRASS, sea=B.WATER, coast=B.ICE_GRASS, mountain=B.STONE, tunnel=B.STONE,
    inner=B.STONE, ores=_stone_ores(0.0, 0.0, 0.005, 0.02, 0.0), tree_on=B.ICE_GRASS,
    tree=B.ICE_SHRUB, lava=B.WATER, spawn=B.ICE_GRASS, floor=B.ICE_GRASS, ladder_up=True,
    ladder_down=True, water_strength=5, water_max=1, mountain_strength=17, mountain_max=1.5,
    light=0.0, water_threshold=0.5, sand_threshold=0.6, tree_uniform=0.4, tree_perlin=0.5)
GRAVEYARD = CaveConfig(
    default=B.PATH, sea=B.PATH, coast=B.PATH, mountain=B.WALL, tunnel=B.WALL, inner=B.WALL,
    ores=((B.WALL, B.WALL_MOSS, 0.1), (B.GRAVE, B.GRAVE2, 0.333), (B.GRAVE, B.GRAVE3, 0.5)),
    tree_on=B.PATH, tree=B.GRAVE, lava=B.WALL, spawn=B.NECROMANCER, floor=B.PATH,
    ladder_up=False, ladder_down=False, water_strength=5, water_max=1, mountain_strength=10,
    mountain_max=10, light=0.0, water_threshold=0.7, sand_threshold=0.6, tree_uniform=0.95,
    tree_perlin=-1.0)


@dataclass(frozen=True)
class DungeonConfig:
    special: int            # put in the first room, two cells in from its corner
    fountain: int
    rare_floor: int         # what a tenth of the item-free floor becomes

    __post_init__ = _plain_blocks


DUNGEON = DungeonConfig(special=B.PATH, fountain=B.FOUNTAIN, rare_floor=B.PATH)
SEWERS = DungeonConfig(special=B.ENCHANTMENT_TABLE_ICE, fountain=B.WATER, rare_floor=B.WATER)
VAULTS = DungeonConfig(special=B.ENCHANTMENT_TABLE_FIRE, fountain=B.FOUNTAIN, rare_floor=B.PATH)

LEVELS: tuple = (OVERWORLD, DUNGEON, GNOMISH_MINES, SEWERS, VAULTS, TROLL_MINES, FIRE_REALM,
                 ICE_REALM, GRAVEYARD)
# what a carved path is made of, per level: a cave level's ladder floor, else dungeon floor
FLOORS = tuple(int(cfg.floor) if isinstance(cfg, CaveConfig) else int(B.PATH) for cfg in LEVELS)


# ---------------------------------------------------------------------------------------------
# Small helpers

def _distance_from(centre: tuple[int, int]) -> np.ndarray:
    r = np.arange(ROWS)[:, None] - centre[0]
    c = np.arange(COLS)[None, :] - centre[1]
    return np.sqrt(r * r + c * c)


_CENTRE_DISTANCE = _distance_from(CENTRE)


@lru_cache(maxsize=None)
def _centre_push(strength: float, most: float) -> np.ndarray:
    """What a noise map is pushed by with the distance from the centre:
    ``clip(d / strength, 0, most) - 1`` (the same for every level of a configuration)."""
    push = np.clip(_CENTRE_DISTANCE / strength, 0, most) - 1
    push.flags.writeable = False
    return push


def _convolve3(mask: np.ndarray, kernel: np.ndarray) -> np.ndarray:
    """``mask`` convolved with a symmetric 3x3 ``kernel``, zero outside the map (scipy's
    ``mode="same"``)."""
    padded = np.zeros((mask.shape[0] + 2, mask.shape[1] + 2))
    padded[1:-1, 1:-1] = mask
    out = np.zeros(mask.shape)
    for dr in range(3):
        for dc in range(3):
            if kernel[dr, dc]:
                out += kernel[dr, dc] * padded[dr:dr + mask.shape[0], dc:dc + mask.shape[1]]
    return out


def _pick_cell(rng: np.random.Generator, where: np.ndarray) -> np.ndarray:
    """A uniformly random cell where ``where`` holds; (0, 0) when it holds nowhere (upstream's
    ``jax.random.choice`` with all-zero weights picks index 0)."""
    flat = np.flatnonzero(where)
    index = flat[rng.integers(len(flat))] if len(flat) else 0
    return np.array(divmod(int(index), where.shape[1]), np.int32)


def _paste_light(light: np.ndarray, patch: np.ndarray, centre: np.ndarray) -> None:
    """Write a 9x9 ``patch`` centred on ``centre``, shifted inside the map at the edges (as
    ``jax.lax.dynamic_update_slice`` clamps its start)."""
    r = min(max(int(centre[0]) - 4, 0), light.shape[0] - 9)
    c = min(max(int(centre[1]) - 4, 0), light.shape[1] - 9)
    light[r:r + 9, c:c + 9] = patch


# ---------------------------------------------------------------------------------------------
# Noise levels

@dataclass
class CaveNoise:
    """A noise level's four Perlin maps (upstream's resolutions on the 48x48 map)."""
    water: np.ndarray       # 3x3 lattice
    mountain: np.ndarray    # 3x3 lattice
    tunnels: np.ndarray     # 6x24 lattice: long thin lines, used as drawn and transposed
    trees: np.ndarray       # 12x12 lattice

    @classmethod
    def draw(cls, rng: np.random.Generator, count: int) -> list["CaveNoise"]:
        """Noise for ``count`` levels (drawn together: numpy works faster on the batch)."""
        coarse = fractal(rng, MAP_SIZE, (ROWS // 16, COLS // 16), 2 * count)
        tunnels = fractal(rng, MAP_SIZE, (ROWS // 8, COLS // 2), count)
        trees = fractal(rng, MAP_SIZE, (ROWS // 4, COLS // 4), count)
        return [cls(coarse[2 * i], coarse[2 * i + 1], tunnels[i], trees[i]) for i in range(count)]


_LAVA_GLOW = np.array([[0.2, 0.7, 0.2], [0.7, 1, 0.7], [0.2, 0.7, 0.2]])


def cave_level(rng: np.random.Generator, cfg: CaveConfig, noise: CaveNoise | None = None):
    """One noise level: (block map, item map, light map, down ladder, up ladder)."""
    shape = MAP_SIZE
    noise = noise or CaveNoise.draw(rng, 1)[0]
    water = noise.water + _centre_push(cfg.water_strength, cfg.water_max)
    block = np.where(water > cfg.water_threshold, cfg.sea, cfg.default).astype(np.int32)
    block[(water > cfg.sand_threshold) & (block != cfg.sea)] = cfg.coast

    mountain = noise.mountain + 0.05
    mountain += _centre_push(cfg.mountain_strength, cfg.mountain_max)
    rock = mountain > 0.7
    block[rock] = cfg.mountain

    tunnels = noise.tunnels
    block[rock & ((tunnels > 0.8) | (tunnels.T > 0.8))] = cfg.tunnel
    block[(mountain > 0.85) & (water > 0.4)] = cfg.inner

    tree_noise = noise.trees
    trees = (tree_noise > cfg.tree_perlin) & (rng.random(shape) > cfg.tree_uniform)
    block[trees & (block == cfg.tree_on)] = cfg.tree

    for replaced, ore, chance in cfg.ores:
        if chance > 0:
            block[(block == replaced) & (rng.random(shape) < chance)] = ore

    lava = (mountain > 0.85) & (tree_noise > 0.7)
    block[lava] = cfg.lava
    if not (block == _STONE).any():
        # upstream's always-diamond step (off by default) still rewrites a random stone cell
        # with stone; with no stone at all (the graveyard) its draw lands on (0, 0)
        block[0, 0] = _STONE
    block[CENTRE] = cfg.spawn

    items = np.zeros(shape, np.int32)
    down = _pick_cell(rng, block == cfg.floor)
    up = _pick_cell(rng, block == cfg.floor)
    if cfg.ladder_down:
        items[tuple(down)] = _LADDER_DOWN
    if cfg.ladder_up:
        items[tuple(up)] = _LADDER_UP

    light = np.full(shape, cfg.light, np.float64)
    _paste_light(light, TORCH_LIGHT_MAP * (1 - cfg.light) + cfg.light, up)
    if cfg.lava == _LAVA:
        light += _convolve3(lava, _LAVA_GLOW)
    light = np.clip(light, 0.0, 1.0).astype(np.float32)
    return block, items, light, down, up


# ---------------------------------------------------------------------------------------------
# Dungeon levels

CHUNK = 16
NUM_ROOMS = 8
MIN_ROOM, MAX_ROOM = 5, 10          # room sides are drawn from [MIN_ROOM, MAX_ROOM)
PAD = MAX_ROOM                      # rooms are laid out on a map padded by this much


def _place_rooms(rng, block, items, cfg: DungeonConfig) -> list[tuple[int, int]]:
    """Eight rooms, each in its own 16x16 chunk (corner jittered up to 10 cells, so rooms
    may spill into the next chunk or off the map); returns their top-left corners."""
    chunks_per_row = ROWS // CHUNK
    free = list(range(chunks_per_row * (COLS // CHUNK)))
    sizes = rng.integers(MIN_ROOM, MAX_ROOM, (NUM_ROOMS, 2))
    # draw(low, high): rng.integers(low, high), scalar by scalar; numpy draws an array of them
    # one after another from the same stream, so (draw(a, b), draw(c, d)) is
    # rng.integers((a, c), (b, d)), at a fraction of the cost
    draw = int_sampler(rng)
    corners = []
    for h, w in sizes.tolist():
        chunk = free.pop(draw(0, len(free)))
        jitter_r, jitter_c = draw(0, CHUNK - MIN_ROOM), draw(0, CHUNK - MIN_ROOM)
        r = chunk % chunks_per_row * CHUNK + PAD + jitter_r
        c = chunk // chunks_per_row * CHUNK + PAD + jitter_c
        corners.append((r, c))
        block[r:r + h, c:c + w] = _PATH
        for tr, tc in ((r, c), (r + h - 1, c), (r, c + w - 1), (r + h - 1, c + w - 1)):
            items[tr, tc] = _TORCH
        cr, cc = draw(1, h - 1), draw(1, w - 1)
        block[r + cr, c + cc] = _CHEST
        fr, fc = draw(1, h - 1), draw(1, w - 1)
        if rng.random() > 0.5:
            block[r + fr, c + fc] = cfg.fountain
    return corners


def _dig_corridors(rng, block, corners) -> None:
    """Each room in turn joins a room already joined (at first only the last room): along the
    source corner's row to the sink corner's column, then along that column to the sink's row,
    turning wall to floor."""
    joined = [NUM_ROOMS - 1]
    draw = int_sampler(rng)         # (rng.integers, faster: see _place_rooms)
    for i, (sr, sc) in enumerate(corners):
        tr, tc = corners[joined[draw(0, len(joined))]]
        lo, hi = sorted((sc, tc))
        row = block[sr, lo:hi + 1]
        row[row == _WALL] = _PATH
        lo, hi = sorted((sr, tr))
        col = block[lo:hi + 1, tc]
        col[col == _WALL] = _PATH
        if i not in joined:
            joined.append(i)


def dungeon_level(rng: np.random.Generator, cfg: DungeonConfig):
    """One dungeon level: (block map, item map, light map, down ladder, up ladder)."""
    block = np.zeros((ROWS + 2 * PAD, COLS + 2 * PAD), np.int32)
    block[PAD:-PAD, PAD:-PAD] = _WALL
    items = np.zeros_like(block)
    corners = _place_rooms(rng, block, items, cfg)
    _dig_corridors(rng, block, corners)
    block[corners[0][0] + 2, corners[0][1] + 2] = cfg.special
    block, items = block[PAD:-PAD, PAD:-PAD], items[PAD:-PAD, PAD:-PAD].copy()

    near_floor = _grow(block != _WALL)     # (upstream: a cross convolution > 0.5)
    rare = rng.random(MAP_SIZE) < 0.1
    floor = np.where(rare & (block == _PATH) & (items == _NO_ITEM), cfg.rare_floor, block)
    wall = np.where(rare, _WALL_MOSS, _WALL)
    block = np.where(~near_floor, _DARKNESS,
                     np.where(block == _WALL, wall, floor)).astype(np.int32)

    down = _pick_cell(rng, block == _PATH)
    items[tuple(down)] = _LADDER_DOWN
    up = _pick_cell(rng, block == _PATH)
    items[tuple(up)] = _LADDER_UP
    return block, items, np.ones(MAP_SIZE, np.float32), down, up


# ---------------------------------------------------------------------------------------------
# Walkability

_STEPS = ((-1, 0), (1, 0), (0, -1), (0, 1))


def walkable(block: np.ndarray) -> np.ndarray:
    """Cells the player can step onto (not solid, not water, not lava), as upstream's move."""
    return _WALKABLE[block]


def _grow(cells: np.ndarray) -> np.ndarray:
    """``cells`` and their 4-neighbours (over the last two axes)."""
    out = cells.copy()
    out[..., 1:, :] |= cells[..., :-1, :]
    out[..., :-1, :] |= cells[..., 1:, :]
    out[..., :, 1:] |= cells[..., :, :-1]
    out[..., :, :-1] |= cells[..., :, 1:]
    return out


@lru_cache(maxsize=None)
def _neighbours(shape: tuple[int, int]) -> tuple[tuple[int, ...], ...]:
    """Per cell of a ``shape`` map (flat index, row-major), its 4-neighbours' flat indices in
    the map, in ``_STEPS`` order."""
    rows, cols = shape
    return tuple(tuple((r + dr) * cols + c + dc for dr, dc in _STEPS
                       if 0 <= r + dr < rows and 0 <= c + dc < cols)
                 for r in range(rows) for c in range(cols))


class _Walk:
    """The walked region of one level as it grows, cells by flat index: ``inside`` (a byte per
    cell, 1 in it; ``inside_map`` is the same bytes as a boolean map) and ``when``, the tick
    each cell joined it (the start cell 0; the clock is ``clock``)."""

    def __init__(self, block: np.ndarray, start) -> None:
        self.neighbours = _neighbours(block.shape)
        walk = _carve_walkable(block)
        self.walk = walk.tobytes()
        self.blocked = _CARVABLE[block] & ~walk       # what a ring may carve
        start = int(start[0]) * block.shape[1] + int(start[1])
        self.inside = bytearray(block.size)
        self.inside_map = np.frombuffer(self.inside, bool).reshape(block.shape)
        self.free = bytearray(self.walk)              # walkable and not yet inside
        self.when = [0] * block.size
        self.clock = 0
        self.join([start], 0)
        self.flood([start])

    def join(self, cells, tick: int) -> None:
        inside, free, when = self.inside, self.free, self.when
        for cell in cells:
            inside[cell] = 1
            free[cell] = 0
            when[cell] = tick

    def flood(self, frontier: list[int]) -> None:
        """Spread from the ``frontier`` cells (just joined) over walkable cells one step a tick
        of ``clock``, writing each new cell's tick. (Every cell joined before the frontier has
        its walkable neighbours inside already, so spreading from the frontier alone gives the
        ticks that spreading from the whole region would. The ticks are the cells' layers in
        ``games.common.grid.bfs_layers``; that function, with its dict of cells, made a world
        2-3 ms slower than this walk over flat indices and byte flags.)"""
        neighbours, free, inside, when = self.neighbours, self.free, self.inside, self.when
        while True:
            tick, new = self.clock + 1, []
            for cell in frontier:
                for n in neighbours[cell]:
                    if free[n]:
                        free[n] = 0
                        inside[n] = 1
                        when[n] = tick
                        new.append(n)
            if not new:
                return
            self.clock, frontier = tick, new

    def ring(self) -> list[int]:
        """The carvable blocking cells beside the region."""
        inside = self.inside_map
        return np.flatnonzero(_grow(inside) & self.blocked & ~inside).tolist()


def _seeds(shape, starts: np.ndarray) -> np.ndarray:
    seeds = np.zeros(shape, bool)
    seeds[np.arange(shape[0]), starts[:, 0], starts[:, 1]] = True
    return seeds


def _run_ids(walk: np.ndarray) -> np.ndarray:
    """Label each maximal horizontal run of ``walk`` cells (along the last axis) with its own
    number from 1 (0 off the runs)."""
    starts = walk.copy()
    starts[..., 1:] &= ~walk[..., :-1]
    return (np.cumsum(starts.ravel()) * walk.ravel()).reshape(walk.shape)


def _spread(inside: np.ndarray, ids: np.ndarray) -> np.ndarray:
    """``inside`` widened to every whole run it touches."""
    touched = np.zeros(int(ids.max()) + 1, bool)
    touched[ids[inside]] = True
    touched[0] = False
    return inside | touched[ids]


def reach(blocks: np.ndarray, starts: np.ndarray) -> np.ndarray:
    """Per level of ``blocks``, the cells reachable from ``starts[level]`` by walking
    (4-neighbour steps onto walkable cells; the start cell counts whatever it holds).
    Alternately fills whole row runs and whole column runs until nothing changes."""
    inside = _seeds(blocks.shape, starts)
    walk = _WALKABLE[blocks] | inside
    rows, cols = _run_ids(walk), _run_ids(walk.swapaxes(1, 2)).swapaxes(1, 2)
    while True:
        grown = _spread(_spread(inside, rows), cols)
        if np.array_equal(grown, inside):
            return inside
        inside = grown


def reachable(block: np.ndarray, start) -> np.ndarray:
    """The cells of one level reachable from ``start`` by walking."""
    return reach(block[None], np.asarray(start).reshape(1, 2))[0]


def _carve_walkable(block: np.ndarray) -> np.ndarray:
    """What a carved path may cross as it is: walkable cells other than a dungeon's darkness
    (walkable upstream, but beyond the walls: a path through it is carved into floor too)."""
    return _WALKABLE[block] & (block != _DARKNESS)


def _carve_to(block: np.ndarray, region: _Walk, goal: np.ndarray, floor: int) -> None:
    """Grow the walked ``region`` of one level ring by ring, each ring carving one more layer of
    carvable cells, until it touches ``goal`` (a mask); then walk back from there through
    ever-earlier cells, turning the blocking ones into ``floor``. Each ring adds one carved
    cell to the way back, so it carves the fewest cells any path needs."""
    inside, when, walk, neighbours = region.inside, region.when, region.walk, region.neighbours
    goals = np.flatnonzero(goal).tolist()
    while not any(inside[g] for g in goals):
        ring = region.ring()
        if not ring:
            return                      # walled off by protected blocks: nothing to do
        region.clock += 1
        region.join(ring, region.clock)
        region.flood(ring)
    cell = min((g for g in goals if inside[g]), key=when.__getitem__)
    while when[cell] > 0:
        if not walk[cell]:
            block[divmod(cell, block.shape[1])] = floor
        cell = min((n for n in neighbours[cell] if inside[n]), key=when.__getitem__)


def ensure_reachable(blocks: np.ndarray, starts: np.ndarray, goals: np.ndarray) -> None:
    """On each level ``i`` of ``blocks``, make the cells of the mask ``goals[i]`` touchable by
    walking from ``starts[i]``: where no walk reaches one, carve the fewest blocking cells into
    the level's floor. Protected blocks are never carved."""
    reached = (reach(blocks, starts) & goals).any(axis=(1, 2))
    for level in np.flatnonzero(~reached):
        block = blocks[level]
        _carve_to(block, _Walk(block, starts[level]), goals[level], FLOORS[level])


def arrival(state: State, level: int) -> np.ndarray:
    """Where the player enters ``level``: the start on level 0, else the level's up ladder."""
    return np.array(CENTRE, np.int32) if level == 0 else state.up_ladders[level]


# ---------------------------------------------------------------------------------------------
# The whole world

def _inventory(god_mode: bool) -> Inventory:
    if not god_mode:
        return Inventory()
    full = {name: 99 for name in ("wood", "stone", "coal", "iron", "diamond", "sapling", "arrows",
                                  "torches", "ruby", "sapphire", "books")}
    return Inventory(**full, pickaxe=4, sword=4, bow=1, potions=np.full(6, 99, np.int32),
                     armour=np.full(4, 2, np.int32))


def _projectile_directions(slots: int) -> np.ndarray:
    return np.ones((NUM_LEVELS, slots, 2), np.int32)


def _state(block, items, light, down, up, potion_mapping, settings: Settings) -> State:
    """A State on the given levels with upstream's initial player, mobs and counters."""
    return State(
        map=block, item_map=items, mob_map=np.zeros(block.shape, bool), light_map=light,
        down_ladders=down, up_ladders=up,
        chests_opened=np.zeros(NUM_LEVELS, bool),
        monsters_killed=np.array([10] + [0] * (NUM_LEVELS - 1), np.int32),  # level 0 starts open
        player_position=np.array(CENTRE, np.int32), player_level=0,
        player_direction=int(Action.UP),
        player_health=9.0, player_food=9, player_drink=9, player_energy=9, player_mana=9,
        is_sleeping=False, is_resting=False,
        player_recover=0.0, player_hunger=0.0, player_thirst=0.0, player_fatigue=0.0,
        player_recover_mana=0.0,
        player_xp=0, player_dexterity=1, player_strength=1, player_intelligence=1,
        inventory=_inventory(settings.god_mode),
        melee_mobs=Mobs.empty(MAX_MELEE), passive_mobs=Mobs.empty(MAX_PASSIVE),
        ranged_mobs=Mobs.empty(MAX_RANGED),
        mob_projectiles=Mobs.empty(MAX_MOB_PROJECTILES),
        mob_projectile_directions=_projectile_directions(MAX_MOB_PROJECTILES),
        player_projectiles=Mobs.empty(MAX_PLAYER_PROJECTILES),
        player_projectile_directions=_projectile_directions(MAX_PLAYER_PROJECTILES),
        growing_plants_positions=np.zeros((MAX_GROWING_PLANTS, 2), np.int32),
        growing_plants_age=np.zeros(MAX_GROWING_PLANTS, np.int32),
        growing_plants_mask=np.zeros(MAX_GROWING_PLANTS, bool),
        potion_mapping=np.asarray(potion_mapping, np.int32),
        learned_spells=np.zeros(2, bool),
        sword_enchantment=0, bow_enchantment=0, armour_enchantments=np.zeros(4, np.int32),
        boss_progress=0, boss_timesteps_to_spawn_this_round=BOSS_FIGHT_SPAWN_TURNS,
        light_level=float(np.float32(light_level(0, settings.day_length))),  # upstream: float32
        achievements=np.zeros(len(Achievement), bool),
        timestep=0,
    )


def make_playable(state: State) -> None:
    """Carve, where needed, a walking path on every level from its arrival point to its down
    ladder, and on the last level to a cell beside the necromancer."""
    goals = np.zeros(state.map.shape, bool)
    for level in range(NUM_LEVELS - 1):
        goals[level][tuple(state.down_ladders[level])] = True
    for dr, dc in _STEPS:
        goals[NUM_LEVELS - 1, CENTRE[0] + dr, CENTRE[1] + dc] = True
    starts = np.stack([arrival(state, level) for level in range(NUM_LEVELS)])
    ensure_reachable(state.map, starts, goals)


def generate(rng: np.random.Generator, settings: Settings = Settings()) -> State:
    """A new world, as upstream's ``generate_world``: nine levels, the player at the centre of
    the overworld facing up, no mobs; every ladder walkable-to (see the module docstring)."""
    noises = iter(CaveNoise.draw(rng, sum(isinstance(cfg, CaveConfig) for cfg in LEVELS)))
    made = [cave_level(rng, cfg, next(noises)) if isinstance(cfg, CaveConfig)
            else dungeon_level(rng, cfg) for cfg in LEVELS]
    block, items, light, down, up = (np.stack(parts) for parts in zip(*made))
    int32 = dict(dtype=np.int32, copy=False)       # (the stacks have these types already)
    state = _state(block.astype(**int32), items.astype(**int32),
                   light.astype(np.float32, copy=False), down.astype(**int32), up.astype(**int32),
                   rng.permutation(6), settings)
    make_playable(state)
    return state


def blank(settings: Settings = Settings(), fill: int = B.GRASS) -> State:
    """Nine levels of nothing but ``fill``, full light, no items or ladders, with upstream's
    initial player: a base for hand-built scenarios and tests."""
    shape = (NUM_LEVELS, *MAP_SIZE)
    return _state(np.full(shape, int(fill), np.int32), np.zeros(shape, np.int32),
                  np.ones(shape, np.float32), np.zeros((NUM_LEVELS, 2), np.int32),
                  np.zeros((NUM_LEVELS, 2), np.int32), np.arange(6), settings)
