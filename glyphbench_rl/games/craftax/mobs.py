"""Craftax's mobs: upstream ``craftax`` 1.6.1's ``update_mobs``, ``spawn_mobs`` and
``boss_logic`` (``craftax/craftax/game_logic.py``) and their helpers
(``util/game_logic_utils.py``), as small loops over the few live mobs of the player's level.

``update(state, settings, draws)`` moves, in upstream's order: melee mobs (chase, attack),
passive mobs (wander), ranged mobs (keep their distance, shoot), mob projectiles, player
projectiles. ``spawn(state, settings, draws)`` spawns at most one mob of each class.
``boss_logic`` and ``damage_necromancer`` are the necromancer's rules, ``attack_mob`` and
``hurt_player`` / ``damage_to_player`` the damage rules; they exist only here, and the step
(``rules``) and the view (``is_boss_vulnerable``) import them. ``add_mob`` places a named mob
(for scenarios). The mob tables are ``bestiary``'s; solid blocks, level and boss-fight
constants and the player's side of combat (armour, the sleeping factor) are ``tables``'.

Randomness comes from ``draws``, one draw per choice that upstream makes at random, and only
when the choice matters (upstream draws for every slot, live or not; we draw for live mobs).
Mob slots are Python lists indexed ``[level][slot]`` (``state.Mobs``); only the player's level
moves, as upstream.
"""

from __future__ import annotations

import numpy as np

from .bestiary import (FLOOR_MOB_MAPPING, FLOOR_MOB_SPAWN_CHANCE, MELEE_ATTACK_COOLDOWN,
                       MOB_ACHIEVEMENT_MAP, MOB_NAMES, MOB_TYPE_DAMAGE_MAPPING,
                       MOB_TYPE_DEFENCE_MAPPING, MOB_TYPE_ENTERABLE, MOB_TYPE_HEALTH_MAPPING,
                       PROJECTILE_DAMAGE, RANGED_ATTACK_COOLDOWN,
                       RANGED_MOB_TYPE_TO_PROJECTILE_TYPE_MAPPING)
from .state import MAP_SIZE, MAX_MELEE, MAX_PASSIVE, MAX_RANGED, Mobs, Settings, State, float32
from .tables import (ARMOUR_DEFENCE_PER_TIER, BOSS_FIGHT_EXTRA_DAMAGE, BOSS_FIGHT_SPAWN_TURNS,
                     BOSS_LEVEL, COW_FOOD, ENCHANTED_ARMOUR_DEFENCE, IS_SOLID,
                     MONSTERS_KILLED_TO_CLEAR_LEVEL, SLEEPING_MELEE_FACTOR, Achievement, BlockType,
                     MobType, ProjectileType, max_food)

# A mob projectile that flies into these breaks them (they become PATH).
_BREAKABLE = (int(BlockType.CRAFTING_TABLE), int(BlockType.FURNACE))

# Where mobs spawn (upstream's all_valid_blocks_map), and the boss level's graves.
_SPAWN_GROUND = np.zeros(len(BlockType), bool)
_SPAWN_GROUND[[BlockType.GRASS, BlockType.PATH, BlockType.FIRE_GRASS, BlockType.ICE_GRASS]] = True
_SPAWN_WATER = np.zeros(len(BlockType), bool)
_SPAWN_WATER[BlockType.WATER] = True
_SPAWN_GRAVES = np.zeros(len(BlockType), bool)
_SPAWN_GRAVES[[BlockType.GRAVE, BlockType.GRAVE2, BlockType.GRAVE3]] = True
_DEEP_THING = 5   # the ranged type that spawns in water ("hack for deep thing" upstream)

