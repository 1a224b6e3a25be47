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
    """Per cell: its lattice corner (row, col) and its offset inside the lattice cell, with
    the offsets' fades."""
    per = (shape[0] // res[0], shape[1] // res[1])
    rows, cols = np.arange(shape[0]), np.arange(shape[1])
    fy = ((rows * res[0] / shape[0]) % 1)[:, None]
    fx = ((cols * res[1] / shape[1]) % 1)[None, :]
    return (rows // per[0])[:, None], (cols // per[1])[None, :], fy, fx, fade(fy), fade(fx)


def perlin(angles: np.ndarray, shape: tuple[int, int]) -> np.ndarray:
    """Perlin noise over ``shape`` cells from gradient ``angles`` (in turns, one per lattice
    corner: ``(..., res_rows + 1, res_cols + 1)``, any leading axes making as many maps);
    each lattice cell spans ``shape // res`` cells."""
    res = (angles.shape[-2] - 1, angles.shape[-1] - 1)
    corner_r, corner_c, fy, fx, ty, tx = _lattice(tuple(shape), res)
    theta = 2 * np.pi * angles
    gy, gx = np.cos(theta), np.sin(theta)    # upstream's gradient (cos, sin) pairs with (row, col)

    def ramp(dr: int, dc: int) -> np.ndarray:
        r, c = corner_r + dr, corner_c + dc
        return (fy - dr) * gy[..., r, c] + (fx - dc) * gx[..., r, c]

    near_col = ramp(0, 0) * (1 - ty) + ty * ramp(1, 0)
    far_col = ramp(0, 1) * (1 - ty) + ty * ramp(1, 1)
    return np.sqrt(2) * ((1 - tx) * near_col + tx * far_col)


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
