"""``mobs`` compiled: the same rules, in the same order, on the packed state (``packed``).

Each function here is its namesake of ``mobs`` (see there for the rules), written for numba on
``packed``'s arrays; ``tests/games/craftax/test_craftax_kernel.py`` plays both from the same
states and draws and finds the same states after every step, and ``test_craftax_kernel_mobs.py``
does the same for ``update`` and ``spawn`` alone, call by call. Floats are Python's (float64) at
every operation, and a mob's health is rounded to float32 where ``mobs`` rounds it, so the two
give the same bits.

The arrays, as ``packed`` names them: ``ints``, ``floats``, ``mobs``, ``health``, ``kills``,
``draws`` and the maps. ``random(ints, draws)`` is ``Draws.random``: the next float. A group's
loops run over its own slots (``_SLOT_COUNT``: ranged mobs have 2 of ``packed``'s 3; the third
stays all zero).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from . import mobs as _reference
from .bestiary import (FLOOR_MOB_MAPPING, FLOOR_MOB_SPAWN_CHANCE, MELEE_ATTACK_COOLDOWN,
                       MOB_ACHIEVEMENT_MAP, MOB_TYPE_DAMAGE_MAPPING, MOB_TYPE_DEFENCE_MAPPING,
                       MOB_TYPE_ENTERABLE, PROJECTILE_DAMAGE, RANGED_ATTACK_COOLDOWN,
                       RANGED_MOB_TYPE_TO_PROJECTILE_TYPE_MAPPING)
from .packed import (ACH, ALIVE, ARMOUR, ARMOUR_ENCH, BOSS_PROGRESS, BOSS_WAVE, BOW_ENCH, COL,
                     COOLDOWN, DCOL, DEX, DRAW_AT, DROW, FOOD, HEALTH, HUNGER, INT, KILLED, LEVEL,
                     LIGHT, MELEE, MOB_COL, MOB_ROW, MOB_SHOTS, PASSIVE, PLAYER_SHOTS, RANGED,
                     RESTING, ROW, SET_DESPAWN, SET_SPAWNING, SLEEPING, SLOTS, TYPE)
from .state import MAX_MELEE, MAX_MOB_PROJECTILES, MAX_PASSIVE, MAX_PLAYER_PROJECTILES, MAX_RANGED
from .tables import (ARMOUR_DEFENCE_PER_TIER, BOSS_FIGHT_EXTRA_DAMAGE, BOSS_FIGHT_SPAWN_TURNS,
                     BOSS_LEVEL, COW_FOOD, ENCHANTED_ARMOUR_DEFENCE, IS_SOLID,
                     MONSTERS_KILLED_TO_CLEAR_LEVEL, SLEEPING_MELEE_FACTOR, Achievement,
                     BlockType)

_DEFENCE = np.array(MOB_TYPE_DEFENCE_MAPPING, np.float64)       # [type, class, element]
_KILL_ACHIEVEMENT = np.array(MOB_ACHIEVEMENT_MAP, np.int64)      # [class, type]
_DAMAGE = np.array(MOB_TYPE_DAMAGE_MAPPING, np.float64)          # [type, class, element]
_PROJECTILE_DAMAGE = np.array(PROJECTILE_DAMAGE, np.float64)     # [kind, element]
_ENTERABLE = np.array(MOB_TYPE_ENTERABLE, np.bool_)              # [type, class, block]
_SHOT_KIND = np.array([int(k) for k in RANGED_MOB_TYPE_TO_PROJECTILE_TYPE_MAPPING], np.int64)
_IS_SOLID = np.array(IS_SOLID, np.bool_)
_FULL_HEALTH = np.array(_reference._FULL_HEALTH, np.float64)    # [type, class] (float32 values)
_FLOOR_MOB = np.array(FLOOR_MOB_MAPPING, np.int64)               # [level, class]
_SPAWN_CHANCE = np.array(FLOOR_MOB_SPAWN_CHANCE, np.float64)     # [level, (p, m, r, night m)]
_SPAWN_GROUND = _reference._SPAWN_GROUND.copy()                  # [block]
_SPAWN_WATER = _reference._SPAWN_WATER.copy()
_SPAWN_GRAVES = _reference._SPAWN_GRAVES.copy()
_STEPS = np.array(_reference._STEPS, np.int64)                   # left, right, up, down
# the slots of each group (``packed`` keeps SLOTS for each; ranged mobs use the first 2)
_SLOT_COUNT = np.array([MAX_PASSIVE, MAX_MELEE, MAX_RANGED, MAX_MOB_PROJECTILES,
                        MAX_PLAYER_PROJECTILES], np.int64)
assert _SLOT_COUNT.max() <= SLOTS
_TABLE, _FURNACE = _reference._BREAKABLE
_PATH = int(BlockType.PATH)
_ARROW, _ARROW2 = _reference._ARROWS
_FIREBALL, _ICEBALL = _reference._SPELLS
_DEEP_THING = _reference._DEEP_THING
_FAR = _reference._FAR
_ROWS, _COLS = _reference._ROWS, _reference._COLS
_WAKE_UP = int(Achievement.WAKE_UP)
_DEFEAT_NECROMANCER = int(Achievement.DEFEAT_NECROMANCER)
_DAMAGE_NECROMANCER = int(Achievement.DAMAGE_NECROMANCER)


@njit(cache=True)
def random(ints, draws):
    """The next float of the draws (``Draws.random``)."""
    at = ints[DRAW_AT]
    if at >= len(draws):        # (never with ``KernelDraws``: a step draws far fewer)
        raise IndexError("Craftax kernel: the draws ran out (KernelDraws.top_up before a step)")
    ints[DRAW_AT] = at + 1
    return draws[at]


@njit(cache=True)
def max_food(dex):      # = max_drink = max_energy (tables)
    return 7 + 2 * dex


# ---------------------------------------------------------------------------------------------
# The necromancer


@njit(cache=True)
def is_boss_vulnerable(ints, mobs):
    level = ints[LEVEL]
    for slot in range(SLOTS):
        if mobs[MELEE, level, slot, ALIVE] or mobs[RANGED, level, slot, ALIVE]:
            return False
    return ints[BOSS_WAVE] <= 0


@njit(cache=True)
def boss_logic(ints):
    if ints[BOSS_PROGRESS] >= BOSS_LEVEL:
        ints[ACH + _DEFEAT_NECROMANCER] = 1
    if ints[LEVEL] == BOSS_LEVEL:
        ints[BOSS_WAVE] -= 1


@njit(cache=True)
def damage_necromancer(ints, mobs):
    if not (ints[LEVEL] == BOSS_LEVEL and is_boss_vulnerable(ints, mobs)):
        return False
    ints[BOSS_PROGRESS] += 1
    ints[BOSS_WAVE] = BOSS_FIGHT_SPAWN_TURNS
    ints[ACH + _DAMAGE_NECROMANCER] = 1
    return True


# ---------------------------------------------------------------------------------------------
# Damage


@njit(cache=True)
def damage_to_player(ints, physical, fire, ice):
    scale = 1.0 + BOSS_FIGHT_EXTRA_DAMAGE if ints[LEVEL] == BOSS_LEVEL else 1.0
    tiers = ints[ARMOUR] + ints[ARMOUR + 1] + ints[ARMOUR + 2] + ints[ARMOUR + 3]
    lost = (1.0 - ARMOUR_DEFENCE_PER_TIER * tiers) * physical * scale
    if not (fire or ice):
        return lost
    fire_pieces = ice_pieces = 0
    for i in range(4):
        e = ints[ARMOUR_ENCH + i]
        fire_pieces += e == 1
        ice_pieces += e == 2
    return (lost + (1.0 - ENCHANTED_ARMOUR_DEFENCE * fire_pieces) * fire * scale
            + (1.0 - ENCHANTED_ARMOUR_DEFENCE * ice_pieces) * ice * scale)


@njit(cache=True)
def hurt_player(ints, floats, physical, fire, ice, melee):
    if melee and ints[SLEEPING]:
        physical, fire, ice = (SLEEPING_MELEE_FACTOR * physical, SLEEPING_MELEE_FACTOR * fire,
                               SLEEPING_MELEE_FACTOR * ice)
        ints[ACH + _WAKE_UP] = 1
    lost = damage_to_player(ints, physical, fire, ice)
    floats[HEALTH] -= lost
    ints[SLEEPING] = 0
    ints[RESTING] = 0
    return lost


@njit(cache=True)
def _attack_class(ints, mobs, health, kills, kind, row, col, physical, fire, ice, achieve):
    """(hit, killed) on the first live mob of class ``kind`` at (row, col)."""
    level = ints[LEVEL]
    for slot in range(SLOTS):
        if mobs[kind, level, slot, ALIVE] and mobs[kind, level, slot, MOB_ROW] == row \
                and mobs[kind, level, slot, MOB_COL] == col:
            type_id = mobs[kind, level, slot, TYPE]
            left = health[kind, level, slot] - (
                (1.0 - _DEFENCE[type_id, kind, 0]) * physical
                + (1.0 - _DEFENCE[type_id, kind, 1]) * fire
                + (1.0 - _DEFENCE[type_id, kind, 2]) * ice)
            health[kind, level, slot] = np.float32(left)
            if left > 0:
                return True, False
            mobs[kind, level, slot, ALIVE] = 0
            kills[kind, type_id] += 1
            if achieve:
                ints[ACH + _KILL_ACHIEVEMENT[kind, type_id]] = 1
            return True, True
    return False, False


@njit(cache=True)
def attack_mob(ints, floats, mobs, health, mob_map, kills, row, col, physical, fire, ice, can_eat):
    """``mobs.attack_mob``; a kill also counts in ``kills[class, type]``."""
    hit, killed = _attack_class(ints, mobs, health, kills, MELEE, row, col, physical, fire, ice,
                                True)
    monster = killed
    if not hit:
        hit, killed = _attack_class(ints, mobs, health, kills, PASSIVE, row, col, physical, fire,
                                    ice, can_eat)
        if killed and can_eat:
            ints[FOOD] = min(max_food(ints[DEX]), ints[FOOD] + COW_FOOD)
            floats[HUNGER] = 0.0
    if not hit:
        hit, killed = _attack_class(ints, mobs, health, kills, RANGED, row, col, physical, fire,
                                    ice, True)
        monster = killed
    if killed:
        level = ints[LEVEL]
        mob_map[level, row, col] = False
        if monster:
            ints[KILLED + level] += 1
    return hit, killed



# ---------------------------------------------------------------------------------------------
# Movement (``mobs.update``: one function per class's loop, as there). ``_free(...)`` is the
# loops' written-out test: on the map, not the player's cell, no mob there, a block the mob may
# enter.


@njit(cache=True)
def _any_alive(mobs, group, level):
    for slot in range(_SLOT_COUNT[group]):
        if mobs[group, level, slot, ALIVE]:
            return True
    return False


@njit(cache=True)
def _free(map, mob_map, level, row, col, p_row, p_col, type_id, kind):
    return (0 <= row < _ROWS and 0 <= col < _COLS and (row != p_row or col != p_col)
            and not mob_map[level, row, col] and _ENTERABLE[type_id, kind, map[level, row, col]])


@njit(cache=True)
def _move_to(mob_map, mobs, group, level, slot, row, col, new_row, new_col):
    mobs[group, level, slot, MOB_ROW] = new_row
    mobs[group, level, slot, MOB_COL] = new_col
    mob_map[level, row, col] = False
    mob_map[level, new_row, new_col] = True


@njit(cache=True)
def _sign(x):
    return 1 if x > 0 else -1 if x < 0 else 0


@njit(cache=True)
def _toward(ints, draws, d_row, d_col):
    """One step toward the player along the larger distance's axis (a tie: one draw)."""
    a_row, a_col = abs(d_row), abs(d_col)
    if a_row > a_col or (a_row == a_col and int(random(ints, draws) * 2) == 0):
        return _sign(d_row), 0
    return 0, _sign(d_col)


