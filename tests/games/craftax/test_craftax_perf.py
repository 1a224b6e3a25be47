"""The fast paths of the Craftax step and view give what the plain versions give."""

import numpy as np

from glyphbench_rl.core import registry
from glyphbench_rl.games.craftax import hud, scenarios, view, worldgen
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
