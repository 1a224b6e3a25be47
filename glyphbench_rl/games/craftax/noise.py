"""Perlin noise for world generation, as upstream Craftax's ``util/noise.py`` (itself Pierre
Vigier's perlin-numpy): a lattice of random unit gradients, one per lattice corner, each cell
blending its four corners' ramps with the quintic fade ``6t^5 - 15t^4 + 10t^3``.

Upstream only ever asks for one octave, normalised to [0, 1]; ``fractal`` does exactly that.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np


def fade(t: np.ndarray) -> np.ndarray:
    return t * t * t * (t * (t * 6 - 15) + 10)


@lru_cache(maxsize=None)
def _lattice(shape: tuple[int, int], res: tuple[int, int]):
    """Per cell, laid out by lattice cell (``(res_rows, per_row, res_cols, per_col)``, which
    reshapes to ``shape``): its offset inside the lattice cell (and that less 1, the offset
    from the far corner) and the offsets' fades (and 1 less them), rows then columns."""
    if shape[0] % res[0] or shape[1] % res[1]:
        raise ValueError(f"a {shape} map needs a lattice that divides it, not {res}")
    per = (shape[0] // res[0], shape[1] // res[1])
    fy = ((np.arange(shape[0]) * res[0] / shape[0]) % 1).reshape(res[0], per[0], 1, 1)
    fx = ((np.arange(shape[1]) * res[1] / shape[1]) % 1).reshape(1, 1, res[1], per[1])
    ty, tx = fade(fy), fade(fx)
    return fy, fy - 1, fx, fx - 1, ty, 1 - ty, tx, 1 - tx


def perlin(angles: np.ndarray, shape: tuple[int, int]) -> np.ndarray:
    """Perlin noise over ``shape`` cells from gradient ``angles`` (in turns, one per lattice
    corner: ``(..., res_rows + 1, res_cols + 1)``, any leading axes making as many maps);
    each lattice cell spans ``shape // res`` cells."""
    res = (angles.shape[-2] - 1, angles.shape[-1] - 1)
    fy, fy1, fx, fx1, ty, ty1, tx, tx1 = _lattice(tuple(shape), res)
    theta = 2 * np.pi * angles
    gy, gx = np.cos(theta), np.sin(theta)    # upstream's gradient (cos, sin) pairs with (row, col)

    # (the cells are laid out by lattice cell, so a corner's gradient reaches its cells by
    # broadcasting, not by gathering it per cell)
    def ramp(dr: int, dc: int) -> np.ndarray:
        corner = (..., slice(dr, dr + res[0]), None, slice(dc, dc + res[1]), None)
        return (fy1 if dr else fy) * gy[corner] + (fx1 if dc else fx) * gx[corner]

    # near_col = ramp(0, 0) * (1 - ty) + ty * ramp(1, 0), far_col likewise with column 1, and
    # sqrt(2) * ((1 - tx) * near_col + tx * far_col): computed in place (the same operations
    # on the same operands, fewer map-sized arrays made)
    near_col = ramp(0, 0)
    near_col *= ty1
    near_col += ty * ramp(1, 0)
    far_col = ramp(0, 1)
    far_col *= ty1
    far_col += ty * ramp(1, 1)
    near_col *= tx1
    far_col *= tx
    near_col += far_col
    near_col *= np.sqrt(2)
    return near_col.reshape(*angles.shape[:-2], *shape)


def fractal(rng: np.random.Generator, shape: tuple[int, int], res: tuple[int, int],
            count: int | None = None) -> np.ndarray:
    """One octave of Perlin noise with fresh random gradients, each map rescaled to span
    [0, 1] (upstream's ``generate_fractal_noise_2d(..., octaves=1)``); ``count`` maps at once
    (leading axis) when given."""
    lattice = (res[0] + 1, res[1] + 1)
    noise = perlin(rng.random(lattice if count is None else (count, *lattice)), shape)
    low = noise.min(axis=(-2, -1), keepdims=True)
    high = noise.max(axis=(-2, -1), keepdims=True)
    return (noise - low) / (high - low)
