"""Grid motion and search: compass moves, a mutable char board, walled rooms, breadth-first
search over cells or over any hashable state, and sliding until blocked."""

from __future__ import annotations

from collections import deque
from typing import Callable, Hashable, Iterable, TypeVar

import numpy as np

from ...core.actions import ActionSet

Cell = tuple[int, int]
S = TypeVar("S", bound=Hashable)
Neighbours = Callable[[S], Iterable[tuple[object, S]]]

# Row/column deltas of the four compass moves, in action order.
MOVES: dict[str, tuple[int, int]] = {"UP": (-1, 0), "DOWN": (1, 0), "LEFT": (0, -1), "RIGHT": (0, 1)}
DELTAS: tuple[tuple[int, int], ...] = tuple(MOVES.values())
OPPOSITE = {0: 1, 1: 0, 2: 3, 3: 2}


def move_actions(verb: str = "move", unit: str = " one cell") -> ActionSet:
    """UP/DOWN/LEFT/RIGHT described as e.g. "move one cell up"."""
    return ActionSet([(name, f"{verb}{unit} {name.lower()}") for name in MOVES])


class Board:
    """A rectangular board of single-character cells, stored as a list of row lists."""

    __slots__ = ("rows", "height", "width")

    def __init__(self, height: int, width: int, fill: str) -> None:
        self.height, self.width = height, width
        self.rows = [[fill] * width for _ in range(height)]

    @classmethod
    def from_lines(cls, lines: Iterable[str]) -> "Board":
        lines = list(lines)
        board = cls(len(lines), len(lines[0]), " ")
        board.rows = [list(line) for line in lines]
        return board

    def inside(self, r: int, c: int) -> bool:
        return 0 <= r < self.height and 0 <= c < self.width

    def __getitem__(self, rc: tuple[int, int]) -> str:
        return self.rows[rc[0]][rc[1]]

    def __setitem__(self, rc: tuple[int, int], ch: str) -> None:
        self.rows[rc[0]][rc[1]] = ch

    def lines(self) -> list[str]:
        return ["".join(row) for row in self.rows]

    def cells(self, ch: str) -> list[tuple[int, int]]:
        return [(r, c) for r, row in enumerate(self.rows) for c, x in enumerate(row) if x == ch]


def interior_cells(n: int) -> list[tuple[int, int]]:
    """The cells of an n x n room inside a one-cell border, row by row."""
    return [(r, c) for r in range(1, n + 1) for c in range(1, n + 1)]


def walled_room(n: int, wall: str, floor: str, blocked: set[tuple[int, int]] = frozenset()) -> Board:
    """An n x n room of ``floor`` inside a ring of ``wall``; ``blocked`` interior cells stay wall."""
    board = Board(n + 2, n + 2, wall)
    for cell in interior_cells(n):
        if cell not in blocked:
            board[cell] = floor
    return board


def random_room(n: int, blocks: int, picks: int, rng: np.random.Generator, wall: str,
                floor: str) -> tuple[Board, list[Cell]]:
    """A walled n x n room with ``blocks`` random interior cells walled up, and ``picks`` more
    random interior cells (a start, an exit, hazards): all distinct, drawn in one
    ``rng.choice`` without replacement."""
    interior = interior_cells(n)
    drawn = rng.choice(len(interior), size=blocks + picks, replace=False).tolist()
    board = walled_room(n, wall, floor, {interior[i] for i in drawn[:blocks]})
    return board, [interior[i] for i in drawn[blocks:]]