@njit(cache=True)
def _move_melee_mobs(map, mob_map, ints, floats, mobs, draws, p_row, p_col, limit):
    """Chase (within 10, or anywhere on the boss level: 75%) or wander; hit an adjacent player
    when the cooldown is over; vanish at ``limit``. Dead slots count their cooldown down."""
    level = ints[LEVEL]
    chases_anywhere = level == BOSS_LEVEL
    for slot in range(_SLOT_COUNT[MELEE]):
        cooldown = mobs[MELEE, level, slot, COOLDOWN]
        if not mobs[MELEE, level, slot, ALIVE]:
            mobs[MELEE, level, slot, COOLDOWN] = cooldown - 1
            continue
        row, col = mobs[MELEE, level, slot, MOB_ROW], mobs[MELEE, level, slot, MOB_COL]
        type_id = mobs[MELEE, level, slot, TYPE]
        d_row, d_col = p_row - row, p_col - col
        distance = abs(d_row) + abs(d_col)
        if (distance < 10 or chases_anywhere) and random(ints, draws) < 0.75:
            step_row, step_col = _toward(ints, draws, d_row, d_col)
        else:
            step = int(random(ints, draws) * 4)
            step_row, step_col = _STEPS[step, 0], _STEPS[step, 1]
        if distance == 1 and cooldown <= 0:
            hurt_player(ints, floats, _DAMAGE[type_id, MELEE, 0], _DAMAGE[type_id, MELEE, 1],
                        _DAMAGE[type_id, MELEE, 2], True)
            mobs[MELEE, level, slot, COOLDOWN] = MELEE_ATTACK_COOLDOWN
        else:
            mobs[MELEE, level, slot, COOLDOWN] = cooldown - 1
            new_row, new_col = row + step_row, col + step_col
            if _free(map, mob_map, level, new_row, new_col, p_row, p_col, type_id, MELEE):
                _move_to(mob_map, mobs, MELEE, level, slot, row, col, new_row, new_col)
                row, col = new_row, new_col
        if distance >= limit:
            mobs[MELEE, level, slot, ALIVE] = 0
            mob_map[level, row, col] = False


