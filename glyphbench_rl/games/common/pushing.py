"""Box pushing (Sokoban rules): rooms as bitmasks, a push-optimal A* solver and reverse play.

Classics' Sokoban and the MiniHack Boxoban levels both build on this. Cells are padded
indices and sets of cells are Python ints used as bitmasks, so flood fills and state keys cost
a handful of big-int operations instead of set walks.
"""

from __future__ import annotations

from collections import deque
from heapq import heappop, heappush
from typing import Iterable

import numpy as np

from .grid import MOVES, shortest_path

Cell = tuple[int, int]
NAMES = tuple(MOVES)      # UP, DOWN, LEFT, RIGHT: the order of PushRoom.steps
FAR = 10**6               # lone-box push distance of a dead square (no goal reachable)


class PushRoom:
    """Walls and goals in padded index space: cell (r, c) is index (r + 1) * W + c + 1.

    The extra ring of wall around the given cells means a shifted bitmask never wraps onto a
    floor cell, and every neighbour index of a floor cell is valid.
    """

    def __init__(self, walls: Iterable[Cell], height: int, width: int, goals: Iterable[Cell]):
        self.W = W = width + 2
        walls = set(walls)
        self.free = sum(1 << self.index(r, c) for r in range(height) for c in range(width)
                        if (r, c) not in walls)
        self.wallmask = ((1 << (height + 2) * W) - 1) & ~self.free
        self.goals = sum(1 << self.index(*g) for g in set(goals))
        self.steps = (-W, W, -1, 1)   # in NAMES order: UP, DOWN, LEFT, RIGHT
        # Fewest pushes taking a lone box to its nearest goal, searched backwards from every
        # goal: a box reaches x from x - d when the player can stand at x - 2d. It is a lower
        # bound that changes by at most one per push, so A* with it is push-optimal.
        self.dist = dist = [FAR] * ((height + 2) * W)
        queue = deque(bits(self.goals))
        for g in queue:
            dist[g] = 0
        while queue:
            x = queue.popleft()
            for d in self.steps:
                prev, stand = x - d, x - 2 * d
                if dist[prev] == FAR and self.is_free(prev) and self.is_free(stand):
                    dist[prev] = dist[x] + 1
                    queue.append(prev)
        # floor from which a lone box can still reach a goal
        self.live = sum(1 << i for i, n in enumerate(dist) if n < FAR)

    def index(self, r: int, c: int) -> int:
        return (r + 1) * self.W + c + 1

    def cell(self, i: int) -> Cell:
        return i // self.W - 1, i % self.W - 1

    def cells(self, mask: int) -> set[Cell]:
        return {self.cell(i) for i in bits(mask)}

    def is_free(self, i: int) -> bool:
        return i >= 0 and (self.free >> i) & 1 == 1

    def flood(self, start: int, boxes: int) -> int:
        """Bitmask of the cells the player can walk to from ``start`` without pushing."""
        open_, W = self.free & ~boxes, self.W
        reach = 1 << start
        while True:
            grown = (reach | reach << 1 | reach >> 1 | reach << W | reach >> W) & open_
            if grown == reach:
                return reach
            reach = grown

    def frozen(self, cell: int, boxes: int) -> bool:
        """A 2x2 square of walls and boxes around ``cell`` holding a box off goal: no box in it
        can ever move again, so the level is lost."""
        block, W = boxes | self.wallmask, self.W
        for a in (-1, 1):
            if block >> cell + a & 1:   # most pushes end in the open: no blocked side, no square
                for b in (-W, W):
                    square = 1 << cell | 1 << cell + a | 1 << cell + b | 1 << cell + a + b
                    if block & square == square and boxes & square & ~self.goals:
                        return True
        return False

    def walk(self, src: int, dst: int, boxes: int) -> list[str]:
        """Action names of a shortest walk from ``src`` to ``dst`` that pushes nothing."""
        open_ = self.free & ~boxes
        return shortest_path(self.cell(src), self.cell(dst), lambda r, c: open_ >> self.index(r, c) & 1)


def bits(mask: int) -> list[int]:
    out = []
    while mask:
        low = mask & -mask
        out.append(low.bit_length() - 1)
        mask ^= low
    return out


def search(room: PushRoom, boxes: int, player: int, limit: int | None = None) -> tuple[list[str], int] | None:
    """A* over pushes. A state is the boxes plus the player's reachable region, named by its
    lowest cell, so walking about does not multiply states. Returns (actions, pushes), or None
    when unsolvable or when more than ``limit`` states were closed."""
    dist, steps = room.dist, room.steps
    h0 = sum(dist[b] for b in bits(boxes))
    if h0 >= FAR:
        return None
    # Heap entries are (f, -g, ...): among equal estimates the deepest state goes first, which
    # reaches the goal far sooner and, the heuristic being consistent, keeps pushes optimal.
    heap = [(h0, 0, 0, boxes, player, None)]
    closed: dict = {}      # (boxes, lowest reachable cell) -> the push that first got there
    covered: dict = {}     # boxes -> union of the player regions already expanded with them
    tie = 0
    while heap:
        f, neg_g, _, bx, pos, came = heappop(heap)
        g = -neg_g
        seen = covered.get(bx, 0)
        if seen >> pos & 1:   # skips the flood for states already expanded
            continue
        reach = room.flood(pos, bx)
        covered[bx] = seen | reach
        key = (bx, reach & -reach)
        closed[key] = came
        if bx == room.goals:
            return _unwind(room, closed, key), g
        if limit is not None and len(closed) > limit:
            return None
        live, h = room.live & ~bx, f - g
        for b in bits(bx):
            for a, d in enumerate(steps):
                dest = b + d
                if (reach >> b - d) & 1 and (live >> dest) & 1:
                    nb = bx ^ (1 << b) ^ (1 << dest)
                    # a state already expanded would only be skipped when popped
                    if not covered.get(nb, 0) >> b & 1 and not room.frozen(dest, nb):
                        tie += 1
                        heappush(heap, (g + 1 + h - dist[b] + dist[dest], -g - 1, tie, nb, b,
                                        (key, bx, pos, b - d, a)))
    return None


