"""Ice Sliding: on an icy floor you slide until a rock stops you; come to the exit.

Levels are random rocks in a walled room. The exit is picked first; a breadth-first search
backwards over slides then gives every cell's fewest moves to the exit, and the start is drawn
among the cells that need at least ``min_moves`` of them, so every level is solvable and its
optimum is known.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import GlyphTask, register_variants
from ...core.params import param
from ..common.grid import DELTAS, MOVES, Board, bfs_layers, move_actions, random_room, slide
from ..common.palette import FLOOR, GOAL, PLAYER, WALL
from ..common.view import overlay, stamped

Cell = tuple[int, int]
_TRIES = 500   # rock layouts tried per reset before the parameters are declared impossible


@dataclass(frozen=True)
class IceSlidingParams:
    size: int = param(7, 4, 16)              # the room's interior is size x size; the grid adds the outer wall
    rocks: int = param(6, 0, lambda p: p.size * p.size // 3)     # rocks scattered on the ice
    min_moves: int = param(3, 1, 30)         # generated levels need at least this many moves
    time_weight: float = param(0.5, 0, 1, open_hi=True)   # share of the win reward lost by using every turn


def slide_graph(board: Board, exit_: Cell) -> dict[Cell, list[Cell]]:
    """For every open cell, the cells one slide in each direction ends on (the exit stops a
    slide that reaches it)."""
    blocked = lambda r, c: board.rows[r][c] == WALL  # noqa: E731  (the outer wall bounds slides)
    stops = lambda r, c: (r, c) == exit_  # noqa: E731
    return {cell: [slide(cell, d, blocked, stops) for d in DELTAS]
            for cell in ((r, c) for r in range(board.height) for c in range(board.width)
                         if not blocked(r, c))}


def moves_to_exit(board: Board, exit_: Cell) -> dict[Cell, int]:
    """Fewest slides from each cell that can reach the exit (the exit itself at 0)."""
    graph = slide_graph(board, exit_)
    back: dict[Cell, list[Cell]] = {}
    for cell, ends in graph.items():
        for end in ends:
            if end != cell:
                back.setdefault(end, []).append(cell)
    return bfs_layers([exit_], lambda cell: back.get(cell, ()))


def solve(board: Board, start: Cell, exit_: Cell) -> list[str] | None:
    """Action names of a shortest sequence of slides from ``start`` to the exit, or None."""
    dist = moves_to_exit(board, exit_)
    if start not in dist:
        return None
    graph, plan, cell = slide_graph(board, exit_), [], start
    while cell != exit_:   # follow any slide that brings the exit one move nearer
        name, cell = next((n, end) for n, end in zip(MOVES, graph[cell]) if dist.get(end) == dist[cell] - 1)
        plan.append(name)
    return plan


class IceSliding(GlyphTask):
    title = "Ice Sliding"
    rules = ("You are in an icy {size}x{size} room. A move sends you sliding in that direction "
             "until the next cell is a wall or rock; you cannot stop on the way, and a move "
             "toward an adjacent wall or rock does nothing. Sliding onto the exit stops you there. "
             "Reach the exit.")
    rewards = "reaching the exit gives 1 minus {time_weight:g} x (turns used / {max_turns})."
    ends = "when you reach the exit"
    Params = IceSlidingParams
    ACTIONS = move_actions("slide", "")
    glyphs = {WALL: "wall or rock", FLOOR: "ice", PLAYER: "you", GOAL: "exit"}
    default_max_turns = 40

    def _setup(self, rng: np.random.Generator) -> None:
        p = self.params
        for _ in range(_TRIES):
            board, (exit_,) = random_room(p.size, p.rocks, 1, rng, WALL, FLOOR)
            dist = moves_to_exit(board, exit_)
            starts = sorted(cell for cell, d in dist.items() if d >= p.min_moves)
            if starts:
                self.board, self.exit = board, exit_
                self.pos = starts[int(rng.integers(len(starts)))]
                self.optimal = dist[self.pos]   # fewest moves, for tests and baselines
                self._still = board.lines()    # what never moves, drawn once
                overlay(self._still, *exit_, GOAL)
                return
        raise RuntimeError(f"{self.task_id}: no level needing {p.min_moves} moves found in {_TRIES} "
                           "layouts; lower min_moves or change rocks")

    def _act(self, action: int) -> None:
        rows = self.board.rows
        end = slide(self.pos, DELTAS[action], lambda r, c: rows[r][c] == WALL,
                    lambda r, c: (r, c) == self.exit)
        if end == self.pos:
            self.say("Blocked: you did not move.")
            return
        self.pos = end
        if end == self.exit:
            self.reward(self.time_bonus(self.params.time_weight))
            self.say("Reached the exit.")
            self.finish(won=True)

    def _grid(self) -> list[str]:
        return stamped(self._still, *self.pos, PLAYER)


register_variants(IceSliding, "Classics", {
    "glyphbench/classics-icesliding-easy-v0": dict(size=6, rocks=5, min_moves=3, max_turns=30),
    "glyphbench/classics-icesliding-medium-v0": dict(size=8, rocks=9, min_moves=5, max_turns=50),
    "glyphbench/classics-icesliding-hard-v0": dict(size=10, rocks=14, min_moves=8, max_turns=80),
})
