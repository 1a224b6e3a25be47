"""The remembered Craftax view (``view.rows``, ``hud.hud``, the task's ``_grid``/``_hud``) shows
exactly what a plain drawing of the state shows, step after step, whatever is edited in the state
between steps: map, items, light, kill counts, mobs and projectiles, inventory and vitals, the
player's place, facing and sleep, whole arrays and mob slot lists replaced (maps also by arrays
of another dtype or layout), other map sizes.

``plain_rows`` draws the window cell by cell straight from upstream's rules as ``view``'s module
docstring states them; ``plain_hud`` is ``hud._hud`` (the HUD written out, nothing remembered)
with the scenario's progress formatted here.
"""

from __future__ import annotations

import numpy as np
import pytest

from glyphbench_rl.core.registry import make
from glyphbench_rl.games.craftax import hud, view, worldgen
from glyphbench_rl.games.craftax.mobs import is_boss_vulnerable
from glyphbench_rl.games.craftax.state import Settings
from glyphbench_rl.games.craftax.tables import BOSS_LEVEL, BlockType, ItemType, ProjectileType

MOB_CLASSES = ("melee_mobs", "passive_mobs", "ranged_mobs", "mob_projectiles", "player_projectiles")
TYPES = (8, 3, 8, 8, 8)        # type ids each class draws
INVENTORY = ("wood", "stone", "coal", "iron", "diamond", "sapling", "arrows", "torches", "ruby",
             "sapphire", "books")


def mob_glyph(k: int, type_id: int) -> str:
    if k < 3:
        return (view.MELEE_GLYPHS, view.PASSIVE_GLYPHS, view.RANGED_GLYPHS)[k][type_id][0]
    glyphs = view.MOB_PROJECTILE_GLYPHS if k == 3 else view.PLAYER_PROJECTILE_GLYPHS
    return glyphs[view.PROJECTILE_KIND[ProjectileType(type_id)]][0]


def plain_rows(state) -> tuple[str, ...]:
    """The window drawn cell by cell: off the map its glyph; an unlit cell (light <= 0.05 in
    float32) dark; else the block, the item over it (a down ladder locked below 8 kills), the
    necromancer vulnerable on the graveyard when no melee or ranged mob is there and the wave is
    over; then mobs and projectiles in class order on lit cells; the player in the middle."""
    level = state.player_level
    pr, pc = (int(v) for v in state.player_position)
    levels, height, width = state.map.shape
    grid = []
    for r in range(pr - 4, pr + 5):
        row = []
        for c in range(pc - 5, pc + 6):
            if not (0 <= r < height and 0 <= c < width):
                row.append(view.BLOCK_GLYPHS[BlockType.OUT_OF_BOUNDS][0])
            elif np.float32(state.light_map[level, r, c]) <= np.float32(0.05):
                row.append(view.DARK[0])
            else:
                item, block = int(state.item_map[level, r, c]), int(state.map[level, r, c])
                if item:
                    if item == ItemType.LADDER_DOWN and state.monsters_killed[level] < 8:
                        item = ItemType.LADDER_DOWN_BLOCKED
                    row.append(view.ITEM_GLYPHS[ItemType(item)][0])
                else:
                    if (block == BlockType.NECROMANCER and level == BOSS_LEVEL
                            and is_boss_vulnerable(state)):
                        block = BlockType.NECROMANCER_VULNERABLE
                    row.append(view.BLOCK_GLYPHS[BlockType(block)][0])
        grid.append(row)
    for k, name in enumerate(MOB_CLASSES):
        mobs = getattr(state, name)
        for slot, alive in enumerate(mobs.mask[level]):
            if alive:
                r = mobs.position[level][slot][0] - pr + 4
                c = mobs.position[level][slot][1] - pc + 5
                if 0 <= r < 9 and 0 <= c < 11 and grid[r][c] != view.DARK[0]:
                    grid[r][c] = mob_glyph(k, mobs.type_id[level][slot])
    grid[4][5] = view.PLAYER_GLYPHS[0 if state.is_sleeping else state.player_direction][0]
    return tuple("".join(row) for row in grid)


