"""Procgen Miner: dig through dirt for diamonds and reach the exit while boulders fall.

Boulder Dash's rule: a boulder falls one cell a turn into an empty cell below it; one resting on
you is held up, but a falling one that lands on you crushes you. Boulders cannot be pushed. A
tunnel along the top row and the right-hand column leads to the exit, so every level is won by
walking it; the diamonds are the reason to dig, and the generator keeps only diamonds that can be
dug to around the resting boulders."""

from __future__ import annotations

from dataclasses import dataclass
from heapq import heapify, heappop, heappush

import numpy as np

from ...core import register_variants
from ...core.params import param
from ..common.grid import bfs_distances
from ..common.palette import GOAL, WALL
from .engine import OPEN, PLAYER_GLYPHS, ProcgenTask

DIRT, DIAMOND, BOULDER = ":", "*", "O"


@dataclass(frozen=True)
class MinerParams:
    size: int = param(20, 8, 20)   # the world is size x size, border included
    dirt: float = param(0.45, 0, 0.8)
    diamonds: float = param(0.07, 0.02, 0.2)
    boulders: float = param(0.06, 0, 0.2)


class ProcgenMiner(ProcgenTask):
    title = "Procgen Miner"
    rules = ("You are a miner in a {size}x{size} mine. Walking into dirt digs it away; walk "
             "onto a diamond to take it. Boulders cannot be pushed; a boulder with an empty cell "
             "below falls one cell a turn. A boulder resting on you is held up, but a falling "
             "boulder that lands on you crushes you. Reach the exit.")
    rewards = "+0.1 for each of the first 8 diamonds, +0.2 for the exit, -1 for being crushed."
    ends = "when you reach the exit or are crushed"
    Params = MinerParams
    glyphs = {WALL: "wall", OPEN: "empty", DIRT: "dirt", DIAMOND: "diamond",
              BOULDER: "boulder", GOAL: "exit", **PLAYER_GLYPHS}
    view_h = view_w = 20

    def _setup(self, rng: np.random.Generator) -> None:
        p, n = self.params, self.params.size
        rows = [[WALL] * n for _ in range(n)]
        draws = rng.random((n - 2, n - 2))
        for r in range(1, n - 1):
            for c in range(1, n - 1):
                x = draws[r - 1, c - 1]
                rows[r][c] = (DIRT if x < p.dirt else DIAMOND if x < p.dirt + p.diamonds
                              else BOULDER if x < p.dirt + p.diamonds + p.boulders else OPEN)
        for i in range(1, n - 1):   # the tunnel: top row and right-hand column
            rows[1][i] = rows[i][n - 2] = OPEN
        rows[n - 2][n - 2] = GOAL
        self.rows = rows
        self.place_player((1, 1))
        self.falling: set[tuple[int, int]] = set()
        self._changed: set[int] = set()   # rows redrawn after this turn
        while self._settle(everything=True):   # boulders come to rest before the first turn
            pass
        self.falling = set()
        self._changed.clear()
        # Every diamond is reachable by digging around the resting boulders; any other becomes
        # dirt, and dirt that can be reached is turned into diamonds until there are at least 8.
        reach = bfs_distances(self.pos, lambda r, c: rows[r][c] != WALL and rows[r][c] != BOULDER)
        for r in range(2, n - 1):
            for c in range(1, n - 2):
                if rows[r][c] == DIAMOND and (r, c) not in reach:
                    rows[r][c] = DIRT
        spots = sorted(cell for cell in reach if rows[cell[0]][cell[1]] == DIRT)
        missing = 8 - sum(row.count(DIAMOND) for row in rows)
        if missing > 0:
            for i in rng.choice(len(spots), min(missing, len(spots)), replace=False).tolist():
                rows[spots[i][0]][spots[i][1]] = DIAMOND
        self.taken = 0
        self.left = sum(row.count(DIAMOND) for row in rows)
        self._lines = ["".join(row) for row in rows]

    def _settle(self, freed: tuple[int, int] | None = None, everything: bool = False) -> bool:
        """One turn of falling; True if any boulder moved. Crushes the player.

        Only a boulder that fell last turn, or the one above ``freed`` (the cell the player
        left), can move: every other boulder rests. They are visited in the order of a full
        scan, lowest row first and left to right, and a boulder that falls puts the one above
        it in the same turn's queue, so a column of boulders falls together. ``everything``
        visits every boulder (the level's first settling)."""
        rows, pos, was_falling = self.rows, self.pos, self.falling
        if everything:
            queue = [(-r, c) for r, row in enumerate(rows) for c, ch in enumerate(row) if ch == BOULDER]
        else:
            queue = [(-r, c) for r, c in was_falling]
            if freed is not None and rows[freed[0] - 1][freed[1]] == BOULDER:
                queue.append((1 - freed[0], freed[1]))
        self.falling = falling = set()
        if not queue:
            return False
        heapify(queue)
        changed = self._changed
        while queue:
            r, c = queue[0]
            r = -r
            while queue and queue[0] == (-r, c):   # the same boulder queued twice
                heappop(queue)
            if rows[r][c] != BOULDER:
                continue
            if (r + 1, c) == pos:
                if (r, c) in was_falling:
                    self.falling = set()
                    self._crush()
                    return False
            elif rows[r + 1][c] == OPEN:
                rows[r][c], rows[r + 1][c] = OPEN, BOULDER
                falling.add((r + 1, c))
                changed.update((r, r + 1))
                heappush(queue, (1 - r, c))
        return bool(falling)

    def _crush(self) -> None:
        self.reward(-1.0)
        self.say("A falling boulder crushed you.")
        self.finish(won=False)

    def _rows(self) -> list[str]:
        return self._lines

    def _extras(self) -> str:
        return f"Diamonds {self.taken} | Left {self.left}"

    def _act(self, action: int) -> None:
        r, c = self.target(action)
        ch = self.rows[r][c]
        freed = None
        if ch != WALL and ch != BOULDER:
            freed, self.pos = self.pos, (r, c)
            if ch == DIAMOND:
                self.left -= 1
                self.taken += 1
                if self.taken <= 8:
                    self.reward(0.1)
                self.say("You took a diamond.")
            elif ch == GOAL:
                self.reward(0.2)
                self.say("You reached the exit.")
                self.finish(won=True)
                return
            if ch != OPEN:
                self.rows[r][c] = OPEN
                self._changed.add(r)
        self._settle(freed)
        if self._changed:
            for row in self._changed:
                self._lines[row] = "".join(self.rows[row])
            self._changed.clear()


register_variants(ProcgenMiner, "Procgen", {"glyphbench/procgen-miner-v0": dict(max_turns=500)})
