"""``rules.step`` in lockstep with the ``craftax`` package's own ``craftax_step``.

The package's step is jitted once for the module. Each sequence starts from one state given to
both engines: ours steps with ``Settings(spawning=False)``, the package's steps its own way
(mobs included), and after each of its steps every mob, mob projectile and player projectile it
has is removed (spawning, mob moves and projectile flight are another module's rules; a player
projectile is only checked to start at the player's cell). After every step the two states must agree on: the inventory; the
vitals (health, food, drink, energy, mana) and their accumulators (recover, hunger, thirst,
fatigue, mana recovery); the achievements and the reward; map, item map and light map; position,
direction, level, sleeping and resting; XP and attributes; spells, enchantments, potion mapping;
chests opened, monsters killed, growing plants; boss counters; timestep and light level.

The start states: one sequence starts from the package's seeded reset (``CraftaxSymbolicEnv``,
converted with ``State.from_upstream``); the others from a plain world built below (grass
overworld, path levels with ladders, the package's initial vitals and counters) edited for the
rule each exercises, converted into the package's ``EnvState``.

Upstream's random draws (a sapling from DO on grass, chest loot, the spell a book teaches when
both are unknown, the armour piece an enchantment picks when several qualify) are kept out of
the sequences: DO never faces grass, the book's reader knows one spell, and the armour
enchanted has one unenchanted piece. Chests are opened with only the loot's deterministic parts
compared (the bow of the dungeon's first chest, the book of the sewers', the chest turned to
path, ``chests_opened``, OPEN_CHEST); the package's inventory is then copied into ours. Melee
hits on mobs (one step each, the mob's cooldown set so it cannot strike back) compare the mob's
health and life before the package's mobs are removed.
"""

from __future__ import annotations

from dataclasses import fields

import numpy as np
import pytest

pytest.importorskip("craftax")

import jax  # noqa: E402

from glyphbench_rl.games.common.lanes import Draws  # noqa: E402
from glyphbench_rl.games.craftax import rules  # noqa: E402
from glyphbench_rl.games.craftax.state import (  # noqa: E402
    MAP_SIZE, MAX_GROWING_PLANTS, MAX_MELEE, MAX_MOB_PROJECTILES, MAX_PASSIVE,
    MAX_PLAYER_PROJECTILES, MAX_RANGED, NUM_LEVELS, Inventory, Mobs, Settings, State,
)
from glyphbench_rl.games.craftax.tables import (  # noqa: E402
    LEVEL_DEFAULT_LIGHT, Achievement, Action, BlockType, ItemType, light_level, max_energy,
)

A, B = Action, BlockType
CENTRE = (24, 24)
SETTINGS = Settings(spawning=False)


# ---------------------------------------------------------------------------- the two engines


@pytest.fixture(scope="module")
def package():
    from craftax.craftax import craftax_state
    from craftax.craftax.envs.craftax_symbolic_env import CraftaxSymbolicEnv
    from craftax.craftax.game_logic import craftax_step

    env = CraftaxSymbolicEnv()
    params, static = env.default_params, env.static_env_params
    step = jax.jit(lambda key, s, a: craftax_step(key, s, a, params, static))
    return env, params, craftax_state, step


def _np(value):
    a = np.asarray(value)
    if a.dtype == bool:
        return a
    return a.astype(np.float32 if a.dtype.kind == "f" else np.int32)


def to_package(state: State, craftax_state):
    """Our state as the package's EnvState (numpy leaves of fixed dtypes: one jit trace)."""
    kw = {}
    for f in fields(State):
        v = getattr(state, f.name)
        if isinstance(v, Mobs):
            kw[f.name] = craftax_state.Mobs(**{name: _np(a) for name, a in v.arrays().items()})
        elif isinstance(v, Inventory):
            kw[f.name] = craftax_state.Inventory(
                **{g.name: _np(getattr(v, g.name)) for g in fields(Inventory)})
        elif f.name in ("player_health", "player_recover", "player_hunger", "player_thirst",
                        "player_fatigue", "player_recover_mana", "light_level"):
            kw[f.name] = np.float32(v)
        else:
            kw[f.name] = _np(v)
    return craftax_state.EnvState(**kw, state_rng=np.zeros(2, np.uint32))


