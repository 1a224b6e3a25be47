"""A scripted MiniHack player for tests: it reads only what the agent reads (the grid, the
legend's meanings, the HUD and the message line) and answers with action names.

The grid is a crop of NetHack's map that grows and, on big levels, scrolls with the hero, so the
player keeps its own map in a fixed frame of its own: after each turn it finds where the new grid
sits in that frame (the hero moved by the action's step or stood still; a teleport is found by
matching the whole grid), then copies the grid into it. On that map it plans shortest paths
(Dijkstra over the 8 moves, with NetHack's rule that nothing moves diagonally through a door),
explores the frontier of unexplored cells, fights, and searches for hidden doors when stuck.
"""

from __future__ import annotations

import heapq
from collections import Counter
from typing import Callable, Iterable

HERO = "you"
BLANK = "unknown"
PASSABLE = {"floor", "dark floor", "doorway", "broken door", "open door", "corridor",
            "lit corridor", "stairs down", "stairs up", "fog/vapor cloud", "fountain", "altar",
            "grave", "sink", "ice", "ladder up", "ladder down", "lowered drawbridge"}
SOLID = {"wall", "tree", "water", "molten lava", "iron bars", "raised drawbridge"}   # (a boulder is pushed)
KIN = {"dark floor": "floor", "lit corridor": "corridor"}   # one cell, lit or not
NO_DIAGONAL = {"open door", "closed door"}         # NetHack: no diagonal step into or out of these
OBJECT_CHARS = set(')[%?/=!"*`$(0_')               # NetHack's object classes
MOVES = {(0, -1): "MOVE_N", (0, 1): "MOVE_S", (1, 0): "MOVE_E", (-1, 0): "MOVE_W",
         (1, -1): "MOVE_NE", (-1, -1): "MOVE_NW", (1, 1): "MOVE_SE", (-1, 1): "MOVE_SW"}
DOORS = {"doorway", "broken door", "open door", "closed door"}
STEP = {name: d for d, name in MOVES.items()}
Cell = tuple[int, int]                             # (x, y) in the player's own frame


def is_trap(meaning: str) -> bool:
    return "trap" in meaning or meaning in ("web", "magic portal", "squeaky board")


