"""The compiled view (``kernel_view``) and the packed HUD (``hud.packed_hud``) against the
reference (``view.cell_codes``, ``view.rows``, ``hud.hud``) on many states: the 60 scenarios'
starts, each varied at random many times (every floor, the player anywhere and at the map's
edges and corners, every facing, asleep or resting, night and darkness, torches, ladders open
and closed, blocks of every kind, the necromancer vulnerable or not, mobs of every class and
type and projectiles of every kind around the player, on it and in the dark, every kind of
inventory, gear, enchantment, potion, spell and attribute), one state edited step after step
through one ``Packed`` (as a task keeps it), maps of other dtypes and layouts, codes with no
glyph; and tasks played with random actions, compared at every step.
"""

from __future__ import annotations

from collections import Counter

import numpy as np
import pytest

from glyphbench_rl.games.craftax import hud, kernel_view, mobs, view
from glyphbench_rl.games.craftax.bestiary import MOB_NAMES
from glyphbench_rl.games.craftax.packed import pack
from glyphbench_rl.games.craftax.scenarios import SCENARIOS
from glyphbench_rl.games.craftax.state import NUM_LEVELS
from glyphbench_rl.games.craftax.tables import BOSS_LEVEL, BlockType, ItemType

GROUPS = ("melee_mobs", "passive_mobs", "ranged_mobs", "mob_projectiles", "player_projectiles")
NAMES = [name for names in MOB_NAMES for name in names]     # every mob, class by class
INVENTORY = ("wood", "stone", "coal", "iron", "diamond", "sapling", "arrows", "torches", "ruby",
             "sapphire", "books")
# every code that has a glyph (the row end, 255, is no cell's)
GLYPH_CODES = {code for code in view._TABLE if code != view._NEWLINE}
LIGHTS = (0.0, 0.05, 0.0500001, 0.04, 0.3, 1.0)


def compare(state, settings, out, seen: Counter | None = None, p=None) -> None:
    """The kernel's codes and rows and the packed HUD equal the reference's (``p``: a Packed to
    pack into, as a task does, else a new one)."""
    p = pack(state, settings, into=p)
    expected = view.cell_codes(state)
    out[:] = 0
    kernel_view.codes(p.map, p.item_map, p.mob_map, p.light_map, p.ints, p.mobs, out)
    assert out.tobytes() == expected.tobytes(), (out, expected)
    assert kernel_view.rows(p, out) == view.rows(state)
    assert hud.packed_hud(p) == hud.hud(state) == hud._hud(state)
    if seen is not None:
        seen.update(out.ravel().tolist())
        line = hud.hud(state)
        seen.update(f"hud:{word}" for word in ("Sleeping", "Resting", "Night", "Day", " dark",
                                               "Kills", "(max", "/1", "Potions", "Spells", "XP",
                                               "Dex", "Str", "Int", "fire", "ice", "iron h",
                                               "diamond b", "bow", "wood pickaxe", "Books", ".")
                    if word in line)
        seen[f"hud:floor {state.player_level}"] += 1


def near(state, rng, spread=(5, 6)):
    """A cell of the player's floor in (or just past) the window."""
    _, rows, cols = state.map.shape
    pr, pc = state.player_position.tolist()
    return (int(np.clip(pr + rng.integers(-spread[0], spread[0] + 1), 0, rows - 1)),
            int(np.clip(pc + rng.integers(-spread[1], spread[1] + 1), 0, cols - 1)))


