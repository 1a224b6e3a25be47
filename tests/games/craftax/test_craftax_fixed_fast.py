"""The step's fixed costs cut short give what the plain rules give: ``clip_vitals`` and
``inventory_achievements`` looking the held counts up; ``is_near_block`` reading a window;
``player_can_enter`` written out; ``daylight`` remembered; a term's units; the tally's
holdings written out; the task asking a steady test (terms, success, events, the HUD's
progress) only after a step in which a steady counter changed."""

import numpy as np
import pytest

from glyphbench_rl import make
from glyphbench_rl.games.craftax import kernel, rules, scenarios, upkeep, worldgen
from glyphbench_rl.games.craftax.packed import LEVEL
from glyphbench_rl.games.craftax.state import Settings
from glyphbench_rl.games.craftax.tables import (
    CLOSE_BLOCKS, GOD_MODE_MIN_HEALTH, INVENTORY_ACHIEVEMENTS, NUM_LEVELS, PLANT_RIPE_AGE,
    STACK_LIMIT, Action, BlockType, light_level, max_food, max_health, max_mana)

COUNTS = ("wood", "stone", "coal", "iron", "diamond", "sapling", "pickaxe", "sword", "bow",
          "arrows", "torches", "ruby", "sapphire", "books")


def plain_clip_vitals(state, settings) -> None:
    """Every count and vital clipped, as upstream writes it."""
    inv = state.inventory
    for name in COUNTS:
        setattr(inv, name, min(getattr(inv, name), STACK_LIMIT))
    low = GOD_MODE_MIN_HEALTH if settings.god_mode else 0
    health = state.player_health
    if health < low or health > max_health(state.player_strength):
        state.player_health = float(min(max(health, low), max_health(state.player_strength)))
    top = max_food(state.player_dexterity)
    for name in ("player_food", "player_drink", "player_energy"):
        setattr(state, name, min(max(getattr(state, name), 0), top))
    state.player_mana = min(max(state.player_mana, 0), max_mana(state.player_intelligence))


def plain_inventory_achievements(state) -> None:
    for name, least, achievement in INVENTORY_ACHIEVEMENTS:
        if getattr(state.inventory, name) >= least:
            state.achievements[achievement] = True


def _snapshot(state) -> tuple:
    inv = state.inventory
    return (tuple((getattr(inv, n), type(getattr(inv, n))) for n in COUNTS),
            tuple((getattr(state, n), type(getattr(state, n))) for n in (
                "player_health", "player_food", "player_drink", "player_energy", "player_mana")),
            state.achievements.tobytes())


@pytest.mark.parametrize("god_mode", [False, True])
def test_clip_vitals_and_inventory_achievements_as_the_plain_rules(god_mode):
    rng = np.random.default_rng(11)
    settings = Settings(god_mode=god_mode)
    base = worldgen.blank(settings)
    for _ in range(600):
        fast, plain = base.copy(), base.copy()
        for state in (fast, plain):
            state.achievements[:] = False
        counts = rng.integers(0, 3, len(COUNTS)) * (rng.random(len(COUNTS)) < 0.4)
        if rng.random() < 0.3:          # now and then a count over the stack limit
            counts[int(rng.integers(len(COUNTS)))] = int(rng.integers(98, 130))
        earned = rng.random(fast.achievements.size) < 0.3 * rng.random()
        vitals = (float(rng.integers(-3, 14)) / (2 if rng.random() < 0.3 else 1),
                  *(int(x) for x in rng.integers(-2, 13, 4)))
        attributes = (int(x) for x in rng.integers(0, 4, 3))     # (0: below any state's)
        for state in (fast, plain):
            for name, n in zip(COUNTS, counts.tolist()):
                setattr(state.inventory, name, n)
            state.achievements[:] = earned
            (state.player_health, state.player_food, state.player_drink, state.player_energy,
             state.player_mana) = vitals
        (fast.player_strength, fast.player_dexterity, fast.player_intelligence) = attributes
        plain.player_strength, plain.player_dexterity, plain.player_intelligence = (
            fast.player_strength, fast.player_dexterity, fast.player_intelligence)
        upkeep.clip_vitals(fast, settings)
        upkeep.inventory_achievements(fast)
        plain_clip_vitals(plain, settings)
        plain_inventory_achievements(plain)
        assert _snapshot(fast) == _snapshot(plain)


