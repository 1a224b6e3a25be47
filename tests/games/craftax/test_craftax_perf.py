"""The fast paths of the Craftax step and view give what the plain versions give."""

import copy

import numpy as np
import pytest

from glyphbench_rl.core import registry
from glyphbench_rl.games.craftax import hud, scenarios, view, worldgen
from glyphbench_rl.games.craftax.mobs import MOB_BY_NAME, add_mob
from glyphbench_rl.games.craftax.state import Settings


def _states():
    for seed in range(3):
        yield worldgen.generate(np.random.default_rng(seed), Settings())


def test_free_ring_is_the_cell_list():
    rng = np.random.default_rng(7)
    for state in _states():
        for _ in range(25):
            level = state.player_level = int(rng.integers(0, 9))
            state.player_position[:] = rng.integers(0, 48, size=2)
            state.mob_map[level] = rng.random((48, 48)) < 0.1
            floor = int(rng.integers(1, 6))
            dmin, dmax = int(rng.integers(0, 4)), int(rng.integers(3, 12))
            want = [p for p in scenarios._cells(state, dmin, dmax)
                    if scenarios._free(state, *p, floor)]
            ok, count, r0, c0, width = scenarios._free_ring(state, dmin, dmax, floor)
            got = [(r0 + k // width, c0 + k % width) for k in np.flatnonzero(ok).tolist()]
            assert got == want and count == len(want)
            cells, n, *box = scenarios._free_cells(state, dmin, dmax, floor)
            assert cells == ok.astype(np.uint8).tobytes() and n == count and box == [r0, c0, width]


def test_waiting_mobs_take_free_slots_and_draw_only_then():
    """A scenario's waiting mobs (``Context.reserve``): one whose class is full waits and
    draws nothing; once a slot frees, it takes a free floor cell of its ring, with one draw."""
    task = registry.make("glyphbench/craftax-fight-zombies-v0")
    task.reset(seed=0)
    state, ctx, rng = task.state, task.ctx, task.play_rng
    level = state.player_level
    zombies = state.melee_mobs
    assert ctx.reserve and False not in zombies.mask[level]      # full: the rest wait
    before = rng.bit_generator.state
    waiting = list(ctx.reserve)
    ctx.admit(state, rng)
    assert ctx.reserve == waiting and rng.bit_generator.state == before
    slot = 0
    r, c = zombies.position[level][slot]
    zombies.mask[level][slot] = False
    state.mob_map[level, r, c] = False
    name, dmin, dmax = ctx.reserve[0]
    ctx.admit(state, rng)
    assert ctx.reserve == waiting[1:] and rng.bit_generator.state != before
    assert zombies.mask[level][slot]
    r, c = zombies.position[level][slot]
    pr, pc = state.player_position.tolist()
    assert dmin <= abs(r - pr) + abs(c - pc) <= dmax and state.mob_map[level, r, c]
    assert state.map[level, r, c] == ctx.floor


def test_remembered_hud_follows_the_state():
    state = next(_states())
    first = hud.hud(state)
    assert first == hud._hud(state)
    state.inventory.wood += 3
    state.inventory.potions[2] = 1
    state.player_position[1] += 1
    assert hud.hud(state) == hud._hud(state) != first
    state.inventory.wood -= 3
    state.inventory.potions[2] = 0
    state.player_position[1] -= 1
    assert hud.hud(state) == first


def test_dark_window_and_map_edge():
    state = next(_states())
    state.player_level = 0
    state.player_position[:] = (0, 0)            # a corner: off-map cells
    rows = view.grid(state)
    off = view.BLOCK_GLYPHS[view.BlockType.OUT_OF_BOUNDS][0]
    assert rows[0][:5] == off * 5 and rows[4][5] in "←→↑↓@"
    state.light_map[0, 0:5, 0:6] = 0.0           # unlit: darkness, even on the map's cells
    rows = view.grid(state)
    assert rows[4][6] == view.DARK[0] and rows[0][0] == off and rows[4][5] != view.DARK[0]


def _plain_admit(ctx, state, rng) -> None:
    """``Context.admit`` as first written: every waiting mob looked at in turn, its ring's free
    cells listed anew."""
    groups = (state.passive_mobs, state.melee_mobs, state.ranged_mobs)
    level, waiting = state.player_level, []
    for name, dmin, dmax in ctx.reserve:
        if False not in groups[MOB_BY_NAME[name][0]].mask[level]:
            waiting.append((name, dmin, dmax))
            continue
        cells = [p for p in scenarios._cells(state, dmin, dmax)
                 if scenarios._free(state, *p, ctx.floor)]
        if not cells or not add_mob(state, name, cells[int(rng.integers(len(cells)))]):
            waiting.append((name, dmin, dmax))
    ctx.reserve = waiting


def _mob_slots(state) -> list:
    return [getattr(state, g).arrays()["mask"].tobytes() + getattr(state, g).arrays()[
        "position"].tobytes() for g in ("passive_mobs", "melee_mobs", "ranged_mobs")]


@pytest.mark.parametrize("task_id", ["craftax-fight-zombies-v0", "craftax-survivehorde-v0"])
def test_admit_skipping_a_full_reserve_is_the_plain_rule(task_id):
    """``Context.admit`` returns at once while its waiting list is the one it left and every
    class is full: it does what the plain walk does, as slots free (kills, edits between
    steps), waiting mobs are added or the list is edited in place."""
    task = registry.make(f"glyphbench/{task_id}")
    edits = np.random.default_rng(3)
    for seed in range(4):
        task.reset(seed=seed)
        for _ in range(120):
            if task.done:
                break
            state, ctx, rng = task.state, task.ctx, task.play_rng
            level = state.player_level
            roll = edits.random()
            if roll < 0.1:          # a slot frees between steps
                group = (state.passive_mobs, state.melee_mobs, state.ranged_mobs)[
                    int(edits.integers(3))]
                slot = int(edits.integers(len(group.mask[level])))
                if group.mask[level][slot]:
                    r, c = group.position[level][slot]
                    group.mask[level][slot] = False
                    state.mob_map[level, r, c] = False
            elif roll < 0.15:       # another mob waits
                ctx.reserve.append((("zombie", "skeleton", "cow")[int(edits.integers(3))], 2, 6))
            elif roll < 0.18 and ctx.reserve:      # the list edited in place
                ctx.reserve[-1] = ("skeleton", 3, 5)
            plain_state, plain_ctx, plain_rng = copy.deepcopy((state, ctx, rng))
            _plain_admit(plain_ctx, plain_state, plain_rng)
            ctx.admit(state, rng)
            assert ctx.reserve == plain_ctx.reserve
            assert rng.bit_generator.state == plain_rng.bit_generator.state
            assert _mob_slots(state) == _mob_slots(plain_state)
            assert np.array_equal(state.mob_map, plain_state.mob_map)
            task.step(int(edits.integers(task.action_space.n)))