@njit(cache=True)
def _move_passive_mobs(map, mob_map, ints, mobs, draws, p_row, p_col, limit):
    """Wander (each step 1/8, else stay); vanish at ``limit``."""
    level = ints[LEVEL]
    for slot in range(_SLOT_COUNT[PASSIVE]):
        if not mobs[PASSIVE, level, slot, ALIVE]:
            continue
        row, col = mobs[PASSIVE, level, slot, MOB_ROW], mobs[PASSIVE, level, slot, MOB_COL]
        choice = int(random(ints, draws) * 8)
        distance = abs(p_row - row) + abs(p_col - col)
        if choice < 4:
            new_row, new_col = row + _STEPS[choice, 0], col + _STEPS[choice, 1]
            if _free(map, mob_map, level, new_row, new_col, p_row, p_col,
                     mobs[PASSIVE, level, slot, TYPE], PASSIVE):
                _move_to(mob_map, mobs, PASSIVE, level, slot, row, col, new_row, new_col)
                row, col = new_row, new_col
        if distance >= limit:
            mobs[PASSIVE, level, slot, ALIVE] = 0
            mob_map[level, row, col] = False


@njit(cache=True)
def _move_ranged_mobs(map, mob_map, ints, mobs, draws, p_row, p_col, limit):
    """Keep a shooting distance (15%: closer from 6, back within 3; else wander); shoot at 4-5,
    or when backing off is blocked; vanish at ``limit``. Dead slots count their cooldown down."""
    level = ints[LEVEL]
    for slot in range(_SLOT_COUNT[RANGED]):
        cooldown = mobs[RANGED, level, slot, COOLDOWN]
        if not mobs[RANGED, level, slot, ALIVE]:
            mobs[RANGED, level, slot, COOLDOWN] = cooldown - 1
            continue
        row, col = mobs[RANGED, level, slot, MOB_ROW], mobs[RANGED, level, slot, MOB_COL]
        type_id = mobs[RANGED, level, slot, TYPE]
        d_row, d_col = p_row - row, p_col - col
        distance = abs(d_row) + abs(d_col)
        toward_row, toward_col = _toward(ints, draws, d_row, d_col)
        too_close = distance <= 3
        if random(ints, draws) > 0.85 and (distance >= 6 or too_close):
            sign = -1 if too_close else 1
            new_row, new_col = row + sign * toward_row, col + sign * toward_col
        else:
            step = int(random(ints, draws) * 4)
            new_row, new_col = row + _STEPS[step, 0], col + _STEPS[step, 1]
        can_move = _free(map, mob_map, level, new_row, new_col, p_row, p_col, type_id, RANGED)
        if cooldown <= 0 and (4 <= distance <= 5 or (too_close and not can_move)):
            _shoot(mobs, level, row, col, toward_row, toward_col, _SHOT_KIND[type_id])
            mobs[RANGED, level, slot, COOLDOWN] = RANGED_ATTACK_COOLDOWN
        else:
            mobs[RANGED, level, slot, COOLDOWN] = cooldown - 1
            if can_move:
                _move_to(mob_map, mobs, RANGED, level, slot, row, col, new_row, new_col)
                row, col = new_row, new_col
        if distance >= limit:
            mobs[RANGED, level, slot, ALIVE] = 0
            mob_map[level, row, col] = False