# Upstream's DIRECTIONS[1:5]: left, right, up, down as (row, col) steps.
_STEPS = ((0, -1), (0, 1), (-1, 0), (1, 0))
_ARROWS = (int(ProjectileType.ARROW), int(ProjectileType.ARROW2))
# the classes as plain ints: an enum member's lookup costs as much as a line of arithmetic
_PASSIVE, _MELEE, _RANGED = int(MobType.PASSIVE), int(MobType.MELEE), int(MobType.RANGED)
_SPELLS = (int(ProjectileType.FIREBALL), int(ProjectileType.ICEBALL))
# a new mob's health by [type][class], as upstream's float32 array holds it (rounded once here)
_FULL_HEALTH = tuple(tuple(float32(health) for health in row) for row in MOB_TYPE_HEALTH_MAPPING)


# ---------------------------------------------------------------------------------------------
# The necromancer (util/game_logic_utils.py, game_logic.boss_logic, do_action's boss part)

def is_fighting_boss(state: State) -> bool:
    return state.player_level == BOSS_LEVEL


def is_boss_spawn_wave(state: State) -> bool:
    return state.player_level == BOSS_LEVEL and state.boss_timesteps_to_spawn_this_round >= 1


def is_boss_vulnerable(state: State) -> bool:
    """No melee or ranged mob alive on the player's level and the spawn wave is over."""
    level = state.player_level
    return (True not in state.melee_mobs.mask[level]
            and True not in state.ranged_mobs.mask[level]
            and state.boss_timesteps_to_spawn_this_round <= 0)


def has_beaten_boss(state: State) -> bool:
    return state.boss_progress >= BOSS_LEVEL


def boss_logic(state: State) -> None:
    """Upstream's boss_logic (the step calls it before the player moves): the defeat
    achievement once the boss's progress is full, and one turn off the spawn wave's clock
    on the boss level."""
    if has_beaten_boss(state):
        state.achievements[Achievement.DEFEAT_NECROMANCER] = True
    if state.player_level == BOSS_LEVEL:
        state.boss_timesteps_to_spawn_this_round -= 1


def damage_necromancer(state: State) -> bool:
    """The player strikes the necromancer block (do_action): when it is vulnerable, one step of
    progress, a new spawn wave of BOSS_FIGHT_SPAWN_TURNS turns, and DAMAGE_NECROMANCER."""
    if not (is_fighting_boss(state) and is_boss_vulnerable(state)):
        return False
    state.boss_progress += 1
    state.boss_timesteps_to_spawn_this_round = BOSS_FIGHT_SPAWN_TURNS
    state.achievements[Achievement.DAMAGE_NECROMANCER] = True
    return True


# ---------------------------------------------------------------------------------------------
# Damage (util/game_logic_utils.py)

def damage_to_player(state: State, damage: tuple) -> float:
    """Upstream's get_damage_done_to_player: armour blocks 10% physical damage per tier (summed
    over the four pieces), each fire (ice) enchanted piece 20% of fire (ice) damage; damage is
    x1.5 on the boss level."""
    physical, fire, ice = damage
    scale = 1.0 + BOSS_FIGHT_EXTRA_DAMAGE if state.player_level == BOSS_LEVEL else 1.0
    lost = (1.0 - ARMOUR_DEFENCE_PER_TIER * sum(state.inventory.armour.tolist())) * physical * scale
    if not (fire or ice):
        # (most blows: the elements' terms are +0.0 (a defence is at most 0.8), and the sum
        # (0 + lost + 0.0 + 0.0) is ``lost`` itself; the enchantments need not be read)
        return lost
    enchant = state.armour_enchantments.tolist()
    return sum((lost, (1.0 - ENCHANTED_ARMOUR_DEFENCE * enchant.count(1)) * fire * scale,
                (1.0 - ENCHANTED_ARMOUR_DEFENCE * enchant.count(2)) * ice * scale))


