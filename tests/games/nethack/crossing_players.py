"""Scripted players for MiniHack's crossing tasks (River, LavaCross, Memento), used by the tests.

A player reads only what the agent reads (``task.frame``: the grid, the legend's meanings, the
HUD and the message line) and answers with one of the 22 action names, or None when it sees no
way on. What a player knows beyond that is what a person who read the task's rules knows: the
river runs north-south with the stairs beyond it, a levitation item lets you float, and (for
Memento) which cue monster goes with which branch.
"""

from __future__ import annotations

import heapq
import re
from collections import deque
from dataclasses import dataclass
from typing import Callable, Iterable

MOVES = {(0, -1): "MOVE_N", (0, 1): "MOVE_S", (1, 0): "MOVE_E", (-1, 0): "MOVE_W",
         (1, -1): "MOVE_NE", (-1, -1): "MOVE_NW", (1, 1): "MOVE_SE", (-1, 1): "MOVE_SW"}
STEP = {name: d for d, name in MOVES.items()}
UNKNOWN = "unknown"
HERO, WATER, LAVA, STAIRS = "you", "water", "molten lava", "stairs down"
SOLID = {"wall", "iron bars", "tree", "closed door", UNKNOWN}
TERRAIN = SOLID | {WATER, LAVA, STAIRS, "stairs up", "floor", "dark floor",
                   "doorway", "open door", "broken door", "corridor", "ice"}

Pos = tuple[int, int]


def is_boulder(meaning: str | None) -> bool:
    return meaning is not None and meaning.endswith("boulder")


def walkable(meaning: str | None) -> bool:
    """A cell the hero may step on (a monster there is attacked instead)."""
    return meaning is not None and meaning not in SOLID and meaning not in (WATER, LAVA) and not is_boulder(meaning)


def is_monster(meaning: str | None) -> bool:
    """Monsters are described by their name alone; the objects of these levels are boulders and
    LavaCross's items (``kind_of``: a potion, ring, boots, wand or horn), counted or not."""
    return (meaning is not None and meaning not in TERRAIN and meaning != HERO and not meaning[:1].isdigit()
            and kind_of(meaning) is None and not meaning.endswith("boulder"))


def attack(cells: dict[Pos, str], hero: Pos) -> str | None:
    """The move that attacks a monster next to the hero, if any (north first, clockwise)."""
    for d in ((0, -1), (1, -1), (1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1)):
        if is_monster(cells.get(add(hero, d))):
            return MOVES[d]
    return None


def add(p: Pos, d: Pos) -> Pos:
    return p[0] + d[0], p[1] + d[1]


class Sight:
    """One frame as cells: ``cells[(x, y)]`` is the legend meaning of the grid character there."""

    def __init__(self, frame) -> None:
        meaning = dict(frame.legend)
        self.grid = frame.grid
        self.hud, self.message = frame.hud, frame.message
        self.cells: dict[Pos, str] = {}
        self.hero: Pos | None = None
        for y, row in enumerate(frame.grid):
            for x, ch in enumerate(row):
                m = meaning[ch]
                self.cells[(x, y)] = m
                if m == HERO:
                    self.hero = (x, y)

    def find(self, test: Callable[[str], bool]) -> list[Pos]:
        return [p for p, m in self.cells.items() if test(m)]

    def inventory(self) -> list[str]:
        """The HUD's ``Inv x, y`` items."""
        inv = next((part[4:] for part in self.hud.split(" | ") if part.startswith("Inv ")), "")
        return [item for item in inv.split(", ") if item]

    def levitating(self) -> bool:
        return "Lev" in self.hud.split(" | ")[1].split() if " | " in self.hud else False


