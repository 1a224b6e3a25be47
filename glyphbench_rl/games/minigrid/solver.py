"""Search over MiniGrid states, for tests, baselines and generators that want a solvability check.

``plan`` is a breadth-first search over (x, y, facing) with MiniGrid's moves, reading the true
world (not the agent's view). Closed doors on the way are opened with TOGGLE, locked ones too
when the agent carries their key. ``solve`` plays a whole episode with it: walk to the goal,
fetching the key of a locked door first when one is in the way, and re-planning every turn in
worlds that move (dynamic obstacles), never walking into an occupied cell.
"""

from __future__ import annotations

from collections import deque
from typing import Callable

from .engine import FORWARD, LEFT, PICKUP, RIGHT, TOGGLE, MiniGridTask
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


def solve(task: MiniGridTask, dynamic: bool = False) -> None:
    """Play the current episode to the goal (see the module docstring); stops early if stuck."""
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