def hurt_player(state: State, damage: tuple, melee: bool = False) -> float:
    """Damage the player by a (physical, fire, ice) vector through the armour; the blow wakes
    them. A melee blow on a sleeping player does x3.5 damage and earns WAKE_UP (upstream's
    melee mobs do both; projectiles do neither, they only wake). Returns the health lost."""
    if melee and state.is_sleeping:
        damage = tuple(SLEEPING_MELEE_FACTOR * x for x in damage)
        state.achievements[Achievement.WAKE_UP] = True
    lost = damage_to_player(state, damage)
    state.player_health -= lost
    state.is_sleeping = False
    state.is_resting = False
    return lost


def _mob_damage(damage: tuple, defence: tuple) -> float:
    """Upstream's get_damage: each element of the damage less the mob's defence against it."""
    return sum((1.0 - d) * x for x, d in zip(damage, defence))


def _attack_class(state: State, mobs: Mobs, kind: int, row: int, col: int, damage: tuple,
                  achieve: bool) -> tuple[bool, bool]:
    """Damage the first live mob of one class at (row, col); (hit, killed). The health kept
    is rounded to float32, as upstream's array keeps it; the kill is decided on the difference
    before rounding."""
    level = state.player_level
    mask, position = mobs.mask[level], mobs.position[level]
    cell = (row, col)
    for slot, alive in enumerate(mask):
        if alive and position[slot] == cell:
            type_id = mobs.type_id[level][slot]
            health = mobs.health[level][slot] - _mob_damage(
                damage, MOB_TYPE_DEFENCE_MAPPING[type_id][kind])
            mobs.health[level][slot] = float32(health)
            if health > 0:
                return True, False
            mask[slot] = False
            if achieve:
                state.achievements[MOB_ACHIEVEMENT_MAP[kind][type_id]] = True
            return True, True
    return False, False


def attack_mob(state: State, row: int, col: int, damage: tuple, can_eat: bool) -> tuple[bool, bool]:
    """Upstream's attack_mob: damage whatever mob stands at (row, col) by a (physical, fire,
    ice) vector less its defence; a kill clears the mob map, counts a monster (melee, ranged)
    and earns its achievement; a passive kill feeds the player (+6 food, hunger reset) and
    earns its achievement only when ``can_eat`` (the player's melee blow, not a projectile).
    Returns (hit, killed)."""
    hit, killed = _attack_class(state, state.melee_mobs, MobType.MELEE, row, col, damage, True)
    monster = killed
    if not hit:
        hit, killed = _attack_class(state, state.passive_mobs, MobType.PASSIVE, row, col, damage,
                                    can_eat)
        if killed and can_eat:
            state.player_food = min(max_food(state.player_dexterity), state.player_food + COW_FOOD)
            state.player_hunger = 0.0
    if not hit:
        hit, killed = _attack_class(state, state.ranged_mobs, MobType.RANGED, row, col, damage,
                                    True)
        monster = killed
    if killed:
        state.mob_map[state.player_level, row, col] = False
        if monster:
            state.monsters_killed[state.player_level] += 1
    return hit, killed


# ---------------------------------------------------------------------------------------------
# Movement
#
# A class's mobs move in one loop (``_move_melee_mobs`` ...: upstream's rule for one mob, for
# each live slot in order), given the player's cell, the draws' next float (``random``: a mover
# draws ``int(random() * n)``, ``draws.below(n)`` without its call) and the despawn limit. The
# slots are lists (``state.Mobs``); the mob map, numpy, is read by ``.item`` and written only
# where it changes. A loop writes upstream's is_position_in_bounds_not_in_mob_not_colliding out
# (a call costs as much as the test): on the map, not the player's cell, no mob there, and a
# block the mob may enter (``bestiary.MOB_TYPE_ENTERABLE``).

_FAR = 1 << 30      # a despawn limit no distance reaches
_ROWS, _COLS = MAP_SIZE     # every state's map (state.py; world generation makes them so)


def _toward(random, d_row: int, d_col: int) -> tuple[int, int]:
    """One step toward the player along the axis of the larger distance (a tie: either axis,
    evenly, one draw of ``random``), upstream's player_move_direction."""
    a_row, a_col = abs(d_row), abs(d_col)
    if a_row > a_col or (a_row == a_col and int(random() * 2) == 0):
        return (d_row > 0) - (d_row < 0), 0
    return 0, (d_col > 0) - (d_col < 0)


