"""Sokoban: push every box onto a goal.

Levels come from reverse play (the player walks backwards from a solved room, pulling boxes
off their goals) and are then proven solvable by a push-optimal search, which also gives the
optimal push count. The search works on padded cell indices with Python ints as bitmasks, so
flood fills and state keys cost a handful of big-int operations instead of set walks.
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass
from heapq import heappop, heappush
from typing import Iterable

import numpy as np

from ...core import GlyphTask, register_variants
from ...core.params import param
from ..common.grid import DELTAS, MOVES, move_actions, shortest_path
from ..common.palette import FLOOR, GOAL, PLAYER, WALL

BOX, BOX_ON_GOAL, PLAYER_ON_GOAL = "$", "*", "+"   # the classic Sokoban text notation
Cell = tuple[int, int]
_NAMES = tuple(MOVES)
_FAR = 10**6              # lone-box push distance of a dead square (no goal reachable)
_SEARCH_LIMIT = 4000      # states the generator lets the solver close before giving a level up
_PULL_RUNS = 8            # straight pulling runs per box in reverse play
_TRIES = 1000             # rooms tried per reset before the parameters are declared impossible


@dataclass(frozen=True)
class SokobanParams:
    size: int = param(6, 4, 12)              # the room's interior is size x size; the grid adds the outer wall
    boxes: int = param(1, 1, 4)              # boxes, and as many goals
    # wall cells tried inside the room (kept only if the room stays connected)
    inner_walls: int = param(2, 0, lambda p: p.size * p.size // 4)
    # generated levels need at least this many pushes to solve
    min_pushes: int = param(3, 1, lambda p: 6 * p.size)
    # ... and a push-optimal solution of at most this many moves
    max_moves: int = param(30, lambda p: p.min_pushes, 512)


class _Room:
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
        self.steps = (-W, W, -1, 1)   # in action order: UP, DOWN, LEFT, RIGHT
        # Fewest pushes taking a lone box to its nearest goal, searched backwards from every
        # goal: a box reaches x from x - d when the player can stand at x - 2d. It is a lower
        # bound that changes by at most one per push, so A* with it is push-optimal.
        self.dist = dist = [_FAR] * ((height + 2) * W)
        queue = deque(_bits(self.goals))
        for g in queue:
            dist[g] = 0
        while queue:
            x = queue.popleft()
            for d in self.steps:
                prev, stand = x - d, x - 2 * d
                if dist[prev] == _FAR and self.is_free(prev) and self.is_free(stand):
                    dist[prev] = dist[x] + 1
                    queue.append(prev)

    def index(self, r: int, c: int) -> int:
        return (r + 1) * self.W + c + 1

    def cell(self, i: int) -> Cell:
        return i // self.W - 1, i % self.W - 1

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


def _bits(mask: int) -> list[int]:
    out = []
    while mask:
        low = mask & -mask
        out.append(low.bit_length() - 1)
        mask ^= low
    return out


def _search(room: _Room, boxes: int, player: int, limit: int | None = None) -> tuple[list[str], int] | None:
    """A* over pushes. A state is the boxes plus the player's reachable region, named by its
    lowest cell, so walking about does not multiply states. Returns (actions, pushes), or None
    when unsolvable or when more than ``limit`` states were closed."""
    dist, steps = room.dist, room.steps
    h0 = sum(dist[b] for b in _bits(boxes))
    if h0 >= _FAR:
        return None
    # Heap entries are (f, -g, ...): among equal estimates the deepest state goes first, which
    # reaches the goal far sooner and, the heuristic being consistent, keeps pushes optimal.
    heap = [(h0, 0, 0, boxes, player, None)]
    closed: dict = {}      # (boxes, lowest reachable cell) -> the push that first got there
    regions: dict = {}     # boxes -> player regions already expanded with them
    tie = 0
    while heap:
        f, neg_g, _, bx, pos, came = heappop(heap)
        g = -neg_g
        done = regions.setdefault(bx, [])
        if any(r >> pos & 1 for r in done):   # skips the flood for states already expanded
            continue
        reach = room.flood(pos, bx)
        done.append(reach)
        key = (bx, reach & -reach)
        closed[key] = came
        if bx == room.goals:
            return _unwind(room, closed, key), g
        if limit is not None and len(closed) > limit:
            return None
        open_, h = room.free & ~bx, f - g
        for b in _bits(bx):
            for a, d in enumerate(steps):
                dest = b + d
                if (reach >> b - d) & 1 and (open_ >> dest) & 1 and dist[dest] < _FAR:
                    nb = bx ^ (1 << b) ^ (1 << dest)
                    if not room.frozen(dest, nb):
                        tie += 1
                        heappush(heap, (g + 1 + h - dist[b] + dist[dest], -g - 1, tie, nb, b,
                                        (key, bx, pos, b - d, a)))
    return None


def _unwind(room: _Room, closed: dict, key) -> list[str]:
    """Turn the chain of pushes ending in ``key`` into walks plus the pushes themselves."""
    chain = []
    while closed[key] is not None:
        key, bx, pos, stand, a = closed[key]
        chain.append(room.walk(pos, stand, bx) + [_NAMES[a]])
    return [name for part in reversed(chain) for name in part]


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
    room = _Room(walls, max(r for r, _ in everything) + 1, max(c for _, c in everything) + 1, goals)
    found = _search(room, sum(1 << room.index(*b) for b in boxes), room.index(*player))
    return None if found is None else found[0]


class Sokoban(GlyphTask):
    title = "Sokoban"
    rules = ("You are in a walled {size}x{size} room with {box_count} and as many goals. "
             "Walking into a box pushes it one cell if the cell beyond it is floor or goal; a "
             "box against a wall or another box does not move, and boxes cannot be pulled, so "
             "a box pushed into a corner is stuck for good. Put every box on a goal.")
    rewards = ("+{box_reward:.4g} each time a box lands on a goal, -{box_reward:.4g} each time "
               "one is pushed off a goal, +{solve_reward:g} when every box is on a goal.")
    ends = "when every box is on a goal"
    Params = SokobanParams
    ACTIONS = move_actions("walk or push", " one cell")
    glyphs = {WALL: "wall", FLOOR: "floor", GOAL: "goal", BOX: "box", BOX_ON_GOAL: "box on goal",
              PLAYER: "you", PLAYER_ON_GOAL: "you on goal"}
    default_max_turns = 60
    SOLVE_REWARD = 0.5     # the other half of the return is shared by the boxes

    def prompt_fields(self) -> dict:
        n = self.params.boxes
        return super().prompt_fields() | {"box_count": f"{n} box" + "es" * (n > 1),
                                          "box_reward": self.box_reward, "solve_reward": self.SOLVE_REWARD}

    def _init(self) -> None:
        self.box_reward = (1 - self.SOLVE_REWARD) / self.params.boxes

    # -- generation -------------------------------------------------------------------------------
    def _setup(self, rng: np.random.Generator) -> None:
        for _ in range(_TRIES):   # each try is a fresh room; most succeed within a few
            level = self._generate(rng)
            if level is not None:
                break
        else:
            raise RuntimeError(f"{self.task_id}: no level found in {_TRIES} rooms for {self.params}; "
                               "lower min_pushes or raise max_moves")
        walls, boxes, goals, player, self.solution, self.optimal_pushes = level
        self._install(walls, boxes, goals, player)

    def _install(self, walls: set[Cell], boxes: set[Cell], goals: frozenset[Cell], player: Cell) -> None:
        """Set up play on a level; tests also use it to load hand-made levels."""
        self.walls, self.goals, self.boxes, self.player = set(walls), frozenset(goals), set(boxes), player
        self.on_goal, self.pushes = len(self.boxes & self.goals), 0
        height, width = max(r for r, _ in walls) + 1, max(c for _, c in walls) + 1
        self.rows = [[WALL] * width for _ in range(height)]
        for r in range(height):
            for c in range(width):
                self._paint((r, c))

    def _make_room(self, rng: np.random.Generator) -> tuple[set[Cell], list[Cell]]:
        """The walls (outer ring plus a few inside, never cutting the room apart) and the floor."""
        n = self.params.size
        walls = {(r, c) for r in range(n + 2) for c in range(n + 2) if r in (0, n + 1) or c in (0, n + 1)}
        floor = [(r, c) for r in range(1, n + 1) for c in range(1, n + 1)]
        for _ in range(self.params.inner_walls):
            cell = floor[int(rng.integers(len(floor)))]
            rest = [x for x in floor if x != cell]
            room = _Room(walls | {cell}, n + 2, n + 2, ())
            if bin(room.flood(room.index(*rest[0]), 0)).count("1") == len(rest):  # still connected
                walls.add(cell)
                floor = rest
        return walls, floor

    def _generate(self, rng: np.random.Generator):
        p = self.params
        walls, floor = self._make_room(rng)
        picks = rng.choice(len(floor), size=p.boxes + 1, replace=False)
        room = _Room(walls, p.size + 2, p.size + 2, [floor[int(i)] for i in picks[:-1]])
        boxes, player = room.goals, room.index(*floor[int(picks[-1])])
        # Reverse play: walk up to a box and pull it a few cells in a straight line, over and
        # over. Every pull is undone by a push, so each state on the way is solvable in at most
        # as many pushes as pulls so far; of those that may still need min_pushes, keep the one
        # whose boxes are farthest (in lone-box pushes) from the goals, none on a goal.
        best, best_score, pulls = None, 0, 0
        for _ in range(_PULL_RUNS * p.boxes):
            reach, open_ = room.flood(player, boxes), room.free & ~boxes
            options = [(b, d) for b in _bits(boxes) for d in room.steps
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
            if pulls >= p.min_pushes and not boxes & room.goals:
                score = sum(room.dist[x] for x in _bits(boxes))
                if score >= best_score:
                    best, best_score = (boxes, player), score
        if best is None or best_score == 0:
            return None
        found = _search(room, *best, limit=_SEARCH_LIMIT)
        if found is None or found[1] < p.min_pushes or len(found[0]) > p.max_moves:
            return None
        cells = lambda mask: {room.cell(i) for i in _bits(mask)}  # noqa: E731
        return walls, cells(best[0]), cells(room.goals), room.cell(best[1]), *found

    # -- play --------------------------------------------------------------------------------------
    def _paint(self, rc: Cell) -> None:
        on_goal = rc in self.goals
        if rc == self.player:
            ch = PLAYER_ON_GOAL if on_goal else PLAYER
        elif rc in self.boxes:
            ch = BOX_ON_GOAL if on_goal else BOX
        elif rc in self.walls:
            ch = WALL
        else:
            ch = GOAL if on_goal else FLOOR
        self.rows[rc[0]][rc[1]] = ch

    def _act(self, action: int) -> None:
        dr, dc = DELTAS[action]
        here = self.player
        nxt = (here[0] + dr, here[1] + dc)
        if nxt in self.walls:
            self.say("You bumped into a wall.")
            return
        if nxt in self.boxes:
            dest = (nxt[0] + dr, nxt[1] + dc)
            if dest in self.walls or dest in self.boxes:
                self.say("The box is blocked and did not move.")
                return
            self.boxes.remove(nxt)
            self.boxes.add(dest)
            self.pushes += 1
            if nxt in self.goals:
                self.on_goal -= 1
                self.reward(-self.box_reward)
                self.say("A box left its goal.")
            if dest in self.goals:
                self.on_goal += 1
                self.reward(self.box_reward)
                self.say("A box is on a goal.")
            self._paint(dest)
        self.player = nxt
        self._paint(here)
        self._paint(nxt)
        if self.on_goal == self.params.boxes:
            self.reward(self.SOLVE_REWARD)
            self.say("Every box is on a goal: solved.")
            self.finish(won=True)

    def _grid(self) -> list[str]:
        return ["".join(row) for row in self.rows]

    def _hud(self) -> str:
        return f"Boxes on goals {self.on_goal}/{self.params.boxes}"


register_variants(Sokoban, "Classics", {
    "glyphbench/classics-sokoban-easy-v0": dict(size=6, boxes=1, inner_walls=2, min_pushes=4, max_moves=30,
                                                max_turns=60),
    "glyphbench/classics-sokoban-medium-v0": dict(size=7, boxes=2, inner_walls=4, min_pushes=7, max_moves=60,
                                                  max_turns=120),
    "glyphbench/classics-sokoban-hard-v0": dict(size=8, boxes=3, inner_walls=6, min_pushes=10, max_moves=100,
                                                max_turns=200),
})
