"""Lights Out: pressing a cell toggles it and its orthogonal neighbours; turn every light off."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import ActionSet, GlyphTask, cell_names, register_variants
from ...core.params import param
from ..common.grid import DELTAS
from ..common.palette import FLOOR

LIT = "●"
MAX_ATTEMPTS = 1000  # generation retries before a parameter set is declared impossible


@dataclass(frozen=True)
class LightsOutParams:
    size: int = param(5, 2, 9)
    # Boards are scrambled by k distinct random presses, k in min_presses..max_scramble. The
    # scramble itself is a solution, so the optimum never exceeds k: k below min_presses could
    # never pass the min_presses check and is not drawn.
    # the optimum of every generated board is at least this
    min_presses: int = param(4, 1, lambda p: p.max_scramble)
    max_scramble: int = param(10, 1, lambda p: p.size * p.size)
    time_weight: float = param(0.5, 0, 1, open_hi=True)   # share of the win reward lost by using every turn


def press_masks(size: int) -> list[int]:
    """For each cell (row-major), the bitmask of the cells a press there toggles."""
    masks = []
    for r in range(size):
        for c in range(size):
            m = 1 << (r * size + c)
            for dr, dc in DELTAS:
                if 0 <= r + dr < size and 0 <= c + dc < size:
                    m |= 1 << ((r + dr) * size + c + dc)
            masks.append(m)
    return masks


def solve(lights: list[list[bool]]) -> list[tuple[int, int]] | None:
    """A minimum set of presses (row, col) that turns every light off, or None if none exists.

    Pressing twice undoes a press and order does not matter, so a solution is a press set x with
    A x = b over GF(2), column j of A being press j's toggle mask. Gauss-Jordan elimination gives
    one solution; every other one differs from it by a null-space vector. The null space is small
    (dimension 2 for 5x5, 0 for 7x7, at most 8 for sizes up to 9), so enumerating it finds the
    lightest solution exactly.
    """
    size = len(lights)
    if size == 0 or any(len(row) != size for row in lights):
        raise ValueError("lights must be a non-empty square board")
    n = size * size
    target = sum(1 << (r * size + c) for r in range(size) for c in range(size) if lights[r][c])
    masks = press_masks(size)
    # Equation i (cell i): the presses that toggle cell i must sum to its light, kept in bit n.
    rows = [sum(1 << j for j in range(n) if masks[j] >> i & 1) | ((target >> i & 1) << n)
            for i in range(n)]
    pivots: list[int] = []  # pivot column of reduced row 0, 1, ...
    for col in range(n):
        rank = len(pivots)
        pick = next((i for i in range(rank, n) if rows[i] >> col & 1), None)
        if pick is None:
            continue
        rows[rank], rows[pick] = rows[pick], rows[rank]
        for i in range(n):
            if i != rank and rows[i] >> col & 1:
                rows[i] ^= rows[rank]
        pivots.append(col)
    if any(rows[i] >> n & 1 for i in range(len(pivots), n)):
        return None  # an equation reduced to 0 = 1
    particular = sum(1 << col for i, col in enumerate(pivots) if rows[i] >> n & 1)
    # One null-space basis vector per free column: set it, and the pivots it forces.
    pivot_set = set(pivots)
    kernel = [(1 << f) | sum(1 << col for i, col in enumerate(pivots) if rows[i] >> f & 1)
              for f in range(n) if f not in pivot_set]
    best = cand = particular
    for step in range(1, 1 << len(kernel)):  # Gray code: one basis vector flips per step
        cand ^= kernel[(step & -step).bit_length() - 1]
        if cand.bit_count() < best.bit_count():
            best = cand
    return [divmod(j, size) for j in range(n) if best >> j & 1]


class LightsOut(GlyphTask):
    title = "Lights Out"
    rules = ("The {size}x{size} board has lights that are on or off. Pressing a cell toggles it "
             "and the cells directly above, below, left and right of it. Turn every light off.")
    rewards = ("turning every light off gives 1 minus {time_weight:g} x (turns used / {max_turns}); "
               "running out of turns gives nothing.")
    ends = "when every light is off"
    Params = LightsOutParams
    glyphs = {LIT: "light on", FLOOR: "light off"}
    axes = True
    default_max_turns = 50

    def _make_actions(self) -> ActionSet:
        size = self.params.size
        return ActionSet(groups=[("press that cell (toggles it and its orthogonal neighbours)",
                                  cell_names(size, size))])

    def _init(self) -> None:
        size = self.params.size
        self.masks = press_masks(size)
        # Every possible row rendered once, so drawing the board is one lookup per row.
        self._row_text = ["".join(LIT if bits >> c & 1 else FLOOR for c in range(size))
                          for bits in range(1 << size)]

    def _setup(self, rng: np.random.Generator) -> None:
        p = self.params
        n = p.size * p.size
        for _ in range(MAX_ATTEMPTS):
            # Scrambling the all-off board makes it solvable by construction; the solver confirms
            # that and measures the optimum, which can be below k where the null space is not 0.
            k = int(rng.integers(p.min_presses, p.max_scramble + 1))
            state = 0
            for j in rng.choice(n, size=k, replace=False).tolist():
                state ^= self.masks[j]
            self.state = state
            solution = solve(self.lights())
            if solution is not None and len(solution) >= p.min_presses:
                self.optimal_presses = len(solution)
                return
        raise RuntimeError(f"{self.task_id}: no board with min_presses={p.min_presses} found in "
                           f"{MAX_ATTEMPTS} tries; lower min_presses or raise max_scramble")

    def lights(self) -> list[list[bool]]:
        size = self.params.size
        return [[bool(self.state >> (r * size + c) & 1) for c in range(size)] for r in range(size)]

    def _act(self, action: int) -> None:
        self.state ^= self.masks[action]
        if self.state == 0:
            # turn >= 1 and time_weight < 1, so a win is worth more than 0 and less than 1
            self.reward(self.time_bonus(self.params.time_weight))
            self.say("All lights are off.")
            self.finish(won=True)

    def _grid(self) -> list[str]:
        size, state, text = self.params.size, self.state, self._row_text
        full = (1 << size) - 1
        return [text[state >> (r * size) & full] for r in range(size)]

    def _hud(self) -> str:
        return f"Lit {self.state.bit_count()}"


register_variants(LightsOut, "Classics", {
    "glyphbench/classics-lightsout-easy-v0": dict(size=5, min_presses=4, max_scramble=10, max_turns=50),
    "glyphbench/classics-lightsout-hard-v0": dict(size=7, min_presses=8, max_scramble=20, max_turns=100),
})
