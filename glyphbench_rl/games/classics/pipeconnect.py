"""Pipe Connect: rotate pipe tiles until water runs from the source to the drain.

A level is a random spanning tree of the board; the tree path from the source to the drain is
laid with the straights and elbows it needs, every other cell gets a random straight, elbow or
tee, and then every tile is turned at random, so the level is solvable by construction. The
solver is a shortest-path search over (cell, side entered) whose step cost is the quarter turns a
tile needs to join its entry and exit sides; a level is kept only when the cheapest route visits
no cell twice, so that cost is the exact minimum number of rotations.
"""

from __future__ import annotations

from dataclasses import dataclass
from heapq import heappop, heappush

import numpy as np

from ...core import GlyphTask, register_variants
from ...core.params import param
from ..common.boards import Bits, cell_actions

# Sides in clockwise order; a tile's openings are a 4-bit mask (bit d = side d), so a quarter
# turn clockwise rotates the mask left by one.
SIDES = "NESW"
DELTAS = ((-1, 0), (0, 1), (1, 0), (0, -1))
STRAIGHT, ELBOW, TEE = 0b0101, 0b0011, 0b0111      # N-S, N-E, N-E-S at rotation 0
KINDS = (STRAIGHT, ELBOW, TEE)
STRAIGHT_KIND, ELBOW_KIND = KINDS.index(STRAIGHT), KINDS.index(ELBOW)
SOURCE, DRAIN = "◉", "◎"
DRY = {0b0101: "│", 0b1010: "─", 0b0011: "└", 0b0110: "┌", 0b1100: "┐", 0b1001: "┘",
       0b0111: "├", 0b1110: "┬", 0b1101: "┤", 0b1011: "┴"}
WET = {0b0101: "┃", 0b1010: "━", 0b0011: "┗", 0b0110: "┏", 0b1100: "┓", 0b1001: "┛",
       0b0111: "┣", 0b1110: "┳", 0b1101: "┫", 0b1011: "┻"}
_INF = 99
_TRIES = 200


def turn(mask: int, quarters: int) -> int:
    """``mask`` turned ``quarters`` quarter turns clockwise."""
    quarters %= 4
    return (mask << quarters | mask >> 4 - quarters) & 0b1111


def _sides(mask: int) -> str:
    return "-".join(s for d, s in enumerate(SIDES) if mask >> d & 1)


# COST[kind][rotation][need]: fewest quarter turns giving the tile every opening in ``need``.
COST = [[[min((q for q in range(4) if turn(base, r + q) & need == need), default=_INF)
          for need in range(16)] for r in range(4)] for base in KINDS]


@dataclass(frozen=True)
class PipeConnectParams:
    size: int = param(5, 3, 12)
    # the fewest rotations solving a level is at least this
    min_rotations: int = param(4, 1, lambda p: 2 * p.size)
    time_weight: float = param(0.5, 0, 1, open_hi=True)      # share of the win reward lost by using every turn


def solve(kinds: list[int], rots: list[int], size: int, source: int, drain: int) -> tuple[int, list[int]] | None:
    """(fewest rotations, cells of the route from the source to the drain) for a board given as
    row-major tile kinds (indices into KINDS) and rotations, or None when no route exists. The
    route may revisit a cell only when that is cheapest, which callers reject (see module doc)."""
    n = size
    best: dict[tuple[int, int], int] = {}
    prev: dict[tuple[int, int], tuple[int, int] | None] = {}
    heap: list = []
    for d, (dr, dc) in enumerate(DELTAS):
        r, c = source // n + dr, source % n + dc
        if 0 <= r < n and 0 <= c < n:
            heap.append((0, r * n + c, (d + 2) % 4, None))
    while heap:
        cost, cell, entry, came = heappop(heap)
        if cell == drain:
            route = [cell]
            while came is not None:
                route.append(came[0])
                came = prev[came]
            return cost, route[::-1]
        if (cell, entry) in best or cell == source:
            continue
        best[(cell, entry)] = cost
        prev[(cell, entry)] = came
        table = COST[kinds[cell]][rots[cell]]
        for d, (dr, dc) in enumerate(DELTAS):
            r, c = cell // n + dr, cell % n + dc
            step = table[1 << entry | 1 << d]
            if d != entry and step < _INF and 0 <= r < n and 0 <= c < n:
                heappush(heap, (cost + step, r * n + c, (d + 2) % 4, (cell, entry)))
    return None


