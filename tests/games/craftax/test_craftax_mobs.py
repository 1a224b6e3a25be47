"""The Craftax mobs (``mobs``): attacks, armour, sleep, collisions, projectiles, kills,
despawning, spawning statistics and the necromancer, on small hand-built states; and, where a
turn is deterministic given the state, the package's own ``update_mobs`` as the oracle (jitted
once for the module; those tests skip without ``craftax``)."""

from __future__ import annotations

import time

import numpy as np
import pytest

from glyphbench_rl.games.common.lanes import Draws
from glyphbench_rl.games.craftax import mobs
from glyphbench_rl.games.craftax.bestiary import (FLOOR_MOB_MAPPING, MOB_NAMES,
                                                   MOB_TYPE_HEALTH_MAPPING)
from glyphbench_rl.games.craftax.state import (MAP_SIZE, NUM_LEVELS, Inventory, Mobs, Settings,
                                               State, float32)
from glyphbench_rl.games.craftax.tables import (BOSS_FIGHT_SPAWN_TURNS, Achievement, BlockType,
                                                MobType, ProjectileType)

G, W, S, L, T = BlockType.GRASS, BlockType.WATER, BlockType.STONE, BlockType.LAVA, BlockType.CRAFTING_TABLE
SETTINGS = Settings()


def blank_state(level: int = 0, player=(24, 24), block=BlockType.GRASS) -> State:
    """A state with every level filled with ``block``, no mobs, the player at ``player``."""
    n, (rows, cols) = NUM_LEVELS, MAP_SIZE
    return State(
        map=np.full((n, rows, cols), int(block), np.int32),
        item_map=np.zeros((n, rows, cols), np.int32),
        mob_map=np.zeros((n, rows, cols), bool),
        light_map=np.ones((n, rows, cols), np.float32),
        down_ladders=np.zeros((n, 2), np.int32), up_ladders=np.zeros((n, 2), np.int32),
        chests_opened=np.zeros(n, bool), monsters_killed=np.zeros(n, np.int32),
        player_position=np.array(player, np.int32), player_level=level, player_direction=4,
        player_health=9.0, player_food=9, player_drink=9, player_energy=9, player_mana=9,
        is_sleeping=False, is_resting=False,
        player_recover=0.0, player_hunger=0.0, player_thirst=0.0, player_fatigue=0.0,
        player_recover_mana=0.0,
        player_xp=0, player_dexterity=1, player_strength=1, player_intelligence=1,
        inventory=Inventory(),
        melee_mobs=Mobs.empty(3), passive_mobs=Mobs.empty(3), ranged_mobs=Mobs.empty(2),
        mob_projectiles=Mobs.empty(3), mob_projectile_directions=np.zeros((n, 3, 2), np.int32),
        player_projectiles=Mobs.empty(3),
        player_projectile_directions=np.zeros((n, 3, 2), np.int32),
        growing_plants_positions=np.zeros((10, 2), np.int32),
        growing_plants_age=np.zeros(10, np.int32), growing_plants_mask=np.zeros(10, bool),
        potion_mapping=np.arange(6, dtype=np.int32), learned_spells=np.zeros(2, bool),
        sword_enchantment=0, bow_enchantment=0, armour_enchantments=np.zeros(4, np.int32),
        boss_progress=0, boss_timesteps_to_spawn_this_round=0,
        light_level=1.0, achievements=np.zeros(67, bool), timestep=0,
    )


def put_mob(state: State, kind: int, pos, type_id: int = 0, slot: int = 0, health=None,
            cooldown: int = 0) -> None:
    group = {MobType.MELEE: state.melee_mobs, MobType.PASSIVE: state.passive_mobs,
             MobType.RANGED: state.ranged_mobs}[kind]
    level = state.player_level
    group.position[level][slot] = (int(pos[0]), int(pos[1]))
    group.mask[level][slot] = True
    group.type_id[level][slot] = type_id
    group.health[level][slot] = float32(MOB_TYPE_HEALTH_MAPPING[type_id][kind] if health is None
                                        else health)
    group.attack_cooldown[level][slot] = cooldown
    state.mob_map[level, pos[0], pos[1]] = True


def put_projectile(state: State, pos, direction, kind: int, slot: int = 0, player: bool = False):
    group = state.player_projectiles if player else state.mob_projectiles
    directions = state.player_projectile_directions if player else state.mob_projectile_directions
    level = state.player_level
    group.position[level][slot] = (int(pos[0]), int(pos[1]))
    group.mask[level][slot] = True
    group.type_id[level][slot] = int(kind)
    directions[level, slot] = direction


def wall_around(state: State, pos, block=BlockType.STONE, keep=()) -> None:
    """Surround ``pos`` on its four sides with ``block`` except the cells in ``keep``."""
    for d_row, d_col in ((0, -1), (0, 1), (-1, 0), (1, 0)):
        cell = (pos[0] + d_row, pos[1] + d_col)
        if cell not in keep:
            state.map[state.player_level, cell[0], cell[1]] = block