def plain_hud(task) -> str:
    line = hud._hud(task.state)
    goal = " ".join(f"{key.split('.')[-1].capitalize()} {_fmt(task.tally.value(key))}"
                    for key in task.scenario.progress_keys)
    return f"{line} | {goal}" if goal else line


def _fmt(v) -> str:
    return f"{v:g}" if isinstance(v, float) else str(v)


def edit(state, rng: np.random.Generator) -> None:
    """A few random edits of what the view and the HUD read, most near the player."""
    level = state.player_level
    pr, pc = (int(v) for v in state.player_position)
    _, height, width = state.map.shape

    def near():
        return (int(np.clip(pr + rng.integers(-5, 6), 0, height - 1)),
                int(np.clip(pc + rng.integers(-6, 7), 0, width - 1)))

    for _ in range(int(rng.integers(0, 4))):
        what = int(rng.integers(0, 16))
        if what == 0:
            state.map[(level, *near())] = rng.integers(0, len(BlockType))
        elif what == 1:
            state.item_map[(level, *near())] = rng.integers(0, len(ItemType))
        elif what == 2:
            state.light_map[(level, *near())] = rng.choice([0.0, 0.05, 0.0500001, 0.3, 1.0])
        elif what == 3:
            state.monsters_killed[level] = rng.integers(0, 11)
        elif what == 4:
            k = int(rng.integers(0, 5))
            mobs = getattr(state, MOB_CLASSES[k])
            slot = int(rng.integers(0, len(mobs.mask[level])))
            mobs.mask[level][slot] = not mobs.mask[level][slot]
            mobs.position[level][slot] = near()
            mobs.type_id[level][slot] = int(rng.integers(0, TYPES[k]))
        elif what == 5:       # a floor's slots of one class all emptied
            mobs = getattr(state, MOB_CLASSES[int(rng.integers(0, 5))])
            floor = int(rng.integers(0, len(mobs.mask)))
            mobs.mask[floor] = [False] * len(mobs.mask[floor])
        elif what == 6:
            name = INVENTORY[int(rng.integers(0, len(INVENTORY)))]
            setattr(state.inventory, name, int(rng.integers(0, 4)))
        elif what == 7:
            inv = state.inventory
            inv.pickaxe, inv.sword, inv.bow = (int(x) for x in rng.integers(0, [5, 5, 2]))
            state.sword_enchantment, state.bow_enchantment = (int(x) for x in rng.integers(0, 3, 2))
        elif what == 8:
            state.inventory.armour[int(rng.integers(0, 4))] = rng.integers(0, 3)
            state.armour_enchantments[int(rng.integers(0, 4))] = rng.integers(0, 3)
            state.inventory.potions[int(rng.integers(0, 6))] = rng.integers(0, 3)
            state.learned_spells[int(rng.integers(0, 2))] = rng.integers(0, 2)
        elif what == 9:
            state.player_health = float(rng.choice([9.0, 4.3, 0.5, 6.0]))
            state.player_food, state.player_drink, state.player_energy, state.player_mana = (
                int(x) for x in rng.integers(0, 10, 4))
        elif what == 10:
            state.player_strength, state.player_dexterity, state.player_intelligence = (
                int(x) for x in rng.integers(1, 4, 3))
            state.player_xp = int(rng.integers(0, 3))
        elif what == 11:
            state.player_direction = int(rng.integers(1, 5))
            state.is_sleeping, state.is_resting = (bool(x) for x in rng.integers(0, 2, 2))
            state.light_level = float(rng.choice([1.0, 0.2]))
        elif what == 12:      # the player put elsewhere, now and then by the map's edge
            r, c = int(rng.integers(0, height)), int(rng.integers(0, width))
            if rng.random() < 0.5:
                r = int(rng.choice([0, 1, 3, height - 4, height - 1]))
            state.player_position[:] = (r, c)
            pr, pc = r, c
        elif what == 13:      # whole arrays or slot lists replaced by copies (the view must
            # not keep the old)
            name = str(rng.choice(["map", "item_map", "light_map", "monsters_killed", *MOB_CLASSES]))
            if name in MOB_CLASSES:
                mobs = getattr(state, name)
                field = str(rng.choice(["mask", "position", "type_id"]))
                setattr(mobs, field, [list(slots) for slots in getattr(mobs, field)])
            else:
                setattr(state, name, getattr(state, name).copy())
        elif what == 14:      # another floor
            state.player_level = level = int(rng.integers(0, len(state.map)))
        else:                 # the light of a whole floor
            state.light_map[level] = rng.choice([0.0, 1.0, 0.5])