class Player:
    """Plays one episode of ``task`` from ``reset(seed)``: ``act(name)`` steps, the rest plans."""

    def __init__(self, task, seed: int, *, fight: bool = True):
        self.task, self.fight = task, fight      # fight=False: keep away from monsters
        self.map: dict[Cell, str] = {}           # the meaning last seen at each cell
        self.chars: dict[Cell, str] = {}         # ... and its grid character
        self.visited: set[Cell] = set()
        self.blocked: set[Cell] = set()          # cells a move into failed (locked doors, rock)
        self.searched: Counter[Cell] = Counter()
        self.hero: Cell = (0, 0)
        self.under = ""                          # what the hero stands on, as last seen
        self.box = (0, 0, 0, 0)                  # x0, y0, x1, y1 of the grid's extent so far
        self.ret, self.done, self.info, self.steps = 0.0, False, {}, 0
        self.terminated = self.truncated = False
        self.last_monster = -1                   # the step a monster was last in view
        self.log: list[tuple[str, str]] = []     # (action, message) of every turn
        task.reset(seed=seed)
        self._read(candidates=[(0, 0)])

    # -- reading the frame --------------------------------------------------------------------
    @property
    def hud(self) -> str:
        return self.task.frame.hud

    @property
    def message(self) -> str:
        return self.task.frame.message

    def _read(self, candidates: list[Cell]) -> None:
        frame = self.task.frame
        meaning = dict(frame.legend)
        rows = frame.grid
        hy = next(y for y, row in enumerate(rows) if any(meaning[ch] == HERO for ch in row))
        hx = next(x for x, ch in enumerate(rows[hy]) if meaning[ch] == HERO)
        seen = [(x - hx, y - hy, ch, meaning[ch]) for y, row in enumerate(rows) for x, ch in enumerate(row)]
        shape = (-hx, -hy, len(rows[0]) - hx, len(rows) - hy, "| View " in frame.hud)
        best = max(candidates, key=lambda h: self._fit(h, seen, shape))
        if self._fit(best, seen, shape) < 0:          # the hero was moved elsewhere (a teleport)
            x0, y0, x1, y1 = self.box
            everywhere = [(x, y) for x in range(x0 - 41, x1 + 42) for y in range(y0 - 21, y1 + 22)]
            best = max(everywhere, key=lambda h: self._fit(h, seen, shape))
        if best != self.hero:
            self.under = self.map.get(best, "")
        self.hero = best
        for dx, dy, ch, m in seen:
            self.map[best[0] + dx, best[1] + dy] = m
            self.chars[best[0] + dx, best[1] + dy] = ch
        self.box = (min(self.box[0], best[0] + shape[0]), min(self.box[1], best[1] + shape[1]),
                    max(self.box[2], best[0] + shape[2] - 1), max(self.box[3], best[1] + shape[3] - 1))
        self.visited.add(best)
        if any(self.is_monster(c) for c in self.map):
            self.last_monster = self.steps

    def _fit(self, hero: Cell, seen, shape) -> int:
        """How well the grid agrees with our map when the hero is at ``hero``: seen cells stay
        seen (NetHack remembers them) and keep their meaning, and, unless the view scrolls, the
        grid still spans everything seen so far (it is the bounding box of the seen cells)."""
        x0, y0, x1, y1 = self.box
        if not shape[4] and self.map and not (hero[0] + shape[0] <= x0 and hero[1] + shape[1] <= y0
                                              and x1 < hero[0] + shape[2] and y1 < hero[1] + shape[3]):
            return -10**6
        score = 0
        for dx, dy, ch, m in seen:
            c = (hero[0] + dx, hero[1] + dy)
            old = self.map.get(c)
            if old is None or old == HERO or m == HERO or old == BLANK or self.is_monster(c):
                continue
            score += 1 if KIN.get(old, old) == KIN.get(m, m) else -3
        return score

    def is_monster(self, c: Cell) -> bool:
        """Whatever is not a known feature, trap or object: NetHack names monsters by their kind."""
        m = self.map.get(c)
        return (m not in (None, HERO, BLANK, "closed door") and m not in PASSABLE and m not in SOLID
                and not is_trap(m) and self.chars[c] not in OBJECT_CHARS)

    def at(self, c: Cell) -> str:
        """The meaning of cell ``c`` (under the hero: what was there when last seen)."""
        return self.under if c == self.hero else self.map.get(c, BLANK)

    def find(self, want: Callable[[str], bool]) -> list[Cell]:
        return [c for c, m in self.map.items() if want(m)]

    def carries(self, word: str) -> bool:
        return any(word in part for part in self.hud.split("| Inv ", 1)[1:])

    # -- acting ----------------------------------------------------------------------------------
    def act(self, name: str) -> None:
        before = self.hero
        _, self.reward, self.terminated, self.truncated, self.info = self.task.step(name)
        self.ret += self.reward
        self.steps += 1
        self.log.append((name, self.message))
        self.done = self.terminated or self.truncated
        if self.done and self.hud.endswith("| Dead"):
            return
        d = STEP.get(name, (0, 0))
        target = (before[0] + d[0], before[1] + d[1])
        was = self.map.get(target)
        self._read(candidates=[target, before] + [(before[0] + x, before[1] + y) for x, y in MOVES])
        if name == "SEARCH":
            for x, y in MOVES:
                self.searched[before[0] + x, before[1] + y] += 1
        elif name in STEP and self.hero == before and was == self.map.get(target) and self.message:
            # a bump NetHack remarks on ("It's solid stone.", "This door is locked."); a door
            # that is merely stuck, a monster we hit, or a teleport back here does not block
            if not self.is_monster(target) and (was != "closed door" or "locked" in self.message):
                self.blocked.add(target)

    # -- planning --------------------------------------------------------------------------------
    def passable(self, c: Cell, traps: bool = False) -> bool:
        m = self.map.get(c)
        if m is None or m == BLANK or m in SOLID or c in self.blocked:
            return False
        return traps or not is_trap(m)

    def _cost(self, c: Cell) -> int:
        cost = 1 + 3 * (self.map.get(c) == "closed door") + 30 * is_trap(self.map.get(c, ""))
        if not self.fight:
            cost += 1000 * self.is_monster(c) + 50 * any(self.is_monster((c[0] + x, c[1] + y)) for x, y in MOVES)
        return cost

    def neighbours(self, c: Cell):
        for (dx, dy), name in MOVES.items():
            n = (c[0] + dx, c[1] + dy)
            if not self.passable(n, traps=True):
                continue
            if dx and dy and (self.at(c) in NO_DIAGONAL or self.at(n) in NO_DIAGONAL):
                continue
            yield n, name

    def path(self, goals: Iterable[Cell]) -> list[str] | None:
        """The moves of a cheapest path from the hero to one of ``goals`` (None if none)."""
        goals = set(goals)
        if not goals:
            return None
        dist, prev = {self.hero: 0}, {}
        heap = [(0, self.hero)]
        while heap:
            d, c = heapq.heappop(heap)
            if c in goals:
                moves = []
                while c != self.hero:
                    c, name = prev[c]
                    moves.append(name)
                return moves[::-1]
            if d > dist[c]:
                continue
            for n, name in self.neighbours(c):
                nd = d + self._cost(n)
                if nd < dist.get(n, 1 << 30):
                    dist[n], prev[n] = nd, (c, name)
                    heapq.heappush(heap, (nd, n))
        return None

    def frontier(self) -> list[Cell]:
        """Known cells next to an unexplored cell we never stood beside."""
        out = []
        for c, m in self.map.items():
            if not self.passable(c) or self.is_monster(c):
                continue
            for dx, dy in MOVES:
                n = (c[0] + dx, c[1] + dy)
                if self.map.get(n, BLANK) == BLANK and not any((n[0] + x, n[1] + y) in self.visited for x, y in MOVES):
                    out.append(c)
                    break
        return out

    def search_spot(self) -> list[Cell]:
        """Where to look for hidden doors: a cell by walls or rock whose surroundings were least searched."""
        spots = {}
        for c in self.map:
            if not self.passable(c):
                continue
            around = [(c[0] + x, c[1] + y) for x, y in MOVES]
            hidden = [n for n in around if self.map.get(n, BLANK) in (BLANK, "wall")]
            if hidden:
                spots[c] = min(self.searched[n] for n in hidden)
        if not spots:
            return []
        least = min(spots.values())
        return [c for c, s in spots.items() if s == least]

    def adjacent_monster(self) -> str | None:
        for (dx, dy), name in MOVES.items():
            n = (self.hero[0] + dx, self.hero[1] + dy)
            if self.is_monster(n) and not self.map[n].startswith("peaceful"):
                if dx and dy and (self.under in NO_DIAGONAL or self.at(n) in NO_DIAGONAL):
                    continue
                return name
        return None

    def toward(self, goals: Iterable[Cell]) -> str | None:
        moves = self.path(goals)
        return moves[0] if moves else None

    def next_move(self, target: Callable[[str], bool]) -> str:
        """One turn toward the nearest cell whose meaning satisfies ``target``: fight what stands
        next to us, else walk there, else explore, else search for hidden passages."""
        if self.fight and (attack := self.adjacent_monster()):
            return attack
        for goals in (self.find(target), self.frontier()):
            if move := self.toward(goals):
                return move
        if move := self.unlock():
            return move
        spots = self.search_spot()
        if self.hero in spots:
            return "SEARCH"
        return self.toward(spots) or "SEARCH"

    def unlock(self) -> str | None:
        """A locked door in the way: stand where it is the nearest door (the direction NetHack's
        question gets), DROP the items after the key or lock pick (APPLY uses the last item it
        offers), and APPLY."""
        locked = [c for c in self.blocked if self.map.get(c) == "closed door"]
        if not locked or not (self.carries("key") or self.carries("lock pick")):
            return None
        doors = self.find(lambda m: m in DOORS)
        spots = [c for door in locked for c in ((door[0] + x, door[1] + y) for x, y in MOVES)
                 if self.passable(c) and min(doors, key=lambda d: _near(c, d)) == door]
        if self.hero not in spots:
            return self.toward(spots)
        last = self.hud.split("| Inv ", 1)[-1].split(", ")[-1]
        if not ("key" in last or "lock pick" in last):
            return "DROP"
        self.blocked -= set(locked)            # (walking into it tells whether it opened)
        return "APPLY"

    # -- whole episodes --------------------------------------------------------------------------
    def play(self, policy: Callable[["Player"], str], max_steps: int = 10**6) -> "Player":
        while not self.done and self.steps < max_steps:
            self.act(policy(self))
        return self