def _move_melee_mobs(state: State, mobs: Mobs, p_row: int, p_col: int, random,
                     limit: int) -> None:
    """Upstream's melee mob move, for each live slot in order: chase the player (within 10,
    or always on the boss level: 75% of turns) or wander; hit an adjacent player when the
    cooldown is over; vanish at ``limit`` or more from the player. Dead slots count their
    cooldown down too, as upstream (a mob spawned into a slot inherits it)."""
    level = state.player_level
    blocks, occupied, chases_anywhere = state.map, state.mob_map, level == BOSS_LEVEL
    mask, positions = mobs.mask[level], mobs.position[level]
    types, cooldowns = mobs.type_id[level], mobs.attack_cooldown[level]
    for slot, alive in enumerate(mask):
        cooldown = cooldowns[slot]
        if not alive:
            cooldowns[slot] = cooldown - 1
            continue
        row, col = positions[slot]
        type_id = types[slot]
        d_row, d_col = p_row - row, p_col - col
        distance = abs(d_row) + abs(d_col)
        if (distance < 10 or chases_anywhere) and random() < 0.75:
            step_row, step_col = _toward(random, d_row, d_col)
        else:
            step_row, step_col = _STEPS[int(random() * 4)]
        if distance == 1 and cooldown <= 0:
            hurt_player(state, MOB_TYPE_DAMAGE_MAPPING[type_id][_MELEE], True)    # (melee)
            cooldowns[slot] = MELEE_ATTACK_COOLDOWN
        else:
            cooldowns[slot] = cooldown - 1
            new_row, new_col = row + step_row, col + step_col
            if (0 <= new_row < _ROWS and 0 <= new_col < _COLS
                    and (new_row != p_row or new_col != p_col)
                    and not occupied.item(level, new_row, new_col)
                    and MOB_TYPE_ENTERABLE[type_id][_MELEE][blocks.item(level, new_row, new_col)]):
                positions[slot] = (new_row, new_col)
                occupied[level, row, col] = False
                occupied[level, new_row, new_col] = True
                row, col = new_row, new_col
        if distance >= limit:
            mask[slot] = False
            occupied[level, row, col] = False


def _move_passive_mobs(state: State, mobs: Mobs, p_row: int, p_col: int, random,
                       limit: int) -> None:
    """Upstream's passive mob move, for each live slot in order: wander, each of the four
    steps with 1/8, else stay (upstream's DIRECTIONS[1:9]); vanish at ``limit`` or more from
    the player."""
    level = state.player_level
    blocks, occupied = state.map, state.mob_map
    mask, positions, types = mobs.mask[level], mobs.position[level], mobs.type_id[level]
    for slot, alive in enumerate(mask):
        if not alive:
            continue
        row, col = positions[slot]
        choice = int(random() * 8)
        distance = abs(p_row - row) + abs(p_col - col)
        if choice < 4:
            step_row, step_col = _STEPS[choice]
            new_row, new_col = row + step_row, col + step_col
            enterable = MOB_TYPE_ENTERABLE[types[slot]][_PASSIVE]
            if (0 <= new_row < _ROWS and 0 <= new_col < _COLS
                    and (new_row != p_row or new_col != p_col)
                    and not occupied.item(level, new_row, new_col)
                    and enterable[blocks.item(level, new_row, new_col)]):
                positions[slot] = (new_row, new_col)
                occupied[level, row, col] = False
                occupied[level, new_row, new_col] = True
                row, col = new_row, new_col
        if distance >= limit:
            mask[slot] = False
            occupied[level, row, col] = False