def _unwind(room: PushRoom, closed: dict, key) -> list[str]:
    """Turn the chain of pushes ending in ``key`` into walks plus the pushes themselves."""
    chain = []
    while closed[key] is not None:
        key, bx, pos, stand, a = closed[key]
        chain.append(room.walk(pos, stand, bx) + [NAMES[a]])
    return [name for part in reversed(chain) for name in part]


def pull_back(room: PushRoom, player: int, rng: np.random.Generator, runs: int,
              min_pulls: int) -> tuple[int, int] | None:
    """Reverse play from the solved room (every box on a goal, the player at ``player``): walk
    up to a box and pull it a few cells in a straight line, ``runs`` times. Every pull is undone
    by a push, so each state on the way is solvable in at most as many pushes as pulls so far;
    of those after at least ``min_pulls`` pulls, returns (boxes, player) of the one whose boxes
    are farthest (in lone-box pushes) from the goals, none on a goal; None if there is none."""
    boxes = room.goals
    best, best_score, pulls = None, 0, 0
    for _ in range(runs):
        reach, open_ = room.flood(player, boxes), room.free & ~boxes
        options = [(b, d) for b in bits(boxes) for d in room.steps
                   if reach >> b + d & 1 and open_ >> b + 2 * d & 1]
        if not options:
            break
        b, d = options[int(rng.integers(len(options)))]
        player = b + d
        for _ in range(1 + int(rng.integers(3))):
            if not open_ >> player + d & 1:
                break
            boxes ^= 1 << b | 1 << player
            open_ ^= 1 << b | 1 << player
            b, player = player, player + d
            pulls += 1
        if pulls >= min_pulls and not boxes & room.goals:
            score = sum(room.dist[x] for x in bits(boxes))
            if score >= best_score:
                best, best_score = (boxes, player), score
    return None if best is None or best_score == 0 else best


def solve(walls: Iterable[Cell], boxes: Iterable[Cell], goals: Iterable[Cell],
          player: Cell) -> list[str] | None:
    """Action names of a solution with the fewest pushes (walks between pushes are shortest
    walks), or None if the level cannot be solved. Cells are (row, col); cells outside the
    bounding box of everything given count as wall."""
    walls, boxes, goals = set(walls), set(boxes), set(goals)
    everything = walls | boxes | goals | {player}
    if min(min(rc) for rc in everything) < 0:
        raise ValueError("cells must have non-negative coordinates")
    if len(boxes) != len(goals) or not boxes:
        raise ValueError(f"need as many boxes as goals (at least one), got {len(boxes)} and {len(goals)}")
    if (boxes | goals | {player}) & walls or player in boxes:
        raise ValueError("boxes, goals and the player must stand on floor, the player not on a box")
    room = PushRoom(walls, max(r for r, _ in everything) + 1, max(c for _, c in everything) + 1, goals)
    found = search(room, sum(1 << room.index(*b) for b in boxes), room.index(*player))
    return None if found is None else found[0]


def pull_layers(room: PushRoom, limit: int) -> list[list[tuple[int, int]]]:
    """Breadth-first reverse play: every state reachable by pulls from the solved room, by
    layer. Layer k holds the (boxes, player region) states whose fewest pushes to the solved
    room are exactly k, since each pull is a push backwards and layer 0 is every solved state
    (the boxes on the goals, the player in any region of what is left). Stops after the layer
    in which ``limit`` states are passed; the layers found until then are exact."""
    free, goals = room.free, room.goals
    layer, rest = [], free & ~goals
    while rest:
        reach = room.flood((rest & -rest).bit_length() - 1, goals)
        rest &= ~reach
        layer.append((goals, reach))
    covered = {goals: free & ~goals}   # boxes -> union of the player regions found with them
    layers, count = [], len(layer)
    while layer:
        layers.append(layer)
        if count >= limit:
            break
        nxt = []
        for boxes, reach in layer:
            open_ = free & ~boxes
            for d in room.steps:
                # boxes with the player's region on the d side and an open cell beyond it
                if d > 0:
                    m = boxes & reach >> d & open_ >> 2 * d
                else:
                    m = boxes & reach << -d & open_ << -2 * d
                while m:
                    low = m & -m
                    m ^= low
                    b = low.bit_length() - 1
                    nb, stand = boxes ^ low ^ 1 << b + d, b + 2 * d
                    seen = covered.get(nb, 0)
                    if not seen >> stand & 1:
                        region = room.flood(stand, nb)
                        covered[nb] = seen | region
                        nxt.append((nb, region))
        count += len(nxt)
        layer = nxt
    return layers
