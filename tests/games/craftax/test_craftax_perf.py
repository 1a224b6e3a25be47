"""The fast paths of the Craftax step and view give what the plain versions give."""

import numpy as np

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


def test_unused_draws_batched_advance_the_generator_as_one_by_one():
    for seed in range(20):
        for bound in (1, 2, 37, 400):
            a, b = np.random.default_rng(seed), np.random.default_rng(seed)
            a.integers(5), b.integers(5)           # a half-used 32-bit buffer
            for _ in range(3):
                a.integers(bound)
            scenarios._draw_unused(b, [bound, 3])
            assert a.integers(1 << 40) == b.integers(1 << 40)


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