class Level:
    """The level seen so far in coordinates fixed for the episode. The grid is the bounding box
    of the cells seen; when it grows at the top or left, everything shown moves: the shift is the
    one that lays the old rows best onto the new."""

    def __init__(self) -> None:
        self.origin = (0, 0)
        self._last: Sight | None = None

    def see(self, sight: Sight) -> None:
        old = self._last
        size = (len(sight.grid[0]), len(sight.grid))
        if old is not None and size != (len(old.grid[0]), len(old.grid)):
            dw, dh = size[0] - len(old.grid[0]), size[1] - len(old.grid)
            kept = [(p, m) for p, m in old.cells.items() if m not in (UNKNOWN, HERO)]

            def score(s: Pos) -> int:
                return sum(sight.cells.get(add(p, s)) == m for p, m in kept)
            shift = max(((sx, sy) for sx in range(max(dw, 0) + 1) for sy in range(max(dh, 0) + 1)),
                        key=lambda s: (score(s), -s[0] - s[1]))
            self.origin = (self.origin[0] - shift[0], self.origin[1] - shift[1])
        self._last = sight
        ox, oy = self.origin
        self.cells = {(x + ox, y + oy): m for (x, y), m in sight.cells.items()}
        self.hero = (sight.hero[0] + ox, sight.hero[1] + oy)


# -- searches ---------------------------------------------------------------------------------
def distances(start: Pos, ok: Callable[[Pos], bool]) -> dict[Pos, tuple[int, Pos | None]]:
    """Breadth-first search over 8-neighbour steps onto cells where ``ok``: cell -> (steps, parent)."""
    seen: dict[Pos, tuple[int, Pos | None]] = {start: (0, None)}
    queue = deque([start])
    while queue:
        p = queue.popleft()
        k = seen[p][0] + 1
        for d in MOVES:
            q = add(p, d)
            if q not in seen and ok(q):
                seen[q] = (k, p)
                queue.append(q)
    return seen


def route(tree: dict[Pos, tuple[int, Pos | None]], goal: Pos) -> list[str]:
    """The move names from the search's start to ``goal``."""
    out = []
    while tree[goal][1] is not None:
        prev = tree[goal][1]
        out.append(MOVES[(goal[0] - prev[0], goal[1] - prev[1])])
        goal = prev
    return out[::-1]


def walk_to(cells: dict[Pos, str], start: Pos, goals: Iterable[Pos], ok=None) -> list[str] | None:
    """The shortest walk from ``start`` onto one of ``goals`` (goals may be unwalkable cells)."""
    goals = set(goals)
    ok = ok or (lambda q: walkable(cells.get(q)))
    tree = distances(start, lambda q: ok(q) or q in goals)
    reached = [g for g in goals if g in tree]
    if not reached:
        return None
    return route(tree, min(reached, key=lambda g: (tree[g][0], g[1], g[0])))


# -- River ------------------------------------------------------------------------------------
def push_plan(cells: dict[Pos, str], hero: Pos, boulder: Pos, targets: set[Pos], boulders: set[Pos],
              banned: frozenset = frozenset()):
    """The cheapest walk (in turns) that pushes ``boulder`` into one of the water cells ``targets``:
    a list of (move, hero after, boulder after, or None once it fell in), or None.
    Search over (boulder cell, hero cell) after each push, with the hero's walk in between;
    ``banned`` (boulder cell, direction) pushes failed lately."""
    others = boulders - {boulder}

    def hero_ok(q: Pos, b: Pos) -> bool:
        return q != b and q not in others and walkable(cells.get(q))

    def boulder_ok(q: Pos) -> bool:
        return q in targets or (q not in others and walkable(cells.get(q)))

    def h(b: Pos) -> int:
        return min(max(abs(b[0] - t[0]), abs(b[1] - t[1])) for t in targets) - 1

    start = (boulder, hero)
    best = {start: 0}
    parent: dict[tuple[Pos, Pos], tuple[tuple[Pos, Pos], Pos, Pos]] = {}
    heap = [(h(boulder), 0, start)]
    end = None
    while heap:
        _, cost, node = heapq.heappop(heap)
        if cost > best[node]:
            continue
        b, at = node
        if b in targets:
            end = node
            break
        tree = distances(at, lambda q: hero_ok(q, b))
        for d in MOVES:
            stand, to = (b[0] - d[0], b[1] - d[1]), add(b, d)
            if stand not in tree or not boulder_ok(to) or (b, d) in banned:
                continue
            nxt, c = (to, b), cost + tree[stand][0] + 1
            if c < best.get(nxt, 1 << 30):
                best[nxt], parent[nxt] = c, (node, stand, d)
                heapq.heappush(heap, (c + h(to), c, nxt))
    if end is None:
        return None
    pushes = []
    node = end
    while node in parent:
        node, stand, d = parent[node]
        pushes.append((node, stand, d))
    plan = []
    for (b, at), stand, d in reversed(pushes):
        tree = distances(at, lambda q: hero_ok(q, b))
        p = at
        for move in route(tree, stand):
            p = add(p, STEP[move])
            plan.append((move, p, b))
        to = add(b, d)
        plan.append((MOVES[d], b, None if to in targets else to))
    return plan