def test_the_upkeep_remembering_its_last_look_up_follows_edits_between_steps():
    """``clip_vitals`` and ``inventory_achievements`` as the step calls them (the held counts
    ``clip_vitals`` returns passed on) on one state edited now and then between calls, as
    scenario events and tests do (an achievement cleared, a count changed, or nothing: the
    remembered look-ups are then used), give what the plain rules give on a copy."""
    rng = np.random.default_rng(12)
    settings = Settings()
    state = worldgen.blank(settings)
    remembered = 0
    for _ in range(3000):
        what = rng.random()
        if what < 0.25:
            name = COUNTS[int(rng.integers(len(COUNTS)))]
            setattr(state.inventory, name, int(rng.integers(0, 3)) if rng.random() < 0.9
                    else int(rng.integers(98, 120)))
        elif what < 0.5:
            state.achievements[int(rng.integers(state.achievements.size))] = bool(
                rng.random() < 0.3)
        elif what < 0.55:
            state.player_food = int(rng.integers(-2, 12))
        plain = state.copy()
        remembered += upkeep.held_counts(state.inventory) == upkeep._EARNED[0][0] and (
            state.achievements.tobytes() == upkeep._EARNED[0][1])
        held = upkeep.clip_vitals(state, settings)
        after = upkeep.inventory_achievements(state, held)
        plain_clip_vitals(plain, settings)
        plain_inventory_achievements(plain)
        assert _snapshot(state) == _snapshot(plain)
        assert held == upkeep.held_counts(state.inventory)
        assert after == state.achievements.tobytes()
    assert 500 < remembered < 2900


def _plain_grow_plants(state) -> None:
    state.growing_plants_age += 1
    state.growing_plants_age *= state.growing_plants_mask
    for i in np.flatnonzero(state.growing_plants_age >= PLANT_RIPE_AGE):
        r, c = state.growing_plants_positions[i]
        state.map[0, r, c] = int(BlockType.RIPE_PLANT)


def test_grow_plants_skipping_no_plants_is_the_plain_rule():
    """No plant and every age 0 returns at once; any plant, a stray age of a free slot, or
    slots kept in other dtypes take the rule, as the plain rule does."""
    rng = np.random.default_rng(13)
    state = worldgen.blank(Settings())
    skipped = 0
    for turn in range(1500):
        what = rng.random()
        if what < 0.05:
            state.growing_plants_mask[int(rng.integers(10))] = True
        elif what < 0.1:
            state.growing_plants_mask[:] = False
        elif what < 0.12:
            state.growing_plants_age[int(rng.integers(10))] = int(rng.integers(0, 700))
        elif what < 0.13:
            state.growing_plants_age = state.growing_plants_age.astype(
                np.int64 if state.growing_plants_age.dtype == np.int32 else np.int32)
        if rng.random() < 0.1:
            state.growing_plants_positions[:] = rng.integers(0, 48, (10, 2))
        plain = state.copy()
        skipped += not state.growing_plants_mask.any() and not state.growing_plants_age.any()
        upkeep.grow_plants(state)
        _plain_grow_plants(plain)
        assert np.array_equal(state.map, plain.map), turn
        assert state.growing_plants_age.tobytes() == plain.growing_plants_age.tobytes(), turn
        assert state.growing_plants_age.dtype == plain.growing_plants_age.dtype
    assert 100 < skipped < 1400


def test_is_near_block_reads_the_eight_cells_around_the_player():
    """Also at the map's edges and corners, and with the block under the player (god mode)."""
    rng = np.random.default_rng(2)
    state = worldgen.blank(Settings())
    _, rows, cols = state.map.shape
    table = int(BlockType.CRAFTING_TABLE)
    near = 0
    for _ in range(3000):
        level = int(rng.integers(NUM_LEVELS))
        r = int(rng.choice([0, 1, rows - 2, rows - 1, int(rng.integers(rows))]))
        c = int(rng.choice([0, 1, cols - 2, cols - 1, int(rng.integers(cols))]))
        state.player_level, state.player_position[:] = level, (r, c)
        state.map[level, max(r - 2, 0):r + 3, max(c - 2, 0):c + 3] = int(BlockType.GRASS)
        for _ in range(int(rng.integers(0, 3))):
            rr, cc = r + int(rng.integers(-2, 3)), c + int(rng.integers(-2, 3))
            if 0 <= rr < rows and 0 <= cc < cols:
                state.map[level, rr, cc] = table
        plain = any(0 <= r + dr < rows and 0 <= c + dc < cols
                    and state.map[level, r + dr, c + dc] == table for dr, dc in CLOSE_BLOCKS)
        assert rules.is_near_block(state, table) == plain
        near += plain
    assert 0 < near < 3000