def mob_map_is_exact(state: State) -> bool:
    expected = np.zeros_like(state.mob_map)
    for group in (state.melee_mobs, state.passive_mobs, state.ranged_mobs):
        for level, slot in zip(*np.nonzero(group.mask)):
            row, col = group.position[level][slot]
            expected[level, row, col] = True
    return bool((expected == state.mob_map).all())


def draws(seed: int = 0) -> Draws:
    return Draws(np.random.default_rng(seed))


# ---------------------------------------------------------------------------------------------
# Melee attacks, armour, sleep

def zombie_in_a_pocket(state: State, cooldown: int = 0) -> None:
    """A zombie right above the player, walled in on its other three sides."""
    pos = (23, 24)
    wall_around(state, pos, keep={(24, 24)})
    put_mob(state, MobType.MELEE, pos, cooldown=cooldown)


def test_adjacent_zombie_attacks_every_six_turns_for_two():
    state = blank_state()
    zombie_in_a_pocket(state)
    rng = draws(1)
    healths = []
    for _ in range(13):
        mobs.update(state, SETTINGS, rng)
        healths.append(state.player_health)
    lost = -np.diff([9.0] + healths)
    assert [i for i, x in enumerate(lost) if x > 0] == [0, 6, 12]
    assert lost[0] == pytest.approx(2.0)
    assert tuple(state.melee_mobs.position[0][0]) == (23, 24)
    assert mob_map_is_exact(state)


def test_armour_and_enchantments_reduce_damage_by_upstreams_formula():
    state = blank_state()
    zombie_in_a_pocket(state)
    state.inventory.armour[:] = (1, 1, 2, 2)          # 10% physical per tier: 60%
    mobs.update(state, SETTINGS, draws())
    assert 9.0 - state.player_health == pytest.approx(2.0 * 0.4)
    # a troll's (6, 1, 1): fire/ice enchanted pieces block 20% each of their element
    state = blank_state()
    state.inventory.armour[:] = (2, 2, 2, 2)
    state.armour_enchantments[:] = (1, 1, 2, 0)
    assert mobs.damage_to_player(state, (6.0, 1.0, 1.0)) == pytest.approx(
        6 * 0.2 + 1 * 0.6 + 1 * 0.8)
    state.player_level = 8                             # the boss fight: x1.5
    assert mobs.damage_to_player(state, (6.0, 1.0, 1.0)) == pytest.approx(
        1.5 * (6 * 0.2 + 1 * 0.6 + 1 * 0.8))


def test_sleeping_player_takes_three_and_a_half_times_and_wakes():
    state = blank_state()
    zombie_in_a_pocket(state)
    state.is_sleeping = state.is_resting = True
    mobs.update(state, SETTINGS, draws())
    assert 9.0 - state.player_health == pytest.approx(7.0)
    assert not state.is_sleeping and not state.is_resting
    assert state.achievements[Achievement.WAKE_UP]


def test_zombie_with_cooldown_waits():
    state = blank_state()
    zombie_in_a_pocket(state, cooldown=3)
    rng = draws(2)
    for turn in range(4):
        mobs.update(state, SETTINGS, rng)
        assert state.player_health == (9.0 if turn < 3 else 7.0)


def test_zombie_closes_in_on_the_player():
    state = blank_state()
    put_mob(state, MobType.MELEE, (24, 30))
    rng = draws(3)
    for _ in range(40):
        mobs.update(state, SETTINGS, rng)
        assert mob_map_is_exact(state)
    assert state.player_health < 9.0


# ---------------------------------------------------------------------------------------------
# Collisions

def random_terrain(level: int, seed: int) -> State:
    state = blank_state(level)
    rng = np.random.default_rng(seed)
    blocks = np.array([G, G, G, G, G, G, W, S, L], np.int32)
    state.map[level] = blocks[rng.integers(0, len(blocks), MAP_SIZE)]
    state.map[level, 24, 24] = G
    return state


@pytest.mark.parametrize("level, kind, type_id, allowed", [
    (0, MobType.MELEE, 0, {G}),                  # zombie: land only
    (0, MobType.PASSIVE, 0, {G}),                # cow: land only
    (2, MobType.PASSIVE, 1, {G, W, L}),          # bat: flies
    (3, MobType.MELEE, 3, {G, W}),               # lizard: amphibian, not lava
    (5, MobType.RANGED, 5, {W}),                 # deep thing: aquatic (no ground, no lava)
    (6, MobType.RANGED, 6, {G, W, L}),           # fire elemental: flies
])
def test_mobs_walk_only_where_their_collision_allows(level, kind, type_id, allowed):
    state = random_terrain(level, seed=level + 10 * kind)
    if allowed == {W}:                            # a lake with stone and lava islands
        lake = state.map[level, 18:31, 22:35]
        lake[lake == G] = W
    start = (24, 28)
    state.map[level, start[0], start[1]] = min(allowed)
    put_mob(state, kind, start, type_id=type_id)
    group = {MobType.MELEE: state.melee_mobs, MobType.PASSIVE: state.passive_mobs,
             MobType.RANGED: state.ranged_mobs}[kind]
    group.attack_cooldown[level][0] = 10 ** 6       # no shooting: only movement matters
    rng = draws(4)
    cells = set()
    for _ in range(300):
        mobs.update(state, Settings(spawning=False), rng)
        row, col = group.position[level][0]
        assert int(state.map[level, row, col]) in allowed
        assert group.mask[level][0]
        cells.add((int(row), int(col)))
    assert len(cells) > 5
    assert mob_map_is_exact(state)