def strip_mobs(state: State) -> None:
    for mobs in (state.melee_mobs, state.passive_mobs, state.ranged_mobs, state.mob_projectiles,
                 state.player_projectiles):
        mobs.mask = [[False] * len(slots) for slots in mobs.mask]
    state.mob_map[:] = False


def blank_state(seed: int = 0) -> State:
    """A plain world with the package's initial player values (world_gen.generate_world)."""
    rng = np.random.default_rng(seed)
    rows, cols = MAP_SIZE
    m = np.full((NUM_LEVELS, rows, cols), int(B.PATH), np.int32)
    m[0] = B.GRASS
    item_map = np.zeros_like(m)
    down = np.array([(30, 30 + i) for i in range(NUM_LEVELS)], np.int32)
    up = np.array([(18, 18 + i) for i in range(NUM_LEVELS)], np.int32)
    for level in range(NUM_LEVELS):
        if level < NUM_LEVELS - 1:
            item_map[level, down[level][0], down[level][1]] = ItemType.LADDER_DOWN
        if level > 0:
            item_map[level, up[level][0], up[level][1]] = ItemType.LADDER_UP
    light = np.stack([np.full((rows, cols), x, np.float32) for x in LEVEL_DEFAULT_LIGHT])
    killed = np.zeros(NUM_LEVELS, np.int32)
    killed[0] = 10
    return State(
        map=m, item_map=item_map, mob_map=np.zeros(m.shape, bool), light_map=light,
        down_ladders=down, up_ladders=up, chests_opened=np.zeros(NUM_LEVELS, bool),
        monsters_killed=killed, player_position=np.array(CENTRE, np.int32), player_level=0,
        player_direction=int(A.UP), player_health=9.0, player_food=9, player_drink=9,
        player_energy=9, player_mana=9, is_sleeping=False, is_resting=False,
        player_recover=0.0, player_hunger=0.0, player_thirst=0.0, player_fatigue=0.0,
        player_recover_mana=0.0, player_xp=0, player_dexterity=1, player_strength=1,
        player_intelligence=1, inventory=Inventory(),
        melee_mobs=Mobs.empty(MAX_MELEE), passive_mobs=Mobs.empty(MAX_PASSIVE),
        ranged_mobs=Mobs.empty(MAX_RANGED), mob_projectiles=Mobs.empty(MAX_MOB_PROJECTILES),
        mob_projectile_directions=np.ones((NUM_LEVELS, MAX_MOB_PROJECTILES, 2), np.int32),
        player_projectiles=Mobs.empty(MAX_PLAYER_PROJECTILES),
        player_projectile_directions=np.ones((NUM_LEVELS, MAX_PLAYER_PROJECTILES, 2), np.int32),
        growing_plants_positions=np.zeros((MAX_GROWING_PLANTS, 2), np.int32),
        growing_plants_age=np.zeros(MAX_GROWING_PLANTS, np.int32),
        growing_plants_mask=np.zeros(MAX_GROWING_PLANTS, bool),
        potion_mapping=rng.permutation(6).astype(np.int32),
        learned_spells=np.zeros(2, bool), sword_enchantment=0, bow_enchantment=0,
        armour_enchantments=np.zeros(4, np.int32), boss_progress=0,
        boss_timesteps_to_spawn_this_round=7, light_level=light_level(0, 300),
        achievements=np.zeros(len(Achievement), bool), timestep=0)


def stamp(state: State, rows: list[str], legend: dict[str, int], level: int = 0) -> None:
    """Write ``rows`` (centred on the player; '.' keeps the cell) onto ``level``'s map."""
    r0 = int(state.player_position[0]) - len(rows) // 2
    c0 = int(state.player_position[1]) - len(rows[0]) // 2
    for i, row in enumerate(rows):
        for j, ch in enumerate(row):
            if ch != ".":
                state.map[level, r0 + i, c0 + j] = legend[ch]