@njit(cache=True)
def _shoot(mobs, level, row, col, d_row, d_col, kind):
    """A mob projectile in the first free slot, if any."""
    for slot in range(_SLOT_COUNT[MOB_SHOTS]):
        if not mobs[MOB_SHOTS, level, slot, ALIVE]:
            mobs[MOB_SHOTS, level, slot, MOB_ROW] = row
            mobs[MOB_SHOTS, level, slot, MOB_COL] = col
            mobs[MOB_SHOTS, level, slot, ALIVE] = 1
            mobs[MOB_SHOTS, level, slot, TYPE] = kind
            mobs[MOB_SHOTS, level, slot, DROW] = d_row
            mobs[MOB_SHOTS, level, slot, DCOL] = d_col
            return


@njit(cache=True)
def _move_mob_projectiles(map, mob_map, ints, floats, mobs, p_row, p_col):
    """Fly one cell; hit the player (its cell or the next), stop at solid blocks, mobs and the
    edge; break a table or furnace in the way."""
    level = ints[LEVEL]
    for slot in range(_SLOT_COUNT[MOB_SHOTS]):
        if not mobs[MOB_SHOTS, level, slot, ALIVE]:
            continue
        row, col = mobs[MOB_SHOTS, level, slot, MOB_ROW], mobs[MOB_SHOTS, level, slot, MOB_COL]
        new_row = row + mobs[MOB_SHOTS, level, slot, DROW]
        new_col = col + mobs[MOB_SHOTS, level, slot, DCOL]
        hit_player = (row == p_row and col == p_col) or (new_row == p_row and new_col == p_col)
        flies_on = 0 <= new_row < _ROWS and 0 <= new_col < _COLS
        if flies_on:
            block = map[level, new_row, new_col]
            flies_on = not (hit_player or _IS_SOLID[block] or mob_map[level, new_row, new_col])
            if block == _TABLE or block == _FURNACE:
                map[level, new_row, new_col] = _PATH
        if hit_player:
            kind = mobs[MOB_SHOTS, level, slot, TYPE]
            hurt_player(ints, floats, _PROJECTILE_DAMAGE[kind, 0], _PROJECTILE_DAMAGE[kind, 1],
                        _PROJECTILE_DAMAGE[kind, 2], False)
        mobs[MOB_SHOTS, level, slot, MOB_ROW] = new_row
        mobs[MOB_SHOTS, level, slot, MOB_COL] = new_col
        if not flies_on:
            mobs[MOB_SHOTS, level, slot, ALIVE] = 0


