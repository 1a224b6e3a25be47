"""Mirror Laser: place mirrors so the laser beam reaches the target.

A level is built backwards from a solution: the beam leaves the laser, runs straight, turns at a
few cells (where the solution's mirrors go) and ends on the target; walls then go on cells off
that route. A search over mirror placements along the beam (the beam is traced as it would run,
each empty cell it meets gets no mirror or one of the two) then keeps a level only when it is
solvable (a random route can fold onto itself), but not with fewer than ``min_mirrors`` mirrors,
and gives the fewest actions that solve it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import GlyphTask, register_variants
from ...core.params import param
from ..common.boards import cell_actions
from ..common.palette import FLOOR, GOAL, WALL

DELTAS = ((-1, 0), (0, 1), (1, 0), (0, -1))          # N E S W
LASERS = "▲▶▼◀"                                        # the laser glyph facing N E S W
SLASH, BACKSLASH = "/", "\\"
# Where each mirror sends a beam moving in direction d (N E S W).
REFLECT = {SLASH: (1, 0, 3, 2), BACKSLASH: (3, 2, 1, 0)}
CYCLE = {FLOOR: SLASH, SLASH: BACKSLASH, BACKSLASH: FLOOR}
PRESSES = {SLASH: 1, BACKSLASH: 2}                     # actions placing each mirror on an empty cell
BEAM = {1: "|", 2: "-", 3: "+"}                        # bit 0: vertical pass, bit 1: horizontal pass
_TRIES = 500


@dataclass(frozen=True)
class MirrorLaserParams:
    size: int = param(7, 5, 12)
    mirrors: int = param(3, 1, 6)            # mirrors you may place (at most this many on the board at once)
    min_mirrors: int = param(2, 1, lambda p: p.mirrors)   # no level can be solved with fewer mirrors than this
    walls: int = param(6, 0, lambda p: p.size * p.size // 3)
    time_weight: float = param(0.5, 0, 1, open_hi=True)   # share of the win reward lost by using every turn


def trace(cells: list[str], size: int, start: int, heading: int) -> tuple[list[tuple[int, int]], bool]:
    """The beam from the laser at ``start``: (cell, direction moving) for every cell it crosses
    before it stops, and whether it reached the target."""
    path, seen = [], set()
    r, c, d = start // size, start % size, heading
    while True:
        r, c = r + DELTAS[d][0], c + DELTAS[d][1]
        i = r * size + c
        if not (0 <= r < size and 0 <= c < size) or (i, d) in seen:
            return path, False
        ch = cells[i]
        if ch == GOAL:
            return path, True
        if ch in REFLECT:
            d = REFLECT[ch][d]
        elif ch != FLOOR:
            return path, False
        seen.add((i, d))
        path.append((i, d))


def solve(cells: list[str], size: int, start: int, heading: int, mirrors: int,
          max_presses: int) -> list[tuple[int, str]] | None:
    """Fewest-action placements [(cell, mirror)] that bring the beam to the target using at most
    ``mirrors`` mirrors and ``max_presses`` actions, or None. Iterative deepening on actions; a
    cell the beam has crossed stays empty on later passes (a mirror there would bend it earlier)."""
    cells = list(cells)
    for budget in range(max_presses + 1):
        found = _dfs(cells, size, start // size, start % size, heading, budget, mirrors, set())
        if found is not None:
            return found
    return None


def _dfs(cells, size, r, c, d, budget, mirrors, crossed):
    added = []
    try:
        for _ in range(4 * size * size):
            r, c = r + DELTAS[d][0], c + DELTAS[d][1]
            if not (0 <= r < size and 0 <= c < size):
                return None
            i = r * size + c
            ch = cells[i]
            if ch == GOAL:
                return []
            if ch in REFLECT:
                d = REFLECT[ch][d]
                continue
            if ch != FLOOR:
                return None
            if i not in crossed and mirrors:
                for mirror, cost in PRESSES.items():
                    if cost <= budget:
                        cells[i] = mirror
                        rest = _dfs(cells, size, r, c, REFLECT[mirror][d], budget - cost, mirrors - 1, crossed)
                        cells[i] = FLOOR
                        if rest is not None:
                            return [(i, mirror)] + rest
            if i not in crossed:
                crossed.add(i)
                added.append(i)
        return None
    finally:
        crossed.difference_update(added)


class MirrorLaser(GlyphTask):
    title = "Mirror Laser"
    rules = ("A laser on the {size}x{size} board fires a beam in the direction it points. Beams "
             "run straight through empty cells, stop at walls and at the edge, and turn at "
             "mirrors: / turns a beam going east to north (and north to east, west to south, "
             "south to west), \\ turns east to south (south to east, west to north, north to "
             "west). Choosing an empty cell places a / mirror, choosing a / turns it into \\, "
             "choosing a \\ removes it. You may have at most {mirrors} mirrors on the board. "
             "Make the beam hit the target.")
    rewards = ("hitting the target gives 1 minus {time_weight:g} x (turns used / {max_turns}); "
               "running out of turns gives nothing.")
    ends = "when the beam hits the target"
    Params = MirrorLaserParams
    glyphs = ({FLOOR: "empty", WALL: "wall", GOAL: "target", SLASH: "mirror", BACKSLASH: "mirror",
               "|": "beam", "-": "beam", "+": "beams crossing"}
              | {g: f"laser facing {'north east south west'.split()[d]}" for d, g in enumerate(LASERS)})
    axes = True
    default_max_turns = 40

    def _make_actions(self):
        n = self.params.size
        return cell_actions(n, n, [("", "cycle that cell: empty, / mirror, \\ mirror, empty")])

    # -- generation ---------------------------------------------------------------------------
    def _setup(self, rng: np.random.Generator) -> None:
        p = self.params
        for _ in range(_TRIES):
            level = self._generate(rng)
            if level is None:
                continue
            cells, start, heading = level
            n = p.size
            if solve(cells, n, start, heading, p.min_mirrors - 1, 2 * (p.min_mirrors - 1)) is None:
                plan = solve(cells, n, start, heading, p.mirrors, 2 * p.mirrors)
                if plan is not None:
                    break
        else:
            raise RuntimeError(f"{self.task_id}: no level needing {p.min_mirrors} mirrors in {_TRIES} "
                               "tries; lower min_mirrors or walls")
        self.cells, self.laser, self.heading, self.plan = cells, start, heading, plan
        self.optimal_presses = sum(PRESSES[m] for _, m in plan)
        self.placed = 0
        self._beam()

    def _generate(self, rng: np.random.Generator):
        """A board with laser, target and walls (no mirrors), built around a random route."""
        n, p = self.params.size, self.params
        side = int(rng.integers(4))                      # the edge the laser sits on
        k = int(rng.integers(1, n - 1))
        r, c = ((0, k), (k, n - 1), (n - 1, k), (k, 0))[side]
        heading = (side + 2) % 4                         # pointing inwards
        start = r * n + c
        route, d = {start}, heading
        turns = int(rng.integers(p.min_mirrors, p.mirrors + 1))
        for leg in range(turns + 1):
            length = int(rng.integers(1, n))
            for _ in range(length):
                nr, nc = r + DELTAS[d][0], c + DELTAS[d][1]
                if not (0 <= nr < n and 0 <= nc < n) or nr * n + nc in route:
                    break
                r, c = nr, nc
                route.add(r * n + c)
            if (r, c) == divmod(start, n):
                return None
            if leg < turns:
                d = (d + (1 if rng.random() < 0.5 else 3)) % 4
        cells = [FLOOR] * (n * n)
        cells[start] = LASERS[heading]
        cells[r * n + c] = GOAL
        free = [i for i in range(n * n) if i not in route]
        for i in rng.choice(len(free), size=min(p.walls, len(free)), replace=False).tolist():
            cells[free[i]] = WALL
        return cells, start, heading

    # -- play -----------------------------------------------------------------------------------
    def _act(self, action: int) -> None:
        ch = self.cells[action]
        if ch not in CYCLE:
            self.say("That cell cannot hold a mirror.")
            return
        if ch == FLOOR and self.placed >= self.params.mirrors:
            self.say("No mirrors left.")
            return
        self.placed += (ch == FLOOR) - (ch == BACKSLASH)
        self.cells[action] = CYCLE[ch]
        if self._beam():
            self.reward(self.time_bonus(self.params.time_weight))
            self.say("The beam hits the target.")
            self.finish(won=True)

    def _beam(self) -> bool:
        """Trace the beam, redraw the board with it, and say whether it hits the target."""
        n = self.params.size
        path, hit = trace(self.cells, n, self.laser, self.heading)
        passes: dict[int, int] = {}
        for i, d in path:
            if self.cells[i] == FLOOR:
                passes[i] = passes.get(i, 0) | (1 if d % 2 == 0 else 2)
        chars = list(self.cells)
        for i, bits in passes.items():
            chars[i] = BEAM[bits]
        self._lines = ["".join(chars[r * n:(r + 1) * n]) for r in range(n)]
        return hit

    def _grid(self) -> list[str]:
        return self._lines

    def _hud(self) -> str:
        return f"Mirrors left {self.params.mirrors - self.placed}"


register_variants(MirrorLaser, "Classics", {
    "glyphbench/classics-mirrorlaser-v0": dict(size=7, mirrors=4, min_mirrors=3, walls=8, max_turns=40),
})
