"""Procgen Heist: three coloured keys open three locked doors that stand between you and the
gem. Keys lie where they can be fetched in order (red, blue, yellow)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from ..common.grid import MOVES, bfs_distances, bfs_search, shortest_path
from ..common.palette import GOAL, WALL
from .engine import DELTAS, OPEN, PLAYER_GLYPHS, ProcgenTask
from .mazes import maze_level, rooms

KEYS, DOORS = "rby", "RBY"
COLOURS = ("red", "blue", "yellow")


@dataclass(frozen=True)
class HeistParams:
    cells: int = param(10, 4, 20)   # cells x cells rooms: the world is 2*cells+1 square


def solve(board, start, goal, keys, doors) -> list[int] | None:
    """Action indices of a shortest win over states (cell, keys held), or None."""
    key_at = {cell: i for i, cell in enumerate(keys)}
    door_at = {cell: i for i, cell in enumerate(doors)}

    def neighbours(state):
        (r, c), held = state
        for action in range(1, 5):
            dr, dc = DELTAS[action]
            cell = (r + dr, c + dc)
            if board[cell] == WALL or (cell in door_at and not held >> door_at[cell] & 1):
                continue
            yield action, (cell, held | (1 << key_at[cell]) if cell in key_at else held)

    return bfs_search((start, 0), neighbours, lambda s: s[0] == goal)


class ProcgenHeist(ProcgenTask):
    title = "Procgen Heist"
    rules = ("Steal the gem from a maze of {size}x{size} cells seen through a window that "
             "follows you. Locked doors (R, B, Y) block the way; walking into a door while "
             "holding the key of its colour (r, b, y) opens it for good. Walk onto a key to take "
             "it. Walls block movement.")
    rewards = "+{key_reward:.3g} for each key taken, +0.6 for reaching the gem."
    ends = "when you reach the gem"
    Params = HeistParams
    glyphs = {WALL: "wall", OPEN: "open", GOAL: "gem",
              **{k: f"{n} key" for k, n in zip(KEYS, COLOURS)},
              **{d: f"{n} locked door" for d, n in zip(DOORS, COLOURS)}, **PLAYER_GLYPHS}

    def prompt_fields(self) -> dict:
        return {"size": 2 * self.params.cells + 1, "key_reward": 0.4 / 3}

    def _setup(self, rng: np.random.Generator) -> None:
        while not self._generate(rng):
            pass
        self.held = 0
        self._draw()

    def _generate(self, rng: np.random.Generator) -> bool:
        board = maze_level(self.params.cells, rng)
        start = (1, 1)
        passable = lambda r, c: board[r, c] != WALL   # noqa: E731
        dist = bfs_distances(start, passable)
        far = max(dist.values())
        goals = [cell for cell in rooms(board) if dist[cell] >= 0.6 * far]
        goal = goals[int(rng.integers(len(goals)))]
        cell, path = start, [start]
        for name in shortest_path(start, goal, passable):
            dr, dc = MOVES[name]
            cell = (cell[0] + dr, cell[1] + dc)
            path.append(cell)
        corridors = [cell for cell in path if (cell[0] + cell[1]) % 2 == 1]
        if len(corridors) < 3:
            return False
        doors = [corridors[i] for i in sorted(rng.choice(len(corridors), 3, replace=False).tolist())]
        keys, before = [], set()
        for k in range(3):   # key k lies where doors k.. are still shut, past door k-1
            shut = set(doors[k:])
            reach = bfs_distances(start, lambda r, c: board[r, c] != WALL and (r, c) not in shut)
            spots = [cell for cell in rooms(board) if cell in reach and cell not in before
                     and cell != start and cell not in keys]
            if not spots:
                return False
            keys.append(spots[int(rng.integers(len(spots)))])
            before |= set(reach)
        plan = solve(board, start, goal, keys, doors)
        if plan is None:
            return False
        self.board, self.goal, self.keys, self.doors = board, goal, keys, doors
        self.place_player(start)
        self.optimal = len(plan)
        return True

    def _draw(self) -> None:
        board = self.board
        for i, cell in enumerate(self.keys):
            board[cell] = KEYS[i] if not self.held >> i & 1 else OPEN
        for i, cell in enumerate(self.doors):
            if board[cell] != OPEN:
                board[cell] = DOORS[i]
        board[self.goal] = GOAL
        self._still = board.lines()

    def solution(self) -> list[int]:
        return solve(self.board, self.pos, self.goal, self.keys, self.doors)

    def _rows(self) -> list[str]:
        return self._still

    def _extras(self) -> str:
        held = [KEYS[i] for i in range(3) if self.held >> i & 1]
        return "Keys " + (" ".join(held) if held else "none")

    def _act(self, action: int) -> None:
        r, c = self.target(action)
        ch = self.board[r, c]
        if ch == WALL:
            return
        if ch in DOORS:
            i = DOORS.index(ch)
            if not self.held >> i & 1:
                self.say(f"The {COLOURS[i]} door is locked.")
                return
            self.board[r, c] = OPEN
            self.say(f"You opened the {COLOURS[i]} door.")
            self._draw()
        self.pos = (r, c)
        if ch in KEYS:
            i = KEYS.index(ch)
            self.held |= 1 << i
            self.reward(0.4 / 3)
            self.say(f"You took the {COLOURS[i]} key.")
            self.board[r, c] = OPEN
            self._draw()
        elif ch == GOAL:
            self.reward(0.6)
            self.say("You stole the gem.")
            self.finish(won=True)


register_variants(ProcgenHeist, "Procgen", {"glyphbench/procgen-heist-v0": dict(max_turns=500)})