# ---------------------------------------------------------------------------------------------
# Projectiles

def test_skeleton_shoots_an_arrow_that_flies_and_hits():
    state = blank_state()
    put_mob(state, MobType.RANGED, (20, 24))            # 4 above the player: in range
    mobs.update(state, SETTINGS, draws(5))
    assert sum(state.mob_projectiles.mask[0]) == 1
    assert state.mob_projectiles.type_id[0][0] == ProjectileType.ARROW
    assert tuple(state.mob_projectile_directions[0, 0]) == (1, 0)
    assert tuple(state.mob_projectiles.position[0][0]) == (21, 24)   # it flew one cell already
    assert state.ranged_mobs.attack_cooldown[0][0] == 4
    state.ranged_mobs.mask[0][0] = False                  # only the arrow from now on
    state.mob_map[0, 20, 24] = False
    for _ in range(3):
        mobs.update(state, SETTINGS, draws(6))
    assert state.player_health == pytest.approx(7.0)
    assert not any(state.mob_projectiles.mask[0])


def test_mob_arrow_breaks_a_table_and_stops_at_stone():
    state = blank_state()
    put_projectile(state, (10, 10), (0, 1), ProjectileType.ARROW)
    state.map[0, 10, 12] = T
    mobs.update(state, SETTINGS, draws())
    assert state.mob_projectiles.mask[0][0]
    mobs.update(state, SETTINGS, draws())
    assert not state.mob_projectiles.mask[0][0]
    assert state.map[0, 10, 12] == BlockType.PATH
    put_projectile(state, (10, 10), (0, 1), ProjectileType.ARROW)
    state.map[0, 10, 11] = S
    mobs.update(state, SETTINGS, draws())
    assert not state.mob_projectiles.mask[0][0] and state.map[0, 10, 11] == S
    put_projectile(state, (5, 5), (1, 0), ProjectileType.ARROW)  # water: it flies over
    state.map[0, 6, 5] = W
    mobs.update(state, SETTINGS, draws())
    assert state.mob_projectiles.mask[0][0]


def moat_zombie(state: State, pos=(24, 30), type_id: int = 0) -> None:
    """A melee mob on an island of one cell in water (it cannot move; projectiles can reach)."""
    wall_around(state, pos, block=W)
    put_mob(state, MobType.MELEE, pos, type_id=type_id)


@pytest.mark.parametrize("kind, intelligence, dexterity", [
    (ProjectileType.ARROW2, 1, 1), (ProjectileType.FIREBALL, 3, 1)])
def test_player_projectile_kills_a_zombie(kind, intelligence, dexterity):
    state = blank_state()
    state.player_intelligence, state.player_dexterity = intelligence, dexterity
    moat_zombie(state)
    put_projectile(state, (24, 26), (0, 1), kind, player=True)
    rng = draws(7)
    mobs.update(state, SETTINGS, rng)     # (24, 27)
    mobs.update(state, SETTINGS, rng)     # (24, 28)
    assert state.melee_mobs.mask[0][0]
    mobs.update(state, SETTINGS, rng)     # strikes (24, 29) -> the zombie at (24, 30)?
    mobs.update(state, SETTINGS, rng)
    # arrow2 does 5 (zombie health 5); a fireball 3 x (1 + 0.5 * 2) = 6 fire
    assert not state.melee_mobs.mask[0][0]
    assert not any(state.player_projectiles.mask[0])
    assert state.monsters_killed[0] == 1
    assert state.achievements[Achievement.DEFEAT_ZOMBIE]
    assert not state.mob_map[0].any()


def test_enchanted_arrow_against_a_knights_defence():
    state = blank_state(level=4)
    state.player_dexterity, state.bow_enchantment = 3, 1
    moat_zombie(state, type_id=4)          # knight: 12 health, 50% physical defence
    put_projectile(state, (24, 29), (0, 1), ProjectileType.ARROW2, player=True)
    mobs.update(state, SETTINGS, draws())
    # (5 physical + 2.5 fire) x 1.4 = (7, 3.5): 3.5 + 3.5 through the defence
    assert state.melee_mobs.health[4][0] == pytest.approx(12 - 7.0)
    assert state.melee_mobs.mask[4][0] and state.monsters_killed[4] == 0
    assert not state.player_projectiles.mask[4][0]


