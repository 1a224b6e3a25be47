"""Gravity Maze: turn gravity to roll a ball through a walled room into the goal.

The ball falls one cell per turn in the direction of gravity; the player only turns gravity.
Levels are random walls and spikes, kept when a breadth-first search over (ball, gravity) states
reaches the goal in at least ``min_moves`` turns, which is also the optimum used by the tests.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import ActionSet, GlyphTask, register_variants
from ...core.params import param
from ..common.grid import DELTAS, Board, bfs_search, interior_cells, random_room
from ..common.palette import FLOOR, GOAL, WALL
from ..common.view import stamped

BALL, SPIKES = "●", "▲"
# Gravity directions as DELTAS indices, in clockwise order as seen on screen: down, left, up, right.
CLOCKWISE = (1, 2, 0, 3)
DIRECTION_NAMES = ("up", "down", "left", "right")
_TRIES = 400   # layouts tried per reset before the parameters are declared impossible

Cell = tuple[int, int]
State = tuple[Cell, int]   # the ball's cell and gravity (a DELTAS index)


@dataclass(frozen=True)
class GravityMazeParams:
    size: int = param(8, 4, 16)              # the room's interior is size x size
    walls: int = param(12, 0, lambda p: p.size * p.size // 3)    # wall blocks scattered inside
    spikes: int = param(3, 0, lambda p: p.size * p.size // 6)    # spike cells: the ball is lost on them
    min_moves: int = param(10, 1, 60)        # generated levels need at least this many turns
    spike_penalty: float = param(0.5, 0, 1)
    time_weight: float = param(0.5, 0, 1, open_hi=True)   # share of the win reward lost by using every turn


def turn(gravity: int, action: int) -> int:
    """Gravity after action 0 (clockwise), 1 (counterclockwise) or 2 (keep)."""
    if action == 2:
        return gravity
    i = CLOCKWISE.index(gravity)
    return CLOCKWISE[(i + (1 if action == 0 else -1)) % 4]


def fall(board: Board, state: State, action: int) -> State:
    """One turn: set gravity, then the ball falls one cell unless a wall is in the way."""
    (r, c), g = state
    g = turn(g, action)
    dr, dc = DELTAS[g]
    if board.rows[r + dr][c + dc] != WALL:
        r, c = r + dr, c + dc
    return (r, c), g


def solve(board: Board, state: State, goal: Cell, spikes: set[Cell]) -> list[int] | None:
    """Action indices of a shortest way to roll the ball into the goal without touching spikes."""
    def neighbours(s: State):
        if s[0] in spikes or s[0] == goal:
            return
        for a in range(3):
            yield a, fall(board, s, a)
    return bfs_search(state, neighbours, lambda s: s[0] == goal)


class GravityMaze(GlyphTask):
    title = "Gravity Maze"
    rules = ("A ball lies in a walled {size}x{size} room. You do not move the ball: each turn you "
             "may turn gravity a quarter turn, then the ball falls one cell in the direction of "
             "gravity unless a wall is in the way. Clockwise turns go down, left, up, right, down. "
             "Roll the ball into the goal; spikes destroy it.")
    rewards = ("reaching the goal gives 1 minus {time_weight:g} x (turns used / {max_turns}); "
               "the ball landing on spikes costs {spike_penalty:g}.")
    ends = "when the ball reaches the goal or hits spikes"
    Params = GravityMazeParams
    ACTIONS = ActionSet([("ROTATE_CW", "turn gravity a quarter turn clockwise, then the ball falls"),
                         ("ROTATE_CCW", "turn gravity a quarter turn counterclockwise, then the ball falls"),
                         ("WAIT", "keep gravity, the ball falls")])
    glyphs = {WALL: "wall", FLOOR: "empty", BALL: "ball", GOAL: "goal", SPIKES: "spikes"}
    default_max_turns = 60

    def _setup(self, rng: np.random.Generator) -> None:
        p = self.params
        n = p.size
        interior = interior_cells(n)
        for _ in range(_TRIES):
            board, picks = random_room(n, p.walls, p.spikes + 1, rng, WALL, FLOOR)
            spikes, goal = set(picks[:-1]), picks[-1]
            # the ball starts at rest: on a free cell with a wall below it
            rests = [cell for cell in interior if board[cell] == FLOOR and cell not in spikes
                     and cell != goal and board[cell[0] + 1, cell[1]] == WALL]
            if not rests:
                continue
            ball = rests[int(rng.integers(len(rests)))]
            plan = solve(board, (ball, 1), goal, spikes)
            if plan is not None and len(plan) >= p.min_moves:
                self.board, self.spikes, self.goal = board, spikes, goal
                self.ball, self.gravity = ball, 1
                self.optimal = len(plan)   # fewest turns, for tests and baselines
                rows = [row.copy() for row in board.rows]   # what never moves, drawn once
                for r, c in spikes:
                    rows[r][c] = SPIKES
                rows[goal[0]][goal[1]] = GOAL
                self._still = ["".join(row) for row in rows]
                return
        raise RuntimeError(f"{self.task_id}: no level needing {p.min_moves} turns found in {_TRIES} "
                           "layouts; lower min_moves or change walls")

    def _act(self, action: int) -> None:
        self.ball, self.gravity = fall(self.board, (self.ball, self.gravity), action)
        if self.ball == self.goal:
            self.reward(self.time_bonus(self.params.time_weight))
            self.say("The ball reached the goal.")
            self.finish(won=True)
        elif self.ball in self.spikes:
            self.reward(-self.params.spike_penalty)
            self.say("The ball hit spikes.")
            self.finish(won=False)

    def _grid(self) -> list[str]:
        return stamped(self._still, *self.ball, BALL)

    def _hud(self) -> str:
        return f"Gravity {DIRECTION_NAMES[self.gravity]}"


register_variants(GravityMaze, "Classics", {
    "glyphbench/classics-gravitymaze-v0": dict(size=8, walls=12, spikes=3, min_moves=10, max_turns=60),
})
