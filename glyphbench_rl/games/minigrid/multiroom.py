"""MultiRoom: a chain of rooms joined by closed doors; the goal is in the last room (MiniGrid
``MultiRoomEnv`` on a 25x25 grid, horizon 20 per room).

IDs: multiroom-n2-s4 is MiniGrid-MultiRoom-N2-S4-v0 (2 rooms of at most 4x4); multiroom-n4-s5
is MiniGrid-MultiRoom-N4-S5-v1 (4 rooms of at most 5x5: MiniGrid's -v0 of that name builds 6
rooms, kept only for backward compatibility); multiroom-n6 is MiniGrid-MultiRoom-N6-v0 (6 rooms
of at most 10x10).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from .engine import MiniGridParams, MiniGridTask, capped
from .world import COLOR_NAMES, Door, Goal, Wall

GRID_SIZE = 25


@dataclass(frozen=True)
class _Room:
    top: tuple[int, int]
    size: tuple[int, int]
    entry_door: tuple[int, int]


@dataclass(frozen=True)
class MultiRoomParams(MiniGridParams):
    rooms: int = param(2, 1, 10)
    max_room_size: int = param(10, 4, 12)     # rooms measure 4..max_room_size cells a side, walls included


class MultiRoom(MiniGridTask):
    title = "MiniGrid MultiRoom"
    about = ("{rooms} rooms in a row are joined by closed doors, which TOGGLE opens; the green "
             "goal square is in the last room.")
    Params = MultiRoomParams
    kinds = ("goal", "door")
    mission = "traverse the rooms to get to the goal"

    def _gen(self, rng: np.random.Generator) -> None:
        n = self.params.rooms
        rooms: list[_Room] = []
        while len(rooms) < n:     # MiniGrid keeps the longest chain of tries until one is long enough
            chain: list[_Room] = []
            entry = (self.rand_int(0, GRID_SIZE - 2), self.rand_int(0, GRID_SIZE - 2))
            self._place_room(n, chain, 4, self.params.max_room_size, 2, entry)
            if len(chain) > len(rooms):
                rooms = chain
        grid = self.new_grid(GRID_SIZE, GRID_SIZE)
        prev_color = None
        for idx, room in enumerate(rooms):
            (x, y), (w, h) = room.top, room.size
            for i in range(w):
                grid.set(x + i, y, Wall())
                grid.set(x + i, y + h - 1, Wall())
            for j in range(h):
                grid.set(x, y + j, Wall())
                grid.set(x + w - 1, y + j, Wall())
            if idx > 0:
                color = self.rand_elem(sorted(set(COLOR_NAMES) - {prev_color}))
                grid.set(*room.entry_door, Door(color))
                prev_color = color
        self.rooms = rooms
        self.place_agent(rooms[0].top, rooms[0].size)
        self.goal_pos = self.place_obj(Goal(), rooms[-1].top, rooms[-1].size)

    def _place_room(self, left: int, rooms: list[_Room], min_size: int, max_size: int,
                    entry_wall: int, entry: tuple[int, int]) -> bool:
        """MiniGrid's recursive _placeRoom: a room whose ``entry_wall`` side (0 east, 1 south,
        2 west, 3 north) holds the door at ``entry``, then the next rooms from one of its walls."""
        w, h = self.rand_int(min_size, max_size + 1), self.rand_int(min_size, max_size + 1)
        ex, ey = entry
        if not rooms:
            x, y = entry
        elif entry_wall == 0:
            x, y = ex - w + 1, self.rand_int(ey - h + 2, ey)
        elif entry_wall == 1:
            x, y = self.rand_int(ex - w + 2, ex), ey - h + 1
        elif entry_wall == 2:
            x, y = ex, self.rand_int(ey - h + 2, ey)
        else:
            x, y = self.rand_int(ex - w + 2, ex), ey
        if x < 0 or y < 0 or x + w > GRID_SIZE or y + h >= GRID_SIZE:
            return False
        for room in rooms[:-1]:   # rooms may share a wall with the previous one, never overlap
            (rx, ry), (rw, rh) = room.top, room.size
            if not (x + w < rx or rx + rw <= x or y + h < ry or ry + rh <= y):
                return False
        rooms.append(_Room((x, y), (w, h), entry))
        if left == 1:
            return True
        for _ in range(8):
            exit_wall = self.rand_elem(sorted({0, 1, 2, 3} - {entry_wall}))
            if exit_wall == 0:
                door = (x + w - 1, y + self.rand_int(1, h - 1))
            elif exit_wall == 1:
                door = (x + self.rand_int(1, w - 1), y + h - 1)
            elif exit_wall == 2:
                door = (x, y + self.rand_int(1, h - 1))
            else:
                door = (x + self.rand_int(1, w - 1), y)
            if self._place_room(left - 1, rooms, min_size, max_size, (exit_wall + 2) % 4, door):
                break
        return True


register_variants(MultiRoom, "MiniGrid", {
    "glyphbench/minigrid-multiroom-n2-s4-v0": dict(rooms=2, max_room_size=4, max_turns=capped(2 * 20)),
    "glyphbench/minigrid-multiroom-n4-s5-v0": dict(rooms=4, max_room_size=5, max_turns=capped(4 * 20)),
    "glyphbench/minigrid-multiroom-n6-v0": dict(rooms=6, max_room_size=10, max_turns=capped(6 * 20)),
})