def test_projectile_kill_of_a_passive_mob_does_not_feed():
    state = blank_state()
    state.player_food = 3
    wall_around(state, (24, 30), block=W)
    put_mob(state, MobType.PASSIVE, (24, 30))           # a cow, 3 health
    put_projectile(state, (24, 29), (0, 1), ProjectileType.ARROW2, player=True)
    mobs.update(state, SETTINGS, draws())
    assert not state.passive_mobs.mask[0][0]
    assert state.player_food == 3 and not state.achievements[Achievement.EAT_COW]
    assert state.monsters_killed[0] == 0
    # a melee blow may eat it
    put_mob(state, MobType.PASSIVE, (24, 25))
    hit, killed = mobs.attack_mob(state, 24, 25, (8.0, 0.0, 0.0), can_eat=True)
    assert hit and killed and state.player_food == 9 and state.achievements[Achievement.EAT_COW]


# ---------------------------------------------------------------------------------------------
# Storage: the slots are lists, the health float32 as upstream's array keeps it

def test_mob_health_is_rounded_as_a_float32_array_stores_it():
    """Blows whose damage a float32 cannot hold exactly: the health kept after each is what
    upstream's float32 array would hold (numpy's float32 store of the same difference), and the
    rounding did happen (the unrounded difference differs)."""
    state = blank_state(level=4)
    moat_zombie(state, type_id=4)                       # a knight: 12 health, 50% physical defence
    array = np.array([12.0], np.float32)
    rounded = 0
    for blow in (0.1, 1 / 3, 0.7, 2.2, 1e-3):
        hit, killed = mobs.attack_mob(state, 24, 30, (blow, 0.0, 0.0), False)
        assert hit and not killed
        exact = float(array[0]) - 0.5 * blow
        array[0] = exact
        kept = state.melee_mobs.health[4][0]
        assert type(kept) is float and kept == float(array[0])
        rounded += kept != exact
    assert rounded > 0
    assert state.melee_mobs.arrays()["health"].dtype == np.float32


def test_slot_lists_convert_to_and_from_upstreams_arrays():
    state = blank_state(level=2)
    put_mob(state, MobType.MELEE, (20, 21), type_id=2, slot=1, health=3.3, cooldown=-4)
    melee = state.melee_mobs
    arrays = melee.arrays()
    assert arrays["position"].shape == (NUM_LEVELS, 3, 2) and arrays["position"].dtype == np.int32
    assert arrays["mask"].dtype == bool and arrays["mask"].sum() == 1 and arrays["mask"][2, 1]
    assert arrays["position"][2, 1].tolist() == [20, 21] and arrays["type_id"][2, 1] == 2
    assert arrays["health"][2, 1] == np.float32(3.3) and arrays["attack_cooldown"][2, 1] == -4
    back = Mobs.from_arrays(**arrays)
    assert back == melee and back.position[2][1] == (20, 21)
    assert type(back.health[2][1]) is float and type(back.type_id[2][1]) is int
    copy = state.copy()                        # a deep copy: the slots are the copy's own
    copy.melee_mobs.mask[2][1] = False
    copy.melee_mobs.position[2][1] = (0, 0)
    assert melee.mask[2][1] and melee.position[2][1] == (20, 21)


# ---------------------------------------------------------------------------------------------
# Despawning

def test_mobs_beyond_the_despawn_distance_vanish():
    state = blank_state()
    put_mob(state, MobType.MELEE, (24, 38))             # 14 away: despawns
    put_mob(state, MobType.RANGED, (24, 11))            # 13 away: stays
    put_mob(state, MobType.PASSIVE, (10, 24))           # 14 away: despawns
    state.ranged_mobs.attack_cooldown[0][0] = 100
    mobs.update(state, SETTINGS, draws())
    assert not state.melee_mobs.mask[0][0] and not state.passive_mobs.mask[0][0]
    assert state.ranged_mobs.mask[0][0]
    assert mob_map_is_exact(state)
    # the boss level keeps its monsters, and spawning off keeps everything
    state = blank_state(level=8)
    put_mob(state, MobType.MELEE, (24, 40))
    mobs.update(state, SETTINGS, draws())
    assert state.melee_mobs.mask[8][0]
    state = blank_state()
    put_mob(state, MobType.MELEE, (24, 40))
    mobs.update(state, Settings(spawning=False), draws())
    assert state.melee_mobs.mask[0][0]


# ---------------------------------------------------------------------------------------------
# Spawning