LEGEND = {"g": B.GRASS, "T": B.TREE, "S": B.STONE, "W": B.WATER, "L": B.LAVA, "C": B.COAL,
          "I": B.IRON, "D": B.DIAMOND, "p": B.PATH, "R": B.RIPE_PLANT, "F": B.ENCHANTMENT_TABLE_FIRE,
          "s": B.SAPPHIRE, "r": B.RUBY, "m": B.STALAGMITE, "f": B.FOUNTAIN, "w": B.WALL}

_FLOATS = ("player_health", "player_recover", "player_hunger", "player_thirst", "player_fatigue",
           "player_recover_mana", "light_level")


def assert_same(ours: State, theirs: State, where: str) -> None:
    for f in fields(State):
        a, b = getattr(ours, f.name), getattr(theirs, f.name)
        if f.name in ("mob_map", "melee_mobs", "passive_mobs", "ranged_mobs", "mob_projectiles",
                      "mob_projectile_directions", "player_projectiles",
                      "player_projectile_directions"):
            continue        # mobs: another module's rules (removed from both after each step)
        if isinstance(a, Inventory):
            for g in fields(Inventory):
                assert np.array_equal(getattr(a, g.name), getattr(b, g.name)), \
                    f"{where}: inventory.{g.name} {getattr(a, g.name)} != {getattr(b, g.name)}"
        elif f.name in _FLOATS or f.name == "light_map":
            assert np.allclose(a, b, atol=1e-4), f"{where}: {f.name} {a} != {b}"
        elif f.name == "achievements":
            diff = [Achievement(i).name for i in np.flatnonzero(np.asarray(a) != np.asarray(b))]
            assert not diff, f"{where}: achievements differ: {diff}"
        else:
            assert np.array_equal(a, b), f"{where}: {f.name} {a} != {b}"


class Lockstep:
    def __init__(self, package, state: State, seed: int = 0):
        self.env, self.params, self.cs, self.jstep = package
        strip_mobs(state)
        self.ours, self.theirs = state.copy(), state.copy()
        self.draws = Draws(np.random.default_rng(seed))
        self.key = jax.random.PRNGKey(seed)
        self.n = 0

    def edit(self, fn) -> None:
        """Apply the same edit to both states."""
        fn(self.ours)
        fn(self.theirs)

    def run(self, actions, label: str = "", check=None, loot: bool = False) -> None:
        """Step both with each action and compare. ``check(ours, theirs, where)`` runs before
        the package's mobs are removed; ``loot`` (a chest opened: random loot) compares only
        the loot's deterministic parts, then copies the package's inventory and achievements
        into ours to go on in lockstep."""
        for action in actions:
            action = int(action)
            self.key, sub = jax.random.split(self.key)
            out, reward_t = self.jstep(sub, to_package(self.theirs, self.cs), action)
            self.theirs = State.from_upstream(out)
            before = (self.ours.inventory.arrows, self.ours.player_mana)
            reward = rules.step(self.ours, action, SETTINGS, self.draws)
            where = f"{label} step {self.n} ({A(action).name})"
            if action in (A.SHOOT_ARROW, A.CAST_FIREBALL, A.CAST_ICEBALL):
                # the projectile starts at the player's cell and mobs.update flies it at once,
                # as the package's update_mobs does: the two must agree before mobs are removed
                fired = (self.ours.inventory.arrows < before[0]
                         or self.ours.player_mana < before[1])   # regen adds at most 1
                p, level = self.ours.player_projectiles.arrays(), self.ours.player_level
                q = self.theirs.player_projectiles.arrays()
                live = np.flatnonzero(p["mask"][level])
                assert live.size <= int(fired), where
                assert live.tolist() == np.flatnonzero(q["mask"][level]).tolist(), where
                for i in live:
                    assert p["position"][level, i].tolist() == q["position"][level, i].tolist(), where
                    assert p["type_id"][level, i] == q["type_id"][level, i], where
            if check is not None:
                check(self.ours, self.theirs, where)
            strip_mobs(self.theirs)
            strip_mobs(self.ours)
            if loot:
                for name in ("bow", "books"):
                    a, b = getattr(self.ours.inventory, name), getattr(self.theirs.inventory, name)
                    assert a == b, f"{where}: {name} {a} != {b}"
                opened = Achievement.OPEN_CHEST
                assert self.ours.achievements[opened] == self.theirs.achievements[opened], where
                self.ours.inventory = self.theirs.copy().inventory
                self.ours.achievements[:] = self.theirs.achievements
                reward = float(reward_t)
            assert abs(reward - float(reward_t)) < 1e-4, f"{where}: reward {reward} != {reward_t}"
            assert_same(self.ours, self.theirs, where)
            self.n += 1