def _move_ranged_mobs(state: State, mobs: Mobs, p_row: int, p_col: int, random,
                      limit: int) -> None:
    """Upstream's ranged mob move, for each live slot in order: keep a shooting distance (15%
    of turns: closer when 6+ away, back when 3 or less; else wander); shoot at range 4-5, or
    when it wants to back off but cannot; vanish at ``limit`` or more from the player. Dead
    slots count their cooldown down too."""
    level = state.player_level
    blocks, occupied = state.map, state.mob_map
    mask, positions = mobs.mask[level], mobs.position[level]
    types, cooldowns = mobs.type_id[level], mobs.attack_cooldown[level]
    for slot, alive in enumerate(mask):
        cooldown = cooldowns[slot]
        if not alive:
            cooldowns[slot] = cooldown - 1
            continue
        row, col = positions[slot]
        type_id = types[slot]
        d_row, d_col = p_row - row, p_col - col
        distance = abs(d_row) + abs(d_col)
        toward = _toward(random, d_row, d_col)
        too_close = distance <= 3
        if random() > 0.85 and (distance >= 6 or too_close):
            sign = -1 if too_close else 1
            new_row, new_col = row + sign * toward[0], col + sign * toward[1]
        else:
            step_row, step_col = _STEPS[int(random() * 4)]
            new_row, new_col = row + step_row, col + step_col
        can_move = (0 <= new_row < _ROWS and 0 <= new_col < _COLS
                    and (new_row != p_row or new_col != p_col)
                    and not occupied.item(level, new_row, new_col)
                    and MOB_TYPE_ENTERABLE[type_id][_RANGED][blocks.item(level, new_row, new_col)])
        if cooldown <= 0 and (4 <= distance <= 5 or (too_close and not can_move)):
            _shoot(state, level, row, col, toward,
                   RANGED_MOB_TYPE_TO_PROJECTILE_TYPE_MAPPING[type_id])
            cooldowns[slot] = RANGED_ATTACK_COOLDOWN
        else:
            cooldowns[slot] = cooldown - 1
            if can_move:
                positions[slot] = (new_row, new_col)
                occupied[level, row, col] = False
                occupied[level, new_row, new_col] = True
                row, col = new_row, new_col
        if distance >= limit:
            mask[slot] = False
            occupied[level, row, col] = False


def _shoot(state: State, level: int, row: int, col: int, direction: tuple, kind: int) -> None:
    """A mob projectile in the first free slot, if any (upstream's spawn_projectile)."""
    projectiles = state.mob_projectiles
    mask = projectiles.mask[level]
    if False not in mask:
        return
    slot = mask.index(False)
    projectiles.position[level][slot] = (row, col)
    mask[slot] = True
    projectiles.type_id[level][slot] = int(kind)
    state.mob_projectile_directions[level, slot] = direction


def _move_mob_projectiles(state: State, p_row: int, p_col: int) -> None:
    """Upstream's mob projectile move, for each live slot in order (a projectile shot this
    turn too): fly one cell; hit the player (on its cell or the next), stop at solid blocks
    (not water or lava), mobs and the map's edge; break a table or furnace in its way."""
    level = state.player_level
    blocks, occupied = state.map, state.mob_map
    projectiles = state.mob_projectiles
    mask, positions, kinds = (projectiles.mask[level], projectiles.position[level],
                              projectiles.type_id[level])
    steps = state.mob_projectile_directions[level].tolist()
    for slot, alive in enumerate(mask):
        if not alive:
            continue
        row, col = positions[slot]
        d_row, d_col = steps[slot]
        new_row, new_col = row + d_row, col + d_col
        hit_player = (row == p_row and col == p_col) or (new_row == p_row and new_col == p_col)
        flies_on = 0 <= new_row < _ROWS and 0 <= new_col < _COLS
        if flies_on:
            block = blocks.item(level, new_row, new_col)
            flies_on = not (hit_player or IS_SOLID[block]
                            or occupied.item(level, new_row, new_col))
            if block in _BREAKABLE:
                blocks[level, new_row, new_col] = BlockType.PATH
        if hit_player:
            hurt_player(state, PROJECTILE_DAMAGE[kinds[slot]])
        positions[slot] = (new_row, new_col)
        if not flies_on:
            mask[slot] = False


