"""Search over MiniGrid states, for tests, baselines and generators that want a solvability check.

``plan`` is a breadth-first search over (x, y, facing) with MiniGrid's moves, reading the true
world (not the agent's view). Closed doors on the way are opened with TOGGLE, locked ones too
when the agent carries their key. ``solve`` plays a whole episode with it: walk to the goal,
fetching the key of a locked door first when one is in the way, and re-planning every turn in
worlds that move (dynamic obstacles), never walking into an occupied cell. Families whose mission
is not the goal square (fetch an object, open doors in order ...) register a win script with
``@win_script(Family)`` in their module; ``solve`` plays that instead.
"""

from __future__ import annotations

import heapq
from collections import deque
from typing import Callable

from .engine import DROP, FORWARD, LEFT, PICKUP, RIGHT, TOGGLE, MiniGridTask
from .world import DIR_VEC, Door, Key, WorldObj

Pos = tuple[int, int]


def _openable(task: MiniGridTask, obj: WorldObj) -> bool:
    if not isinstance(obj, Door) or obj.is_open:
        return False
    carried = task.carrying
    return not obj.is_locked or (isinstance(carried, Key) and carried.color == obj.color)


def plan(task: MiniGridTask, target: Pos, *, face: bool = False,
         blocked: Callable[[Pos], bool] | None = None) -> list[int] | None:
    """Actions that bring the agent onto ``target`` (or, with ``face``, next to it and facing
    it), fewest BFS edges first; None if no such path. Never enters lava, the goal (unless it is
    the target) or a cell ``blocked`` rejects."""
    grid = task.grid
    start = (*task.agent_pos, task.agent_dir)
    prev: dict[tuple[int, int, int], tuple[tuple[int, int, int], tuple[int, ...]] | None] = {start: None}
    queue = deque([start])
    while queue:
        state = queue.popleft()
        x, y, d = state
        fx, fy = x + DIR_VEC[d][0], y + DIR_VEC[d][1]
        if (face and (fx, fy) == target) or (not face and (x, y) == target):
            actions: list[int] = []
            while prev[state] is not None:
                state, step = prev[state]
                actions[:0] = step
            return actions
        moves = [((x, y, (d - 1) % 4), (LEFT,)), ((x, y, (d + 1) % 4), (RIGHT,))]
        front = grid.get(fx, fy)
        if blocked is None or not blocked((fx, fy)):
            if front is None or (front.overlap and front.kind not in ("lava", "goal")) or \
                    (front.kind == "goal" and (fx, fy) == target and not face):
                moves.append(((fx, fy, d), (FORWARD,)))
            elif _openable(task, front):
                moves.append(((fx, fy, d), (TOGGLE, FORWARD)))
        for nxt, step in moves:
            if nxt not in prev:
                prev[nxt] = (state, step)
                queue.append(nxt)
    return None


def find(task: MiniGridTask, kind: str, color: str | None = None) -> list[Pos]:
    return [o.pos for o in task.grid.objects() if o.kind == kind and (color is None or o.color == color)]


def run(task: MiniGridTask, actions: list[int]) -> None:
    for a in actions:
        if task.done:
            return
        task.step(a)


# Family class -> its win script, for missions other than reaching the goal square.
WIN_SCRIPTS: dict[type, Callable[[MiniGridTask], None]] = {}


def win_script(family: type) -> Callable[[Callable[[MiniGridTask], None]], Callable[[MiniGridTask], None]]:
    """Decorator: register ``fn(task)`` as the way ``solve`` wins episodes of ``family``."""
    def register(fn: Callable[[MiniGridTask], None]) -> Callable[[MiniGridTask], None]:
        WIN_SCRIPTS[family] = fn
        return fn
    return register


def solve(task: MiniGridTask, dynamic: bool = False) -> None:
    """Play the current episode to the goal (see the module docstring); stops early if stuck."""
    script = next((WIN_SCRIPTS[c] for c in type(task).__mro__ if c in WIN_SCRIPTS), None)
    if script is not None:
        script(task)
        return
    while not task.done:
        goals = find(task, "goal")
        if not goals:
            return
        if dynamic:
            _safe_step(task, goals[0])
            continue
        path = plan(task, goals[0])
        if path is not None:
            run(task, path)
            return
        if not _fetch_key(task):
            return