def test_add_mob_places_a_named_mob_until_its_class_is_full():
    """``mobs.add_mob`` (the scenarios' way to place a mob): the named mob's class and type, its
    type's full health, cooldown 0, the mob map set; False (and nothing changed) on a taken,
    solid or off-map cell and once the class's slots are full."""
    state = blank_state(level=3, player=(24, 24))
    state.melee_mobs.attack_cooldown[3] = [4] * 3    # a dead slot's cooldown is not inherited
    assert mobs.add_mob(state, "knight", (20, 21))
    melee = state.melee_mobs
    assert melee.mask[3][0] and tuple(melee.position[3][0]) == (20, 21)
    assert melee.type_id[3][0] == MOB_NAMES[MobType.MELEE].index("knight") == 4
    assert melee.health[3][0] == MOB_TYPE_HEALTH_MAPPING[4][MobType.MELEE] == 12.0
    assert melee.attack_cooldown[3][0] == 0 and state.mob_map[3, 20, 21]
    assert mobs.add_mob(state, "snail", (21, 21))
    assert state.passive_mobs.mask[3][0] and state.passive_mobs.type_id[3][0] == 2
    assert state.passive_mobs.health[3][0] == MOB_TYPE_HEALTH_MAPPING[2][MobType.PASSIVE] == 6.0
    assert mobs.add_mob(state, "deep thing", (22, 21))
    assert state.ranged_mobs.type_id[3][0] == 5 and state.ranged_mobs.health[3][0] == 4.0
    before = (melee.arrays()["mask"], state.mob_map.copy())
    state.map[3, 10, 10] = BlockType.STONE
    for cell in ((20, 21), (24, 24), (10, 10), (-1, 5), (48, 0)):   # mob, player, stone, off
        assert not mobs.add_mob(state, "zombie", cell)
    assert (melee.arrays()["mask"] == before[0]).all() and (state.mob_map == before[1]).all()
    assert mob_map_is_exact(state)
    free = [(30, c) for c in range(10, 40)]
    placed = sum(mobs.add_mob(state, "zombie", cell) for cell in free)
    assert placed == len(melee.mask[3]) - 1 and all(melee.mask[3])   # one slot was the knight
    assert not state.mob_map[3, 30, 10 + placed]
    assert not any(melee.mask[0])                   # only the player's level
    with pytest.raises(ValueError):
        mobs.add_mob(state, "dragon", (31, 31))


def spawn_rate(state_maker, kind, trials=4000, seed=0):
    rng = draws(seed)
    spawned = 0
    for _ in range(trials):
        state = state_maker()
        mobs.spawn(state, SETTINGS, rng)
        group = {MobType.MELEE: state.melee_mobs, MobType.PASSIVE: state.passive_mobs,
                 MobType.RANGED: state.ranged_mobs}[kind]
        spawned += int(sum(group.mask[state.player_level]))
    return spawned / trials


def within(rate, p, trials=4000):
    return abs(rate - p) < 4 * np.sqrt(p * (1 - p) / trials) + 1e-9


def test_spawn_chances_by_day_night_and_clearing():
    day = blank_state
    assert within(spawn_rate(day, MobType.PASSIVE), 0.1)
    assert within(spawn_rate(day, MobType.MELEE), 0.02 * 3)      # uncleared: x3
    assert within(spawn_rate(day, MobType.RANGED), 0.05 * 3)

    def cleared():
        state = blank_state()
        state.monsters_killed[0] = 8
        return state
    assert within(spawn_rate(cleared, MobType.MELEE), 0.02)

    def night():
        state = blank_state()
        state.light_level = 0.0
        return state
    assert within(spawn_rate(night, MobType.MELEE), (0.02 + 0.1) * 3)

    def ice_realm():
        return blank_state(level=7)
    assert spawn_rate(ice_realm, MobType.PASSIVE, trials=500) == 0.0


def test_spawn_places_respect_distances_caps_and_types():
    state = blank_state(level=2)
    rng = draws(8)
    for _ in range(400):
        mobs.spawn(state, SETTINGS, rng)
        for kind, group, cap in ((MobType.PASSIVE, state.passive_mobs, 3),
                                 (MobType.MELEE, state.melee_mobs, 3),
                                 (MobType.RANGED, state.ranged_mobs, 2)):
            live = np.flatnonzero(group.mask[2])
            assert len(live) <= cap
            for slot in live:
                row, col = group.position[2][slot]
                distance = np.hypot(row - 24, col - 24)
                assert distance < 14 and distance > (3 if kind == MobType.PASSIVE else 9)
                assert group.type_id[2][slot] == FLOOR_MOB_MAPPING[2][kind]
                assert group.health[2][slot] == MOB_TYPE_HEALTH_MAPPING[FLOOR_MOB_MAPPING[2][kind]][kind]
    assert sum(state.passive_mobs.mask[2]) == 3 and sum(state.melee_mobs.mask[2]) == 3
    assert sum(state.ranged_mobs.mask[2]) == 2
    assert mob_map_is_exact(state)
    assert not state.mob_map[[0, 1, 3]].any()


def test_spawn_only_on_allowed_blocks_and_deep_things_in_water():
    state = random_terrain(5, seed=3)
    rng = draws(9)
    for _ in range(300):
        mobs.spawn(state, SETTINGS, rng)
        for group, allowed in ((state.ranged_mobs, {W}), (state.melee_mobs, {G}),
                               (state.passive_mobs, {G})):
            for slot in np.flatnonzero(group.mask[5]):
                row, col = group.position[5][slot]
                assert state.map[5, row, col] in allowed
        # empty the level again now and then so that spawning goes on
        if rng.random() < 0.2:
            for group in (state.ranged_mobs, state.melee_mobs, state.passive_mobs):
                group.mask[5] = [False] * len(group.mask[5])
            state.mob_map[5] = False
    state = blank_state(level=5)                         # no water: no deep thing
    for _ in range(200):
        mobs.spawn(state, SETTINGS, rng)
    assert not any(state.ranged_mobs.mask[5]) and any(state.melee_mobs.mask[5])


