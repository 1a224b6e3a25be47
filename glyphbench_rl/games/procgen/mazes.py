"""Maze levels for the Procgen maze games: a perfect maze from the task's generator
(``games.common.grid.carve_maze``), optionally braided (some walls between rooms knocked out so
that loops exist: a chase needs escape routes), and distance maps over its open cells cached by
source cell (chasers look them up every turn; the player revisits cells, so most are reused)."""

from __future__ import annotations

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
        self._maps: dict[Cell, dict[Cell, int]] = {}

    def from_(self, source: Cell) -> dict[Cell, int]:
        dist = self._maps.get(source)
        if dist is None:
            # breadth-first, a frontier at a time, over the neighbour table built once
            nbrs, dist, frontier, d = self.neighbours, {source: 0}, [source], 0
            while frontier:
                d += 1
                nxt = []
                for cell in frontier:
                    for n in nbrs[cell]:
                        if n not in dist:
                            dist[n] = d
                            nxt.append(n)
                frontier = nxt
            self._maps[source] = dist
        return dist
