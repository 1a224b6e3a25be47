"""A scripted Craftax player: goals (gather, craft, place, fight, descend ...) played turn by
turn on a ``CraftaxTask`` through its public ``step``, re-planned every turn (mobs move).

It shows each task winnable in the tests and serves as a competent scripted baseline. Paths are
breadth-first searches over the cells the player can enter (``rules.player_can_enter``); every
goal gives up after a budget of turns and reports whether it got there.

Two melee goals: ``hunt`` (walk up and hit, drinking and resting between blows, shooting a mob
in line, exploring for more) and ``skirmish`` (reads the mobs' cooldowns: ambushes melee mobs,
keeps off archers' lines, rests away from monsters; for fights against several at once). At
range: ``shoot`` (arrows, keeping away) and ``cast`` (spells).
"""

from __future__ import annotations

import heapq
from collections import deque

import numpy as np

from . import mobs as mobrules
from . import rules
from .bestiary import MOB_NAMES, MOB_TYPE_DAMAGE_MAPPING, MOB_TYPE_DEFENCE_MAPPING
from .state import MOB_GROUPS
from .tables import (DRINK_BLOCKS, IS_SOLID, MINING_BY_BLOCK, MONSTERS_KILLED_TO_CLEAR_LEVEL, NUM_LEVELS,
                     PLAYER_ARROW, SLEEPING_MELEE_FACTOR, SPELLS, Action, BlockType)
from .task import POTION_EFFECTS

MOVES = {(0, -1): Action.LEFT, (0, 1): Action.RIGHT, (-1, 0): Action.UP, (1, 0): Action.DOWN}
ROOM_WEIGHT = 0.1     # evade: worth of one cell of running room (``_room``) against one of distance


class Mob:
    """A live mob as the combat goals see it: cell, class (0 passive, 1 melee, 2 ranged), name,
    attack cooldown and health."""
    __slots__ = ("cell", "kind", "name", "cooldown", "health")

    def __init__(self, cell, kind, name, cooldown, health) -> None:
        self.cell, self.kind, self.name, self.cooldown, self.health = cell, kind, name, cooldown, health


def live_mobs(state) -> list[Mob]:
    level, out = state.player_level, []
    for k, kind in enumerate(MOB_GROUPS):
        mobs = getattr(state, kind)
        for i, alive in enumerate(mobs.mask[level]):
            if alive:
                out.append(Mob(mobs.position[level][i], k, MOB_NAMES[k][mobs.type_id[level][i]],
                               mobs.attack_cooldown[level][i], mobs.health[level][i]))
    return out


def _matches(mob: Mob, name) -> bool:
    """``name``: a mob name, a tuple of names, or None for every monster (melee or ranged)."""
    if name is None:
        return mob.kind > 0
    if isinstance(name, str):
        return mob.name == name
    return mob.name in name


def _type_id(mob: Mob) -> int:
    return MOB_NAMES[mob.kind].index(mob.name)


def _dist(a, b) -> int:
    return abs(a[0] - b[0]) + abs(a[1] - b[1])


def _toward(a, b) -> tuple[int, int]:
    """The unit step from ``a`` toward ``b`` (on one row or column: the direction to face)."""
    return (b[0] > a[0]) - (b[0] < a[0]), (b[1] > a[1]) - (b[1] < a[1])


def _beside(a, b) -> bool:
    return abs(a[0] - b[0]) + abs(a[1] - b[1]) == 1


def _nearest(cells, pos, k: int) -> list:
    return sorted(cells, key=lambda p: abs(p[0] - pos[0]) + abs(p[1] - pos[1]))[:k]


