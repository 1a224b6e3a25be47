"""Lane movement and auto-scroll for the Procgen games whose world moves on its own.

- ``Strip`` / ``LaneLevel``: a Frogger level, rows of ``common.lanes.Lane`` (or safe rows). A
  lane's cells are a pure function of the tick, so ``LaneLevel.move`` is a pure step of the
  player (what Leaper plays) and ``LaneLevel.solve`` searches (row, column, tick mod cycle) with
  that same step: a level is kept only if the search reaches the goal row.
- ``fall_turn`` / ``fall_route``: a course the player falls through one row a turn (two when
  hurrying) while moving sideways, stopped by walls (Fruitbot). ``fall_route`` searches it for a
  clean run: no wall bumped, no cell of ``avoid`` entered.
- ``LeadView``: a view window that keeps the player ``lead`` rows from its top, so a falling
  player sees what is coming rather than where it has been.
"""

from __future__ import annotations

from collections import deque
from math import lcm
from typing import Callable, ClassVar, Sequence

from ..common.lanes import Lane
from .engine import DELTAS, OPEN, ProcgenTask

__all__ = ["OPEN", "Strip", "LaneLevel", "fall_turn", "fall_route", "LeadView"]
Cell = tuple[int, int]


class Strip:
    """One moving row: a ``Lane`` plus what it does to the player. ``deadly``: cells that kill
    (cars, water); ``ride``: the player standing on it moves with it (logs)."""

    __slots__ = ("lane", "deadly", "ride", "marker")

    def __init__(self, lane: Lane, deadly: str, ride: bool, marker: str) -> None:
        self.lane, self.deadly, self.ride, self.marker = lane, deadly, ride, marker


class LaneLevel:
    """Rows ``0..height-1`` of ``width`` cells: each a ``Strip`` or ``None`` (a safe row)."""

    def __init__(self, strips: Sequence[Strip | None], width: int) -> None:
        self.strips, self.width, self.height = list(strips), width, len(strips)
        self.cycle = lcm(1, *(s.lane.period * width for s in self.strips if s))

    def move(self, r: int, c: int, tick: int, action: int) -> tuple[int, int, str]:
        """The player at (r, c) after ``tick`` takes ``action`` (an index into ``DELTAS``), then
        the lanes move (tick + 1). Returns the new cell and "" or the cause of death: "car"
        (walked into one, or one drove into you), "water", "edge" (a log carried you off)."""
        nr, nc = r + DELTAS[action][0], c + DELTAS[action][1]
        if not (0 <= nr < self.height and 0 <= nc < self.width):
            nr, nc = r, c
        strip = self.strips[nr]
        if strip is None:
            return nr, nc, ""
        lane = strip.lane
        if strip.ride:
            if lane.row(tick)[nc] in strip.deadly:
                return nr, nc, "water"
            nc += lane.moves_at(tick + 1)
            return nr, nc, "" if 0 <= nc < self.width else "edge"
        if lane.row(tick)[nc] in strip.deadly or lane.row(tick + 1)[nc] in strip.deadly:
            return nr, nc, "car"
        return nr, nc, ""

    def solve(self, start: Cell, goal_row: int = 0, tick: int = 0) -> list[int] | None:
        """The shortest action list from ``start`` at ``tick`` to ``goal_row`` (breadth-first
        over (row, column, tick mod cycle) with ``move``), or None if there is none."""
        first = (start[0], start[1], tick % self.cycle)
        parents: dict[tuple[int, int, int], tuple[tuple[int, int, int], int] | None] = {first: None}
        queue = deque([(start[0], start[1], tick)])
        while queue:
            r, c, t = queue.popleft()
            if r == goal_row:
                state, actions = (r, c, t % self.cycle), []
                while parents[state] is not None:
                    state, action = parents[state]
                    actions.append(action)
                return actions[::-1]
            for action in range(len(DELTAS)):
                nr, nc, death = self.move(r, c, t, action)
                key = (nr, nc, (t + 1) % self.cycle)
                if not death and key not in parents:
                    parents[key] = ((r, c, t % self.cycle), action)
                    queue.append((nr, nc, t + 1))
        return None


def fall_turn(is_wall: Callable[[int, int], bool], height: int, width: int, r: int, c: int,
              dc: int, fall: int) -> tuple[int, int, bool, list[Cell]]:
    """One turn of a falling player: a sideways step ``dc`` (the edges stop it, a wall stops it
    with a bump), then ``fall`` rows down, one at a time, until a wall below stops it (a bump).
    Returns the new cell, whether it bumped, and the cells entered in order."""
    entered, bumped = [], False
    if dc:
        nc = c + dc
        if 0 <= nc < width:
            if is_wall(r, nc):
                bumped = True
            else:
                c = nc
                entered.append((r, c))
    for _ in range(fall):
        if r + 1 >= height:
            break
        if is_wall(r + 1, c):
            bumped = True
            break
        r += 1
        entered.append((r, c))
    return r, c, bumped, entered


def fall_route(is_wall: Callable[[int, int], bool], avoid: Callable[[int, int], bool],
               height: int, width: int, start: Cell,
               moves: Sequence[tuple[int, int, int]]) -> list[int] | None:
    """The shortest clean run from ``start`` to the last row: actions from ``moves`` (action,
    sideways step, rows fallen) that never bump a wall or enter a cell of ``avoid``; None if
    there is none. The course is still, so the state is the cell alone."""
    parents: dict[Cell, tuple[Cell, int] | None] = {start: None}
    queue = deque([start])
    while queue:
        cell = queue.popleft()
        if cell[0] == height - 1:
            actions = []
            while parents[cell] is not None:
                cell, action = parents[cell]
                actions.append(action)
            return actions[::-1]
        for action, dc, fall in moves:
            r, c, bumped, entered = fall_turn(is_wall, height, width, *cell, dc, fall)
            if bumped or (r, c) in parents or any(avoid(*x) for x in entered):
                continue
            parents[(r, c)] = (cell, action)
            queue.append((r, c))
    return None


class LeadView(ProcgenTask):
    """A ProcgenTask whose view keeps the player ``lead`` rows below the view's top edge."""

    lead: ClassVar[int] = 3

    def _origin(self) -> tuple[int, int]:
        rows = self._rows()
        r, c = self.pos
        return (min(max(r - self.lead, 0), max(len(rows) - self.view_h, 0)),
                min(max(c - self.view_w // 2, 0), max(len(rows[0]) - self.view_w, 0)))
