"""A scripted Craftax player: goals (collect, craft, place, fight, descend ...) played turn by
turn on a ``CraftaxTask`` through its public ``step``, re-planned every turn (mobs move).

It shows each task winnable in the tests and serves as a competent scripted baseline. Paths are
breadth-first searches over the cells the player can walk (``rules.walkable``); every goal gives
up after a budget of turns and reports whether it got there.
"""

from __future__ import annotations

from collections import deque

import numpy as np

from . import rules
from .bestiary import MOB_NAMES
from .tables import Action, BlockType, ItemType

MOVES = {(0, -1): Action.LEFT, (0, 1): Action.RIGHT, (-1, 0): Action.UP, (1, 0): Action.DOWN}
KINDS = ("passive_mobs", "melee_mobs", "ranged_mobs")


class Planner:
    def __init__(self, task, budget: int = 10_000) -> None:
        self.task, self.budget, self.total = task, budget, 0.0

    # -- basics -------------------------------------------------------------------------------------
    @property
    def state(self):
        return self.task.state

    @property
    def done(self) -> bool:
        return self.task.done

    @property
    def pos(self) -> tuple[int, int]:
        r, c = self.state.player_position
        return int(r), int(c)

    def act(self, action: int) -> bool:
        """One turn; False once the episode is over or the budget is spent."""
        if self.task.done or self.budget <= 0:
            return False
        self.budget -= 1
        self.total += self.task.step(int(action))[1]
        return not self.task.done

    def wait(self, turns: int) -> None:
        for _ in range(turns):
            if not self.act(Action.NOOP):
                return

    # -- where things are ---------------------------------------------------------------------------
    def cells(self, block: int) -> list[tuple[int, int]]:
        level = self.state.player_level
        return [tuple(int(v) for v in p) for p in np.argwhere(self.state.map[level] == block)]

    def mobs(self, name: str | None = None) -> list[tuple[int, int]]:
        """Positions of live mobs on the player's level (called ``name``, or monsters)."""
        s, level, out = self.state, self.state.player_level, []
        for k, kind in enumerate(KINDS):
            mobs = getattr(s, kind)
            for i in np.flatnonzero(mobs.mask[level]):
                mob = MOB_NAMES[k][int(mobs.type_id[level, i])]
                if (name is None and k > 0) or mob == name:
                    out.append(tuple(int(v) for v in mobs.position[level, i]))
        return out

    def _path(self, goals: set, onto: bool) -> list[tuple[int, int]] | None:
        """Cells from the player to a goal cell (``onto``) or to a cell beside one, by walking."""
        s, level, start = self.state, self.state.player_level, self.pos
        if (start in goals) if onto else any(_beside(start, g) for g in goals):
            return []
        prev, queue = {start: None}, deque([start])
        rows, cols = s.map.shape[1:]
        while queue:
            cell = queue.popleft()
            for dr, dc in MOVES:
                nxt = (cell[0] + dr, cell[1] + dc)
                if nxt in prev or not (0 <= nxt[0] < rows and 0 <= nxt[1] < cols):
                    continue
                if not rules.player_can_enter(s, *nxt):
                    continue
                prev[nxt] = cell
                if (nxt in goals) if onto else any(_beside(nxt, g) for g in goals):
                    path = [nxt]
                    while prev[path[-1]] != start:
                        path.append(prev[path[-1]])
                    return path[::-1]
                queue.append(nxt)
        return None

    def go(self, goals, onto: bool = False, limit: int = 400) -> bool:
        """Walk next to (or onto) one of ``goals``; False if none can be reached in ``limit``."""
        goals = set(goals)
        for _ in range(limit):
            if not goals:
                return False
            path = self._path(goals, onto)
            if path is None:
                return False
            if not path:
                return True
            r, c = self.pos
            if not self.act(MOVES[(path[0][0] - r, path[0][1] - c)]):
                return False
        return False

    def face(self, cell: tuple[int, int]) -> bool:
        r, c = self.pos
        step = (cell[0] - r, cell[1] - c)
        if step not in MOVES:
            return False
        if rules.facing(self.state) == cell:
            return True
        return self.act(MOVES[step])

    # -- goals --------------------------------------------------------------------------------------
    def collect(self, block: int, until, limit: int = 600) -> bool:
        """Mine or chop the nearest ``block`` until ``until()`` holds."""
        for _ in range(limit):
            if until():
                return True
            targets = self.cells(block)
            if not targets or not self.go(_nearest(targets, self.pos, 12)):
                return until()
            target = next(t for t in targets if _beside(self.pos, t))
            if not self.face(target):
                continue
            if not self.act(Action.DO):
                return until()
        return until()

    def near(self, block: int) -> bool:
        r, c = self.pos
        level = self.state.player_level
        return any(0 <= r + dr < self.state.map.shape[1] and 0 <= c + dc < self.state.map.shape[2]
                   and self.state.map[level, r + dr, c + dc] == block
                   for dr in (-1, 0, 1) for dc in (-1, 0, 1) if dr or dc)

    def place(self, action: int, block: int) -> bool:
        """Place ``block`` (with ``action``) on the cell ahead, turning or stepping to find one."""
        level = self.state.player_level
        for direction in (Action.RIGHT, Action.DOWN, Action.LEFT, Action.UP) * 2:
            ahead = rules.facing(self.state)
            if rules.in_bounds(self.state, *ahead) and self.state.map[level][ahead] != block:
                before = int(self.state.map[level][ahead])
                if not self.act(action):
                    return False
                if int(self.state.map[level][ahead]) == block and before != block:
                    return True
            if not self.act(direction):
                return False
        return False

    def craft(self, action: int, station: int = BlockType.CRAFTING_TABLE) -> bool:
        if not self.near(station) and not self.go(self.cells(station)):
            return False
        return self.act(action)

    def table(self) -> bool:
        """Be next to a crafting table: the nearest one, or a new one (2 wood... as the rules say)."""
        near = _nearest(self.cells(BlockType.CRAFTING_TABLE), self.pos, 8)
        if near:
            return self.go(near)
        return self.place(Action.PLACE_TABLE, BlockType.CRAFTING_TABLE)

    def fight(self, name: str | None = None, count: int = 1, limit: int = 600) -> int:
        """Kill ``count`` mobs called ``name`` (monsters when None) with DO; how many died."""
        killed = 0
        for _ in range(limit):
            if killed >= count or self.done:
                break
            targets = self.mobs(name)
            if not targets:
                if not self.act(Action.NOOP):
                    break
                continue
            before = len(targets)
            nearest = _nearest(targets, self.pos, 1)
            if not self.go(nearest, limit=1):
                if not self.act(Action.NOOP):
                    break
                continue
            beside = [t for t in self.mobs(name) if _beside(self.pos, t)]
            if beside and self.face(beside[0]) and rules.facing(self.state) == beside[0]:
                self.act(Action.DO)
            if len(self.mobs(name)) < before:
                killed += before - len(self.mobs(name))
        return killed

    def descend(self, limit: int = 400) -> bool:
        level = self.state.player_level
        ladder = tuple(int(v) for v in self.state.down_ladders[level])
        if self.state.item_map[level][ladder] != ItemType.LADDER_DOWN:
            return False
        return self.go([ladder], onto=True, limit=limit) and self.act(Action.DESCEND) or \
            self.state.player_level > level


def _beside(a, b) -> bool:
    return abs(a[0] - b[0]) + abs(a[1] - b[1]) == 1


def _nearest(cells, pos, k: int) -> list:
    return sorted(cells, key=lambda p: abs(p[0] - pos[0]) + abs(p[1] - pos[1]))[:k]