# ---------------------------------------------------------------------------------------------
# The necromancer

def boss_state() -> State:
    state = blank_state(level=8, block=BlockType.PATH)
    state.map[8, 24, 20] = BlockType.NECROMANCER
    for cell in ((20, 24), (24, 28), (28, 24), (24, 18), (24, 16), (40, 40)):
        state.map[8, cell[0], cell[1]] = BlockType.GRAVE
    return state


def test_necromancer_vulnerability_waves_and_progress():
    state = boss_state()
    assert mobs.is_boss_vulnerable(state)
    assert mobs.damage_necromancer(state)
    assert state.boss_progress == 1
    assert state.boss_timesteps_to_spawn_this_round == BOSS_FIGHT_SPAWN_TURNS
    assert state.achievements[Achievement.DAMAGE_NECROMANCER]
    assert not mobs.is_boss_vulnerable(state) and mobs.is_boss_spawn_wave(state)
    assert not mobs.damage_necromancer(state) and state.boss_progress == 1
    rng = draws(10)
    for _ in range(BOSS_FIGHT_SPAWN_TURNS):
        mobs.boss_logic(state)
        mobs.spawn(state, SETTINGS, rng)
    assert state.boss_timesteps_to_spawn_this_round == 0 and not mobs.is_boss_spawn_wave(state)
    # the wave filled the graves within 6 with the monsters of level 1 (progress 1): orcs
    live = [(group, slot) for group in (state.melee_mobs, state.ranged_mobs)
            for slot in np.flatnonzero(group.mask[8])]
    assert len(live) == 4 and not any(state.passive_mobs.mask[8])
    for group, slot in live:
        row, col = group.position[8][slot]
        assert state.map[8, row, col] == BlockType.GRAVE and np.hypot(row - 24, col - 24) <= 6
        assert group.type_id[8][slot] == FLOOR_MOB_MAPPING[1][MobType.MELEE] == 2
    assert not mobs.is_boss_vulnerable(state)
    for group, slot in live:                             # kill them: vulnerable again
        row, col = group.position[8][slot]
        assert mobs.attack_mob(state, int(row), int(col), (100.0, 0.0, 0.0), True)[1]
    for _ in range(50):                                  # no wave, no spawning
        mobs.spawn(state, SETTINGS, rng)
    assert mobs.is_boss_vulnerable(state)
    state.boss_progress = 7
    assert mobs.damage_necromancer(state) and mobs.has_beaten_boss(state)
    mobs.boss_logic(state)
    assert state.achievements[Achievement.DEFEAT_NECROMANCER]


# ---------------------------------------------------------------------------------------------
# Speed

def test_update_speed_with_a_few_mobs():
    state = blank_state()
    for slot, pos in enumerate(((24, 30), (20, 20), (28, 26))):
        put_mob(state, MobType.MELEE, pos, slot=slot)
    for slot, pos in enumerate(((30, 30), (16, 24))):
        put_mob(state, MobType.PASSIVE, pos, slot=slot)
    for slot, pos in enumerate(((24, 16), (32, 24))):
        put_mob(state, MobType.RANGED, pos, slot=slot)
    rng = draws(11)
    base = state.copy()
    times = []
    for _ in range(5):
        state = base.copy()
        start = time.perf_counter()
        for _ in range(200):
            mobs.update(state, Settings(spawning=False), rng)
        times.append((time.perf_counter() - start) / 200)
    assert min(times) < 2e-3          # generous: a smoke check, the figure goes in the report


# ---------------------------------------------------------------------------------------------
# The package as the oracle, on turns that are deterministic given the state