@pytest.mark.parametrize("name", ["firstday", "fight-skeletons", "dungeonexplore", "necromancer",
                                  "gatherresources", "survivenight"])
def test_task_grid_and_hud_follow_every_edit(name):
    task = make(f"glyphbench/craftax-{name}-v0")
    rng = np.random.default_rng(5)
    for episode in range(2):
        task.reset(seed=episode)
        for turn in range(150):
            if task.done:
                break
            task.step(int(rng.integers(task.action_space.n)))
            assert task._grid() == plain_rows(task.state), (name, turn)
            assert task._hud() == plain_hud(task), (name, turn)
            if turn % 3:
                edit(task.state, rng)
                assert task._grid() == plain_rows(task.state), (name, turn, "edited")
                assert task._hud() == plain_hud(task), (name, turn, "edited")


def test_episodes_stepped_in_turn_each_show_their_own_state():
    tasks = [make(f"glyphbench/craftax-{name}-v0") for name in ("firstday", "dungeonexplore",
                                                                "fight-zombies")]
    rng = np.random.default_rng(9)
    for seed, task in enumerate(tasks):
        task.reset(seed=seed)
    for turn in range(120):
        for task in tasks:
            if task.done:
                task.reset(seed=turn)
            task.step(int(rng.integers(task.action_space.n)))
            if turn % 2:
                edit(task.state, rng)
            assert task._grid() == plain_rows(task.state), turn
            assert task._hud() == plain_hud(task), turn


def test_view_of_edited_states_and_other_layouts():
    rng = np.random.default_rng(11)
    state = worldgen.generate(np.random.default_rng(3), Settings())
    for turn in range(1500):
        edit(state, rng)
        if turn % 100 == 50:       # maps kept in another dtype or memory layout
            state.map = np.asfortranarray(state.map.astype(np.int64))
            state.light_map = state.light_map.astype(np.float64)
        elif turn % 100 == 99:
            state.map = np.ascontiguousarray(state.map, np.int32)
            state.light_map = np.ascontiguousarray(state.light_map, np.float32)
        assert view.rows(state) == plain_rows(state), turn
        assert hud.hud(state) == hud._hud(state), turn
        codes = view.cell_codes(state)
        assert "".join(view._TABLE[code] for code in codes.ravel().tolist()) == "".join(plain_rows(state))


def test_view_of_a_smaller_map():
    rng = np.random.default_rng(2)
    state = worldgen.generate(np.random.default_rng(4), Settings())
    state.map, state.item_map, state.light_map = (
        np.ascontiguousarray(a[:, 5:20, 10:40]) for a in (state.map, state.item_map, state.light_map))
    state.player_position[:] = (7, 15)
    for mobs in (getattr(state, name) for name in MOB_CLASSES):
        mobs.mask = [[False] * len(slots) for slots in mobs.mask]
    for turn in range(600):
        edit(state, rng)
        assert view.rows(state) == plain_rows(state), turn


def test_a_mob_on_the_player_or_in_the_dark_is_not_drawn():
    state = worldgen.generate(np.random.default_rng(0), Settings())
    level = state.player_level = 0
    pr, pc = (int(v) for v in state.player_position)
    for name in MOB_CLASSES:
        mobs = getattr(state, name)
        mobs.mask = [[False] * len(slots) for slots in mobs.mask]
    mobs = state.melee_mobs
    mobs.mask[level][:2] = [True, True]
    mobs.position[level][0] = (pr, pc)                   # on the player
    mobs.position[level][1] = (pr - 1, pc)
    mobs.type_id[level][:2] = [0, 0]
    assert view.rows(state)[4][5] == view.PLAYER_GLYPHS[state.player_direction][0]
    assert view.rows(state)[3][5] == "z"
    state.light_map[level, pr - 1, pc] = 0.0
    assert view.rows(state)[3][5] == view.DARK[0] == plain_rows(state)[3][5]
