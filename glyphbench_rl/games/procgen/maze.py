"""Procgen Maze: a mouse walks a freshly carved perfect maze to the cheese."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from ..common.grid import bfs_distances
from ..common.palette import GOAL, WALL
from .engine import OPEN, PLAYER_GLYPHS, ProcgenTask
from .mazes import maze_level


@dataclass(frozen=True)
class MazeParams:
    cells: int = param(10, 2, 20)   # cells x cells rooms: the world is 2*cells+1 square


class ProcgenMaze(ProcgenTask):
    title = "Procgen Maze"
    rules = ("You are a mouse in a maze of {size}x{size} cells, seen through a window that "
             "follows you. Walk to the cheese. Walls block movement; there is exactly one path "
             "between any two open cells.")
    rewards = "reaching the cheese gives +1."
    ends = "when you reach the cheese"
    Params = MazeParams
    glyphs = {WALL: "wall", OPEN: "open", GOAL: "cheese", **PLAYER_GLYPHS}

    def prompt_fields(self) -> dict:
        return {"size": 2 * self.params.cells + 1}

    def _setup(self, rng: np.random.Generator) -> None:
        self.board = maze_level(self.params.cells, rng)
        far = self.board.height - 2
        self.place_player((1, 1))
        self.goal = (far, far)
        self.optimal = bfs_distances(self.pos, lambda r, c: self.board[r, c] != WALL)[self.goal]
        self._still = self.board.lines()
        row = self._still[far]
        self._still[far] = row[:far] + GOAL + row[far + 1:]

    def _rows(self) -> list[str]:
        return self._still

    def _act(self, action: int) -> None:
        r, c = self.target(action)
        if self.board[r, c] == WALL:
            return
        self.pos = (r, c)
        if self.pos == self.goal:
            self.reward(1.0)
            self.say("You found the cheese.")
            self.finish(won=True)


register_variants(ProcgenMaze, "Procgen", {"glyphbench/procgen-maze-v0": dict(max_turns=500)})