class RiverPlayer:
    """Builds a ford: pushes boulders one by one into the westmost water cell of one row (the
    river runs north-south, the stairs lie east of it), first walking out onto the ford to see
    past the water (it blocks the view), then walks to the stairs once they are in reach. It
    attacks any monster next to it; a push that fails is not tried again for a while (a monster
    behind the boulder), nor ever into water that refused a boulder (one lies under it)."""

    def __init__(self) -> None:
        self.level = Level()
        self.plan: list[tuple[str, Pos, Pos | None]] = []
        self.expect: tuple[Pos, Pos | None] | None = None
        self.row: int | None = None                # the ford's row
        self.turn = 0
        self.pushing: tuple[Pos, Pos, Pos] | None = None   # (hero, boulder, direction) of a push
        self.banned: dict[tuple[Pos, Pos], int] = {}        # failed pushes -> turn to retry
        self.looked: set[Pos] = set()             # cells the explorer went to
        self.sunk: set[Pos] = set()               # water cells no boulder can enter

    def __call__(self, frame) -> str | None:
        self.turn += 1
        self.level.see(Sight(frame))
        cells, hero = self.level.cells, self.level.hero
        if self.pushing is not None and self.pushing[0] == hero:      # the boulder did not move
            self.banned[self.pushing[1:]] = self.turn + 8
            to = add(*self.pushing[1:])
            if cells.get(to) == WATER and "in vain" in frame.message:
                self.sunk.add(to)                  # a boulder lies under that water already
            self.plan = []
        self.pushing = None
        self.looked.add(hero)
        fight = attack(cells, hero)
        if fight:
            self.plan = []
            return fight
        stairs = [p for p, m in cells.items() if m == STAIRS]
        if stairs:
            path = walk_to(cells, hero, stairs)
            if path:
                return path[0]
        if not (self.plan and self.expect and self.expect[0] == hero and (
                self.expect[1] is None or is_boulder(cells.get(self.expect[1])))):
            look = self._explore(cells, hero)     # first see what lies beyond the ford so far
            if look:
                return look
            self.plan = self._plan(cells, hero) or []
        if not self.plan:
            return None
        move, at, b = self.plan.pop(0)
        if is_boulder(cells.get(at)):
            self.pushing = (hero, at, STEP[move])
        self.expect = (at, b)
        return move

    def _plan(self, cells: dict[Pos, str], hero: Pos):
        """Pushes for the next boulder, into the westmost water cell of the ford's row. The ford
        runs along one row (a boulder pushed east along it can always reach its next cell); the
        row is the one of fewest water or unexplored cells, then of the cheapest first push.
        Unexplored cells west of the river (hidden behind boulders) are taken for floor."""
        west = min((x for (x, _), m in cells.items() if m in (WATER, LAVA)), default=0)
        cells = {p: "floor" if m == UNKNOWN and p[0] < west else m for p, m in cells.items()}
        land = distances(hero, lambda q: walkable(cells.get(q)))
        boulders = {p for p, m in cells.items() if is_boulder(m)}
        near = [b for b in boulders if any(add(b, d) in land for d in MOVES)]
        fords = {y: f for y, f in _fords(cells).items() if f[1] not in self.sunk}
        if self.row in fords:
            fords = {self.row: fords[self.row]}
        banned = frozenset(k for k, t in self.banned.items() if t > self.turn)
        for cost in sorted({c for c, _ in fords.values()}):
            targets = {t for c, t in fords.values() if c == cost and any(add(t, d) in land for d in MOVES)}
            plans = [p for p in (push_plan(cells, hero, b, targets, boulders, banned) for b in near) if p]
            if plans:
                plan = min(plans, key=len)
                move, at, _ = plan[-1]
                self.row = add(at, STEP[move])[1]      # (where the last push sends it)
                return plan
        return None

    def _explore(self, cells: dict[Pos, str], hero: Pos) -> str | None:
        """Toward the nearest reachable cell next to an unexplored one in or past the river
        (water blocks the view here: the far side shows only from a cell next to it)."""
        river = [x for (x, _), m in cells.items() if m in (WATER, LAVA)]
        west, x1 = min(river, default=-1), max(x for x, _ in cells)
        land = distances(hero, lambda q: walkable(cells.get(q)))
        edge = [p for p in land if p not in self.looked and any(
            q[0] >= west and (cells.get(q) == UNKNOWN or q[0] > x1) for q in (add(p, d) for d in MOVES))]
        if not edge:
            return None
        return route(land, min(edge, key=lambda p: (land[p][0], p[1], p[0])))[0]


