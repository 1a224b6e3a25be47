"""``kernel_mobs.update`` and ``kernel_mobs.spawn`` in lockstep with ``mobs.update`` and
``mobs.spawn``: many varied states (generated worlds and the scenarios' starts, every level,
many live mobs of every class and type, projectiles, sleep, armour, the boss fight, water,
tables in the way, the despawn distance and the spawning switch), several turns each (the
player stepping to a free cell between turns); after every call the two states are the same,
field for field and bit for bit, as are the draws taken, and the kernel's ``kills`` count
exactly the slots that died with health <= 0. The reference is wrapped to count the branches
the cases reach (asserted at the end)."""

from __future__ import annotations

import copy
from collections import Counter
from dataclasses import fields

import numpy as np
import pytest

from glyphbench_rl.games.common.lanes import Draws
from glyphbench_rl.games.craftax import kernel_mobs, mobs, scenarios, worldgen
from glyphbench_rl.games.craftax.bestiary import MOB_NAMES, MOB_TYPE_HEALTH_MAPPING
from glyphbench_rl.games.craftax.packed import COL, DRAW_AT, RANGED, ROW, SLEEPING, pack, unpack
from glyphbench_rl.games.craftax.state import (MAP_SIZE, MOB_GROUPS, Inventory, Mobs, Settings,
                                               State, float32)
from glyphbench_rl.games.craftax.tables import BOSS_LEVEL, IS_SOLID, BlockType

CASES = 700
TURNS = 5
ROWS, COLS = MAP_SIZE
STEPS = ((0, -1), (0, 1), (-1, 0), (1, 0))
WORLDS = [worldgen.generate(np.random.default_rng(5000 + i), Settings()) for i in range(16)]
SCENARIO_NAMES = list(scenarios.SCENARIOS)


# ---------------------------------------------------------------------------------------------
# States


def _free(state: State, level: int, row: int, col: int) -> bool:
    return (0 <= row < ROWS and 0 <= col < COLS and not IS_SOLID[state.map[level, row, col]]
            and not state.mob_map[level, row, col])


def _free_cells(state: State, level: int) -> np.ndarray:
    solid = np.array(IS_SOLID)[state.map[level]]
    return np.argwhere(~solid & ~state.mob_map[level])


def _near(rng, state: State, level: int, centre, radius: int, tries: int = 8):
    """A free cell within ``radius`` (square) of ``centre``, not the player's; None if none found."""
    p = tuple(state.player_position.tolist())
    for _ in range(tries):
        row = int(centre[0] + rng.integers(-radius, radius + 1))
        col = int(centre[1] + rng.integers(-radius, radius + 1))
        if _free(state, level, row, col) and (row, col) != p:
            return row, col
    return None


def _stamp(rng, state: State, level: int, block: int, count: int, near: int, far: int) -> None:
    """``count`` 2x2 patches of ``block`` between ``near`` and ``far`` (square) from the player,
    where no mob stands and not on the player's cell."""
    p_row, p_col = state.player_position.tolist()
    for _ in range(count):
        d_row, d_col = rng.integers(-far, far + 1, 2)
        if max(abs(d_row), abs(d_col)) < near:
            continue
        for r in range(p_row + d_row, p_row + d_row + 2):
            for c in range(p_col + d_col, p_col + d_col + 2):
                if (0 <= r < ROWS and 0 <= c < COLS and (r, c) != (p_row, p_col)
                        and not state.mob_map[level, r, c]):
                    state.map[level, r, c] = block


def _put_shot(rng, state: State, group: Mobs, directions: np.ndarray, slot: int, cell,
              player: bool) -> None:
    level = state.player_level
    p_row, p_col = state.player_position.tolist()
    row, col = cell
    if rng.random() < 0.5 and (row == p_row or col == p_col) and (row, col) != (p_row, p_col):
        direction = (int(np.sign(p_row - row)), int(np.sign(p_col - col)))     # at the player
    else:
        direction = STEPS[rng.integers(4)]
    group.position[level][slot] = (row, col)
    group.mask[level][slot] = True
    group.type_id[level][slot] = int(rng.integers(8))
    directions[level, slot] = direction
    ahead = (row + direction[0], col + direction[1])
    if (not player and rng.random() < 0.3 and 0 <= ahead[0] < ROWS and 0 <= ahead[1] < COLS
            and ahead != (p_row, p_col) and not state.mob_map[level, ahead[0], ahead[1]]):
        state.map[level, ahead[0], ahead[1]] = (BlockType.CRAFTING_TABLE, BlockType.FURNACE)[
            rng.integers(2)]