@njit(cache=True)
def player_projectile_damage(ints, kind):
    """(physical, fire, ice): an arrow gains half its physical damage as the bow's element and
    scales with dexterity, a spell with intelligence."""
    physical, fire, ice = (_PROJECTILE_DAMAGE[kind, 0], _PROJECTILE_DAMAGE[kind, 1],
                           _PROJECTILE_DAMAGE[kind, 2])
    if kind == _ARROW or kind == _ARROW2:
        if ints[BOW_ENCH] == 1:
            fire += physical / 2
        elif ints[BOW_ENCH] == 2:
            ice += physical / 2
        scale = 1.0 + 0.2 * (ints[DEX] - 1)
    elif kind == _FIREBALL or kind == _ICEBALL:
        scale = 1.0 + 0.5 * (ints[INT] - 1)
    else:
        scale = 1.0
    return physical * scale, fire * scale, ice * scale


@njit(cache=True)
def _move_player_projectiles(map, mob_map, ints, floats, mobs, health, kills):
    """Strike a mob on the projectile's cell, else on its next; fly on unless it struck, left
    the map or met a solid block."""
    level = ints[LEVEL]
    for slot in range(_SLOT_COUNT[PLAYER_SHOTS]):
        if not mobs[PLAYER_SHOTS, level, slot, ALIVE]:
            continue
        row = mobs[PLAYER_SHOTS, level, slot, MOB_ROW]
        col = mobs[PLAYER_SHOTS, level, slot, MOB_COL]
        new_row = row + mobs[PLAYER_SHOTS, level, slot, DROW]
        new_col = col + mobs[PLAYER_SHOTS, level, slot, DCOL]
        physical, fire, ice = player_projectile_damage(ints, mobs[PLAYER_SHOTS, level, slot, TYPE])
        on_map = 0 <= new_row < _ROWS and 0 <= new_col < _COLS
        hit = False
        if mob_map[level, row, col]:
            hit = attack_mob(ints, floats, mobs, health, mob_map, kills, row, col, physical, fire,
                             ice, False)[0]
        if not hit and on_map and mob_map[level, new_row, new_col]:
            hit = attack_mob(ints, floats, mobs, health, mob_map, kills, new_row, new_col,
                             physical, fire, ice, False)[0]
        flies_on = not hit and on_map and not _IS_SOLID[map[level, new_row, new_col]]
        mobs[PLAYER_SHOTS, level, slot, MOB_ROW] = new_row
        mobs[PLAYER_SHOTS, level, slot, MOB_COL] = new_col
        if not flies_on:
            mobs[PLAYER_SHOTS, level, slot, ALIVE] = 0