@pytest.fixture(scope="module")
def upstream():
    pytest.importorskip("craftax")
    import jax
    import jax.numpy as jnp
    from craftax.craftax import craftax_state as cs
    from craftax.craftax.game_logic import spawn_mobs, update_mobs

    params, static = cs.EnvParams(), cs.StaticEnvParams()
    step = jax.jit(lambda key, s: update_mobs(key, s, params, static))

    def convert(value):
        if isinstance(value, bool):
            return jnp.asarray(value)
        if isinstance(value, float):
            return jnp.asarray(value, jnp.float32)
        if isinstance(value, int):
            return jnp.asarray(value, jnp.int32)
        return jnp.asarray(value)

    def to_upstream(state: State):
        fields = {}
        for name, value in vars(state).items():
            if isinstance(value, Mobs):
                value = cs.Mobs(**{k: jnp.asarray(v) for k, v in value.arrays().items()})
            elif isinstance(value, Inventory):
                value = cs.Inventory(**{k: convert(v) for k, v in vars(value).items()})
            else:
                value = convert(value)
            fields[name] = value
        return cs.EnvState(**fields, state_rng=jax.random.PRNGKey(0))

    def run(state: State, seed: int = 0) -> State:
        return State.from_upstream(step(jax.random.PRNGKey(seed), to_upstream(state)))

    def positions(key, s):
        """After update_mobs, and (separately) after spawn_mobs: the level's mob slots."""
        moved = update_mobs(key, s, params, static)
        spawned = spawn_mobs(s, jax.random.fold_in(key, 1), params, static)
        names = ("melee_mobs", "passive_mobs", "ranged_mobs")
        return ({name: getattr(moved, name).position[s.player_level] for name in names},
                {name: (getattr(spawned, name).position[s.player_level],
                        getattr(spawned, name).mask[s.player_level],
                        getattr(spawned, name).type_id[s.player_level]) for name in names})
    many = jax.jit(jax.vmap(positions, in_axes=(0, None)))

    def run_many(state: State, samples: int):
        """The live mobs' positions after one update, per sample: {(group, slot): (n, 2)}."""
        out = many(jax.random.split(jax.random.PRNGKey(1), samples), to_upstream(state))[0]
        return {(name, slot): np.asarray(out[name])[:, slot]
                for name, slot in live_slots(state)}

    def spawn_many(state: State, samples: int):
        """Per sample and class, the spawned mob's (row, col, type), or None."""
        out = many(jax.random.split(jax.random.PRNGKey(2), samples), to_upstream(state))[1]
        return {name: new_mobs(np.array(getattr(state, name).mask[state.player_level]),
                               *map(np.asarray, value))
                for name, value in out.items()}
    run.many, run.spawn_many = run_many, spawn_many
    return run


def new_mobs(before, positions, masks, types):
    """Per sample, the (row, col, type) of the mob in a slot that was empty before, or None."""
    out = []
    for position, mask, type_id in zip(positions, masks, types):
        fresh = np.flatnonzero(mask & ~before)
        out.append(None if fresh.size == 0 else
                   (int(position[fresh[0], 0]), int(position[fresh[0], 1]), int(type_id[fresh[0]])))
    return out


def live_slots(state: State):
    return [(name, int(slot)) for name in ("melee_mobs", "passive_mobs", "ranged_mobs")
            for slot in np.flatnonzero(getattr(state, name).mask[state.player_level])]


def assert_same_distribution(theirs: list, ours: list, what) -> None:
    """Two samples of the same size from one distribution: every outcome's frequency agrees
    within five standard errors of their difference (a rare outcome that one side never
    shows fails this, where a total-variation bound would let it through)."""
    n = len(theirs)
    a, b = {}, {}
    for outcome in theirs:
        a[outcome] = a.get(outcome, 0) + 1 / n
    for outcome in ours:
        b[outcome] = b.get(outcome, 0) + 1 / n
    for outcome in set(a) | set(b):
        p = (a.get(outcome, 0) + b.get(outcome, 0)) / 2
        bound = 5 * np.sqrt(2 * p * (1 - p) / n) + 1e-3
        assert abs(a.get(outcome, 0) - b.get(outcome, 0)) <= bound, (
            what, outcome, sorted(a.items(), key=str), sorted(b.items(), key=str))


def test_random_moves_follow_the_packages_probabilities(upstream):
    """Chasing (75%, along the longer axis, ties evenly), wandering, keeping a ranged
    distance (15% of turns): our next-position distributions against the package's."""
    state = blank_state()
    put_mob(state, MobType.MELEE, (21, 28), slot=0)        # off-axis: chases along columns
    put_mob(state, MobType.MELEE, (20, 20), slot=1)        # a tie: either axis
    put_mob(state, MobType.MELEE, (24, 36), slot=2)        # 12 away: wanders only
    put_mob(state, MobType.PASSIVE, (30, 30))
    put_mob(state, MobType.RANGED, (24, 16), slot=0, cooldown=9)   # far: comes closer
    put_mob(state, MobType.RANGED, (26, 25), slot=1, cooldown=9)   # too close: backs off
    samples = 3000
    theirs = upstream.many(state, samples)
    ours = {key: [] for key in theirs}
    rng = draws(12)
    for _ in range(samples):
        copy = state.copy()
        mobs.update(copy, SETTINGS, rng)
        for name, slot in ours:
            ours[(name, slot)].append(tuple(getattr(copy, name).position[0][slot]))
    for key, positions in theirs.items():
        assert_same_distribution([tuple(p) for p in positions.tolist()],
                                 [(int(p[0]), int(p[1])) for p in ours[key]], key)