def build(case: int) -> tuple[State, Settings]:
    rng = np.random.default_rng(case)
    if case % 4 == 0:
        name = SCENARIO_NAMES[(case // 4) % len(SCENARIO_NAMES)]
        state, _ = scenarios.SCENARIOS[name].build(np.random.default_rng(case))
        level = state.player_level if rng.random() < 0.3 else int(rng.integers(9))
    else:
        state = copy.deepcopy(WORLDS[case % len(WORLDS)])
        level = BOSS_LEVEL if rng.random() < 0.2 else int(rng.integers(9))
    state.player_level = level
    if rng.random() < 0.3:      # next to the map's edge (clipped spawn windows, shots leaving)
        edge = rng.integers(0, 3)
        state.player_position[:] = (edge if rng.random() < 0.5 else ROWS - 1 - edge,
                                    rng.integers(COLS))
    cells = _free_cells(state, level)
    if not _free(state, level, *state.player_position.tolist()):
        state.player_position[:] = cells[rng.integers(len(cells))]
    p = tuple(state.player_position.tolist())

    # the ground
    if rng.random() < 0.4:
        _stamp(rng, state, level, int(BlockType.WATER), int(rng.integers(1, 12)), 2, 14)
    if level == BOSS_LEVEL and rng.random() < 0.5:
        _stamp(rng, state, level, int((BlockType.GRAVE, BlockType.GRAVE2, BlockType.GRAVE3)[
            rng.integers(3)]), int(rng.integers(1, 6)), 1, 6)
    if rng.random() < 0.3:
        _stamp(rng, state, level, int(BlockType.CRAFTING_TABLE), int(rng.integers(1, 4)), 1, 5)

    # mobs of every class and type, near and far
    empty = rng.random() < 0.1
    for kind, names in enumerate(MOB_NAMES):
        for _ in range(0 if empty else int(rng.integers(0, 4))):
            radius = int(rng.choice((1, 2, 4, 8, 12, 20)))
            cell = _near(rng, state, level, p, radius)
            if cell is not None:
                mobs.add_mob(state, names[rng.integers(len(names))], cell)
    for kind, name in enumerate(MOB_GROUPS):
        group: Mobs = getattr(state, name)
        for slot, alive in enumerate(group.mask[level]):
            group.attack_cooldown[level][slot] = int(rng.integers(-3, 7))
            if alive and rng.random() < 0.6:
                full = MOB_TYPE_HEALTH_MAPPING[group.type_id[level][slot]][kind]
                group.health[level][slot] = float32(rng.uniform(0.05, max(full, 0.1)))

    # projectiles
    if not empty:
        for player, group, directions in (
                (False, state.mob_projectiles, state.mob_projectile_directions),
                (True, state.player_projectiles, state.player_projectile_directions)):
            for slot in range(len(group.mask[level])):
                if rng.random() < 0.5:
                    continue
                if player and rng.random() < 0.4:
                    cell = p
                else:
                    cell = _near(rng, state, level, p, int(rng.choice((1, 3, 6))))
                    if cell is None:
                        continue
                    if rng.random() < 0.3:        # on a mob's cell
                        group_of = getattr(state, MOB_GROUPS[rng.integers(3)])
                        live = [c for c, a in zip(group_of.position[level], group_of.mask[level])
                                if a]
                        if live:
                            cell = live[rng.integers(len(live))]
                _put_shot(rng, state, group, directions, slot, cell, player)

    # the player
    state.player_health = float(rng.uniform(0.5, 9.0))
    state.is_sleeping = bool(rng.random() < 0.3)
    state.is_resting = bool(rng.random() < 0.2)
    state.player_dexterity = int(rng.integers(1, 6))
    state.player_intelligence = int(rng.integers(1, 6))
    state.bow_enchantment = int(rng.integers(3))
    state.inventory.armour[:] = rng.integers(0, 3, 4)
    state.armour_enchantments[:] = rng.integers(0, 3, 4)
    state.player_food = int(rng.integers(0, 10))
    state.player_hunger = float(rng.uniform(0, 1))
    state.light_level = float(rng.uniform(0, 1))
    state.monsters_killed[level] = rng.integers(0, 11)
    state.boss_progress = int(rng.integers(0, 9))
    state.boss_timesteps_to_spawn_this_round = int(rng.integers(-2, 8))
    settings = Settings(mob_despawn_distance=int(rng.choice((3, 6, 9, 10, 12, 14, 14, 20))),
                        spawning=bool(rng.random() < 0.85))
    return state, settings


# ---------------------------------------------------------------------------------------------
# Comparison


def _same(a, b, where: str) -> None:
    if isinstance(a, np.ndarray):
        assert (a.dtype, a.shape) == (b.dtype, b.shape) and a.tobytes() == b.tobytes(), where
    elif isinstance(a, Mobs):
        for f in fields(Mobs):
            x, y = getattr(a, f.name), getattr(b, f.name)
            assert x == y and repr(x) == repr(y), f"{where}.{f.name}: {x} != {y}"
    elif isinstance(a, Inventory):
        for f in fields(Inventory):
            _same(getattr(a, f.name), getattr(b, f.name), f"{where}.{f.name}")
    elif isinstance(a, float):
        assert isinstance(b, float) and repr(a) == repr(b), f"{where}: {a!r} != {b!r}"
    else:
        assert a == b and type(a) is type(b), f"{where}: {a!r} != {b!r}"


def same_states(ref: State, ker: State, tag: str) -> None:
    for f in fields(State):
        _same(getattr(ref, f.name), getattr(ker, f.name), f"{tag}: {f.name}")


def _slots(state: State):
    """[class] -> [(alive, type)] on the player's level."""
    level = state.player_level
    return [list(zip(getattr(state, name).mask[level], getattr(state, name).type_id[level]))
            for name in MOB_GROUPS]


def check(ref: State, ker: State, p, draws: Draws, before, kills_before, seen, tag) -> None:
    unpack(p, ker)
    same_states(ref, ker, tag)
    assert draws.random() == p.draws[p.ints[DRAW_AT]], f"{tag}: draws taken"
    p.ints[DRAW_AT] += 1
    assert not p.mobs[RANGED, :, 2:].any() and not p.health[RANGED, :, 2:].any(), tag
    expected = np.zeros_like(p.kills)
    level = ref.player_level
    for kind, name in enumerate(MOB_GROUPS):
        group = getattr(ref, name)
        for slot, (alive, _) in enumerate(before[kind]):
            if alive and not group.mask[level][slot]:
                if group.health[level][slot] <= 0:
                    expected[kind, group.type_id[level][slot]] += 1
                    seen[f"kill class {kind}"] += 1
                else:
                    seen[f"despawn class {kind}" + (" boss" if level == BOSS_LEVEL else "")] += 1
    assert (p.kills - kills_before == expected).all(), f"{tag}: kills"


# ---------------------------------------------------------------------------------------------
# The reference, wrapped to count branches


def _on(state: State, group: Mobs, cell) -> bool:
    """A live one of ``group`` is at ``cell`` on the player's level."""
    level = state.player_level
    return any(alive and position == cell
               for position, alive in zip(group.position[level], group.mask[level]))


@pytest.fixture
def seen(monkeypatch):
    """A Counter of the reference's branches taken, by name."""
    counts = Counter()

    def wrap(name, record):
        """``mobs.<name>`` calls ``record(result, *args)`` after each call."""
        original = getattr(mobs, name)

        def wrapper(*args, **kwargs):
            result = original(*args, **kwargs)
            record(result, *args, **kwargs)
            return result
        monkeypatch.setattr(mobs, name, wrapper)

    original_hurt = mobs.hurt_player

    def hurt(state, damage, melee=False):
        if melee:
            counts["hurt melee" + (" sleeping" if state.is_sleeping else "")] += 1
        else:
            counts["hurt shot, " + ("on the player's cell" if _on(
                state, state.mob_projectiles, tuple(state.player_position.tolist()))
                else "the next cell")] += 1
        return original_hurt(state, damage, melee)
    monkeypatch.setattr(mobs, "hurt_player", hurt)

    original_shoot = mobs._shoot

    def shoot(state, level, *args):
        counts["shoot" if False in state.mob_projectiles.mask[level] else "shoot, no slot"] += 1
        return original_shoot(state, level, *args)
    monkeypatch.setattr(mobs, "_shoot", shoot)

    def attack(result, state, row, col, damage, can_eat):
        counts[f"arrow hit={result[0]} killed={result[1]}"] += 1
        counts["arrow strikes " + ("its own cell" if _on(state, state.player_projectiles,
                                                         (row, col)) else "the next cell")] += 1
    wrap("attack_mob", attack)

    def toward(result, random, d_row, d_col):
        counts["toward tie"] += abs(d_row) == abs(d_col)
    wrap("_toward", toward)

    def cell(result, state, allowed, near, far, draws):
        table = ("ground" if allowed is mobs._SPAWN_GROUND else "water"
                 if allowed is mobs._SPAWN_WATER else "graves")
        counts[f"spawn cell {table} " + ("none" if result is None else "found")] += 1
    wrap("_spawn_cell", cell)

    def added(result, state, group, kind, type_id, cell, cooldown=None):
        if cooldown is None:    # (spawn's, not the test's add_mob)
            counts[f"spawned class {kind}" + (" boss" if state.player_level == BOSS_LEVEL else "")] \
                += result
    wrap("_add_mob", added)
    return counts


def _step_player(rng, state: State, p) -> None:
    """The player to a free cell within 2 (both copies), maybe waking or falling asleep."""
    level = state.player_level
    row, col = state.player_position.tolist()
    for _ in range(6):
        r, c = row + int(rng.integers(-2, 3)), col + int(rng.integers(-2, 3))
        if _free(state, level, r, c):
            state.player_position[:] = r, c
            p.ints[ROW], p.ints[COL] = r, c
            break
    if rng.random() < 0.2:
        state.is_sleeping = not state.is_sleeping
        p.ints[SLEEPING] = int(state.is_sleeping)


def test_update_and_spawn_lockstep(seen):
    for case in range(CASES):
        state, settings = build(case)
        ref, ker = state, copy.deepcopy(state)
        p = pack(ker, settings)
        draws = Draws(np.random.default_rng(case))
        p.draws = np.random.default_rng(case).random(2048)
        p.ints[DRAW_AT] = 0
        rng = np.random.default_rng(10_000 + case)
        seen["spawning off" if not settings.spawning else "spawning on"] += 1
        for turn in range(TURNS):
            level = ref.player_level
            live = any(True in getattr(ref, name).mask[level] for name in
                       MOB_GROUPS + ("mob_projectiles", "player_projectiles"))
            seen["update, nothing live" if not live else "update"] += 1
            map_before = ref.map[level].copy()
            before, kills_before = _slots(ref), p.kills.copy()
            shots_before = [(name, list(getattr(ref, name).mask[level]))
                            for name in ("mob_projectiles", "player_projectiles")]
            mobs.update(ref, settings, draws)
            kernel_mobs.update(p.map, p.mob_map, p.ints, p.floats, p.mobs, p.health, p.kills,
                               p.draws, p.settings)
            check(ref, ker, p, draws, before, kills_before, seen, f"case {case} turn {turn} update")
            seen["table/furnace broken"] += int((ref.map[level] != map_before).sum())
            for name, flying in shots_before:
                group = getattr(ref, name)
                for slot, alive in enumerate(flying):
                    row, col = group.position[level][slot]
                    if alive and not (0 <= row < ROWS and 0 <= col < COLS):
                        seen[f"{name} left the map"] += 1
            before, kills_before = _slots(ref), p.kills.copy()
            mobs.spawn(ref, settings, draws)
            kernel_mobs.spawn(p.map, p.mob_map, p.ints, p.floats, p.mobs, p.health, p.draws,
                              p.settings)
            check(ref, ker, p, draws, before, kills_before, seen, f"case {case} turn {turn} spawn")
            _step_player(rng, ref, p)

    print(sorted(seen.items()))
    for event, least in (
            ("update, nothing live", 20), ("spawning off", 20), ("toward tie", 50),
            ("hurt melee", 50), ("hurt melee sleeping", 20),
            ("hurt shot, on the player's cell", 20), ("hurt shot, the next cell", 50),
            ("shoot", 100), ("shoot, no slot", 5), ("table/furnace broken", 50),
            ("mob_projectiles left the map", 5), ("player_projectiles left the map", 5),
            ("arrow hit=True killed=False", 50), ("arrow hit=True killed=True", 50),
            ("arrow strikes its own cell", 20), ("arrow strikes the next cell", 20),
            ("kill class 0", 5), ("kill class 1", 5), ("kill class 2", 5),
            ("despawn class 0", 20), ("despawn class 1", 20), ("despawn class 2", 20),
            ("despawn class 0 boss", 3),
            ("spawned class 0", 50), ("spawned class 1", 50), ("spawned class 2", 50),
            ("spawned class 1 boss", 20), ("spawned class 2 boss", 20),
            ("spawn cell ground none", 20), ("spawn cell graves none", 5),
            ("spawn cell water found", 5), ("spawn cell water none", 5)):
        assert seen[event] >= least, (event, seen[event])