def player_projectile_damage(state: State, kind: int) -> tuple:
    """A player projectile's damage vector: an arrow gains half its physical damage as the
    bow's element (if enchanted) and scales with dexterity (+20% a point), a spell with
    intelligence (+50% a point)."""
    damage = list(PROJECTILE_DAMAGE[kind])
    if kind in _ARROWS:
        if state.bow_enchantment in (1, 2):
            damage[state.bow_enchantment] += damage[0] / 2
        scale = 1.0 + 0.2 * (state.player_dexterity - 1)
    elif kind in _SPELLS:
        scale = 1.0 + 0.5 * (state.player_intelligence - 1)
    else:
        scale = 1.0
    return tuple(x * scale for x in damage)


def _move_player_projectiles(state: State) -> None:
    """Upstream's player projectile move, for each live slot in order: strike a mob on its own
    cell (one stepped onto it), else on its next cell; fly on unless it struck, left the map
    or met a solid block (it crosses water and lava)."""
    level = state.player_level
    occupied = state.mob_map
    projectiles = state.player_projectiles
    mask, positions, kinds = (projectiles.mask[level], projectiles.position[level],
                              projectiles.type_id[level])
    steps = state.player_projectile_directions[level].tolist()
    for slot, alive in enumerate(mask):
        if not alive:
            continue
        row, col = positions[slot]
        d_row, d_col = steps[slot]
        new_row, new_col = row + d_row, col + d_col
        damage = player_projectile_damage(state, kinds[slot])
        on_map = 0 <= new_row < _ROWS and 0 <= new_col < _COLS
        hit = ((occupied.item(level, row, col) and attack_mob(state, row, col, damage, False)[0])
               or (on_map and occupied.item(level, new_row, new_col)
                   and attack_mob(state, new_row, new_col, damage, False)[0]))
        flies_on = not hit and on_map and not IS_SOLID[state.map.item(level, new_row, new_col)]
        positions[slot] = (new_row, new_col)
        if not flies_on:
            mask[slot] = False


def _count_down(group: Mobs, level: int) -> None:
    """A class with no live mob on the level: its cooldowns count down (as dead slots' do)."""
    group.attack_cooldown[level] = [cooldown - 1 for cooldown in group.attack_cooldown[level]]


def update(state: State, settings: Settings, draws) -> None:
    """Upstream's update_mobs on the player's level: melee, passive and ranged mobs in slot
    order, then mob projectiles, then the player's projectiles."""
    level = state.player_level
    melee, passive, ranged = state.melee_mobs, state.passive_mobs, state.ranged_mobs
    any_melee, any_ranged = True in melee.mask[level], True in ranged.mask[level]
    any_passive = True in passive.mask[level]
    shots, arrows = state.mob_projectiles.mask[level], state.player_projectiles.mask[level]
    if not (any_melee or any_passive or any_ranged or True in shots or True in arrows):
        _count_down(melee, level)
        _count_down(ranged, level)
        return
    p_row, p_col = state.player_position.tolist()
    random = draws.random
    # mobs at this Manhattan distance or more (measured before they move) vanish; upstream
    # keeps the boss level's monsters (not its passive mobs), and we keep all when spawning
    # is switched off
    despawn = settings.mob_despawn_distance if settings.spawning else _FAR
    monster_limit = _FAR if level == BOSS_LEVEL else despawn
    if any_melee:
        _move_melee_mobs(state, melee, p_row, p_col, random, monster_limit)
    else:
        _count_down(melee, level)
    if any_passive:
        _move_passive_mobs(state, passive, p_row, p_col, random, despawn)
    if any_ranged:
        _move_ranged_mobs(state, ranged, p_row, p_col, random, monster_limit)
    else:
        _count_down(ranged, level)
    # (the mask lists are the state's own: a projectile a ranged mob shot this turn flies too)
    if True in shots:
        _move_mob_projectiles(state, p_row, p_col)
    if True in arrows:
        _move_player_projectiles(state)


