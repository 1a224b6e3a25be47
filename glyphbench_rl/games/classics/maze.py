"""Maze: walk from the start to the exit of a randomly carved perfect maze."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import GlyphTask, register_variants
from ...core.params import param
from ..common.grid import DELTAS, bfs_distances, carve_maze, move_actions
from ..common.palette import FLOOR, GOAL, PLAYER, WALL
from ..common.view import overlay, stamped


@dataclass(frozen=True)
class MazeParams:
    cells: int = param(5, 2, 20)      # the maze is cells x cells rooms; the grid is 2*cells+1 wide
    time_weight: float = param(0.9, 0, 1, open_hi=True)   # share of the win reward lost by using every turn


class Maze(GlyphTask):
    title = "Maze"
    rules = ("Walk through the maze from your position to the exit. Walls block movement; "
             "walking into a wall wastes the turn. There is exactly one path between any two "
             "open cells.")
    rewards = "reaching the exit gives 1 minus {time_weight:g} x (turns used / {max_turns})."
    ends = "when you reach the exit"
    Params = MazeParams
    ACTIONS = move_actions()
    glyphs = {WALL: "wall", FLOOR: "open", PLAYER: "you", GOAL: "exit"}
    default_max_turns = 100

    def _setup(self, rng: np.random.Generator) -> None:
        self.board = carve_maze(self.params.cells, rng, WALL, FLOOR)
        rooms = self.board.cells(FLOOR)
        self.pos = rooms[int(rng.integers(len(rooms)))]
        dist = bfs_distances(self.pos, lambda r, c: self.board[r, c] != WALL)
        far = max(dist.values())
        ends = sorted(cell for cell, d in dist.items() if d == far)
        self.exit = ends[int(rng.integers(len(ends)))]
        self.optimal = far   # shortest path length, for tests and baselines
        self._still = self.board.lines()   # the maze never changes: drawn once
        overlay(self._still, *self.exit, GOAL)

    def _grid(self) -> list[str]:
        return stamped(self._still, *self.pos, PLAYER)

    def _act(self, action: int) -> None:
        dr, dc = DELTAS[action]
        r, c = self.pos[0] + dr, self.pos[1] + dc
        if self.board[r, c] == WALL:   # the outer wall keeps indices in range
            self.say("Bumped into a wall.")
            return
        self.pos = (r, c)
        if self.pos == self.exit:
            self.reward(self.time_bonus(self.params.time_weight))
            self.say("Reached the exit.")
            self.finish(won=True)


register_variants(Maze, "Classics", {
    "glyphbench/classics-maze-easy-v0": dict(cells=5, max_turns=100),
    "glyphbench/classics-maze-medium-v0": dict(cells=7, max_turns=200),
    "glyphbench/classics-maze-hard-v0": dict(cells=10, max_turns=400),
})