# ---------------------------------------------------------------------------- the sequences


def test_walking_into_obstacles_water_and_lava(package):
    s = blank_state()
    stamp(s, ["ggSgg",
              "ggggg",
              "Wg.gL",
              "ggggg",
              "ggTgg"], LEGEND)
    ls = Lockstep(package, s)
    ls.run([A.UP, A.UP, A.DOWN, A.DOWN, A.DOWN, A.DOWN, A.UP, A.LEFT, A.LEFT, A.LEFT,
            A.RIGHT, A.RIGHT, A.RIGHT, A.RIGHT, A.RIGHT, A.NOOP, A.UP, A.UP, A.LEFT], "walk")
    assert tuple(ls.ours.player_position) == (22, 25)  # blocked by water, lava, stone, tree


def put(state: State, cells: dict, level: int = 0) -> None:
    """Set blocks at offsets (drow, dcol) from the player."""
    r, c = (int(x) for x in state.player_position)
    for (dr, dc), block in cells.items():
        state.map[level, r + dr, c + dc] = block


def test_crafting_chain(package):
    s = blank_state()
    put(s, {(-1, 0): B.STONE, (0, -1): B.TREE, (0, 1): B.TREE, (1, 0): B.TREE,
            (4, -2): B.COAL, (4, -1): B.IRON, (4, 0): B.DIAMOND, (4, 1): B.RUBY,
            (4, 2): B.SAPPHIRE, (4, 3): B.STALAGMITE})
    ls = Lockstep(package, s)
    # no pickaxe: the stone above stays; chop the trees left, right and below
    ls.run([A.DO, A.LEFT, A.DO, A.RIGHT, A.DO, A.DOWN, A.DO], "wood")
    assert ls.ours.inventory.wood == 3 and ls.ours.map[0, 23, 24] == B.STONE
    ls.run([A.PLACE_TABLE, A.MAKE_WOOD_PICKAXE, A.MAKE_WOOD_PICKAXE, A.MAKE_WOOD_SWORD],
           "table")
    ls.edit(lambda st: setattr(st.inventory, "wood", st.inventory.wood + 3))
    ls.run([A.MAKE_WOOD_SWORD, A.UP, A.DO, A.PLACE_STONE, A.DO, A.PLACE_FURNACE], "stone")
    ls.edit(lambda st: (setattr(st.inventory, "wood", st.inventory.wood + 2),
                        setattr(st.inventory, "stone", st.inventory.stone + 2)))
    ls.run([A.MAKE_STONE_PICKAXE, A.MAKE_STONE_SWORD, A.MAKE_IRON_PICKAXE], "stone-tools")

    def kit(st):
        inv = st.inventory
        inv.wood, inv.stone, inv.coal, inv.iron, inv.diamond = 10, 10, 10, 10, 12
    ls.edit(kit)
    ls.run([A.MAKE_IRON_PICKAXE, A.MAKE_IRON_SWORD, A.MAKE_DIAMOND_PICKAXE,
            A.MAKE_DIAMOND_SWORD, A.MAKE_IRON_ARMOUR, A.MAKE_IRON_ARMOUR, A.MAKE_DIAMOND_ARMOUR,
            A.MAKE_IRON_ARMOUR, A.MAKE_ARROW, A.MAKE_TORCH, A.MAKE_DIAMOND_ARMOUR,
            A.MAKE_DIAMOND_ARMOUR], "iron-diamond")
    ours = ls.ours
    assert ours.inventory.pickaxe == 4 and ours.inventory.sword == 4
    assert list(ours.inventory.armour) == [2, 2, 0, 0]
    ls.run([A.LEFT, A.PLACE_TORCH, A.PLACE_TORCH, A.UP, A.PLACE_TORCH], "torch")
    assert ls.ours.achievements[Achievement.PLACE_TORCH]
    assert (ls.ours.item_map[0] == ItemType.TORCH).sum() == 2
    # ores by pickaxe tier: stone pickaxe gets coal and iron, not diamond
    ls.edit(lambda st: (st.player_position.__setitem__(slice(None), (27, 22)),
                        setattr(st.inventory, "pickaxe", 2)))
    ls.run([A.DOWN, A.DO, A.RIGHT, A.DOWN, A.DO, A.RIGHT, A.DOWN, A.DO], "ores")
    assert ls.ours.map[0, 28, 24] == B.DIAMOND
    ls.edit(lambda st: setattr(st.inventory, "pickaxe", 4))
    ls.run([A.DO, A.RIGHT, A.DOWN, A.DO, A.RIGHT, A.DOWN, A.DO, A.RIGHT, A.DOWN, A.DO],
           "gems")
    assert (ls.ours.map[0, 28, 22:28] == B.PATH).all()