def _fetch_key(task: MiniGridTask) -> bool:
    """Pick up the key of some locked door (dropping whatever is carried first)."""
    for door in find(task, "door"):
        obj = task.grid.get(*door)
        if not obj.is_locked:
            continue
        for key in find(task, "key", obj.color):
            path = plan(task, key, face=True)
            if path is not None:
                run(task, path + [PICKUP])
                return task.carrying is not None and task.carrying.kind == "key"
    return False


def _safe_step(task: MiniGridTask, goal: Pos) -> None:
    """One move toward ``goal`` around the current obstacles; turns rather than walk into any."""
    occupied = {o.pos for o in task.grid.objects() if o.kind == "ball"}
    path = plan(task, goal, blocked=lambda p: p in occupied) or [LEFT]
    action = path[0]
    if action == FORWARD:
        front = task.grid.get(*task.front_pos)
        if front is not None and front.kind != "goal":
            action = LEFT
    task.step(action)


# -- helpers for win scripts of pick-up and unlock missions ------------------------------------------

def drop_beside(task: MiniGridTask) -> bool:
    """Drop what is carried on an empty cell to the left, right or behind, then turn back to the
    facing before; False (nothing done) if all three cells are taken."""
    x, y = task.agent_pos
    d = task.agent_dir
    for turn, back, nd in (([LEFT], [RIGHT], d - 1), ([RIGHT], [LEFT], d + 1),
                           ([LEFT, LEFT], [RIGHT, RIGHT], d + 2)):
        dx, dy = DIR_VEC[nd % 4]
        if task.grid.get(x + dx, y + dy) is None:
            run(task, turn + [DROP] + back)
            return True
    return False


def fetch(task: MiniGridTask, pos: Pos) -> bool:
    """Pick up the object at ``pos``: fetch the key of a locked door in the way first, and drop
    what is carried beside the object just before picking it up. True if it ends up carried."""
    obj = task.grid.get(*pos)
    path = plan(task, pos, face=True)
    if path is None:
        if task.carrying is not None and not drop_beside(task):
            return False
        if not _fetch_key(task):
            return False
        path = plan(task, pos, face=True)
        if path is None:
            return False
    run(task, path)
    if task.carrying is not None and not task.done and not drop_beside(task):
        return False
    run(task, [PICKUP])
    return obj is not None and task.carrying is obj


def open_door(task: MiniGridTask, pos: Pos) -> None:
    """Face the door at ``pos`` and TOGGLE it, fetching its key first if it is locked."""
    door = task.grid.get(*pos)
    carried = task.carrying
    if door.is_locked and not (isinstance(carried, Key) and carried.color == door.color):
        keys = find(task, "key", door.color)
        if not keys or not fetch(task, keys[0]):
            return
    path = plan(task, pos, face=True)
    if path is not None:
        run(task, path + [TOGGLE])


# -- clearing the way (ObstructedMaze): objects carried aside, keys taken out of boxes ----------------

_WORK = 50      # relaxed-path cost of a cell that needs work first: an object, a door still locked


def pick_up(task: MiniGridTask, obj: WorldObj, _depth: int = 0) -> bool:
    """Pick up ``obj`` wherever it lies, doing whatever the way needs: objects in it are carried
    aside, locked doors opened with their key (taken out of its box when hidden), what is
    carried put down first. True if ``obj`` ends up carried."""
    for _ in range(6):
        if task.carrying is obj:
            return True
        if task.done or obj.pos is None or _depth > 6:
            return False
        if task.carrying is not None:
            if not _drop_aside(task, set(_relaxed_path(task, obj.pos) or ())):
                return False
            continue
        if not reach(task, obj.pos, _depth):
            return False
        if task.carrying is None:
            task.step(PICKUP)
    return task.carrying is obj


