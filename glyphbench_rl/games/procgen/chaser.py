"""Procgen Chaser: Pac-Man in a braided maze. Eat every pellet; ghosts hunt you, and a power
pellet turns them scared (edible) for a while.

Differences from Procgen, for an agent that sees a window: the maze has loops (a perfect maze
is a trap), ghosts move two turns out of three (scared ones every other turn), so a careful
player can always outrun one."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from ..common.lanes import Draws
from ..common.palette import WALL
from .engine import OPEN, PLAYER_GLYPHS, ProcgenTask
from .mazes import DistanceMaps, maze_level, rooms

PELLET, POWER, GHOST, SCARED = "o", "O", "E", "F"


@dataclass(frozen=True)
class ChaserParams:
    cells: int = param(10, 4, 20)       # cells x cells rooms: the world is 2*cells+1 square
    ghosts: int = param(3, 0, 6)
    powers: int = param(2, 0, 4)        # power pellets
    scared_turns: int = param(15, 1, 100)
    randomness: float = param(0.3, 0, 1)   # share of ghost moves that are random


class ProcgenChaser(ProcgenTask):
    title = "Procgen Chaser"
    rules = ("Eat every pellet (o) in a maze of {size}x{size} cells with loops, seen through a "
             "window that follows you. {ghosts} ghosts (E) hunt you; they move two turns out of "
             "three. A power pellet (O) makes them scared (F) for {scared_turns} turns: walk "
             "into a scared ghost to eat it (it returns to its lair); walking into a hunting "
             "ghost, or one walking into you, ends the game.")
    rewards = ("+0.5 shared over all pellets (power pellets included), +0.1 for each of the "
               "first 2 scared ghosts eaten, +0.3 for clearing the maze; being caught costs "
               "nothing but ends the game.")
    ends = "when the maze is cleared or a ghost catches you"
    Params = ChaserParams
    shows_motion = True
    glyphs = {WALL: "wall", OPEN: "open", PELLET: "pellet", POWER: "power pellet",
              GHOST: "ghost", SCARED: "scared ghost", **PLAYER_GLYPHS}

    def prompt_fields(self) -> dict:
        return {**super().prompt_fields(), "size": 2 * self.params.cells + 1}

    def _setup(self, rng: np.random.Generator) -> None:
        p = self.params
        board = maze_level(p.cells, rng, braid=0.15)
        self.place_player((1, 1))
        self.maps = DistanceMaps(board)   # the maze is connected: every pellet is reachable
        dist = self.maps.from_(self.pos)
        far = max(dist.values())
        lairs = [cell for cell in rooms(board) if dist[cell] >= far // 2]
        self.lairs = [lairs[i] for i in rng.choice(len(lairs), p.ghosts, replace=False).tolist()]
        self.ghosts = list(self.lairs)
        self.moved = [(0, 0)] * p.ghosts   # each ghost's last step
        self.scared = [False] * p.ghosts
        spots = [cell for cell in rooms(board) if cell != self.pos]
        self.rows = [[PELLET if ch == OPEN else ch for ch in row] for row in board.rows]
        for i in rng.choice(len(spots), p.powers, replace=False).tolist():
            self.rows[spots[i][0]][spots[i][1]] = POWER
        self.rows[1][1] = OPEN
        self.pellets = self.total = sum(row.count(PELLET) + row.count(POWER) for row in self.rows)
        self._lines = ["".join(row) for row in self.rows]
        self.timer = self.eaten = 0
        self.draws = Draws(self.stream("ghosts"))

    def _rows(self) -> list[str]:
        return self._lines

    def _sprites(self):
        return [(r, c, SCARED if s else GHOST) for (r, c), s in zip(self.ghosts, self.scared)]

    def _movers(self):
        return [(SCARED if s else GHOST, r, c, dr, dc)
                for (r, c), s, (dr, dc) in zip(self.ghosts, self.scared, self.moved)]

    def _extras(self) -> str:
        scared = f" | Scared {self.timer}" if self.timer else ""
        return f"Pellets {self.pellets}{scared}"

    def _act(self, action: int) -> None:
        r, c = self.target(action)
        ch = self.rows[r][c]
        if ch != WALL:
            self.pos = (r, c)
            if ch == PELLET or ch == POWER:
                self.rows[r][c] = OPEN
                self._lines[r] = "".join(self.rows[r])
                self.pellets -= 1
                self.reward(0.5 / self.total)
                if ch == POWER:
                    self.timer = self.params.scared_turns + 1
                    self.scared = [True] * len(self.ghosts)
                    self.say("Power pellet: the ghosts are scared.")
                if not self.pellets:
                    self.reward(0.3)
                    self.say("You cleared the maze.")
                    self.finish(won=True)
                    return
        if self._meet():
            return
        if self.timer:
            self.timer -= 1
            if not self.timer:
                self.scared = [False] * len(self.ghosts)
        self._move_ghosts()
        self._meet()

    def _meet(self) -> bool:
        """Ghosts on the player's cell: scared ones are eaten, a hunting one ends the game."""
        for i, ghost in enumerate(self.ghosts):
            if ghost != self.pos:
                continue
            if not self.scared[i]:
                self.say("A ghost caught you.")
                self.finish(won=False)
                return True
            self.ghosts[i], self.scared[i], self.moved[i] = self.lairs[i], False, (0, 0)
            self.say("You ate a ghost.")
            if self.eaten < 2:
                self.eaten += 1
                self.reward(0.1)
        return False

    def _move_ghosts(self) -> None:
        if self.turn % 3 == 0:
            return
        rng = self.draws
        dist = self.maps.from_(self.pos)
        nbrs = self.maps.neighbours
        for i, ghost in enumerate(self.ghosts):
            scared = self.scared[i]
            if scared and self.turn % 2:
                continue
            options = nbrs[ghost]
            if rng.random() < self.params.randomness:
                nxt = options[rng.below(len(options))]
            elif scared:
                nxt = max(options, key=dist.__getitem__)
            else:
                nxt = min(options, key=dist.__getitem__)
            self.ghosts[i], self.moved[i] = nxt, (nxt[0] - ghost[0], nxt[1] - ghost[1])


register_variants(ProcgenChaser, "Procgen", {"glyphbench/procgen-chaser-v0": dict(max_turns=500)})