def _fords(cells: dict[Pos, str]) -> dict[int, tuple[int, Pos]]:
    """For each row the river can be forded on (water, no lava): the cells still to fill (water or
    unexplored, up to the far bank or the edge of what is shown) and the westmost water cell."""
    xs = [x for x, _ in cells]
    x1 = max(xs)
    out = {}
    for y in sorted({y for _, y in cells}):
        row = [cells.get((x, y), UNKNOWN) for x in range(min(xs), x1 + 1)]
        wet = [i for i, m in enumerate(row) if m in (WATER, LAVA)]
        if not wet or LAVA in row or row[wet[0]] != WATER:
            continue
        fill = 0
        for m in row[wet[0]:]:
            if m not in (WATER, UNKNOWN):
                break
            fill += 1
        out[y] = (fill, (min(xs) + wet[0], y))
    return out


# -- LavaCross --------------------------------------------------------------------------------
KINDS = ("potion", "ring", "boots", "wand", "horn")
USE = {"potion": "QUAFF", "ring": "WIELD", "boots": "WIELD", "wand": "ZAP", "horn": "APPLY"}


def kind_of(name: str) -> str | None:
    return next((k for k in KINDS if re.search(rf"\b{k}\b", name)), None)


class LavaCrossPlayer:
    """Fetches the item (PICKUP), uses it, then walks to the stairs over the lava. A potion, ring
    or boots make you float (QUAFF, WIELD); a wand of cold or a frost horn freezes the lava along
    a ray (ZAP, APPLY) that goes the way you last moved (no monster or door is in view): the
    player steps east toward the lava from three cells west of it first, so the ray, bouncing off
    the far wall, runs out before it comes back to you."""

    def __init__(self) -> None:
        self.used = False
        self.last: str | None = None

    def __call__(self, frame) -> str | None:
        action = self._choose(Sight(frame))
        self.last = action
        return action

    def _choose(self, s: Sight) -> str | None:
        cells, hero = s.cells, s.hero
        stairs = s.find(lambda m: m == STAIRS)
        lev = s.levitating()
        over = (lambda q: walkable(cells.get(q)) or cells.get(q) == LAVA) if lev else None
        path = walk_to(cells, hero, stairs, over) if stairs else None
        if path:
            return path[0]
        held = next((k for k in map(kind_of, s.inventory()) if k), None)
        if held is None:
            items = s.find(lambda m: kind_of(m) is not None)
            if not items:
                return "PICKUP"                  # it lies under you
            return walk_to(cells, hero, items)[0]
        if self.used and held in ("potion", "ring", "boots"):
            return None
        if held in ("potion", "ring", "boots"):
            self.used = True
            return USE[held]
        # a freezer: three cells west of the lava on the stairs' row, having stepped east
        lava_x = min(x for x, _ in s.find(lambda m: m == LAVA))
        row = stairs[0][1] if stairs else hero[1]
        spot = (lava_x - 3, row)
        if hero == spot and self.last == "MOVE_E":
            self.used = True
            return USE[held]
        if hero == spot:
            return "MOVE_W"
        if hero == (spot[0] - 1, row):
            return "MOVE_E"
        return walk_to(cells, hero, [(spot[0] - 1, row)])[0]