def reach(task: MiniGridTask, pos: Pos, _depth: int = 0) -> bool:
    """Stand facing ``pos``, clearing the way as :func:`pick_up` does; True if it got there."""
    for _ in range(12):
        path = _relaxed_path(task, pos)
        if task.done or path is None:
            return False
        block = next((c for c in path[:-1] if _needs_work(task, task.grid.get(*c))), None)
        if block is None:
            steps = plan(task, pos, face=True)
            if steps is not None:
                run(task, steps)
            return steps is not None
        obj = task.grid.get(*block)
        if obj.kind == "door":
            if not _get_key(task, obj.color, _depth + 1):
                return False
        elif not pick_up(task, obj, _depth + 1) or not _drop_aside(task, set(path)):
            return False
    return False


def _needs_work(task: MiniGridTask, obj: WorldObj | None) -> bool:
    return obj is not None and not obj.overlap and not _openable(task, obj)


def _get_key(task: MiniGridTask, color: str, depth: int) -> bool:
    carried = task.carrying
    if isinstance(carried, Key) and carried.color == color:
        return True
    for obj in task.grid.objects():
        if isinstance(obj, Key) and obj.color == color:
            return pick_up(task, obj, depth)
    for obj in task.grid.objects():
        if obj.kind == "box" and isinstance(obj.contains, Key) and obj.contains.color == color:
            key = obj.contains
            if not reach(task, obj.pos, depth):
                return False
            task.step(TOGGLE)
            return pick_up(task, key, depth)
    return False


def _relaxed_path(task: MiniGridTask, target: Pos) -> list[Pos] | None:
    """The cells from the agent to ``target`` (included), fewest obstacles first: a cell holding
    an object or a door locked to the agent costs ``_WORK`` steps, walls, lava and goals block."""
    grid = task.grid
    start = task.agent_pos
    dist, prev = {start: 0}, {start: start}
    heap = [(0, start)]
    while heap:
        d, cell = heapq.heappop(heap)
        if cell == target:
            path = [cell]
            while prev[path[-1]] != start:
                path.append(prev[path[-1]])
            return path[::-1]
        if d > dist[cell]:
            continue
        for dx, dy in DIR_VEC:
            nxt = (cell[0] + dx, cell[1] + dy)
            obj = grid.get(*nxt)
            if nxt == target or obj is None or (obj.overlap and obj.kind not in ("lava", "goal")):
                cost = 1
            elif obj.pickup or obj.kind == "door":
                cost = 1 if _openable(task, obj) else _WORK
            else:
                continue
            if d + cost < dist.get(nxt, d + cost + 1):
                dist[nxt], prev[nxt] = d + cost, cell
                heapq.heappush(heap, (d + cost, nxt))
    return None


def _drop_aside(task: MiniGridTask, avoid: set[Pos]) -> bool:
    """Put down what is carried on the nearest empty cell off ``avoid`` and, if there is one,
    not beside a door (where it would block the way again)."""
    grid = task.grid

    def free(cell: Pos, strict: bool) -> bool:
        if not grid.inside(*cell) or grid.get(*cell) is not None or cell in avoid:
            return False
        return not strict or not any(isinstance(grid.get(cell[0] + dx, cell[1] + dy), Door)
                                     for dx, dy in DIR_VEC)

    for strict in (True, False):
        start = (*task.agent_pos, task.agent_dir)
        prev: dict = {start: None}
        queue = deque([start])
        while queue:
            state = queue.popleft()
            x, y, d = state
            front = (x + DIR_VEC[d][0], y + DIR_VEC[d][1])
            if free(front, strict):
                actions = [DROP]
                while prev[state] is not None:
                    state, step = prev[state]
                    actions.insert(0, step)
                run(task, actions)
                return task.carrying is None
            cell = grid.get(*front)
            moves = [((x, y, (d - 1) % 4), LEFT), ((x, y, (d + 1) % 4), RIGHT)]
            if cell is None or (cell.overlap and cell.kind not in ("lava", "goal")):
                moves.append(((*front, d), FORWARD))
            for nxt, step in moves:
                if nxt not in prev:
                    prev[nxt] = (state, step)
                    queue.append(nxt)
    return False
