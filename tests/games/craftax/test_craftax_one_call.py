"""A task's step is one compiled call (``kernel``): the step draws the window it leaves, flags
what the HUD line shows (``CHANGED_HUD``, ``MOVED``) and keeps the free mob classes (``FREE``).
A task played that way shows what a task whose State is handed out (``task.state``: every
frame then packed, drawn and written anew from the State) shows, turn for turn."""

import numpy as np
import pytest

from glyphbench_rl import make
from glyphbench_rl.games.common.lanes import Draws
from glyphbench_rl.games.craftax import kernel
from glyphbench_rl.games.craftax.packed import (COL, DRAW_AT, DRAWS_RESERVE, FREE, LEVEL, ROW,
                                                KernelDraws, free_classes, pack)
from glyphbench_rl.games.craftax.scenarios import SCENARIOS

# moves, fights, crafting, placing, sleeping, descending: scenarios whose HUD, window and mobs
# change in every way (events, waiting mobs, floors, night)
NAMES = ["firstday", "fight-zombies", "bow-kite", "survive-night", "necromancer",
         "dungeonexplore", "torchdescend", "wave-defense", "build-shelter", "xp-attribute-spend"]


@pytest.mark.parametrize("name", NAMES)
def test_played_in_one_call_as_with_the_state_handed_out(name):
    fast, lent = make(f"glyphbench/craftax-{name}-v0"), make(f"glyphbench/craftax-{name}-v0")
    rng = np.random.default_rng(11)
    turns = 0
    for seed in range(3):
        a, b = fast.reset(seed=seed), lent.reset(seed=seed)
        lent.state      # (handed out: every frame from the State)
        assert a[0] == b[0]
        while not fast.done and turns < 250 * (seed + 1):
            if rng.random() < 0.05:
                a, b = fast.forfeit("no_tag"), lent.forfeit("no_tag")
            else:
                action = int(rng.integers(fast.action_space.n))
                a, b = fast.step(action), lent.step(action)
            turns += 1
            assert a[:4] == b[:4], (name, seed, fast.turn)
            assert a[4]["frame"] == b[4]["frame"]
            p = fast.packed
            assert p.ints[FREE] == free_classes(p.mobs, int(p.ints[LEVEL]))
        assert lent.done == fast.done


def test_step_flags_say_what_the_hud_shows():
    """A step without CHANGED_HUD left the line's key as it was, without MOVED the position."""
    task = make("glyphbench/craftax-firstday-v0")
    task.reset(seed=3)
    rng = np.random.default_rng(0)
    seen = {kernel.CHANGED_HUD: 0, kernel.MOVED: 0}
    for _ in range(400):
        key, line = task.line.key, task.line.line
        position = task.packed.ints[[ROW, COL]].tolist()
        task.step(int(rng.integers(task.action_space.n)))
        if task.done:
            break
        flags = int(task.packed.ints[kernel.STEP_FLAGS])
        fresh = type(task.line)()
        fresh.update(task.packed)
        for bit in seen:
            seen[bit] += bool(flags & bit)
        if not flags & kernel.CHANGED_HUD:
            assert fresh.key == key
        if not flags & (kernel.CHANGED_HUD | kernel.MOVED):
            assert fresh.line == line
        if not flags & kernel.MOVED:
            assert task.packed.ints[[ROW, COL]].tolist() == position
    assert all(seen.values())


def test_draws_refilled_in_place_are_the_streams_in_turn():
    """``KernelDraws`` keeps one buffer (the compiled step is bound to it) whose floats, taken in
    turn across refills, are ``Draws``' from the same stream."""
    p = pack(SCENARIOS["firstday"].build(np.random.default_rng(0))[0], SCENARIOS["firstday"].settings)
    kd, ref = KernelDraws(np.random.default_rng(5)), Draws(np.random.default_rng(5))
    kd.top_up(p)
    buffer = p.draws
    rng = np.random.default_rng(1)
    for _ in range(300):
        for _ in range(int(rng.integers(0, 60))):
            assert p.draws[p.ints[DRAW_AT]] == ref.random()
            p.ints[DRAW_AT] += 1
        kd.top_up(p)
        assert p.draws is buffer and len(p.draws) - p.ints[DRAW_AT] >= DRAWS_RESERVE


def test_a_step_with_too_few_draws_raises_rather_than_reading_past_them():
    task = make("glyphbench/craftax-fight-zombies-v0")
    task.reset(seed=0)
    p = task.packed
    p.ints[DRAW_AT] = len(p.draws)
    with pytest.raises(IndexError, match="draws ran out"):
        for _ in range(50):
            kernel.step(p, 0)
