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

    # -- floors, fights at range, magic, upkeep (added for the floor tasks) ------------------------
    def kills(self, name: str | None = None) -> int:
        """Kills so far in the episode (of ``name``; monsters when None), from the task's tally."""
        tally = self.task.tally.kills
        return tally.get(name.replace(" ", "_"), tally.get(name, 0)) if name else tally["monsters"]

    def drink(self, effect: str) -> bool:
        """Drink a potion whose effect (``task.POTION_EFFECTS``: heal, harm, mana ...) is
        ``effect``, if one is held; the colour's effect is read from the state."""
        from .task import POTION_EFFECTS
        for colour, held in enumerate(self.state.inventory.potions):
            if held > 0 and POTION_EFFECTS[int(self.state.potion_mapping[colour])] == effect:
                return self.act(Action.DRINK_POTION_RED + colour)
        return False

    def upkeep(self, heal_below: float = 4.0) -> bool:
        """Between fight turns: drink a healing potion when health falls below ``heal_below``;
        without one, REST while no monster is within 10 steps (a hit ends the rest). True when
        it took a turn."""
        s = self.state
        if s.player_drink <= 3 and not any(_beside(self.pos, t) for t in self.mobs()) \
                and self.quench(reach=25):
            return True
        if s.player_health >= heal_below:
            return False
        if self.drink("heal"):
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
        from .tables import DRINK_BLOCKS
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
            self.act(Action.DO if rules.facing(self.state) == t else MOVES[(t[0] - self.pos[0], t[1] - self.pos[1])])
            took = True
        return took

    def _step_along(self, path) -> bool:
        """One step along ``path``; if that cell is in a projectile's way this turn and the
        current one is not, wait a turn instead (``danger``)."""
        r, c = self.pos
        danger = self.danger()
        if path[0] in danger and (r, c) not in danger:
            return self.act(Action.NOOP)
        return self.act(MOVES[(path[0][0] - r, path[0][1] - c)])

    def danger(self) -> set:
        """Cells a mob projectile hits this turn: the cell it is on and the next one on its way."""
        s, level = self.state, self.state.player_level
        out = set()
        for i in np.flatnonzero(s.mob_projectiles.mask[level]):
            r, c = (int(v) for v in s.mob_projectiles.position[level, i])
            dr, dc = (int(v) for v in s.mob_projectile_directions[level, i])
            out.update({(r, c), (r + dr, c + dc)})
        return out

    def dodge(self) -> bool:
        """Step out of a projectile's way (to a free cell it does not cross); True if it took
        the turn."""
        danger = self.danger()
        if self.pos not in danger:
            return False
        r, c = self.pos
        for (dr, dc), action in MOVES.items():
            cell = (r + dr, c + dc)
            if cell not in danger and rules.player_can_enter(self.state, *cell):
                return self.act(action) or True
        return False

    def _reachable(self, limit: int = 4000) -> dict:
        """Walking distance from the player to each cell it can reach."""
        s, start = self.state, self.pos
        rows, cols = s.map.shape[1:]
        dist, queue = {start: 0}, deque([start])
        while queue and len(dist) < limit:
            cell = queue.popleft()
            for dr, dc in MOVES:
                nxt = (cell[0] + dr, cell[1] + dc)
                if nxt not in dist and 0 <= nxt[0] < rows and 0 <= nxt[1] < cols \
                        and rules.player_can_enter(s, *nxt):
                    dist[nxt] = dist[cell] + 1
                    queue.append(nxt)
        return dist

    def explore(self, turns: int = 12, rng=None) -> bool:
        """Walk up to ``turns`` toward a far reachable cell (new mobs spawn near the player and
        monsters come to it): one drawn from the cells 8 to 20 steps away."""
        rng = rng if rng is not None else self.__dict__.setdefault("_rng", np.random.default_rng(0))
        dist = self._reachable()
        far = [c for c, d in dist.items() if 8 <= d <= 20] or [c for c, d in dist.items() if d >= 2]
        if not far:
            return self.act(Action.NOOP)
        goal = far[int(rng.integers(len(far)))]
        for i in range(turns):
            if i and self.kills_wanted and self._path(set(self.mobs()), onto=False):
                return True
            path = self._path({goal}, onto=True)
            if not path:
                return self.act(Action.NOOP) if i == 0 else not self.done
            if not self._step_along(path):
                return False
        return not self.done

    kills_wanted = False

    def hunt(self, name: str | None = None, count: int = 1, limit: int = 400,
             heal_below: float = 4.0, explore: bool = True, ranged: bool = True) -> bool:
        """Kill ``count`` more mobs called ``name`` (monsters when None) in melee: walk beside
        the nearest reachable one (re-planned every turn: mobs move), face it, DO; drink a
        healing potion when health is low; explore when none can be reached. With ``ranged``,
        a mob in line 2 or more cells away is first shot at (``_fire_at``)."""
        goal = self.kills(name) + count
        self.kills_wanted = True
        try:
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
                        self.act(MOVES[(t[0] - self.pos[0], t[1] - self.pos[1])])
                        continue
                    shot = self._projectile(t) if ranged else None
                    better = shot is not None and self.damage_to(t, shot) > 2 * self.damage_to(t)
                    self.act(shot if better else Action.DO)
                    continue
                path = self._path(set(targets), onto=False) if targets else None
                if path:
                    self._step_along(path)
                elif explore:
                    self.explore(6)
                else:
                    self.act(Action.NOOP)
            return self.kills(name) >= goal
        finally:
            self.kills_wanted = False

    def _mob_at(self, cell):
        """(class, type id) of the live mob at ``cell`` of the player's level, or None."""
        s, level = self.state, self.state.player_level
        for k, kind in enumerate(KINDS):
            mobs = getattr(s, kind)
            for i in np.flatnonzero(mobs.mask[level]):
                if tuple(int(v) for v in mobs.position[level, i]) == tuple(cell):
                    return k, int(mobs.type_id[level, i])
        return None

    def damage_to(self, target, action: int = Action.DO) -> float:
        """Health the mob at ``target`` would lose to ``action`` (DO: the sword; SHOOT_ARROW or
        a spell: the projectile), by the tables (its defence against each element)."""
        from . import mobs as mob_rules
        from .bestiary import MOB_TYPE_DEFENCE_MAPPING
        from .tables import PLAYER_ARROW, SPELLS
        mob = self._mob_at(target)
        if mob is None:
            return 0.0
        defence = MOB_TYPE_DEFENCE_MAPPING[mob[1]][mob[0]]
        if action == Action.DO:
            damage = rules.player_damage_vector(self.state)
        else:
            kind = PLAYER_ARROW if action == Action.SHOOT_ARROW else SPELLS[action][1]
            damage = mob_rules.player_projectile_damage(self.state, int(kind))
        return mob_rules._mob_damage(damage, defence)

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

    def _name_at(self, cell) -> str | None:
        s, level = self.state, self.state.player_level
        for k, kind in enumerate(KINDS):
            mobs = getattr(s, kind)
            for i in np.flatnonzero(mobs.mask[level]):
                if tuple(int(v) for v in mobs.position[level, i]) == tuple(cell):
                    return MOB_NAMES[k][int(mobs.type_id[level, i])]
        return None

    def _fire_at(self, targets, reach: int = 5) -> bool:
        """One turn of shooting at a mob in line (2..reach cells, nothing solid between): turn
        toward it, or shoot if already facing it. False (no turn taken) when none is."""
        for t in _nearest([t for t in targets if self.in_line(t, reach)], self.pos, 3):
            action = self._projectile(t)
            if action is None:
                continue
            dr, dc = (t[0] > self.pos[0]) - (t[0] < self.pos[0]), (t[1] > self.pos[1]) - (t[1] < self.pos[1])
            if rules.facing(self.state) != (self.pos[0] + dr, self.pos[1] + dc):
                return self.act(MOVES[(dr, dc)]) or True
            return self.act(action) or True
        return False

    def clear_gate(self, limit: int = 400, **kw) -> bool:
        """Kill monsters until the level's ladder opens (Craftax: 8 kills on the level)."""
        from .tables import MONSTERS_KILLED_TO_CLEAR_LEVEL
        for _ in range(limit):
            level = self.state.player_level
            need = MONSTERS_KILLED_TO_CLEAR_LEVEL - int(self.state.monsters_killed[level])
            if need <= 0:
                return True
            if not self.hunt(count=need, limit=limit, **kw):
                return False
        return False

    def descend_floor(self, limit: int = 480, **kw) -> bool:
        """Open the level's ladder (kill monsters until its gate opens), walk onto it, DESCEND."""
        level = self.state.player_level
        if not self.clear_gate(limit=limit, **kw):
            return False
        ladder = tuple(int(v) for v in self.state.down_ladders[level])
        for _ in range(limit):
            if self.state.player_level > level or self.done or self.budget <= 0:
                break
            if self.upkeep(kw.get("heal_below", 4.0)):
                continue
            if self.pos == ladder:
                self.act(Action.DESCEND)
                continue
            beside = [t for t in self.mobs() if _beside(self.pos, t)]
            path = self._path({ladder}, onto=True)
            if beside and (not path or path[0] in beside):
                t = beside[0]                  # a monster in the way (or at our back): fight it
                self.act(Action.DO if rules.facing(self.state) == t else MOVES[(t[0] - self.pos[0], t[1] - self.pos[1])])
            elif path:
                self._step_along(path)
            else:
                self.act(Action.NOOP)
        return self.state.player_level > level

    def in_line(self, target, reach: int = 8) -> bool:
        """``target`` is in the player's row or column within ``reach``, nothing solid between."""
        (r, c), (tr, tc) = self.pos, target
        if (r != tr and c != tc) or abs(r - tr) + abs(c - tc) > reach:
            return False
        dr, dc = (tr > r) - (tr < r), (tc > c) - (tc < c)
        level, m = self.state.player_level, self.state.map
        from .tables import IS_SOLID
        cell = (r + dr, c + dc)
        while cell != (tr, tc):
            if IS_SOLID[int(m[level][cell])] or self.state.mob_map[level][cell]:
                return False
            cell = (cell[0] + dr, cell[1] + dc)
        return True

    def shoot(self, name: str | None = None, count: int = 1, action: int = Action.SHOOT_ARROW,
              limit: int = 300, reach: int = 6, can=None) -> bool:
        """Kill ``count`` more mobs called ``name`` with a projectile (``action``: an arrow or a
        spell): get in line with the nearest one, face it and shoot while ``can()`` (ammunition
        or mana left); walk into line otherwise."""
        goal = self.kills(name) + count
        can = can or (lambda: True)
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
                dr, dc = (t[0] > self.pos[0]) - (t[0] < self.pos[0]), (t[1] > self.pos[1]) - (t[1] < self.pos[1])
                if rules.facing(self.state) != (self.pos[0] + dr, self.pos[1] + dc):
                    self.act(MOVES[(dr, dc)])    # (turns; the cell ahead may be free: then a step)
                    continue
                if not can():
                    return False
                self.act(action)
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

    def cast(self, name: str | None = None, count: int = 1, spell: int = Action.CAST_FIREBALL, **kw) -> bool:
        """``shoot`` with a spell, while mana lasts (2 a cast)."""
        return self.shoot(name, count, action=spell, can=lambda: self.state.player_mana >= 2, **kw)

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
                self.act(Action.DO if rules.facing(self.state) == t else MOVES[(t[0] - self.pos[0], t[1] - self.pos[1])])
            elif path:
                self._step_along(path)
            else:
                self.act(Action.NOOP)
        return False

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

    def boss(self, limit: int = 420, **kw) -> bool:
        """The necromancer fight (the graveyard): kill the monsters of each spawn wave; while he
        is vulnerable (none alive, the wave over) stand beside his block and hit him (DO)."""
        from .tables import NUM_LEVELS
        for _ in range(limit):
            s = self.state
            if self.done or self.budget <= 0 or s.boss_progress >= NUM_LEVELS - 1:
                break
            if self.upkeep(kw.get("heal_below", 4.0)):
                continue
            necro = self.cells(BlockType.NECROMANCER)
            if not necro:
                return False
            mobs = self.mobs()
            if mobs and (s.boss_timesteps_to_spawn_this_round < 1
                         or any(_beside(self.pos, t) for t in mobs) or self.danger()):
                self.hunt(count=1, limit=1, explore=False, **kw)
                continue
            if mobs and self._fire_at(mobs):     # (the wave is on: hold the necromancer's side)
                continue
            if not any(_beside(self.pos, n) for n in necro):
                path = self._path(set(necro), onto=False)
                self._step_along(path) if path else self.act(Action.NOOP)
                continue
            t = next(n for n in necro if _beside(self.pos, n))
            if rules.facing(self.state) != t:
                self.act(MOVES[(t[0] - self.pos[0], t[1] - self.pos[1])])
            else:
                self.act(Action.DO if s.boss_timesteps_to_spawn_this_round <= 0 else Action.NOOP)
        return self.state.boss_progress >= NUM_LEVELS - 1

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
        from .tables import ENCHANT_MANA_COST, NUM_LEVELS
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
                if s.player_health < heal_below and self.quaff("heal"):
                    continue
                mobs = self.mobs()
                if mobs and self._strike_ahead(mobs):     # (before dodging: a deep thing on a
                    continue                              # grave cannot move and shoots at once)
                if mobs and (s.boss_timesteps_to_spawn_this_round < 1      # (as ``boss``: hold
                             # the necromancer's side while the wave spawns)
                             or any(_beside(self.pos, t) for t in mobs) or self.danger()):
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
            if s.player_health < ready_health and self.quaff("heal"):
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
                    if not self.quaff("mana"):
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

    def quaff(self, effect: str) -> bool:
        """Drink a held potion whose effect (``task.POTION_EFFECTS``) is ``effect``; False (no
        turn taken) when none is held. (As ``drink`` with an effect; a name of its own.)"""
        from .task import POTION_EFFECTS
        for colour, held in enumerate(self.state.inventory.potions.tolist()):
            if held > 0 and POTION_EFFECTS[int(self.state.potion_mapping[colour])] == effect:
                return self.act(Action.DRINK_POTION_RED + colour) or True
        return False

    def surrender(self, limit: int = 500) -> bool:
        """A losing policy: walk up to the nearest monster (exploring until one comes) and stand
        there doing nothing until the player dies. True once dead."""
        for _ in range(limit):
            if self.done:
                break
            targets = self.mobs()
            if any(_beside(self.pos, t) for t in targets):
                self.act(Action.NOOP)
                continue
            path = self._path(set(targets), onto=False) if targets else None
            if path:
                self._step_along(path)
            else:
                self.kills_wanted = True
                self.explore(6)
                self.kills_wanted = False
        return self.state.player_health <= 0


def _beside(a, b) -> bool:
    return abs(a[0] - b[0]) + abs(a[1] - b[1]) == 1


def _nearest(cells, pos, k: int) -> list:
    return sorted(cells, key=lambda p: abs(p[0] - pos[0]) + abs(p[1] - pos[1]))[:k]