@njit(cache=True)
def _count_down(mobs, group, level):
    """A class with no live mob on the level: its (real) slots' cooldowns count down."""
    for slot in range(_SLOT_COUNT[group]):
        mobs[group, level, slot, COOLDOWN] -= 1


@njit(cache=True)
def update(map, mob_map, ints, floats, mobs, health, kills, draws, settings):
    """``mobs.update``: melee, passive and ranged mobs, then mob and player projectiles."""
    level = ints[LEVEL]
    any_melee, any_ranged = _any_alive(mobs, MELEE, level), _any_alive(mobs, RANGED, level)
    any_passive = _any_alive(mobs, PASSIVE, level)
    if not (any_melee or any_passive or any_ranged or _any_alive(mobs, MOB_SHOTS, level)
            or _any_alive(mobs, PLAYER_SHOTS, level)):
        _count_down(mobs, MELEE, level)
        _count_down(mobs, RANGED, level)
        return
    p_row, p_col = ints[ROW], ints[COL]
    despawn = settings[SET_DESPAWN] if settings[SET_SPAWNING] else _FAR
    monster_limit = _FAR if level == BOSS_LEVEL else despawn
    if any_melee:
        _move_melee_mobs(map, mob_map, ints, floats, mobs, draws, p_row, p_col, monster_limit)
    else:
        _count_down(mobs, MELEE, level)
    if any_passive:
        _move_passive_mobs(map, mob_map, ints, mobs, draws, p_row, p_col, despawn)
    if any_ranged:
        _move_ranged_mobs(map, mob_map, ints, mobs, draws, p_row, p_col, monster_limit)
    else:
        _count_down(mobs, RANGED, level)
    # (a projectile a ranged mob shot this turn flies too)
    if _any_alive(mobs, MOB_SHOTS, level):
        _move_mob_projectiles(map, mob_map, ints, floats, mobs, p_row, p_col)
    if _any_alive(mobs, PLAYER_SHOTS, level):
        _move_player_projectiles(map, mob_map, ints, floats, mobs, health, kills)


# ---------------------------------------------------------------------------------------------
# Spawning (``mobs.spawn``)


@njit(cache=True)
def _ring(near, far, d_row, d_col):
    """``mobs._ring``'s mask at (d_row, d_col) from its centre: near < d2 < far (the mask's
    half-side, ceil(sqrt(far)) + 1, is the window ``_spawn_cell`` scans)."""
    d2 = d_row * d_row + d_col * d_col
    return near < d2 < far