# ---------------------------------------------------------------------------------------------
# Spawning (game_logic.spawn_mobs)

_RINGS: dict[tuple[int, int], np.ndarray] = {}


def _ring(near: int, far: int) -> np.ndarray:
    """The cells of a square around its centre (half-side ceil(sqrt(far)) + 1) whose squared
    Euclidean distance d2 from it has near < d2 < far; made once per (near, far)."""
    ring = _RINGS.get((near, far))
    if ring is None:
        radius = int(np.ceil(np.sqrt(far))) + 1
        d = np.arange(-radius, radius + 1)
        d2 = d[:, None] ** 2 + d[None, :] ** 2
        ring = _RINGS[near, far] = (d2 > near) & (d2 < far)
    return ring


def _spawn_cell(state: State, allowed: np.ndarray, near: int, far: int, draws):
    """A uniformly drawn cell whose block ``allowed`` marks, with no mob on it, at a Euclidean
    squared distance d2 from the player with near < d2 < far; None if there is none. Cells
    count in row-major order (upstream draws over the flattened map)."""
    level = state.player_level
    ring = _ring(near, far)
    radius = ring.shape[0] // 2
    p_row, p_col = state.player_position.tolist()
    rows, cols = state.map.shape[1:]
    r0, r1 = max(0, p_row - radius), min(rows, p_row + radius + 1)
    c0, c1 = max(0, p_col - radius), min(cols, p_col + radius + 1)
    # (``take`` and ``ravel().nonzero()`` do what ``allowed[...]`` and ``flatnonzero`` do, in
    # about half the time: fewer checks on the way in)
    ok = allowed.take(state.map[level, r0:r1, c0:c1])
    ok &= ring[r0 - p_row + radius:r1 - p_row + radius, c0 - p_col + radius:c1 - p_col + radius]
    np.greater(ok, state.mob_map[level, r0:r1, c0:c1], out=ok)      # (and no mob there)
    cells = ok.ravel().nonzero()[0]
    if cells.size == 0:
        return None
    k = int(cells[draws.below(cells.size)])
    width = c1 - c0
    return r0 + k // width, c0 + k % width


def _add_mob(state: State, mobs: Mobs, kind: int, type_id: int, cell: tuple,
             cooldown: int | None = None) -> bool:
    """A mob of class ``kind`` and type ``type_id`` at ``cell`` of the player's level, in the
    class's first free slot, at its type's full health; False (nothing changed) when the class
    has no free slot. The slot keeps its attack cooldown (upstream: a spawned mob inherits it)
    unless ``cooldown`` is given."""
    level = state.player_level
    live = mobs.mask[level]
    if False not in live:
        return False
    slot = live.index(False)
    row, col = int(cell[0]), int(cell[1])
    mobs.position[level][slot] = (row, col)
    mobs.health[level][slot] = _FULL_HEALTH[type_id][kind]
    live[slot] = True
    mobs.type_id[level][slot] = int(type_id)
    if cooldown is not None:
        mobs.attack_cooldown[level][slot] = cooldown
    state.mob_map[level, row, col] = True
    return True


# bestiary.MOB_NAMES: name -> (class, type_id)
MOB_BY_NAME = {name: (kind, type_id) for kind, names in enumerate(MOB_NAMES)
               for type_id, name in enumerate(names)}