def vary(state, rng) -> None:
    """Random edits of everything the view and the HUD read."""
    _, rows, cols = state.map.shape
    if rng.random() < 0.4:                      # another floor, the player anywhere on it
        state.player_level = int(rng.integers(0, NUM_LEVELS))
        r, c = int(rng.integers(0, rows)), int(rng.integers(0, cols))
        if rng.random() < 0.5:                  # by an edge or in a corner
            r = int(rng.choice([0, 1, 3, 4, rows - 5, rows - 2, rows - 1, r]))
            c = int(rng.choice([0, 1, 4, 5, cols - 6, cols - 2, cols - 1, c]))
        state.player_position[:] = (r, c)
    level = state.player_level
    state.player_direction = int(rng.integers(1, 5))
    state.is_sleeping, state.is_resting = (bool(x) for x in rng.random(2) < 0.25)
    state.light_level = float(rng.choice([0.0, 0.2, 0.4999, 0.5, 0.75, 1.0]))
    for _ in range(int(rng.integers(0, 12))):   # blocks, items, light, around the player
        cell = (level, *near(state, rng))
        what = rng.integers(0, 4)
        if what == 0:
            state.map[cell] = rng.integers(0, len(BlockType))
        elif what == 1:
            state.item_map[cell] = rng.integers(0, len(ItemType))
        else:
            state.light_map[cell] = rng.choice(LIGHTS)
    if rng.random() < 0.15:                     # a dark floor, or patches lit by a torch
        state.light_map[level] = rng.choice([0.0, 0.05, 1.0])
        for _ in range(int(rng.integers(0, 4))):
            r, c = near(state, rng)
            state.item_map[level, r, c] = ItemType.TORCH
            state.light_map[level, max(r - 2, 0):r + 3, max(c - 2, 0):c + 3] = 0.8
    if rng.random() < 0.3:                      # ladders, open or closed
        for item in (ItemType.LADDER_DOWN, ItemType.LADDER_UP, ItemType.LADDER_DOWN_BLOCKED):
            state.item_map[(level, *near(state, rng))] = item
    state.monsters_killed[level] = int(rng.choice([0, 3, 7, 8, 9, 12]))
    if level == BOSS_LEVEL or rng.random() < 0.1:     # the necromancer and its wave
        state.map[(level, *near(state, rng, (2, 3)))] = BlockType.NECROMANCER
        state.boss_timesteps_to_spawn_this_round = int(rng.choice([-3, 0, 0, 1, 7]))
        if rng.random() < 0.5:
            for name in ("melee_mobs", "ranged_mobs"):
                group = getattr(state, name)
                group.mask[level] = [False] * len(group.mask[level])
    for _ in range(int(rng.integers(0, 7))):    # mobs by name (on a walkable cell)
        r, c = near(state, rng)
        if rng.random() < 0.5:
            state.map[level, r, c] = BlockType.PATH
        mobs.add_mob(state, NAMES[int(rng.integers(0, len(NAMES)))], (r, c))
    for _ in range(int(rng.integers(0, 6))):    # any slot of any class: projectiles, a mob on
        # the player, in the dark, outside the window, switched off
        group = getattr(state, GROUPS[int(rng.integers(0, 5))])
        slot = int(rng.integers(0, len(group.mask[level])))
        group.mask[level][slot] = bool(rng.random() < 0.8)
        where = rng.random()
        group.position[level][slot] = (tuple(state.player_position.tolist()) if where < 0.1
                                       else near(state, rng, (7, 8)))
        group.type_id[level][slot] = int(rng.integers(0, 3 if group is state.passive_mobs else 8))
    if rng.random() < 0.05:                     # a class emptied on every floor
        group = getattr(state, GROUPS[int(rng.integers(0, 5))])
        group.mask = [[False] * len(slots) for slots in group.mask]
    # the HUD's values
    inv = state.inventory
    for name in INVENTORY:
        setattr(inv, name, int(rng.choice([0, 0, 0, 1, 2, 9, 99])))
    inv.pickaxe, inv.sword = (int(x) for x in rng.integers(0, 5, 2))
    inv.bow = int(rng.integers(0, 2))
    state.sword_enchantment, state.bow_enchantment = (int(x) for x in rng.integers(0, 3, 2))
    inv.armour[:] = rng.integers(0, 3, 4) * (rng.random() < 0.7)
    state.armour_enchantments[:] = rng.integers(0, 3, 4)
    inv.potions[:] = rng.integers(0, 3, 6) * (rng.random(6) < 0.4)
    state.learned_spells[:] = rng.random(2) < 0.4
    state.player_xp = int(rng.choice([0, 0, 1, 4]))
    state.player_strength, state.player_dexterity, state.player_intelligence = (
        int(x) for x in rng.choice([1, 1, 1, 2, 5], 3))
    state.player_health = float(rng.choice([9.0, 10.0, 4.3, 0.5, 6.25, 7.05, 0.04, 1.0 / 3, 0.0,
                                            -0.5, 12.0]))
    state.player_food, state.player_drink, state.player_energy, state.player_mana = (
        int(x) for x in rng.integers(0, 12, 4))