@njit(cache=True)
def _spawn_cell(map, mob_map, ints, draws, allowed, near, far):
    """(found, row, col): a uniformly drawn cell of an ``allowed`` block, no mob on it, with
    near < d2 < far from the player; the cells count in row-major order over the window."""
    level = ints[LEVEL]
    radius = int(np.ceil(np.sqrt(far))) + 1
    p_row, p_col = ints[ROW], ints[COL]
    r0, r1 = max(0, p_row - radius), min(_ROWS, p_row + radius + 1)
    c0, c1 = max(0, p_col - radius), min(_COLS, p_col + radius + 1)
    count = 0
    for row in range(r0, r1):
        for col in range(c0, c1):
            if (allowed[map[level, row, col]] and _ring(near, far, row - p_row, col - p_col)
                    and not mob_map[level, row, col]):
                count += 1
    if count == 0:
        return False, 0, 0
    k = int(random(ints, draws) * count)
    for row in range(r0, r1):
        for col in range(c0, c1):
            if (allowed[map[level, row, col]] and _ring(near, far, row - p_row, col - p_col)
                    and not mob_map[level, row, col]):
                if k == 0:
                    return True, row, col
                k -= 1
    return False, 0, 0      # (not reached)


@njit(cache=True)
def _add_mob(mob_map, ints, mobs, health, kind, type_id, row, col):
    """A mob in the class's first free slot at full health (keeping the slot's cooldown);
    False when there is none."""
    level = ints[LEVEL]
    for slot in range(_SLOT_COUNT[kind]):
        if not mobs[kind, level, slot, ALIVE]:
            mobs[kind, level, slot, MOB_ROW] = row
            mobs[kind, level, slot, MOB_COL] = col
            health[kind, level, slot] = _FULL_HEALTH[type_id, kind]
            mobs[kind, level, slot, ALIVE] = 1
            mobs[kind, level, slot, TYPE] = type_id
            mob_map[level, row, col] = True
            return True
    return False


@njit(cache=True)
def _count_alive(mobs, group, level):
    count = 0
    for slot in range(_SLOT_COUNT[group]):
        count += mobs[group, level, slot, ALIVE] != 0
    return count


@njit(cache=True)
def spawn(map, mob_map, ints, floats, mobs, health, draws, settings):
    """``mobs.spawn``: at most one passive, one melee and one ranged mob."""
    if not settings[SET_SPAWNING]:
        return
    level = ints[LEVEL]
    boss = level == BOSS_LEVEL
    far = settings[SET_DESPAWN] ** 2
    coeff = 3.0 if ints[KILLED + level] < MONSTERS_KILLED_TO_CLEAR_LEVEL else 1.0
    if boss:
        coeff *= 1000.0 if ints[BOSS_WAVE] >= 1 else 0.0

    if (not boss and _count_alive(mobs, PASSIVE, level) < MAX_PASSIVE
            and random(ints, draws) < _SPAWN_CHANCE[level, 0]):
        found, row, col = _spawn_cell(map, mob_map, ints, draws, _SPAWN_GROUND, 9, far)
        if found:
            _add_mob(mob_map, ints, mobs, health, PASSIVE, _FLOOR_MOB[level, PASSIVE], row, col)
    if (_count_alive(mobs, MELEE, level) < MAX_MELEE
            and random(ints, draws) < (_SPAWN_CHANCE[level, 1] + _SPAWN_CHANCE[level, 3]
                                       * (1.0 - floats[LIGHT]) ** 2) * coeff):
        _spawn_monster(map, mob_map, ints, mobs, health, draws, MELEE, far)
    if (_count_alive(mobs, RANGED, level) < MAX_RANGED
            and random(ints, draws) < _SPAWN_CHANCE[level, 2] * coeff):
        _spawn_monster(map, mob_map, ints, mobs, health, draws, RANGED, far)


@njit(cache=True)
def _spawn_monster(map, mob_map, ints, mobs, health, draws, kind, far):
    """A melee or ranged mob of the level's type on ground 9 to the despawn distance away (deep
    things in water); on the boss level, of the boss's progress's type, on graves within 6."""
    level = ints[LEVEL]
    if level == BOSS_LEVEL:
        type_id = _FLOOR_MOB[ints[BOSS_PROGRESS], kind]
        found, row, col = _spawn_cell(map, mob_map, ints, draws, _SPAWN_GRAVES, -1, min(far, 37))
    else:
        type_id = _FLOOR_MOB[level, kind]
        water = kind == RANGED and type_id == _DEEP_THING
        found, row, col = _spawn_cell(map, mob_map, ints, draws,
                                      _SPAWN_WATER if water else _SPAWN_GROUND, 81, far)
    if found:
        _add_mob(mob_map, ints, mobs, health, kind, type_id, row, col)