def test_player_can_enter_is_free_and_neither_water_nor_lava():
    rng = np.random.default_rng(6)
    state = worldgen.generate(rng, Settings())
    _, rows, cols = state.map.shape
    water, lava = int(BlockType.WATER), int(BlockType.LAVA)
    seen = set()
    for _ in range(4000):
        state.player_level = level = int(rng.integers(NUM_LEVELS))
        r, c = (int(x) for x in rng.integers(-2, [rows + 2, cols + 2]))
        if 0 <= r < rows and 0 <= c < cols and rng.random() < 0.3:
            state.map[level, r, c] = int(rng.choice([water, lava, int(rng.integers(len(BlockType)))]))
        plain = (rules.is_free(state, level, (r, c))
                 and state.map[level, r, c] not in (water, lava))
        assert rules.player_can_enter(state, r, c) == plain
        seen.add(plain)
    assert seen == {True, False}


def test_daylight_remembered_is_light_level():
    rng = np.random.default_rng(3)
    for day_length in (300, 7, 1000):
        settings = Settings(day_length=day_length)
        for t in [*rng.integers(0, 20_000, 300).tolist(), *range(0, 700)]:
            assert upkeep.daylight(t, settings) == light_level(t, day_length)
    assert upkeep.daylight(5, Settings(daylight=False)) == 1.0


def _ask_everything(task) -> None:
    """Make ``task`` ask every test after every step (the plain way)."""
    task._live = task._open
    task._success_live = task._success is not None
    task.events = [(event, when, False) for event, when, _ in task.events]
    task._goal_steady = False


def _edit(state, rng) -> None:
    """An edit between steps of what steady counters read off the state."""
    what = int(rng.integers(0, 4))
    if what == 0:
        name = COUNTS[int(rng.integers(len(COUNTS)))]
        setattr(state.inventory, name, int(rng.integers(0, 2 if name == "bow" else 5)))
    elif what == 1:
        state.achievements[int(rng.integers(state.achievements.size))] = bool(rng.integers(2))
    elif what == 2:
        state.player_level = int(rng.integers(0, NUM_LEVELS))
    else:
        state.inventory.armour[int(rng.integers(4))] = int(rng.integers(0, 3))


@pytest.mark.parametrize("name", ["firstday", "iron-bootstrap", "gatherresources", "choptrees",
                                  "fight-zombies", "reach-dungeon", "survivehorde",
                                  "plant-farm", "xp-attribute-spend", "potion-id-stakes"])
def test_steady_tests_asked_only_after_a_change_pay_and_end_as_asked_every_step(name):
    fast, plain = make(f"glyphbench/craftax-{name}-v0"), make(f"glyphbench/craftax-{name}-v0")
    rng = np.random.default_rng(4)
    edits = 0
    for seed in range(3):
        fast.reset(seed=seed)
        plain.reset(seed=seed)
        _ask_everything(plain)
        assert fast._hud() == plain._hud()
        for turn in range(300):
            # (DO two turns in five: kills and gathering happen)
            action = int(Action.DO) if rng.random() < 0.4 else int(rng.integers(fast.action_space.n))
            a, b = fast.step(action), plain.step(action)
            assert a[0] == b[0] and a[1:4] == b[1:4], (name, seed, turn)
            assert fast._hud() == plain._hud(), (name, seed, turn)
            if fast.done:
                break
            if seed and rng.random() < 0.2:       # the later episodes edited now and then
                state = rng.bit_generator.state
                _edit(fast.state, rng)
                rng.bit_generator.state = state
                _edit(plain.state, rng)
                edits += 1
    assert edits > 0