def walk_into_lava(frame) -> str | None:
    """A loss: straight to the nearest lava."""
    s = Sight(frame)
    return (walk_to(s.cells, s.hero, s.find(lambda m: m == LAVA)) or [None])[0]


# -- Memento ----------------------------------------------------------------------------------
# The branch of each cue (rows from the corridor: negative is north), as in upstream's des files:
# memento_short.des and memento_easy.des: a jelly shown -> the north branch, a lichen -> south;
# memento_hard.des: the jelly (blue/spotted) and the mold (red/green) pick one of four.
TWO_WAY = {"blue jelly": -3, "lichen": 3}
FOUR_WAY = {("blue jelly", "red mold"): -3, ("spotted jelly", "red mold"): -1,
            ("blue jelly", "green mold"): 1, ("spotted jelly", "green mold"): 3}


def memento_branch(cues: set[str]) -> int:
    jelly = next((c for c in cues if c.endswith("jelly")), None)
    mold = next((c for c in cues if c.endswith("mold")), None)
    if mold is not None:
        return FOUR_WAY[(jelly, mold)]
    return TWO_WAY[jelly or "lichen"]


class MementoPlayer:
    """Remembers the monsters shown at the start, walks the corridor east to its end, turns
    into the branch those monsters stand for (``branch``: rows north (-) or south (+) of the
    corridor; by default the right one), then east until the grid bug is next to it and attacks."""

    CUES = ("jelly", "lichen", "mold")

    def __init__(self, wrong: bool = False) -> None:
        self.wrong = wrong
        self.branch: int | None = None
        self.turned = 0

    def __call__(self, frame) -> str | None:
        s = Sight(frame)
        if self.branch is None:
            cues = {m for m in s.cells.values() if m.endswith(self.CUES)}
            self.branch = memento_branch(cues)
            if self.wrong:
                self.branch = -self.branch
        hero, cells = s.hero, s.cells
        for d, move in MOVES.items():
            if cells.get(add(hero, d)) == "grid bug":
                return move
        if self.turned == 0 and walkable(cells.get(add(hero, (1, 0)))):
            return "MOVE_E"                        # the corridor
        if self.turned < abs(self.branch):
            self.turned += 1
            return "MOVE_N" if self.branch < 0 else "MOVE_S"
        return "MOVE_E"


# -- driving ----------------------------------------------------------------------------------
@dataclass
class Episode:
    actions: list[str]
    messages: list[str]                   # each turn's message line
    reward: float = 0.0                   # of the last step
    terminated: bool = False
    truncated: bool = False
    won: bool | None = None


def play(task, player, seed: int, max_steps: int | None = None) -> Episode:
    """Reset ``task`` on ``seed`` and let ``player`` act until the episode ends, the player has
    no move, or ``max_steps`` turns."""
    task.reset(seed=seed)
    ep = Episode([], [])
    for _ in range(max_steps or task.max_turns):
        action = player(task.frame)
        if action is None:
            break
        _, ep.reward, ep.terminated, ep.truncated, info = task.step(action)
        ep.actions.append(action)
        ep.messages.append(task.frame.message)
        ep.won = info["won"]
        if ep.terminated or ep.truncated:
            break
    return ep