def add_mob(state: State, name: str, cell) -> bool:
    """Place a mob named ``name`` (``bestiary.MOB_NAMES``) at ``cell`` (row, col) of the player's
    level: full health for its type, attack cooldown 0, the mob map set. False (nothing changed)
    when the cell is off the map, solid, or taken by a mob or the player, or when the mob's
    class has no free slot. (For scenarios; the game's own spawning is ``spawn``.)"""
    if name not in MOB_BY_NAME:
        raise ValueError(f"unknown mob {name!r}; known: {', '.join(MOB_BY_NAME)}")
    kind, type_id = MOB_BY_NAME[name]
    level = state.player_level
    row, col = int(cell[0]), int(cell[1])
    rows, cols = state.map.shape[1:]
    if not (0 <= row < rows and 0 <= col < cols) or IS_SOLID[state.map.item(level, row, col)]:
        return False
    if state.mob_map.item(level, row, col) or (row, col) == tuple(state.player_position.tolist()):
        return False
    group = (state.passive_mobs, state.melee_mobs, state.ranged_mobs)[kind]
    return _add_mob(state, group, kind, type_id, (row, col), cooldown=0)


def spawn(state: State, settings: Settings, draws) -> None:
    """Upstream's spawn_mobs: at most one passive, one melee and one ranged mob a turn, each
    with its level's chance while its class has a free slot. Passive mobs spawn on grass or
    path 3 to the despawn distance away; monsters 9 to the despawn distance away, at three
    times the rate until the level is cleared (8 kills), melee ones more at night. On the
    boss level only monsters spawn, during a spawn wave (x1000 rate), on graves within 6,
    of the kinds of the boss's progress. Deep things spawn in water."""
    if not settings.spawning:
        return
    level = state.player_level
    chances = FLOOR_MOB_SPAWN_CHANCE[level]
    boss = level == BOSS_LEVEL
    random = draws.random
    far = settings.mob_despawn_distance ** 2
    coeff = 3.0 if state.monsters_killed.item(level) < MONSTERS_KILLED_TO_CLEAR_LEVEL else 1.0
    if boss:
        coeff *= 1000.0 if state.boss_timesteps_to_spawn_this_round >= 1 else 0.0

    if (not boss and state.passive_mobs.mask[level].count(True) < MAX_PASSIVE
            and random() < chances[0]):
        cell = _spawn_cell(state, _SPAWN_GROUND, 9, far, draws)
        if cell is not None:
            _add_mob(state, state.passive_mobs, _PASSIVE, FLOOR_MOB_MAPPING[level][_PASSIVE], cell)
    if (state.melee_mobs.mask[level].count(True) < MAX_MELEE
            and random() < (chances[1] + chances[3] * (1.0 - state.light_level) ** 2) * coeff):
        _spawn_monster(state, state.melee_mobs, _MELEE, far, draws)
    if (state.ranged_mobs.mask[level].count(True) < MAX_RANGED
            and random() < chances[2] * coeff):
        _spawn_monster(state, state.ranged_mobs, _RANGED, far, draws)


def _spawn_monster(state: State, mobs: Mobs, kind: int, far: int, draws) -> None:
    """A melee or ranged mob (``kind``) whose spawn roll came up: of its level's type, on
    ground 9 to the despawn distance (squared: ``far``) away, deep things in water; on the
    boss level, of the boss's progress's type, on graves within 6."""
    level = state.player_level
    if level == BOSS_LEVEL:
        type_id = FLOOR_MOB_MAPPING[state.boss_progress][kind]
        cell = _spawn_cell(state, _SPAWN_GRAVES, -1, min(far, 37), draws)
    else:
        type_id = FLOOR_MOB_MAPPING[level][kind]
        water = kind == _RANGED and type_id == _DEEP_THING
        cell = _spawn_cell(state, _SPAWN_WATER if water else _SPAWN_GROUND, 81, far, draws)
    if cell is not None:
        _add_mob(state, mobs, kind, type_id, cell)


__all__ = ["update", "spawn", "add_mob", "boss_logic", "damage_necromancer", "attack_mob",
           "hurt_player", "damage_to_player", "player_projectile_damage", "is_fighting_boss",
           "is_boss_spawn_wave", "is_boss_vulnerable", "has_beaten_boss"]
