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


def test_owed_draws_made_together_advance_the_generator_as_one_by_one():
    """``Context``'s owed draws, made in one call with the next used draw (or by ``settle``):
    the used value and the generator afterwards are those of one ``integers`` call a bound.
    Bounds near 2**31 make Lemire's method reject draws often, bounds over 2**32 take the 64-bit
    path; an odd number of 32-bit draws before leaves half a 64-bit output buffered."""
    rng = np.random.default_rng(3)
    for seed in range(60):
        bounds = [int(b) for b in rng.choice([1, 2, 37, 400, 961, 2**31 + 1, 3 * 2**30, 2**32,
                                              2**33 + 7], size=int(rng.integers(0, 9)))]
        used = int(rng.choice([1, 37, 961, 2**31 + 1]))
        a, b = np.random.default_rng(seed), np.random.default_rng(seed)
        for _ in range(seed % 3):
            a.integers(5), b.integers(5)
        for bound in bounds:
            a.integers(bound)
        value = int(a.integers(used))
        ctx = scenarios.Context.__new__(scenarios.Context)
        ctx.owed, ctx.owed_rng = list(bounds), b
        assert ctx._draw(b, used) == value and ctx.owed == []
        assert a.integers(1 << 40) == b.integers(1 << 40) and a.random() == b.random()
        for bound in bounds:                     # settle: the draws owed, no used one
            a.integers(bound)
        ctx.owed = list(bounds)
        ctx.settle()
        assert ctx.owed == [] and a.integers(1 << 40) == b.integers(1 << 40)


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