def test_drink_eat_plant_and_grow(package):
    s = blank_state()
    stamp(s, ["ggggg",
              "ggWgg",
              "gR.fg",
              "ggggg",
              "ggggg"], LEGEND)
    s.player_food, s.player_drink = 3, 2
    s.inventory.sapling = 2
    s.growing_plants_positions[0] = (24, 23)
    s.growing_plants_mask[0] = True
    s.growing_plants_age[0] = 700
    ls = Lockstep(package, s)
    ls.run([A.UP, A.DO, A.DO, A.RIGHT, A.DO, A.LEFT, A.DO, A.NOOP], "drink-eat")
    ls.run([A.DOWN, A.PLACE_PLANT, A.PLACE_PLANT], "plant")
    ls.edit(lambda st: st.growing_plants_age.__setitem__(1, 596))
    ls.run([A.NOOP] * 6, "grow")
    assert ls.ours.map[0, 26, 24] == B.RIPE_PLANT
    ls.run([A.DO, A.NOOP], "eat-grown")
    assert ls.ours.achievements[Achievement.EAT_PLANT]


def test_sleep_rest_and_intrinsics(package):
    s = blank_state()
    s.player_energy, s.player_health = 2, 5.0
    ls = Lockstep(package, s)
    ls.run([A.SLEEP] + [A.NOOP] * 90, "sleep")
    assert ls.ours.achievements[Achievement.WAKE_UP] and not ls.ours.is_sleeping
    ls.edit(lambda st: setattr(st, "player_health", 4.0))
    ls.run([A.REST] + [A.NOOP] * 40, "rest")
    ls.run([A.NOOP] * 120, "noop")
    ls.edit(lambda st: (setattr(st, "player_food", 0), setattr(st, "player_drink", 1)))
    ls.run([A.NOOP] * 60, "starve")
    assert ls.ours.player_health < 9