@pytest.fixture(scope="module")
def seen():
    return Counter()


@pytest.mark.parametrize("names", [list(SCENARIOS)[i::4] for i in range(4)])
def test_scenario_starts_and_random_variations(names, seen):
    out = np.zeros((view.ROWS, view.COLS), np.uint8)
    for n, name in enumerate(names):
        scenario = SCENARIOS[name]
        rng = np.random.default_rng(n)
        state, _ = scenario.build(rng)
        compare(state, scenario.settings, out, seen)
        for _ in range(30):
            vary(state, rng)
            compare(state, scenario.settings, out, seen)


def _set(name, values):
    def change(state, rng):
        obj, _, field = name.rpartition(".")
        setattr(state.inventory if obj else state, field, values[int(rng.integers(0, len(values)))])
    return change


def _toggle(name, size):
    def change(state, rng):
        array = getattr(state.inventory if name in ("armour", "potions") else state, name)
        i = int(rng.integers(0, size))
        array[i] = (array[i] + 1) % 3 if array.dtype != bool else not array[i]
    return change


# single changes of each value the HUD reads (another helper may key on all of them but one)
ONE_VALUE = (
    _set("player_direction", (1, 2, 3, 4)), _set("player_health", (9.0, 8.5, 3.2)),
    _set("player_food", (3, 9)), _set("player_drink", (3, 9)), _set("player_energy", (3, 9)),
    _set("player_mana", (3, 9)), _set("is_sleeping", (False, True)),
    _set("is_resting", (False, True)), _set("player_xp", (0, 2)),
    _set("player_dexterity", (1, 2)), _set("player_strength", (1, 2)),
    _set("player_intelligence", (1, 2)), _set("sword_enchantment", (0, 1, 2)),
    _set("bow_enchantment", (0, 1, 2)), _set("light_level", (0.3, 1.0)),
    *(_set(f"inventory.{name}", (0, 1, 2)) for name in (*INVENTORY, "pickaxe", "sword", "bow")),
    _toggle("armour", 4), _toggle("potions", 6), _toggle("armour_enchantments", 4),
    _toggle("learned_spells", 2),
    lambda state, rng: state.monsters_killed.__setitem__(state.player_level,
                                                         int(rng.integers(6, 10))),
)


def test_one_state_edited_step_after_step_through_one_packed(seen):
    """A task's use: one State and one Packed, edited a little each step (the memos see each
    change), with every floor visited."""
    scenario = SCENARIOS["firstday"]
    rng = np.random.default_rng(99)
    state, _ = scenario.build(rng)
    p = pack(state, scenario.settings)
    out = np.zeros((view.ROWS, view.COLS), np.uint8)
    for turn in range(1500):
        if turn % 10 == 0:
            vary(state, rng)
        else:       # small steps: a move, or one value the HUD shows changed alone
            what = int(rng.integers(0, len(ONE_VALUE) + 1))
            if what == len(ONE_VALUE):
                _, rows, cols = state.map.shape
                r, c = state.player_position.tolist()
                state.player_position[:] = (int(np.clip(r + rng.integers(-1, 2), 0, rows - 1)),
                                            int(np.clip(c + rng.integers(-1, 2), 0, cols - 1)))
            else:
                ONE_VALUE[what](state, rng)
        compare(state, scenario.settings, out, seen, p)