class PipeConnect(GlyphTask):
    title = "Pipe Connect"
    rules = ("The {size}x{size} board is tiled with pipes: straights, elbows and tees, drawn as "
             "lines joining the sides they open to (the legend names the sides). Rotating a tile "
             "turns it a quarter turn clockwise. Water flows from the source into every pipe "
             "that opens towards it and on through every pair of touching openings; heavy lines "
             "hold water. The source and the drain open on all sides and do not turn. Make "
             "water reach the drain.")
    rewards = ("connecting gives 1 minus {time_weight:g} x (turns used / {max_turns}); running out "
               "of turns gives nothing.")
    ends = "when water reaches the drain"
    Params = PipeConnectParams
    glyphs = ({SOURCE: "source", DRAIN: "drain"} | {g: _sides(m) for m, g in DRY.items()}
              | {g: _sides(m) + " wet" for m, g in WET.items()})
    axes = True
    default_max_turns = 30

    def _make_actions(self):
        n = self.params.size
        return cell_actions(n, n, [("", "rotate that tile a quarter turn clockwise")])

    def _init(self) -> None:
        n = self.params.size
        self.bits = Bits(n, n)
        self.neighbours = [[(r + dr) * n + c + dc if 0 <= r + dr < n and 0 <= c + dc < n else -1
                            for dr, dc in DELTAS] for r in range(n) for c in range(n)]

    # -- generation ---------------------------------------------------------------------------
    def _setup(self, rng: np.random.Generator) -> None:
        n = self.params.size
        for _ in range(_TRIES):
            source, drain = int(rng.integers(n)) * n, int(rng.integers(n)) * n + n - 1
            kinds = rng.choice(3, size=n * n, p=(0.35, 0.45, 0.2)).tolist()
            path = self._tree_path(rng, source, drain)
            for a, b, c in zip(path, path[1:], path[2:]):
                kinds[b] = STRAIGHT_KIND if b - a == c - b else ELBOW_KIND
            rots = rng.integers(4, size=n * n).tolist()
            found = solve(kinds, rots, n, source, drain)
            if found and found[0] >= self.params.min_rotations and len(set(found[1])) == len(found[1]):
                break
        else:
            raise RuntimeError(f"{self.task_id}: no level needing {self.params.min_rotations} rotations "
                               f"in {_TRIES} tries; lower min_rotations")
        self.kinds, self.rots, self.source, self.drain = kinds, rots, source, drain
        self.optimal_rotations, self.route = found
        self.masks = [turn(KINDS[k], r) for k, r in zip(kinds, rots)]
        self._wet, self._chars = 0, [""] * (n * n)
        for i in range(n * n):
            self._paint(i)
        self._lines = ["".join(self._chars[r * n:(r + 1) * n]) for r in range(n)]
        self._flow()

    def _tree_path(self, rng: np.random.Generator, source: int, drain: int) -> list[int]:
        """Cells from ``source`` to ``drain`` along a random depth-first spanning tree."""
        parent = {source: -1}
        stack = [source]
        while stack:
            cell = stack[-1]
            options = [j for j in self.neighbours[cell] if j >= 0 and j not in parent]
            if not options:
                stack.pop()
                continue
            nxt = options[int(rng.integers(len(options)))]
            parent[nxt] = cell
            stack.append(nxt)
        path = [drain]
        while path[-1] != source:
            path.append(parent[path[-1]])
        return path[::-1]

    # -- play -----------------------------------------------------------------------------------
    def _act(self, action: int) -> None:
        if action in (self.source, self.drain):
            self.say("The source and the drain do not turn.")
            return
        self.rots[action] = (self.rots[action] + 1) % 4
        self.masks[action] = turn(self.masks[action], 1)
        if self.bits.grow(self._wet) >> action & 1:
            self._flow(action)
        else:   # water neither touches nor reaches the tile: only the tile changes
            self._paint(action)
            n = self.params.size
            r = action // n
            self._lines[r] = "".join(self._chars[r * n:(r + 1) * n])
        if self.connected:
            self.reward(self.time_bonus(self.params.time_weight))
            self.say("Water reaches the drain.")
            self.finish(won=True)

    def _flow(self, turned: int = -1) -> None:
        """Recompute the wet cells and redraw the rows whose glyphs changed."""
        masks, neighbours, drain = self.masks, self.neighbours, self.drain
        wet, stack, connected = 1 << self.source, [self.source], False
        while stack:
            i = stack.pop()
            m = 0b1111 if i == self.source else masks[i]
            for d in range(4):
                j = neighbours[i][d]
                if m >> d & 1 and j >= 0 and not wet >> j & 1:
                    if j == drain:
                        connected = True
                    elif masks[j] >> (d + 2) % 4 & 1 and j != self.source:
                        wet |= 1 << j
                        stack.append(j)
        changed, self._wet, self.connected = wet ^ self._wet, wet, connected
        if turned >= 0:
            changed |= 1 << turned
        n, rows = self.params.size, set()
        while changed:
            low = changed & -changed
            i = low.bit_length() - 1
            changed ^= low
            self._paint(i)
            rows.add(i // n)
        for r in rows:
            self._lines[r] = "".join(self._chars[r * n:(r + 1) * n])

    def _paint(self, i: int) -> None:
        if i == self.source:
            self._chars[i] = SOURCE
        elif i == self.drain:
            self._chars[i] = DRAIN
        else:
            self._chars[i] = (WET if self._wet >> i & 1 else DRY)[self.masks[i]]

    def _grid(self) -> list[str]:
        return self._lines


register_variants(PipeConnect, "Classics", {
    "glyphbench/classics-pipeconnect-easy-v0": dict(size=5, min_rotations=4, max_turns=30),
    "glyphbench/classics-pipeconnect-medium-v0": dict(size=7, min_rotations=6, max_turns=50),
    "glyphbench/classics-pipeconnect-hard-v0": dict(size=9, min_rotations=8, max_turns=80),
})