def test_floors_potions_books_enchanting_levelling(package):
    s = blank_state()
    s.player_position[:] = s.down_ladders[0]
    s.inventory.potions[:] = 1
    s.inventory.books = 1
    s.learned_spells[0] = True
    s.player_mana = 9
    ls = Lockstep(package, s)
    ls.run([A.DESCEND, A.ASCEND], "ladders")          # level 0 opens (10 kills at reset)
    assert ls.ours.player_level == 0 and ls.ours.player_xp == 1
    ls.run([A.DESCEND, A.NOOP], "dungeon")
    ls.edit(lambda st: st.player_position.__setitem__(slice(None), st.down_ladders[1]))
    ls.run([A.DESCEND], "gated")                      # level 1 needs 8 kills: refused
    ls.edit(lambda st: st.monsters_killed.__setitem__(1, 8))
    ls.run([A.DESCEND, A.LEFT], "opened")
    assert ls.ours.player_level == 2
    ls.run([A.DRINK_POTION_RED, A.DRINK_POTION_GREEN, A.DRINK_POTION_BLUE, A.DRINK_POTION_PINK,
            A.DRINK_POTION_CYAN, A.DRINK_POTION_YELLOW, A.DRINK_POTION_RED], "potions")
    ls.run([A.READ_BOOK, A.READ_BOOK, A.CAST_ICEBALL, A.CAST_FIREBALL], "book")

    def table(st):
        r, c = st.player_position
        st.map[st.player_level, r, c - 1] = B.ENCHANTMENT_TABLE_FIRE
        st.map[st.player_level, r + 1, c] = B.ENCHANTMENT_TABLE_ICE
        st.player_mana, st.player_intelligence = 20, 5
        st.inventory.ruby, st.inventory.sapphire = 3, 1
        st.inventory.sword, st.inventory.bow = 2, 1
        st.inventory.armour[:] = (1, 1, 2, 0)
        st.armour_enchantments[:] = (1, 2, 0, 1)
    ls.edit(table)
    ls.run([A.ENCHANT_SWORD, A.ENCHANT_ARMOUR, A.ENCHANT_BOW, A.NOOP], "enchant")
    ours = ls.ours
    assert ours.sword_enchantment == 1 and list(ours.armour_enchantments) == [1, 2, 1, 1]
    assert ours.bow_enchantment == 0                  # mana 2 left
    ls.edit(lambda st: setattr(st, "player_mana", 20))
    ls.run([A.ENCHANT_BOW, A.DOWN, A.ENCHANT_SWORD, A.ENCHANT_ARMOUR, A.LEFT, A.ENCHANT_BOW],
           "enchant-ice")
    assert ls.ours.bow_enchantment == 1 and ls.ours.sword_enchantment == 2
    ls.edit(lambda st: setattr(st, "player_xp", 3))
    ls.run([A.LEVEL_UP_DEXTERITY, A.LEVEL_UP_STRENGTH, A.LEVEL_UP_INTELLIGENCE,
            A.LEVEL_UP_DEXTERITY], "level-up")
    ours = ls.ours
    assert (ours.player_dexterity, ours.player_strength, ours.player_xp) == (3, 2, 0)
    ls.edit(lambda st: (setattr(st.inventory, "arrows", 2), setattr(st.inventory, "bow", 1)))
    ls.run([A.SHOOT_ARROW, A.SHOOT_ARROW, A.SHOOT_ARROW], "bow")
    ls.run([A.UP, A.ASCEND], "no-ladder")


def test_torches_on_a_dark_level_and_at_the_map_edge(package):
    s = blank_state()
    s.player_level = 2
    s.achievements[Achievement.ENTER_GNOMISH_MINES] = True
    s.player_position[:] = (0, 2)
    s.inventory.torches = 5
    s.map[2, 2, 1] = B.WALL                      # not a block torches go on
    ls = Lockstep(package, s)
    ls.run([A.LEFT, A.PLACE_TORCH, A.DOWN, A.PLACE_TORCH, A.RIGHT, A.PLACE_TORCH], "corner")
    assert ls.ours.light_map[2, 0, 0] == 1.0 and ls.ours.inventory.torches == 3
    ls.edit(lambda st: st.player_position.__setitem__(slice(None), (47, 45)))
    ls.run([A.RIGHT, A.PLACE_TORCH, A.UP, A.PLACE_TORCH, A.PLACE_TORCH], "far corner")
    assert ls.ours.inventory.torches == 1