def assert_same_outcome(ours: State, theirs: State) -> None:
    assert ours.player_health == pytest.approx(theirs.player_health, abs=1e-4)
    assert ours.is_sleeping == theirs.is_sleeping and ours.is_resting == theirs.is_resting
    np.testing.assert_array_equal(ours.achievements, theirs.achievements)
    np.testing.assert_array_equal(ours.mob_map, theirs.mob_map)
    np.testing.assert_array_equal(ours.map, theirs.map)
    np.testing.assert_array_equal(ours.monsters_killed, theirs.monsters_killed)
    level = ours.player_level
    for name in ("melee_mobs", "passive_mobs", "ranged_mobs", "mob_projectiles",
                 "player_projectiles"):
        a, b = getattr(ours, name).arrays(), getattr(theirs, name).arrays()
        np.testing.assert_array_equal(a["mask"], b["mask"], err_msg=name)
        live = a["mask"][level]
        np.testing.assert_array_equal(a["position"][level][live], b["position"][level][live],
                                      err_msg=name)
        np.testing.assert_allclose(a["health"][level][live], b["health"][level][live], atol=1e-4)
        np.testing.assert_array_equal(a["type_id"][level][live], b["type_id"][level][live])
        if name in ("melee_mobs", "ranged_mobs"):
            np.testing.assert_array_equal(a["attack_cooldown"][level], b["attack_cooldown"][level])
    live = np.array(ours.mob_projectiles.mask[level])
    np.testing.assert_array_equal(ours.mob_projectile_directions[level][live],
                                  theirs.mob_projectile_directions[level][live])


def deterministic_scenarios():
    """States whose next update_mobs does not depend on the random draws."""
    # a sleeping, armoured player next to a zombie; a troll on the boss level
    a = blank_state()
    zombie_in_a_pocket(a)
    a.is_sleeping = True
    a.inventory.armour[:] = (1, 2, 0, 1)
    a.armour_enchantments[:] = (1, 0, 2, 0)
    b = blank_state(level=8)
    wall_around(b, (23, 24), keep={(24, 24)})
    put_mob(b, MobType.MELEE, (23, 24), type_id=5)
    # a skeleton in range shooting; an arrow hitting the player; a fireball breaking a furnace
    c = blank_state()
    put_mob(c, MobType.RANGED, (24, 19))
    put_projectile(c, (23, 24), (1, 0), ProjectileType.ARROW, slot=1)
    put_projectile(c, (10, 10), (0, -1), ProjectileType.FIREBALL2, slot=2)
    c.map[0, 10, 9] = BlockType.FURNACE
    # player projectiles: an enchanted arrow into a knight, a fireball into a moated zombie,
    # an iceball into a moated cow, an arrow into a stone
    d = blank_state(level=4)
    d.player_dexterity, d.player_intelligence, d.bow_enchantment = 2, 4, 2
    wall_around(d, (24, 30), block=W)
    put_mob(d, MobType.MELEE, (24, 30), type_id=4, slot=0)             # knight, 12 health
    put_projectile(d, (24, 29), (0, 1), ProjectileType.ARROW2, slot=0, player=True)
    wall_around(d, (20, 30), block=W)
    put_mob(d, MobType.MELEE, (20, 30), type_id=4, slot=1, health=2.0)
    put_projectile(d, (20, 28), (0, 1), ProjectileType.FIREBALL, slot=1, player=True)
    put_projectile(d, (30, 10), (-1, 0), ProjectileType.ARROW2, slot=2, player=True)
    d.map[4, 29, 10] = S
    # despawning: monsters 14+ away, walled in
    e = blank_state()
    for slot, pos in enumerate(((24, 38), (10, 24), (40, 40))):
        wall_around(e, pos)
        put_mob(e, MobType.MELEE, pos, slot=slot)
    return [a, b, c, d, e]


def test_deterministic_turns_match_the_package(upstream):
    for index, state in enumerate(deterministic_scenarios()):
        theirs = upstream(state.copy(), seed=index)
        ours = state.copy()
        mobs.update(ours, SETTINGS, draws(index))
        assert_same_outcome(ours, theirs)


def test_spawning_follows_the_packages_probabilities(upstream):
    """Per class: how often a mob spawns, where (a few allowed cells, some too near or too
    far), and of which kind, at dusk on an uncleared level; and on the boss level in a wave."""
    dusk = blank_state(block=BlockType.STONE)
    dusk.light_level, dusk.monsters_killed[0] = 0.4, 5
    for cell, block in (((24, 27), G), ((24, 30), G), ((13, 24), BlockType.PATH), ((30, 33), G),
                        ((34, 24), BlockType.SAND), ((24, 40), G), ((20, 20), BlockType.FIRE_GRASS),
                        ((35, 28), G)):
        dusk.map[0, cell[0], cell[1]] = block
    put_mob(dusk, MobType.MELEE, (30, 33), slot=1)      # occupied: no spawning there
    boss = boss_state()
    boss.boss_progress, boss.boss_timesteps_to_spawn_this_round = 3, 2
    put_mob(boss, MobType.MELEE, (20, 24), type_id=3, slot=0)
    samples = 3000
    for state in (dusk, boss):
        theirs = upstream.spawn_many(state, samples)
        rng = draws(13)
        ours = {name: [] for name in theirs}
        for _ in range(samples):
            copy = state.copy()
            mobs.spawn(copy, SETTINGS, rng)
            for name in theirs:
                level = state.player_level
                group, before = getattr(copy, name).arrays(), getattr(state, name).mask[level]
                ours[name] += new_mobs(np.array(before), [group["position"][level]],
                                       [group["mask"][level]], [group["type_id"][level]])
        for name in theirs:
            assert_same_distribution(theirs[name], ours[name], name)
