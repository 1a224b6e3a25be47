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
from .tables import IS_SOLID, MINING_BY_BLOCK, Action, BlockType, ItemType

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


    # -- goals added for the crafting and survival tasks (p1) ---------------------------------------
    def guard(self) -> bool:
        """If a monster stands beside the player, turn to it and hit it (one turn); True if so.
        With ``self.alert`` (default 1) above 1, a monster that many steps away (by the
        Manhattan distance) is walked up to first."""
        monsters, pos = self.mobs(), self.pos
        beside = [m for m in monsters if _beside(pos, m)]
        if not beside and not self.done:
            close = [m for m in monsters if abs(m[0] - pos[0]) + abs(m[1] - pos[1]) <= getattr(self, "alert", 1)]
            if close:
                return self.go(_nearest(close, pos, 1), limit=1) or True
        if not beside or self.done:
            return False
        target = beside[0]
        if rules.facing(self.state) != target:
            self.face(target)
        else:
            self.act(Action.DO)
        return True

    def _dig_path(self, goals: set) -> list[tuple[int, int]] | None:
        """Cells from the player to a cell beside a goal, walking or mining through blocks the
        pickaxe can mine (each mined cell costs two turns: mine, then step)."""
        import heapq
        s, level, start = self.state, self.state.player_level, self.pos
        if any(_beside(start, g) for g in goals):
            return []
        rows, cols = s.map.shape[1:]
        tier = s.inventory.pickaxe
        best, prev, heap = {start: 0}, {start: None}, [(0, start)]
        while heap:
            cost, cell = heapq.heappop(heap)
            if cost > best[cell]:
                continue
            if cell != start and any(_beside(cell, g) for g in goals):
                path = [cell]
                while prev[path[-1]] != start:
                    path.append(prev[path[-1]])
                return path[::-1]
            for dr, dc in MOVES:
                nxt = (cell[0] + dr, cell[1] + dc)
                if not (0 <= nxt[0] < rows and 0 <= nxt[1] < cols) or nxt in goals:
                    continue
                if rules.player_can_enter(s, *nxt):
                    step = 1
                else:
                    mined = MINING_BY_BLOCK.get(int(s.map[level][nxt]))
                    if mined is None or mined[0] > tier or s.mob_map[level][nxt] \
                            or s.item_map[level][nxt]:
                        continue
                    step = 3
                if cost + step < best.get(nxt, 1 << 30):
                    best[nxt], prev[nxt] = cost + step, cell
                    heapq.heappush(heap, (cost + step, nxt))
        return None

    def gather(self, block: int, until, limit: int = 600, dig: bool = True) -> bool:
        """Like ``collect``, one turn at a time: fight off monsters that come beside the player,
        and (``dig``) mine a way through blocks to a ``block`` no walk reaches."""
        for _ in range(limit):
            if until():
                return True
            if self.done:
                return False
            if self.guard():
                continue
            if self.state.player_health <= getattr(self, "heal_at", 0) and self.state.inventory.stone >= 4:
                self.recover(getattr(self, "heal_to", 8))
                continue
            targets = set(self.cells(block))
            if not targets:
                return until()
            path = self._path(targets, False)
            if path is None and dig:
                path = self._dig_path(targets)
            if path is None:
                return until()
            if path:
                r, c = self.pos
                step = MOVES[(path[0][0] - r, path[0][1] - c)]
                if rules.player_can_enter(self.state, *path[0]) or rules.facing(self.state) != path[0]:
                    self.act(step)
                else:
                    self.act(Action.DO)
                continue
            target = next(t for t in targets if _beside(self.pos, t))
            if rules.facing(self.state) != target:
                self.face(target)
            else:
                self.act(Action.DO)
        return until()

    def drink(self, upto: int) -> bool:
        """Drink at the nearest water until drink reaches ``upto``."""
        return self.gather(BlockType.WATER, lambda: self.state.player_drink >= upto, dig=False)

    def eat(self, upto: int, limit: int = 300) -> bool:
        """Eat until food reaches ``upto``: a ripe plant if one is in reach, else hunt a cow;
        False at once when there is neither."""
        for _ in range(limit):
            if self.state.player_food >= upto:
                return True
            if self.done:
                return False
            if self.guard():
                continue
            if self.cells(BlockType.RIPE_PLANT) and self._path(set(self.cells(BlockType.RIPE_PLANT)), False) is not None:
                self.gather(BlockType.RIPE_PLANT, lambda: self.state.player_food >= upto, limit=40, dig=False)
                continue
            cows = self.mobs("cow")
            if not cows:
                return False
            beside = [m for m in cows if _beside(self.pos, m)]
            if not beside:
                if not self.go(_nearest(cows, self.pos, 1), limit=1):
                    self.act(Action.NOOP)
            elif rules.facing(self.state) != beside[0]:
                self.face(beside[0])
            else:
                self.act(Action.DO)
        return self.state.player_food >= upto

    def place_n(self, action: int, block: int, count: int, limit: int = 200) -> int:
        """Place ``block`` ``count`` times on the cell ahead, walking between placements (a move
        into a free cell is a step, so the cell ahead is the next one in the walking direction)
        and never walling the player in; monsters beside the player are fought off first."""
        placed, turn = 0, 0
        for _ in range(limit):
            if placed >= count or self.done:
                break
            if self.guard():
                continue
            s, level = self.state, self.state.player_level
            r, c = self.pos
            ahead = rules.facing(s)
            walk = [(r + dr, c + dc) for dr, dc in MOVES if rules.player_can_enter(s, r + dr, c + dc)]
            here = int(s.map[level][ahead]) if rules.in_bounds(s, *ahead) else -1
            fits = (ahead in walk and (action != Action.PLACE_PLANT or here == BlockType.GRASS)) or \
                (action == Action.PLACE_STONE and here == BlockType.WATER)
            if fits and len([x for x in walk if x != ahead]) >= 1:
                self.act(action)
                if rules.in_bounds(s, *ahead) and int(s.map[level][ahead]) == block and here != block:
                    placed += 1
                continue
            if not walk:
                self.act(Action.NOOP)
                continue
            turn += 1     # walk on, to a side with an open cell beyond it (turning each time)
            order = list(MOVES)[turn % 4:] + list(MOVES)[:turn % 4]
            onward = [d for d in order if (r + d[0], c + d[1]) in walk
                      and rules.player_can_enter(s, r + 2 * d[0], c + 2 * d[1])]
            dr, dc = (onward or [d for d in order if (r + d[0], c + d[1]) in walk])[0]
            self.act(MOVES[(dr, dc)])
        return placed

    def _walled(self, cell) -> bool:
        """A cell nothing walks through: in bounds, solid (or water, lava) and no mob on it."""
        s, level = self.state, self.state.player_level
        if not rules.in_bounds(s, *cell):
            return True
        block = int(s.map[level][cell])
        return (IS_SOLID[block] or block in (BlockType.WATER, BlockType.LAVA)) and not s.mob_map[level][cell]

    def _diggable(self, cell) -> bool:
        s, level = self.state, self.state.player_level
        mined = MINING_BY_BLOCK.get(int(s.map[level][cell]))
        return mined is not None and mined[0] <= s.inventory.pickaxe and not s.item_map[level][cell] \
            and IS_SOLID[int(s.map[level][cell])]

    def _pocket(self, radius: int = 12):
        """The nearest two-cell pocket (entrance E, cells A and B = A + d, B + d and the sides
        of A and B walled; A and B walkable or diggable) reachable by walking to E."""
        s = self.state
        r0, c0 = self.pos
        best = None
        for (dr, dc) in MOVES:
            sides = ((dc, dr), (-dc, -dr))
            for r in range(r0 - radius, r0 + radius + 1):
                for c in range(c0 - radius, c0 + radius + 1):
                    a, b, e = (r, c), (r + dr, c + dc), (r - dr, c - dc)
                    if not all(rules.in_bounds(s, *x) for x in (a, b, e)):
                        continue
                    if not all(rules.player_can_enter(s, *x) or self._diggable(x) for x in (a, b)):
                        continue
                    if not (rules.player_can_enter(s, *e) or e == self.pos):
                        continue
                    walls = [(b[0] + dr, b[1] + dc)] + [(x[0] + sr, x[1] + sc) for x in (a, b) for sr, sc in sides]
                    if not all(self._walled(w) for w in walls):
                        continue
                    cost = abs(e[0] - r0) + abs(e[1] - c0)
                    if best is None or cost < best[0]:
                        best = (cost, e, (dr, dc))
        return None if best is None else best[1:]

    def sealed(self) -> bool:
        """The player stands in a closed space of at most two cells."""
        seen, todo = {self.pos}, [self.pos]
        while todo:
            r, c = todo.pop()
            for dr, dc in MOVES:
                x = (r + dr, c + dc)
                if x not in seen and not self._walled(x):
                    seen.add(x)
                    todo.append(x)
                    if len(seen) > 2:
                        return False
        return True

    def wall_in(self, limit: int = 60) -> bool:
        """Stand sealed in a two-cell pocket (found, or dug into stone): walk in two cells and
        back one, which faces the entrance, and place a stone there (a move into a free cell is
        a step, so the only cell one can face to seal is the one just walked away from). Needs
        one stone; True once sealed."""
        if self.sealed():
            return True
        if self.state.inventory.stone < 1:
            return False
        found = self._pocket()
        if found is None:
            return False
        e, d = found
        a = (e[0] + d[0], e[1] + d[1])
        b = (a[0] + d[0], a[1] + d[1])
        back = MOVES[(-d[0], -d[1])]
        for _ in range(limit):
            if self.done:
                return False
            pos = self.pos
            if pos == a and rules.facing(self.state) == e:
                if self._walled(e):
                    return True
                self.act(Action.DO if self.state.mob_map[self.state.player_level][e] else Action.PLACE_STONE)
                continue
            if pos == b:
                self.act(back)
                continue
            if pos in (e, a):
                ahead = (pos[0] + d[0], pos[1] + d[1])
                if rules.facing(self.state) == ahead and self._diggable(ahead):
                    self.act(Action.DO)
                else:
                    self.act(MOVES[d])     # turns toward a block, steps into a free cell
                continue
            if self.guard():
                continue
            if not self.go([e], onto=True, limit=1):
                return False
        return False

    def survive(self, turns: int, food: int = 4, drink: int = 4, shelter: bool = False) -> None:
        """Live ``turns`` more turns: fight off monsters beside the player, drink and eat when
        low; with ``shelter``, wait walled in by stone at night (the walls mined open after)."""
        end = self.task.tally.counts["turn"] + turns
        while self.task.tally.counts["turn"] < end and not self.done and self.budget > 0:
            s, before = self.state, self.budget
            if self.guard():
                continue
            if s.player_drink <= drink:
                self.drink(9)
            elif s.player_food <= food:
                self.eat(9)
            elif shelter and s.light_level < 0.5 and s.inventory.stone >= 4:
                self.wall_in()
            if self.budget == before:     # nothing to do (or no way to do it): wait a turn
                self.act(Action.NOOP)

    def take_ladder(self, limit: int = 400) -> bool:
        """``descend``, one turn at a time: monsters beside the player are fought off, and a mob
        standing on the ladder is attacked from beside it; True once on the next level."""
        level = self.state.player_level
        ladder = tuple(int(v) for v in self.state.down_ladders[level])
        for _ in range(limit):
            if self.state.player_level > level:
                return True
            if self.done or self.state.item_map[level][ladder] != ItemType.LADDER_DOWN:
                return False
            if self.guard():
                continue
            if self.pos == ladder:
                self.act(Action.DESCEND)
                if self.state.player_level == level:
                    self.fight(None, 1, limit=30)     # the ladder is shut: a kill may open it
                continue
            if self.state.mob_map[level][ladder]:
                if _beside(self.pos, ladder):
                    if rules.facing(self.state) != ladder:
                        self.face(ladder)
                    else:
                        self.act(Action.DO)
                elif not self.go([ladder], limit=1):
                    self.act(Action.NOOP)
                continue
            if not self.go([ladder], onto=True, limit=1):
                self.act(Action.NOOP)
        return self.state.player_level > level

    def recover(self, upto: int, limit: int = 200) -> bool:
        """Wall in with stone and sleep (or wait) until health reaches ``upto`` (needs the
        stone for the open sides; the wall ahead is mined open again after)."""
        if not self.wall_in():
            return self.state.player_health >= upto
        for _ in range(limit):
            s = self.state
            if s.player_health >= upto or self.done or s.player_food <= 1 or s.player_drink <= 1:
                break
            self.act(Action.SLEEP if s.player_energy < 9 and not s.is_sleeping else Action.NOOP)
        for _ in range(40):     # a sleeper sleeps on until its energy is full
            if not self.state.is_sleeping or self.done:
                break
            self.act(Action.NOOP)
        ahead = rules.facing(self.state)
        if not self.done and rules.in_bounds(self.state, *ahead) and \
                int(self.state.map[self.state.player_level][ahead]) == BlockType.STONE:
            self.act(Action.DO)
        return self.state.player_health >= upto

    def perish(self, limit: int = 512) -> bool:
        """A losing policy: go and stand beside the nearest monster, doing nothing; True once
        the player is dead."""
        for _ in range(limit):
            if self.done or self.budget <= 0:
                break
            monsters = self.mobs()
            if monsters and not any(_beside(self.pos, m) for m in monsters):
                if not self.go(_nearest(monsters, self.pos, 3), limit=1):
                    self.act(Action.NOOP)
            else:
                self.act(Action.NOOP)
        return self.state.player_health <= 0

def _beside(a, b) -> bool:
    return abs(a[0] - b[0]) + abs(a[1] - b[1]) == 1


def _nearest(cells, pos, k: int) -> list:
    return sorted(cells, key=lambda p: abs(p[0] - pos[0]) + abs(p[1] - pos[1]))[:k]