def test_from_the_package_reset(package):
    """The package's own seeded reset, converted: walking, turning and 60 idle turns of drains
    on a generated world (the issue's lockstep start; a second jit of ~33 s)."""
    env, params, _, _ = package
    reset = jax.jit(lambda key: env.reset_env(key, params))
    _, start = reset(jax.random.PRNGKey(7))
    s = State.from_upstream(start)
    ls = Lockstep(package, s)
    ls.run([A.NOOP, A.LEFT, A.LEFT, A.UP, A.UP, A.RIGHT, A.DOWN] + [A.NOOP] * 60, "reset")


MOB_HITS = [  # (class, type_id, health, sword, strength, intelligence, sword enchantment)
    ("passive_mobs", 0, 3.0, 4, 1, 1, 0),      # cow: killed, eaten
    ("passive_mobs", 1, 4.0, 1, 1, 1, 0),      # bat: 2 damage, lives
    ("melee_mobs", 0, 5.0, 1, 1, 1, 0),        # zombie: 2 damage, lives
    ("melee_mobs", 0, 2.0, 1, 1, 1, 0),        # zombie: killed
    ("melee_mobs", 4, 12.0, 4, 3, 3, 1),       # knight (0.5 physical defence), fire sword
    ("melee_mobs", 6, 20.0, 4, 3, 3, 2),       # pigman (fire-proof), ice sword
    ("ranged_mobs", 6, 9.0, 4, 3, 3, 2),       # fire elemental, ice sword
    ("ranged_mobs", 7, 9.0, 3, 5, 5, 2),       # ice elemental, ice sword: no ice damage
    ("ranged_mobs", 0, 3.0, 0, 5, 1, 0),       # skeleton, bare hands x2 strength
]


def test_melee_hits_on_mobs(package):
    """DO on a mob in front: upstream's damage (sword, strength, enchantment vs the mob's
    defence), the kill bookkeeping (food from passive mobs, monsters_killed, achievements).
    The mob's attack cooldown is set so that it does not strike back this step; its health
    and life are compared before the package's mobs (which may have moved) are removed."""
    s = blank_state()
    s.player_food = 2
    ls = Lockstep(package, s)
    for kind, type_id, health, sword, strength, intelligence, enchant in MOB_HITS:
        def setup(st):
            r, c = (int(x) for x in st.player_position)
            mobs = getattr(st, kind)
            mobs.mask[0][0], mobs.position[0][0] = True, (r - 1, c)
            mobs.health[0][0], mobs.type_id[0][0], mobs.attack_cooldown[0][0] = health, type_id, 9
            st.mob_map[0, r - 1, c] = True
            st.inventory.sword, st.sword_enchantment = sword, enchant
            st.player_strength, st.player_intelligence = strength, intelligence
            st.player_direction = int(A.UP)
        ls.edit(setup)

        def check(ours, theirs, where, kind=kind):
            a, b = getattr(ours, kind), getattr(theirs, kind)
            assert a.mask[0][0] == b.mask[0][0], f"{where}: {kind} alive {a.mask[0][0]}"
            assert np.isclose(a.health[0][0], b.health[0][0]), \
                f"{where}: {kind} health {a.health[0][0]} != {b.health[0][0]}"
        ls.run([A.DO], f"hit {kind} {type_id}", check=check)
    ours = ls.ours
    assert ours.achievements[Achievement.EAT_COW] and ours.achievements[Achievement.DEFEAT_ZOMBIE]
    assert ours.monsters_killed[0] > 10