def _near(c: Cell, d: Cell) -> tuple[int, int, int]:
    """The engine's order of doors for a direction question asked at ``c``: nearest, then top, then left."""
    return max(abs(d[0] - c[0]), abs(d[1] - c[1])), d[1], d[0]


def stairs(p: Player) -> str:
    """Make for the staircase down (exploring, fighting and searching on the way)."""
    return p.next_move(lambda m: m == "stairs down")


def keyroom(p: Player) -> str:
    """KeyRoom: pick up the key, then make for the stairs (the locked door on the way is
    APPLYed to by ``Player.unlock``)."""
    if not p.carries("key"):
        if "key" in p.under:
            return "PICKUP"
        return p.next_move(lambda m: "key" in m)
    return stairs(p)


def hold_corridor(p: Player, wait: int = 20) -> str:
    """CorridorBattle: stand in the corridor and fight the rats one at a time; go on to the
    stairs once no monster has been in view for ``wait`` turns."""
    if attack := p.adjacent_monster():
        return attack
    if p.steps - p.last_monster < wait or p.steps < wait:
        corridor = p.find(lambda m: KIN.get(m, m) == "corridor")
        if corridor:
            spot = sorted(corridor)[len(corridor) // 2]
            return p.toward([spot]) or "WAIT"
    return stairs(p)


def hunt(p: Player) -> str:
    """A way to die: go for the nearest monster and attack it (never onto the stairs)."""
    p.blocked |= set(p.find(lambda m: m == "stairs down"))
    if attack := p.adjacent_monster():
        return attack
    return p.toward([c for c in p.map if p.is_monster(c)]) or p.next_move(lambda m: False)