def test_tally_follows_the_holdings_it_writes_out():
    """``after_step`` keeps the holdings as ``_holdings`` reads them (``upkeep.COUNTS``' order)
    from the packed inventory."""
    task = make("glyphbench/craftax-choptrees-v0")
    task.reset(seed=0)
    rng = np.random.default_rng(9)
    for _ in range(50):
        name = COUNTS[int(rng.integers(len(COUNTS)))]
        setattr(task.state.inventory, name, int(rng.integers(0, 5)))
        task._take_edits()
        task.tally.after_step(0, kernel.CHANGED_INVENTORY, None)
        assert task.tally._held == tuple(upkeep.held_counts(task.state.inventory))


@pytest.mark.parametrize("name", ["choptrees", "iron-bootstrap", "fight-zombies"])
def test_tally_counts_what_the_steps_flags_say_changed(name):
    """The tally counts from the step's flags (``kernel``): ``got`` counts what a plain reading
    of the inventory after each step counts, with the inventory and achievements also edited
    between steps (``changes`` follows a ``done.`` counter then), and ``changes`` moves after
    a step that changed a steady counter."""
    task = make(f"glyphbench/craftax-{name}-v0")
    rng = np.random.default_rng(10)
    for seed in range(2):
        task.reset(seed=seed)
        task.tally.getter("done.collect_wood")       # (the tally follows the achievements)
        held = upkeep.held_counts(task.state.inventory)
        achieved = task.state.achievements.tobytes()
        level = task.state.player_level
        got = dict.fromkeys(COUNTS, 0)
        for _ in range(150):
            if task.done:
                break
            action = int(Action.DO) if rng.random() < 0.4 else int(rng.integers(task.action_space.n))
            changes = task.tally.changes
            task.step(action)
            now = upkeep.held_counts(task.state.inventory)
            for name_, old, new in zip(upkeep.COUNTS, held, now):
                got[name_] += max(new - old, 0)
            steady = (now != held or task.state.achievements.tobytes() != achieved
                      or task.state.player_level != level)
            held, achieved = now, task.state.achievements.tobytes()
            level = task.state.player_level
            assert task.tally._held == now and task.tally.got == {k: got[k] for k in task.tally.got}
            if steady:
                assert task.tally.changes == changes + 1
            if rng.random() < 0.2:      # an edit between steps, as scenario events make
                item = str(rng.choice(["wood", "stone", "coal", "iron", "sapling", "arrows"]))
                setattr(task.state.inventory, item, int(rng.integers(0, 6)))
            if rng.random() < 0.1:
                task.state.achievements[int(rng.integers(task.state.achievements.size))] ^= True


class _Values:
    """A stand-in tally: counters read from a dict."""

    def __init__(self, values):
        self.values = values

    def getter(self, key):
        return lambda t: t.values[key]


def test_term_units_as_the_plain_rule():
    rng = np.random.default_rng(8)
    for _ in range(500):
        text = str(rng.choice(["x", "x >= 2", "x >= 1 and y < 3", "x > 1 and y >= 1 and x < 4"]))
        term = scenarios.Term("t", text, 0.5, "", cap=int(rng.integers(1, 6)),
                              per=int(rng.integers(1, 4)))
        tally = _Values({"x": int(rng.integers(0, 12)), "y": int(rng.integers(0, 5))})
        fn = scenarios.parse_test(text, tally)
        value = fn(tally)
        plain = int(value) if isinstance(value, bool) else min(int(value) // term.per, term.cap)
        assert term.counter(fn)(tally) == plain


def test_a_kill_or_a_new_floor_is_a_change_of_the_steady_counters():
    """A step after which ``kills`` or the floor differ bumps ``changes`` (a kill term is then
    asked)."""
    task = make("glyphbench/craftax-fight-zombies-v0")
    task.reset(seed=0)
    tally, p = task.tally, task.packed
    for change in ("none", "kill", "floor", "none"):
        before = tally.changes
        flags = 0
        if change == "kill":
            p.kills[1, 0] += 1
            flags = kernel.KILLED_MOB
        elif change == "floor":
            p.ints[LEVEL] += 1
            flags = kernel.CHANGED_LEVEL
        tally.after_step(0, flags, None)
        assert tally.changes == before + (change != "none"), change
    assert tally.kills["zombie"] == 1 and tally.counts["deepest"] == 1