def test_chests_and_the_necromancer(package):
    s = blank_state()
    s.player_level = 1
    s.achievements[Achievement.ENTER_DUNGEON] = True
    put(s, {(-1, 0): B.CHEST, (1, 0): B.CHEST}, level=1)
    ls = Lockstep(package, s)
    ls.run([A.DO], "first chest", loot=True)          # the dungeon's first chest: the bow
    assert ls.ours.inventory.bow == 1 and ls.ours.chests_opened[1]
    ls.run([A.DOWN, A.DO], "second chest", loot=True)

    def sewers(st):
        st.player_level = 3
        st.achievements[Achievement.ENTER_SEWERS] = True
        put(st, {(0, 1): B.CHEST, (0, -1): B.CHEST}, level=3)
    ls.edit(sewers)
    ls.run([A.RIGHT, A.DO, A.LEFT, A.DO], "sewer chests", loot=True)   # a book, then none
    assert ls.ours.inventory.books == 1

    def graveyard(st):
        st.player_level = 8
        st.achievements[Achievement.ENTER_GRAVEYARD] = True
        st.boss_progress, st.boss_timesteps_to_spawn_this_round = 6, 0
        put(st, {(-1, 0): B.NECROMANCER}, level=8)
        st.player_food = st.player_drink = 0          # the boss fight: the needs do not hurt
    ls.edit(graveyard)
    ls.run([A.UP, A.DO, A.DO], "necromancer")          # hit, then invulnerable (spawn wave)
    assert ls.ours.boss_progress == 7
    ls.edit(lambda st: setattr(st, "boss_timesteps_to_spawn_this_round", 0))
    ls.run([A.DO] + [A.NOOP] * 20, "defeat")
    assert ls.ours.achievements[Achievement.DEFEAT_NECROMANCER]


def test_switches_leave_their_sub_rules_out():
    """``Settings(intrinsics=False)``: hunger, thirst and fatigue stay, so do food, drink and
    energy; health still recovers. ``Settings(daylight=False)``: the light level stays 1."""
    s = blank_state()
    s.player_health, s.player_food, s.player_drink, s.player_energy = 5.0, 4, 3, 2
    off = Settings(spawning=False, intrinsics=False, daylight=False)
    draws = Draws(np.random.default_rng(0))
    for _ in range(200):
        rules.step(s, int(A.NOOP), off, draws)
        assert s.light_level == 1.0
    assert (s.player_food, s.player_drink, s.player_energy) == (4, 3, 2)
    assert (s.player_hunger, s.player_thirst, s.player_fatigue) == (0.0, 0.0, 0.0)
    assert s.player_health == 9.0 and s.timestep == 200
    on = blank_state()
    on.player_food = 4
    for _ in range(200):
        rules.step(on, int(A.NOOP), SETTINGS, draws)
    assert on.player_food < 4 and on.light_level != 1.0


def _steps_to_wake(settings: Settings) -> tuple[int, State]:
    s = blank_state()
    s.player_food, s.player_drink, s.player_energy = 4, 3, 2
    draws = Draws(np.random.default_rng(0))
    rules.step(s, int(A.SLEEP), settings, draws)
    assert s.is_sleeping
    steps, energy = 1, s.player_energy
    while s.is_sleeping and steps < 500:
        rules.step(s, int(A.LEFT), settings, draws)     # (asleep, every action is a NOOP)
        assert s.player_energy >= energy and s.player_direction != int(A.LEFT)
        energy = s.player_energy
        steps += 1
    return steps, s


def test_sleep_restores_energy_and_wakes_with_intrinsics_off():
    """``Settings(intrinsics=False)`` stops the drains, not sleep: asleep, fatigue still falls
    and energy still grows (one point per 11 steps, as with intrinsics on), the player wakes at
    full energy (WAKE_UP) and acts again; food and drink do not fall meanwhile."""
    off = Settings(spawning=False, intrinsics=False, daylight=False)
    steps, s = _steps_to_wake(off)
    assert not s.is_sleeping and s.player_energy == max_energy(s.player_dexterity) == 9
    assert s.achievements[Achievement.WAKE_UP]
    assert steps == 7 * 11 + 1        # 7 points of energy, then the step that wakes
    assert steps == _steps_to_wake(Settings(spawning=False, daylight=False))[0]
    assert (s.player_food, s.player_drink, s.player_hunger, s.player_thirst) == (4, 3, 0.0, 0.0)
    row, col = s.player_position.tolist()
    rules.step(s, int(A.LEFT), off, Draws(np.random.default_rng(1)))
    assert s.player_direction == int(A.LEFT) and s.player_position.tolist() == [row, col - 1]