def carve_maze(cells: int, rng: np.random.Generator, wall: str, floor: str) -> Board:
    """A perfect maze (one path between any two rooms) of cells x cells rooms by randomised
    depth-first search: a (2*cells+1)-square board whose rooms sit at odd (row, column)."""
    size = 2 * cells + 1
    board = Board(size, size, wall)
    start = (int(rng.integers(cells)), int(rng.integers(cells)))
    seen = {start}
    stack = [start]
    board[2 * start[0] + 1, 2 * start[1] + 1] = floor
    while stack:
        r, c = stack[-1]
        options = [(r + dr, c + dc) for dr, dc in DELTAS
                   if 0 <= r + dr < cells and 0 <= c + dc < cells and (r + dr, c + dc) not in seen]
        if not options:
            stack.pop()
            continue
        nr, nc = options[int(rng.integers(len(options)))]
        board[r + nr + 1, c + nc + 1] = floor      # the wall between the two rooms
        board[2 * nr + 1, 2 * nc + 1] = floor
        seen.add((nr, nc))
        stack.append((nr, nc))
    return board


def bfs_distances(start: tuple[int, int], passable: Callable[[int, int], bool]) -> dict[tuple[int, int], int]:
    """Shortest 4-connected step counts from ``start`` to every reachable passable cell."""
    dist = {start: 0}
    queue = deque([start])
    while queue:
        r, c = queue.popleft()
        d = dist[(r, c)] + 1
        for dr, dc in DELTAS:
            nxt = (r + dr, c + dc)
            if nxt not in dist and passable(*nxt):
                dist[nxt] = d
                queue.append(nxt)
    return dist


def shortest_path(start: tuple[int, int], goal: tuple[int, int],
                  passable: Callable[[int, int], bool]) -> list[str] | None:
    """Action names of one shortest 4-connected path, or None when ``goal`` is unreachable."""
    prev: dict[tuple[int, int], tuple[tuple[int, int], str] | None] = {start: None}
    queue = deque([start])
    while queue:
        cur = queue.popleft()
        if cur == goal:
            path = []
            while prev[cur] is not None:
                cur, name = prev[cur]
                path.append(name)
            return path[::-1]
        for name, (dr, dc) in MOVES.items():
            nxt = (cur[0] + dr, cur[1] + dc)
            if nxt not in prev and passable(*nxt):
                prev[nxt] = (cur, name)
                queue.append(nxt)
    return None


def slide(start: Cell, delta: Cell, blocked: Callable[[int, int], bool],
          stops: Callable[[int, int], bool] | None = None) -> Cell:
    """Where something moving from ``start`` by ``delta`` comes to rest: the last cell before a
    blocked one, or the first cell where ``stops`` holds (an exit, a hole). ``blocked`` must hold
    outside the board, so a slide always ends."""
    r, c = start
    dr, dc = delta
    while not blocked(r + dr, c + dc):
        r, c = r + dr, c + dc
        if stops is not None and stops(r, c):
            break
    return r, c


def bfs_search(start: S, neighbours: Neighbours, is_goal: Callable[[S], bool],
               limit: int | None = None) -> list | None:
    """The actions of one shortest path from ``start`` to a goal state, or None when no goal is
    reachable (or more than ``limit`` states were seen). ``neighbours(state)`` yields
    ``(action, next state)``, the action being a name or an index; states that lose simply have
    no neighbours and are no goal."""
    if is_goal(start):
        return []
    prev: dict = {start: None}
    queue = deque([start])
    while queue:
        state = queue.popleft()
        for name, nxt in neighbours(state):
            if nxt in prev:
                continue
            prev[nxt] = (state, name)
            if is_goal(nxt):
                path = []
                while prev[nxt] is not None:
                    nxt, step = prev[nxt]
                    path.append(step)
                return path[::-1]
            if limit is not None and len(prev) > limit:
                return None
            queue.append(nxt)
    return None


def bfs_layers(sources: Iterable[S], neighbours: Callable[[S], Iterable[S]],
               limit: int | None = None) -> dict[S, int] | None:
    """Distance (in steps) from the nearest source to every reachable state, or None when more
    than ``limit`` states are reachable. ``neighbours`` yields bare states here."""
    dist = {s: 0 for s in sources}
    queue = deque(dist)
    while queue:
        state = queue.popleft()
        d = dist[state] + 1
        for nxt in neighbours(state):
            if nxt not in dist:
                dist[nxt] = d
                queue.append(nxt)
                if limit is not None and len(dist) > limit:
                    return None
    return dist