def test_maps_of_other_dtypes_and_layouts_are_refused_by_name():
    scenario = SCENARIOS["dungeonexplore"]
    state, _ = scenario.build(np.random.default_rng(5))
    state.map = np.asfortranarray(state.map)
    with pytest.raises(ValueError, match="map must be a C-contiguous int32 array"):
        pack(state, scenario.settings)
    state.map = np.ascontiguousarray(state.map)
    state.light_map = state.light_map.astype(np.float64)
    with pytest.raises(ValueError, match="light_map must be a C-contiguous float32"):
        pack(state, scenario.settings)


def test_a_code_with_no_glyph_raises_as_the_view_does():
    scenario = SCENARIOS["firstday"]
    state, _ = scenario.build(np.random.default_rng(0))
    level, (r, c) = state.player_level, state.player_position.tolist()
    state.light_map[level] = 1.0
    state.item_map[level, r - 1, c] = 0
    state.map[level, r - 1, c] = 100          # no glyph
    p = pack(state, scenario.settings)
    out = np.zeros((view.ROWS, view.COLS), np.uint8)
    kernel_view.codes(p.map, p.item_map, p.mob_map, p.light_map, p.ints, p.mobs, out)
    assert out.tobytes() == view.cell_codes(state).tobytes() and out[3, 5] == 100
    with pytest.raises(UnicodeDecodeError):
        view.rows(state)
    with pytest.raises(UnicodeDecodeError):
        kernel_view.rows(p, out)
    state.map[level, r - 1, c] = 256 + BlockType.TREE     # (a block is read by its low byte)
    compare(state, scenario.settings, out)
    assert kernel_view.rows(pack(state, scenario.settings), out)[3][5] == "T"
    state.map[level, r - 1, c] = view._NEWLINE         # (the row end's code, a glyph: "\n")
    compare(state, scenario.settings, out)
    assert kernel_view.rows(pack(state, scenario.settings), out)[3][5] == "\n"


@pytest.mark.parametrize("name", ["firstday", "fight-skeletons", "necromancer", "dungeonexplore",
                                  "night-horde-no-shelter", "torchdescend"])
def test_played_tasks_at_every_step(name, seen):
    from glyphbench_rl import make
    task = make(f"glyphbench/craftax-{name}-v0")
    rng = np.random.default_rng(7)
    out = np.zeros((view.ROWS, view.COLS), np.uint8)
    steps = episode = 0
    while steps < 250:      # (episodes of up to 150 steps; a lost fight ends sooner)
        task.reset(seed=episode)
        episode += 1
        compare(task.state, task.settings, out, seen)
        for _ in range(150):
            if task.done:
                break
            task.step(int(rng.integers(task.action_space.n)))
            compare(task.state, task.settings, out, seen)
            steps += 1


def test_coverage(seen):
    """(Runs last: what the tests above drew.) Every code with a glyph was drawn, and every
    kind of HUD part written, on every floor."""
    if not seen:
        pytest.skip("run with the tests above")
    missing = sorted(GLYPH_CODES - set(seen))
    assert not missing, [view._TABLE[code] for code in missing]
    words = ("Sleeping", "Resting", "Night", "Day", " dark", "Kills", "(max", "/1", "Potions",
             "Spells", "XP", "Dex", "Str", "Int", "fire", "ice", "iron h", "diamond b", "bow",
             "wood pickaxe", "Books", ".")
    assert all(seen[f"hud:{word}"] for word in words), [w for w in words if not seen[f"hud:{w}"]]
    assert all(seen[f"hud:floor {level}"] for level in range(NUM_LEVELS))
    print(f"\ncells drawn by code: dark {seen[view._DARK]}, off the map {seen[int(BlockType.OUT_OF_BOUNDS)]}, "
          f"necromancer {seen[int(BlockType.NECROMANCER)]} / vulnerable "
          f"{seen[int(BlockType.NECROMANCER_VULNERABLE)]}, ladder open "
          f"{seen[view._ITEM0 + ItemType.LADDER_DOWN]} / locked "
          f"{seen[view._ITEM0 + ItemType.LADDER_DOWN_BLOCKED]}, mobs and projectiles "
          f"{sum(seen[c] for c in range(view._MOB0, 256))}, least drawn glyph "
          f"{min(seen[c] for c in GLYPH_CODES)}")

