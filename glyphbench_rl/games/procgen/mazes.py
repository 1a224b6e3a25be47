"""Maze levels for the Procgen maze games: a perfect maze from the task's generator
(``games.common.grid.carve_maze``), optionally braided (some walls between rooms knocked out so
that loops exist: a chase needs escape routes), and distance maps over its open cells cached by
source cell (chasers look them up every turn; the player revisits cells, so most are reused)."""

from __future__ import annotations

from typing import Sequence

import numpy as np

from ..common.grid import DELTAS, Board, carve_maze
from ..common.palette import WALL
from .engine import OPEN

Cell = tuple[int, int]


def maze_level(cells: int, rng: np.random.Generator, braid: float = 0.0) -> Board:
    """A (2*cells+1)-square maze of WALL and OPEN with rooms at odd (row, column); ``braid``
    is the share of the remaining inner walls between two rooms that are knocked out."""
    board = carve_maze(cells, rng, WALL, OPEN)
    if braid > 0:
        size = board.height
        walls = [(r, c) for r in range(1, size - 1) for c in range(1, size - 1)
                 if (r + c) % 2 == 1 and board[r, c] == WALL]
        count = int(round(braid * len(walls)))
        for i in rng.choice(len(walls), size=count, replace=False).tolist():
            board[walls[i]] = OPEN
    return board


def rooms(board: Board) -> list[Cell]:
    """The open cells at odd (row, column): a maze's rooms, where things are placed."""
    return [(r, c) for r in range(1, board.height, 2) for c in range(1, board.width, 2)
            if board[r, c] != WALL]


class DistanceMaps:
    """Step distances between open cells of a fixed maze, one BFS per source cell, cached."""

    def __init__(self, board: Board) -> None:
        self.width = board.width
        open_ = {(r, c) for r in range(board.height) for c in range(board.width) if board[r, c] != WALL}
        self.neighbours: dict[Cell, tuple[Cell, ...]] = {
            cell: tuple((cell[0] + dr, cell[1] + dc) for dr, dc in DELTAS
                        if (cell[0] + dr, cell[1] + dc) in open_) for cell in open_}
        # cells by flat index r * width + c: a BFS over ints and a list of distances is about
        # twice as fast as one over (row, column) tuples (a tuple is hashed at every look-up)
        self.size = board.height * board.width
        self._next: list[tuple[int, ...]] = [()] * self.size
        for (r, c), cells in self.neighbours.items():
            self._next[r * self.width + c] = tuple(nr * self.width + nc for nr, nc in cells)
        # source -> [distances so far (-1: not yet), the BFS frontier, its distance]: a search is
        # carried only as far as asked (a chaser needs its few neighbours, usually nearer)
        self._maps: dict[int, list] = {}

    def from_(self, source: Cell) -> dict[Cell, int]:
        """Distances from ``source`` to every open cell reachable from it."""
        dist, w = self.reaching(source, None), self.width
        return {cell: dist[cell[0] * w + cell[1]] for cell in self.neighbours
                if dist[cell[0] * w + cell[1]] >= 0}

    def reaching(self, source: Cell, cells: Sequence[Cell] | None) -> list[int]:
        """Distances from ``source`` by flat index (``r * width + c``; -1 where not reached),
        holding at least those to ``cells`` (every reachable cell when None): the breadth-first
        search is resumed a frontier at a time until they are all in it."""
        w = self.width
        s = source[0] * w + source[1]
        entry = self._maps.get(s)
        if entry is None:
            dist = [-1] * self.size
            dist[s] = 0
            entry = self._maps[s] = [dist, [s], 0]
        dist, frontier, d = entry
        if not frontier:
            return dist
        needed = None
        if cells is not None:
            needed = [i for i in (r * w + c for r, c in cells) if dist[i] < 0]
            if not needed:
                return dist
        nbrs = self._next
        while frontier:
            d += 1
            nxt = []
            for i in frontier:
                for n in nbrs[i]:
                    if dist[n] < 0:
                        dist[n] = d
                        nxt.append(n)
            frontier = nxt
            if needed is not None:
                needed = [i for i in needed if dist[i] < 0]
                if not needed:
                    break
        entry[1], entry[2] = frontier, d
        return dist