class Planner:
    """The scripted player: one method a goal, each played a turn at a time through
    ``task.step`` (re-planned every turn) and reading only the state an agent could see."""

    def __init__(self, task, budget: int = 10_000) -> None:
        self.task, self.budget, self.total = task, budget, 0.0
        self._waited = 0          # turns spent waiting in ambush for the same approach (skirmish)
        self.heal_at, self.heal_to = 0.0, 8   # gather: at or below heal_at health, recover to heal_to
        self.alert = 1            # guard: walk up to a monster this many steps away
        self._rng = np.random.default_rng(0)  # explore's choice of a far cell

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
        return [m.cell for m in live_mobs(self.state) if _matches(m, name)]

    def _path(self, goals: set, onto: bool) -> list[tuple[int, int]] | None:
        """Cells from the player to a goal cell (``onto``) or to a cell beside one, by walking."""
        s, start = self.state, self.pos
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

    def _mob_at(self, cell):
        """(class, type id) of the live mob at ``cell`` of the player's level, or None."""
        return next(((m.kind, _type_id(m)) for m in live_mobs(self.state) if m.cell == tuple(cell)), None)

    def in_line(self, target, reach: int = 8) -> bool:
        """``target`` is in the player's row or column within ``reach``, nothing solid and no
        mob between (the player's line of fire; ``_clear_line`` lets mobs through)."""
        (r, c), (tr, tc) = self.pos, target
        if (r != tr and c != tc) or abs(r - tr) + abs(c - tc) > reach:
            return False
        dr, dc = (tr > r) - (tr < r), (tc > c) - (tc < c)
        level, m = self.state.player_level, self.state.map
        cell = (r + dr, c + dc)
        while cell != (tr, tc):
            if IS_SOLID[int(m[level][cell])] or self.state.mob_map[level][cell]:
                return False
            cell = (cell[0] + dr, cell[1] + dc)
        return True

    def _clear_line(self, a, b) -> bool:
        """No solid block strictly between a and b on one row or column (a projectile's way)."""
        s, level = self.state, self.state.player_level
        if a[0] != b[0] and a[1] != b[1]:
            return False
        dr = (b[0] > a[0]) - (b[0] < a[0])
        dc = (b[1] > a[1]) - (b[1] < a[1])
        r, c = a[0] + dr, a[1] + dc
        while (r, c) != b:
            if not rules.player_can_enter(s, r, c) and not s.mob_map[level, r, c] \
                    and s.map.item(level, r, c) not in (BlockType.WATER, BlockType.LAVA):
                return False
            r, c = r + dr, c + dc
        return True

    def _steps(self):
        """(action, cell) for staying and each enterable neighbour."""
        r, c = self.pos
        out = [(Action.NOOP, (r, c))]
        for (dr, dc), a in MOVES.items():
            n = (r + dr, c + dc)
            if rules.in_bounds(self.state, *n) and rules.player_can_enter(self.state, *n):
                out.append((a, n))
        return out

    def _distances(self, goals: set, limit: int = 40) -> dict:
        """Walking distance from every cell within ``limit`` steps of the goal cells (BFS from
        them; from ``{self.pos}``: to every cell the player reaches)."""
        s = self.state
        dist = {g: 0 for g in goals}
        queue = deque(goals)
        me = self.pos
        while queue:
            cell = queue.popleft()
            if dist[cell] >= limit:
                continue
            for dr, dc in MOVES:
                n = (cell[0] + dr, cell[1] + dc)
                if n in dist or not rules.in_bounds(s, *n):
                    continue
                if n != me and not rules.player_can_enter(s, *n):
                    continue
                dist[n] = dist[cell] + 1
                queue.append(n)
        return dist

    # -- gathering, crafting, building --------------------------------------------------------------
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

    def _dig_path(self, goals: set) -> list[tuple[int, int]] | None:
        """Cells from the player to a cell beside a goal, walking or mining through blocks the
        pickaxe can mine (each mined cell costs two turns: mine, then step)."""
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
        """Mine (or chop, or drink at, or eat) the nearest ``block`` until ``until()`` holds,
        one turn at a time: fight off monsters that come beside the player, heal walled in at
        ``self.heal_at`` health, and (``dig``) mine a way through blocks to a ``block`` no walk
        reaches."""
        for _ in range(limit):
            if until():
                return True
            if self.done:
                return False
            if self.guard():
                continue
            if self.state.player_health <= self.heal_at and self.state.inventory.stone >= 4:
                self.recover(self.heal_to)
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
            self.strike(next(t for t in targets if _beside(self.pos, t)))
        return until()

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
            else:
                self.strike(beside[0])
        return self.state.player_food >= upto

    # -- upkeep: potions, water, rest, shelter ------------------------------------------------------
    def drink_potion(self, effect: str) -> bool:
        """Drink a potion whose effect is ``effect`` (``task.POTION_EFFECTS``: heal, harm, mana,
        drain, energy, tire), read from the episode's potion mapping; False if none is held."""
        want = POTION_EFFECTS.index(effect)
        s = self.state
        for colour, e in enumerate(s.potion_mapping):
            if int(e) == want and s.inventory.potions[colour] > 0:
                self.act(Action.DRINK_POTION_RED + colour)
                return True
        return False

    def try_potions(self, until, safe_health: float = 4.0, limit: int = 200) -> bool:
        """Find a potion by its effect without knowing the colours: keep away from monsters
        until health is at least ``safe_health`` (a harmful potion takes 3), then drink the
        colours held one by one (after the harmful one showed itself, without waiting) until
        ``until()`` (e.g. health went up) holds. True if it did."""
        harmed = False          # the harmful one is found (health fell by 3 as it was drunk)
        for _ in range(limit):
            if self.done:
                return False
            if until():
                return True
            if self.state.player_health < safe_health and not harmed:
                self.survive(1, keep_away=True)
                continue
            held = [c for c in range(6) if self.state.inventory.potions[c] > 0]
            if not held:
                break
            health = self.state.player_health
            self.act(Action.DRINK_POTION_RED + held[0])
            harmed = harmed or self.state.player_health <= health - 3
        return not self.done and until()

    def upkeep(self, heal_below: float = 4.0) -> bool:
        """Between fight turns: drink water (``quench``) when thirsty and no monster is beside;
        drink a healing potion when health falls below ``heal_below``; without one, REST while
        no monster is within 10 steps (a hit ends the rest). True when it took a turn."""
        s = self.state
        if s.player_drink <= 3 and not any(_beside(self.pos, t) for t in self.mobs()) \
                and self.quench(reach=25):
            return True
        if s.player_health >= heal_below:
            return False
        if self.drink_potion("heal"):
            return True
        if not any(abs(r - self.pos[0]) + abs(c - self.pos[1]) <= 10 for r, c in self.mobs()) \
                and s.player_food > 0 and s.player_drink > 0:
            self.act(Action.REST)
            while s.is_resting and not self.done and self.budget > 0 and \
                    not any(abs(r - self.pos[0]) + abs(c - self.pos[1]) <= 3 for r, c in self.mobs()):
                self.act(Action.NOOP)
            return True
        return False

    def quench(self, reach: int = 25, until: int = 8) -> bool:
        """Drink (DO facing water or a fountain) up to ``until``, walking to the nearest one
        within ``reach`` steps; True if it took a turn."""
        sources = [c for b in DRINK_BLOCKS for c in self.cells(b)]
        sources = [c for c in sources if abs(c[0] - self.pos[0]) + abs(c[1] - self.pos[1]) <= reach]
        if not sources:
            return False
        beside = [c for c in sources if _beside(self.pos, c)]
        if not beside:
            path = self._path(set(sources), onto=False)
            if not path or len(path) > reach:
                return False
            return self._step_along(path) or True
        took = False
        while self.state.player_drink < until and not self.done and self.budget > 0 \
                and not any(_beside(self.pos, t) for t in self.mobs()):
            t = beside[0]
            self.strike(t)
            took = True
        return took

    def drink_water(self, upto: int, limit: int = 300) -> bool:
        """Drink at the nearest water or fountain until drink reaches ``upto``: monsters beside
        the player are fought off (``guard``), else a turn of ``quench``."""
        for _ in range(limit):
            if self.state.player_drink >= upto:
                return True
            if self.done or (not self.guard() and not self.quench(reach=1_000, until=upto)):
                break
        return self.state.player_drink >= upto

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

    def survive(self, turns: int, food: int = 4, drink: int = 4, shelter: bool = False,
                keep_away: bool = False) -> None:
        """Live ``turns`` more turns: drink and eat when at or below ``drink`` / ``food``; with
        ``shelter``, wait walled in by stone at night (the walls mined open after). Monsters:
        one beside the player is fought off (``guard``); with ``keep_away`` the player keeps
        away from them instead (``evade``), hitting only a lone one beside it on cooldown."""
        end = self.task.tally.value("turn") + turns
        while self.task.tally.value("turn") < end and not self.done and self.budget > 0:
            s, before = self.state, self.budget
            if keep_away:
                mobs = live_mobs(s)
                beside = [m for m in mobs if m.kind > 0 and _dist(m.cell, self.pos) == 1]
                if len(beside) == 1 and beside[0].cooldown > 1:
                    self.strike(beside[0].cell)
                    continue
            elif self.guard():
                continue
            if s.player_drink <= drink:
                self.drink_water(9)
            elif s.player_food <= food:
                self.eat(9)
            elif shelter and s.light_level < 0.5 and s.inventory.stone >= 4:
                self.wall_in()
            if self.budget == before:     # nothing to do (or no way to do it)
                self.evade(mobs) if keep_away else self.act(Action.NOOP)

    # -- moving among monsters ---------------------------------------------------------------------
    def _step_along(self, path) -> bool:
        """One step along ``path``; if that cell is in a projectile's way this turn and the
        current one is not, wait a turn instead (``projectile_cells``)."""
        r, c = self.pos
        danger = self.projectile_cells()
        if path[0] in danger and (r, c) not in danger:
            return self.act(Action.NOOP)
        return self.act(MOVES[(path[0][0] - r, path[0][1] - c)])

    def projectile_cells(self) -> set:
        """Cells a mob projectile hits this turn: the cell it is on and the next one on its way."""
        s, level = self.state, self.state.player_level
        out = set()
        for i, alive in enumerate(s.mob_projectiles.mask[level]):
            if not alive:
                continue
            r, c = s.mob_projectiles.position[level][i]
            dr, dc = (int(v) for v in s.mob_projectile_directions[level, i])
            out.update({(r, c), (r + dr, c + dc)})
        return out

    def dodge(self) -> bool:
        """Step out of a projectile's way (to a free cell it does not cross); True if it took
        the turn."""
        danger = self.projectile_cells()
        if self.pos not in danger:
            return False
        r, c = self.pos
        for (dr, dc), action in MOVES.items():
            cell = (r + dr, c + dc)
            if cell not in danger and rules.player_can_enter(self.state, *cell):
                return self.act(action) or True
        return False

    def explore(self, turns: int = 12) -> bool:
        """Walk up to ``turns`` toward a far reachable cell (new mobs spawn near the player and
        monsters come to it): one drawn from the cells 8 to 20 steps away; stop early once a
        monster can be reached."""
        dist = self._distances({self.pos}, limit=20)
        far = [c for c, d in dist.items() if 8 <= d <= 20] or [c for c, d in dist.items() if d >= 2]
        if not far:
            return self.act(Action.NOOP)
        goal = far[int(self._rng.integers(len(far)))]
        for i in range(turns):
            if i and self._path(set(self.mobs()), onto=False):
                return True
            path = self._path({goal}, onto=True)
            if not path:
                return self.act(Action.NOOP) if i == 0 else not self.done
            if not self._step_along(path):
                return False
        return not self.done


    def walk(self, goals, onto: bool = False, limit: int = 300) -> bool:
        """``go`` that does not give up when the way is blocked for a while (a mob in a
        corridor): it fights a mob beside the player or waits, and plans again."""
        goals = set(goals)
        for _ in range(limit):
            if not goals or self.done or self.budget <= 0:
                return False
            path = self._path(goals, onto)
            if path == []:
                return True
            beside = [t for t in self.mobs() if _beside(self.pos, t)]
            if beside and (path is None or path[0] in beside):
                t = beside[0]
                self.strike(t)
            elif path:
                self._step_along(path)
            else:
                self.act(Action.NOOP)
        return False

    def danger(self, cell, mobs, target=None) -> float:
        """How much harm standing on ``cell`` next turn risks: a ready melee monster beside it
        or (other than ``target``, the one the player means to meet) two away, a ranged
        monster with a clear straight line to it, a mob projectile flying at it."""
        d = 0.0
        for m in mobs:
            if m.kind == 0:
                continue
            dist = _dist(cell, m.cell)
            if m.kind == 1:
                if dist <= 1 and m.cooldown <= 0:
                    d += 3.0
                elif dist == 2 and m.cooldown <= 1 and m.cell != target:
                    d += 1.0
            elif 1 <= dist <= 6 and self._clear_line(m.cell, cell):
                d += 2.0 if m.cooldown <= 1 else 0.5
        s, level = self.state, self.state.player_level
        shots = s.mob_projectiles
        for i, alive in enumerate(shots.mask[level]):
            if not alive:
                continue
            p = shots.position[level][i]
            dr, dc = (int(v) for v in s.mob_projectile_directions[level, i])
            for k in range(0, 4):
                if (p[0] + k * dr, p[1] + k * dc) == cell:
                    d += 3.0
                    break
        return d

    def evade(self, mobs=None) -> bool:
        """One turn keeping away from monsters: the step (or staying) with the least danger,
        then the largest distance to the nearest melee monster."""
        mobs = live_mobs(self.state) if mobs is None else mobs
        monsters = [m for m in mobs if m.kind > 0]
        best = None
        chasers = [m.cell for m in monsters if m.kind == 1]
        for action, cell in self._steps():
            near = min((_dist(cell, m) for m in chasers), default=20)
            score = 4.0 * self.danger(cell, mobs) - min(near, 8) - ROOM_WEIGHT * self._room(cell, chasers)
            if best is None or score < best[0]:
                best = (score, action)
        return self.act(best[1])

    def _room(self, cell, chasers, depth: int = 5) -> int:
        """Cells within ``depth`` steps of ``cell`` that the player reaches before any chaser
        could (by Manhattan distance): room to keep running."""
        s = self.state
        seen, frontier, count = {cell}, [cell], 0
        for step in range(1, depth + 1):
            nxt = []
            for r, c in frontier:
                for dr, dc in MOVES:
                    n = (r + dr, c + dc)
                    if n in seen or not rules.in_bounds(s, *n) or not rules.player_can_enter(s, *n):
                        continue
                    seen.add(n)
                    if all(_dist(n, m) > step for m in chasers):
                        count += 1
                        nxt.append(n)
            frontier = nxt
        return count

    # -- melee --------------------------------------------------------------------------------------
    def kills(self, name=None) -> int:
        """Kills so far in the episode, from the task's tally: of ``name`` (a mob name or a
        tuple of names, written with spaces or _), of every monster when None."""
        tally = self.task.tally.kills
        if name is None:
            return tally["monsters"]
        names = (name,) if isinstance(name, str) else name
        return sum(tally.get(n.replace(" ", "_"), tally.get(n, 0)) for n in names)

    def guard(self) -> bool:
        """If a monster stands beside the player, turn to it and hit it (one turn); True if so.
        With ``self.alert`` above 1, a monster that many steps away (by the
        Manhattan distance) is walked up to first."""
        monsters, pos = self.mobs(), self.pos
        beside = [m for m in monsters if _beside(pos, m)]
        if not beside and not self.done:
            close = [m for m in monsters if abs(m[0] - pos[0]) + abs(m[1] - pos[1]) <= self.alert]
            if close:
                return self.go(_nearest(close, pos, 1), limit=1) or True
        if not beside or self.done:
            return False
        self.strike(beside[0])
        return True

    def hunt(self, name: str | None = None, count: int = 1, limit: int = 400,
             heal_below: float = 4.0, explore: bool = True, ranged: bool = True) -> bool:
        """Kill ``count`` more mobs called ``name`` (monsters when None) in melee: walk beside
        the nearest reachable one (re-planned every turn: mobs move), face it, DO; drink a
        healing potion when health is low; explore when none can be reached. With ``ranged``,
        a mob in line 2 or more cells away is first shot at (``_fire_at``)."""
        goal = self.kills(name) + count
        for _ in range(limit):
            if self.kills(name) >= goal:
                return True
            if self.done or self.budget <= 0:
                return False
            if self.upkeep(heal_below):
                continue
            targets = self.mobs(name)
            beside = [t for t in targets if _beside(self.pos, t)]
            if self.dodge():
                continue
            if ranged and not beside and self._fire_at(targets):
                continue
            if beside:
                t = beside[0]
                if rules.facing(self.state) != t:
                    self.face(t)
                    continue
                shot = self._projectile(t) if ranged else None
                better = shot is not None and self.damage_to(t, shot) > 2 * self.damage_to(t)
                self.act(shot if better else Action.DO)
                continue
            self._approach(targets, explore)
        return self.kills(name) >= goal

    def _approach(self, targets, explore: bool) -> None:
        """One turn toward beside the nearest reachable of ``targets`` (cells; a projectile's way
        is waited out); with none reachable, ``explore`` (or wait a turn)."""
        path = self._path(set(targets), onto=False) if targets else None
        if path:
            self._step_along(path)
        elif explore:
            self.explore(6)
        else:
            self.act(Action.NOOP)

    def strike(self, cell) -> bool:
        """One turn toward DO on the ``cell`` beside the player (a mob, a block, water): turn
        to face it, or DO when facing it."""
        if rules.facing(self.state) != cell:
            return self.face(cell)
        return self.act(Action.DO)

    def skirmish(self, name=None, count: int = 1, limit: int = 600, rest_below: float = 0.0,
                 rest_to: float = 0.0, until=None) -> int:
        """Kill ``count`` mobs matching ``name`` (see ``_matches``) in melee, choosing each turn
        the step that closes in while keeping off ranged monsters' lines and away from ready
        melee monsters other than the one engaged; below ``rest_below`` health it keeps away
        from every monster (mobs chase at 3/4 of the player's speed) until ``rest_to``. A melee
        mob is met in front when it can be (``_ambush``). Returns the kills (by the task's
        tally) made."""
        start = self.kills(name)
        resting = False
        for _ in range(limit):
            if self.done or self.kills(name) - start >= count or (until is not None and until()):
                break
            mobs = live_mobs(self.state)
            targets = [m for m in mobs if _matches(m, name)]
            health = self.state.player_health
            if rest_below and health < rest_below:
                resting = True
            if resting and health >= rest_to:
                resting = False
            beside = [m for m in targets if _dist(m.cell, self.pos) == 1]
            if beside and self._engage(beside, mobs, resting):
                continue
            if resting or not targets:
                self.evade(mobs)
                continue
            first = min(targets, key=lambda m: _dist(m.cell, self.pos))
            if first.kind == 1 and self._ambush(first, mobs):
                continue
            goal_cells = {(t.cell[0] + dr, t.cell[1] + dc) for t in targets for dr, dc in MOVES}
            dist = self._distances(goal_cells)
            best = None
            for action, cell in self._steps():
                score = dist.get(cell, 99) + 2.0 * self.danger(cell, mobs, first.cell)
                if best is None or score < best[0]:
                    best = (score, action)
            self.act(best[1])
        return self.kills(name) - start

    def _ambush(self, target: Mob, mobs: list) -> bool:
        """Let a melee mob come to the player's sword: a chasing mob steps along its longer axis,
        so stand in its row or column, 3 or more away, facing it, and wait; it then arrives
        in front and takes the first blow (a few turns at most). False when not in line (the
        caller closes in instead)."""
        me, t = self.pos, target.cell
        d = _dist(me, t)
        if d > 9:
            return False
        inline = (me[0] == t[0] or me[1] == t[1]) and self._clear_line(me, t)
        if inline and d >= 2:
            step = _toward(me, t)
            ahead = (me[0] + step[0], me[1] + step[1])
            waited = self._waited
            chase = d == 2 and target.cooldown > 1        # it stepped back while it cannot strike
            if rules.facing(self.state) == ahead and self.danger(me, mobs, t) < 1 and waited < 4 \
                    and not chase:
                self._waited = waited + 1
                return self.act(Action.NOOP)
            self._waited = 0
            if (d >= 3 or target.cooldown > 1) and self.danger(ahead, mobs, t) < 1:
                return self.act(MOVES[step])
        return False

    def _ready_beside(self, cell, mobs, but=None) -> list:
        """Melee monsters that would strike a player on ``cell`` this turn (beside, ready)."""
        return [m for m in mobs if m.kind == 1 and m.cooldown <= 0 and m is not but
                and _dist(m.cell, cell) == 1]

    def _engage(self, beside: list, mobs: list, resting: bool) -> bool:
        """One melee turn with targets beside: finish one a hit kills; hit (or turn to) one when
        at most that one strikes back this turn and health allows; else step away. False once
        the episode is over."""
        damage = rules.player_damage_vector(self.state)
        facing = rules.facing(self.state)
        health = self.state.player_health
        ahead = next((m for m in beside if m.cell == facing), None)
        if ahead is not None:
            dealt = mobrules._mob_damage(damage, MOB_TYPE_DEFENCE_MAPPING[_type_id(ahead)][ahead.kind])
            back = self._ready_beside(self.pos, mobs, ahead if dealt >= ahead.health else None)
            if sum(self._strength(m) for m in back) < health and not (resting and back):
                return self.act(Action.DO)
        # the one to face: off cooldown first, then the weakest
        beside = sorted(beside, key=lambda m: (m.cooldown <= 0, m.health))
        first = beside[0]
        back = self._ready_beside(self.pos, mobs)
        if (not back or back == [first]) and not resting and \
                sum(self._strength(m) for m in back) < health:
            return self.strike(first.cell)
        return self.evade(mobs)

    def _strength(self, mob: Mob) -> float:
        """The health a melee blow of ``mob`` takes from the player (``mobs.hurt_player``'s
        sum, without dealing it)."""
        damage = MOB_TYPE_DAMAGE_MAPPING[_type_id(mob)][mob.kind]
        if self.state.is_sleeping:
            damage = tuple(SLEEPING_MELEE_FACTOR * x for x in damage)
        return mobrules.damage_to_player(self.state, damage)

    # -- at range: arrows and spells ---------------------------------------------------------------
    def damage_to(self, target, action: int = Action.DO) -> float:
        """Health the mob at ``target`` would lose to ``action`` (DO: the sword; SHOOT_ARROW or
        a spell: the projectile), by the tables (its defence against each element)."""
        mob = self._mob_at(target)
        if mob is None:
            return 0.0
        defence = MOB_TYPE_DEFENCE_MAPPING[mob[1]][mob[0]]
        if action == Action.DO:
            damage = rules.player_damage_vector(self.state)
        else:
            kind = PLAYER_ARROW if action == Action.SHOOT_ARROW else SPELLS[action][1]
            damage = mobrules.player_projectile_damage(self.state, int(kind))
        return mobrules._mob_damage(damage, defence)

    def _projectile(self, target) -> int | None:
        """The projectile action that does most damage to the mob at ``target`` among those
        at hand (an arrow with a bow and arrows; a learned spell with 2 mana), or None."""
        s, options = self.state, []
        if s.inventory.bow >= 1 and s.inventory.arrows >= 1:
            options.append(Action.SHOOT_ARROW)
        if s.player_mana >= 2:
            options += [a for i, a in enumerate((Action.CAST_FIREBALL, Action.CAST_ICEBALL)) if s.learned_spells[i]]
        options = [(self.damage_to(target, a), a) for a in options]
        options = [o for o in options if o[0] > 0]
        return max(options)[1] if options else None

    def _fire_at(self, targets, reach: int = 5) -> bool:
        """One turn of shooting at a mob in line (2..reach cells, nothing solid between): turn
        toward it, or shoot if already facing it. False (no turn taken) when none is."""
        for t in _nearest([t for t in targets if self.in_line(t, reach)], self.pos, 3):
            action = self._projectile(t)
            if action is None:
                continue
            self._aim(t, action)
            return True
        return False

    def _aiming_at(self, target) -> bool:
        """The player faces ``target`` (in its row or column)."""
        dr, dc = _toward(self.pos, target)
        return rules.facing(self.state) == (self.pos[0] + dr, self.pos[1] + dc)

    def _aim(self, target, action: int) -> bool:
        """One turn of fire at ``target`` (in the player's row or column): turn toward it (a
        move: it steps instead when the cell ahead is free), or ``action`` once facing it."""
        if not self._aiming_at(target):
            return self.act(MOVES[_toward(self.pos, target)])
        return self.act(action)

    def cast(self, name: str | None = None, count: int = 1, spell: int = Action.CAST_FIREBALL,
             limit: int = 300, reach: int = 6) -> bool:
        """Kill ``count`` more mobs called ``name`` with ``spell`` while mana lasts (2 a cast):
        get in line with the nearest one (even beside it: a weak sword is no help), face it and
        cast; walk into line otherwise. (``shoot`` is the arrow goal, which keeps away.)"""
        goal = self.kills(name) + count
        for _ in range(limit):
            if self.kills(name) >= goal:
                return True
            if self.done or self.budget <= 0:
                return False
            targets = self.mobs(name)
            if not targets:
                self.act(Action.NOOP)
                continue
            lined = [t for t in targets if self.in_line(t, reach)]
            if lined:
                t = _nearest(lined, self.pos, 1)[0]
                if self._aiming_at(t) and self.state.player_mana < 2:
                    return False
                self._aim(t, spell)
                continue
            # cells in line with a target, two or more from it, reachable by walking
            goals = set()
            for tr, tc in targets:
                for d in range(2, reach + 1):
                    goals.update({(tr + d, tc), (tr - d, tc), (tr, tc + d), (tr, tc - d)})
            goals = {g for g in goals if rules.in_bounds(self.state, *g) and (g == self.pos or rules.player_can_enter(self.state, *g))}
            path = self._path(goals, onto=True) if goals else None
            if path:
                self._step_along(path)
            else:
                self.act(Action.NOOP)
        return self.kills(name) >= goal

    def shoot(self, name=None, count: int = 1, limit: int = 400, until=None) -> int:
        """Kill ``count`` mobs matching ``name`` with arrows: get in a straight clear line with
        one, 2 to 6 cells away, face it and SHOOT_ARROW; melee when one is beside. Stops when
        the arrows run out (then returns the kills so far)."""
        start = self.kills(name)
        for _ in range(limit):
            if self.done or self.kills(name) - start >= count or (until is not None and until()):
                break
            mobs = live_mobs(self.state)
            targets = [m for m in mobs if _matches(m, name)]
            if not targets:
                self.evade(mobs)
                continue
            beside = [m for m in targets if _dist(m.cell, self.pos) == 1]
            if beside:
                self.strike(beside[0].cell)
                continue
            if self.state.inventory.arrows <= 0:
                break
            inline = [m for m in targets if 2 <= _dist(m.cell, self.pos) <= 6
                      and self._clear_line(self.pos, m.cell)]
            if inline:
                self._aim(min(inline, key=lambda m: _dist(m.cell, self.pos)).cell, Action.SHOOT_ARROW)
                continue
            # a cell in line with a target, 2-4 away, clear
            goals = set()
            for t in targets:
                for dr, dc in MOVES:
                    for k in range(2, 5):
                        cell = (t.cell[0] + k * dr, t.cell[1] + k * dc)
                        if rules.in_bounds(self.state, *cell) and rules.player_can_enter(self.state, *cell) \
                                and self._clear_line(cell, t.cell):
                            goals.add(cell)
            dist = self._distances(goals) if goals else {}
            best = None
            for action, cell in self._steps():
                score = dist.get(cell, 99) + 1.0 * self.danger(cell, mobs)
                if best is None or score < best[0]:
                    best = (score, action)
            self.act(best[1])
        return self.kills(name) - start

    # -- floors: ladders, chests, tables, torches, the boss ----------------------------------------
    def clear_gate(self, limit: int = 400, **kw) -> bool:
        """Kill monsters until the level's ladder opens (Craftax: 8 kills on the level)."""
        for _ in range(limit):
            level = self.state.player_level
            need = MONSTERS_KILLED_TO_CLEAR_LEVEL - int(self.state.monsters_killed[level])
            if need <= 0:
                return True
            if not self.hunt(count=need, limit=limit, **kw):
                return False
        return False

    def descend_floor(self, limit: int = 480, **kw) -> bool:
        """Open the level's ladder (kill monsters until its gate opens: ``clear_gate``, which
        takes ``hunt``'s keywords), then ``take_ladder``."""
        return self.clear_gate(limit=limit, **kw) and self.take_ladder(limit, kw.get("heal_below", 4.0))

    def take_ladder(self, limit: int = 400, heal_below: float = 4.0) -> bool:
        """Walk onto the level's ladder down and DESCEND (again, while it is shut), one turn at
        a time: ``upkeep`` first; a monster in the way (or at the player's back) is fought.
        True once on the next level."""
        level = self.state.player_level
        ladder = tuple(int(v) for v in self.state.down_ladders[level])
        for _ in range(limit):
            if self.state.player_level > level or self.done or self.budget <= 0:
                break
            if self.upkeep(heal_below):
                continue
            if self.pos == ladder:
                self.act(Action.DESCEND)
                continue
            beside = [t for t in self.mobs() if _beside(self.pos, t)]
            path = self._path({ladder}, onto=True)
            if beside and (not path or path[0] in beside):
                self.strike(beside[0])
            elif path:
                self._step_along(path)
            else:
                self.act(Action.NOOP)
        return self.state.player_level > level

    def enchant(self, action: int, table: int) -> bool:
        """Walk beside an enchantment ``table`` (a block), face it and enchant (``action``)."""
        cells = self.cells(table)
        if not cells or not self.walk(cells):
            return False
        t = next(c for c in cells if _beside(self.pos, c))
        return self.face(t) and rules.facing(self.state) == t and self.act(action)

    def open_chest(self, limit: int = 300) -> bool:
        """Walk to the nearest reachable chest, face it and open it (DO)."""
        before = len(self.cells(BlockType.CHEST))
        if not self.walk(self.cells(BlockType.CHEST), limit=limit):
            return False
        t = next(c for c in self.cells(BlockType.CHEST) if _beside(self.pos, c))
        if self.face(t) and rules.facing(self.state) == t:
            self.act(Action.DO)
        return len(self.cells(BlockType.CHEST)) < before

    def torch(self) -> bool:
        """Place a torch on a cell beside the player (turning to find one that takes it)."""
        before = self.state.inventory.torches
        for direction in (None, Action.RIGHT, Action.DOWN, Action.LEFT, Action.UP):
            if direction is not None and not self.act(direction):
                return False
            if not self.act(Action.PLACE_TORCH):
                return False
            if self.state.inventory.torches < before:
                return True
        return False

    # the sword element that hurts each wave of the necromancer fight (by the wave's row of
    # FLOOR_MOB_MAPPING, which is the boss's progress): ice for the fire realm's fire-proof
    # pigmen and fire elementals, fire for everything else (the ice realm's mobs are ice-proof)
    WAVE_ELEMENT = {6: 2}
    # the armour element that guards against each wave's elemental blows (fire realm: fire;
    # ice realm: ice), where there are gems and mana to spare
    WAVE_ARMOUR = {6: 1, 7: 2}

    def necromancer(self, limit: int = 512, heal_below: float = 7.0, ready_health: float = 8.0) -> bool:
        """The necromancer fight, played the Craftax way: fight each spawn wave (``hunt``:
        the sword, or an arrow or spell where it does more); once he is vulnerable, get ready
        for the next wave before hitting him: drink a healing potion below ``ready_health``,
        and re-enchant the sword at the enchantment table of the element the next wave's
        mobs are weak to (a mana potion first when short of mana); then hit him (DO)."""
        from .mobs import is_boss_vulnerable
        from .tables import ENCHANT_MANA_COST
        tables = {1: (BlockType.ENCHANTMENT_TABLE_FIRE, "ruby"), 2: (BlockType.ENCHANTMENT_TABLE_ICE, "sapphire")}
        stuck = set()
        for _ in range(limit):
            s = self.state
            if self.done or self.budget <= 0 or s.boss_progress >= NUM_LEVELS - 1:
                break
            necro = self.cells(BlockType.NECROMANCER)
            if not necro:
                return False
            if not is_boss_vulnerable(s):
                if s.player_health < heal_below and self.drink_potion("heal"):
                    continue
                mobs = self.mobs()
                if mobs and self._strike_ahead(mobs):     # (before dodging: a deep thing on a
                    continue                              # grave cannot move and shoots at once)
                if mobs and (s.boss_timesteps_to_spawn_this_round < 1      # (as ``boss``: hold
                             # the necromancer's side while the wave spawns)
                             or any(_beside(self.pos, t) for t in mobs) or self.projectile_cells()):
                    self.hunt(count=1, limit=1, explore=False, heal_below=0.0)   # (healing: above)
                elif mobs and self._fire_at(mobs):
                    pass
                elif not any(_beside(self.pos, n) for n in necro):
                    path = self._path(set(necro), onto=False)
                    self._step_along(path) if path else self.act(Action.NOOP)
                else:
                    self.act(Action.NOOP)
                continue
            # vulnerable: nothing can hurt the player until the next hit
            if s.player_health < ready_health and self.drink_potion("heal"):
                continue
            want = self.WAVE_ELEMENT.get(s.boss_progress + 1, 1)
            armour = self.WAVE_ARMOUR.get(s.boss_progress + 1)
            jobs = [(Action.ENCHANT_SWORD, want)] * (s.sword_enchantment != want)
            jobs += [(Action.ENCHANT_ARMOUR, armour)] * (armour is not None and bool(
                (s.armour_enchantments != armour).any()))
            jobs = [(a, e) for a, e in jobs if (a, e) not in stuck and self.cells(tables[e][0])
                    and getattr(s.inventory, tables[e][1]) >= 1]
            if jobs:
                action, element = jobs[0]
                if s.player_mana < ENCHANT_MANA_COST:
                    if not self.drink_potion("mana"):
                        stuck.add(jobs[0])
                    continue
                before = self.budget
                if not self.enchant(action, tables[element][0]) and self.budget == before:
                    stuck.add(jobs[0])
                continue
            if not any(_beside(self.pos, n) for n in necro):
                path = self._path(set(necro), onto=False)
                self._step_along(path) if path else self.act(Action.NOOP)
                continue
            t = next(n for n in necro if _beside(self.pos, n))
            self.act(Action.DO if rules.facing(self.state) == t else MOVES[(t[0] - self.pos[0], t[1] - self.pos[1])])
        return self.state.boss_progress >= NUM_LEVELS - 1

    def _strike_ahead(self, targets) -> bool:
        """If the player faces a mob beside it, strike (DO); if it faces one in line 2..5 cells
        away and holds a projectile that hurts it, shoot. True if it took the turn."""
        ahead = rules.facing(self.state)
        step = (ahead[0] - self.pos[0], ahead[1] - self.pos[1])
        for t in _nearest(targets, self.pos, 3):
            if t == ahead:
                return self.act(Action.DO) or True
            d = abs(t[0] - self.pos[0]) + abs(t[1] - self.pos[1])
            toward = ((t[0] > self.pos[0]) - (t[0] < self.pos[0]), (t[1] > self.pos[1]) - (t[1] < self.pos[1]))
            if toward == step and 2 <= d <= 5 and self.in_line(t, 5):
                shot = self._projectile(t)
                if shot is not None:
                    return self.act(shot) or True
        return False

    # -- losing policies ---------------------------------------------------------------------------
    def surrender(self, limit: int = 500, explore: bool = True) -> bool:
        """A losing policy: walk up to the nearest monster and stand there doing nothing until
        the player dies; with none in reach, explore until one comes (``explore``) or wait for
        them. True once dead."""
        for _ in range(limit):
            if self.done or self.budget <= 0:
                break
            targets = self.mobs()
            if any(_beside(self.pos, t) for t in targets):
                self.act(Action.NOOP)
                continue
            self._approach(targets, explore)
        return self.state.player_health <= 0
