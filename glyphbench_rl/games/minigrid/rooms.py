"""Room grids: MiniGrid's ``RoomGrid`` (``minigrid/core/roomgrid.py``), for the families built on it
(Unlock, UnlockPickup, BlockedUnlockPickup, KeyCorridor, ObstructedMaze ...).

The world is ``num_cols`` x ``num_rows`` square rooms of ``room_size`` cells (walls included,
neighbours sharing a wall). Each shared wall gets a door position drawn in advance; doors are
added with ``add_door``, walls knocked down with ``remove_wall``, objects dropped with
``add_object``. Every helper draws from the generator exactly as MiniGrid's does, so a family
ported call for call from MiniGrid builds MiniGrid's level for the same seed. A family
subclasses :class:`RoomGridTask`, calls ``super()._gen(rng)`` first in its own ``_gen`` and
takes its sizes from ``RoomGridParams`` fields. MiniGrid's RoomGrid.place_agent(i, j) is
``place_agent_in_room`` here (the plain ``place_agent`` keeps the base signature).

Shared by several families: ``TwoRoomParams`` (two 6x6 rooms side by side: Unlock,
UnlockPickup, BlockedUnlockPickup) and ``PickupTask`` (won by picking up ``self.obj``:
KeyCorridor, UnlockPickup, BlockedUnlockPickup).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np

from ...core.params import param
from .engine import PICKUP, MiniGridParams, MiniGridTask
from .world import COLOR_NAMES, PORTABLE, Door, WorldObj

Pos = tuple[int, int]


def reject_next_to(task: MiniGridTask, pos: Pos) -> bool:
    """MiniGrid's filter keeping objects off the agent's start cell and its four neighbours."""
    sx, sy = task.agent_pos
    return abs(sx - pos[0]) + abs(sy - pos[1]) < 2


@dataclass(eq=False)
class Room:
    top: Pos
    size: Pos
    doors: list = field(default_factory=lambda: [None] * 4)        # Door, True (no wall) or None
    door_pos: list = field(default_factory=lambda: [None] * 4)     # 0 east, 1 south, 2 west, 3 north
    neighbors: list = field(default_factory=lambda: [None] * 4)
    locked: bool = False
    objs: list = field(default_factory=list)

    def pos_inside(self, x: int, y: int) -> bool:
        return (self.top[0] <= x < self.top[0] + self.size[0]
                and self.top[1] <= y < self.top[1] + self.size[1])


@dataclass(frozen=True)
class RoomGridParams(MiniGridParams):
    room_size: int = param(7, 3, 16)
    num_rows: int = param(3, 1, 8)
    num_cols: int = param(3, 1, 8)


@dataclass(frozen=True)
class TwoRoomParams(RoomGridParams):
    """Two rooms of 6x6 cells side by side: Unlock, UnlockPickup, BlockedUnlockPickup."""
    room_size: int = 6
    num_rows: int = 1
    num_cols: int = param(2, 2, 8)


class RoomGridTask(MiniGridTask):
    Params = RoomGridParams

    def _gen(self, rng: np.random.Generator) -> None:
        p = self.params
        step = p.room_size - 1
        self.new_grid(step * p.num_cols + 1, step * p.num_rows + 1)
        self.room_grid = [[Room((i * step, j * step), (p.room_size, p.room_size)) for i in range(p.num_cols)]
                          for j in range(p.num_rows)]
        for row in self.room_grid:
            for room in row:
                self.grid.wall_rect(*room.top, *room.size)
        for j in range(p.num_rows):
            for i in range(p.num_cols):
                room = self.room_grid[j][i]
                x_l, y_l = room.top[0] + 1, room.top[1] + 1
                x_m, y_m = room.top[0] + room.size[0] - 1, room.top[1] + room.size[1] - 1
                if i < p.num_cols - 1:
                    room.neighbors[0] = self.room_grid[j][i + 1]
                    room.door_pos[0] = (x_m, self.rand_int(y_l, y_m))
                if j < p.num_rows - 1:
                    room.neighbors[1] = self.room_grid[j + 1][i]
                    room.door_pos[1] = (self.rand_int(x_l, x_m), y_m)
                if i > 0:
                    room.neighbors[2] = self.room_grid[j][i - 1]
                    room.door_pos[2] = room.neighbors[2].door_pos[0]
                if j > 0:
                    room.neighbors[3] = self.room_grid[j - 1][i]
                    room.door_pos[3] = room.neighbors[3].door_pos[1]
        # MiniGrid parks the agent in the middle room until the family places it: objects
        # placed before that avoid this cell (and reject_next_to measures from it).
        self.agent_pos = ((p.num_cols // 2) * step + p.room_size // 2, (p.num_rows // 2) * step + p.room_size // 2)
        self.agent_dir = 0

    def room_from_pos(self, x: int, y: int) -> Room:
        step = self.params.room_size - 1
        return self.room_grid[y // step][x // step]

    def get_room(self, i: int, j: int) -> Room:
        return self.room_grid[j][i]

    def place_in_room(self, i: int, j: int, obj: WorldObj) -> tuple[WorldObj, Pos]:
        room = self.get_room(i, j)
        pos = self.place_obj(obj, room.top, room.size, reject_fn=reject_next_to, max_tries=1000)
        room.objs.append(obj)
        return obj, pos

    def add_object(self, i: int, j: int, kind: str | None = None,
                   color: str | None = None) -> tuple[WorldObj, Pos]:
        if kind is None:
            kind = self.rand_elem(list(PORTABLE))
        if color is None:
            color = self.rand_color()
        obj = PORTABLE[kind](color)
        return self.place_in_room(i, j, obj)

    def add_door(self, i: int, j: int, door_idx: int | None = None, color: str | None = None,
                 locked: bool | None = None) -> tuple[Door, Pos]:
        room = self.get_room(i, j)
        if door_idx is None:
            while True:
                door_idx = self.rand_int(0, 4)
                if room.neighbors[door_idx] and room.doors[door_idx] is None:
                    break
        if color is None:
            color = self.rand_color()
        if locked is None:
            locked = self.rand_bool()
        if room.doors[door_idx] is not None:
            raise ValueError(f"room ({i}, {j}) already has a door on side {door_idx}")
        room.locked = locked
        door = Door(color, is_locked=locked)
        pos = room.door_pos[door_idx]
        self.grid.set(*pos, door)
        room.doors[door_idx] = door
        room.neighbors[door_idx].doors[(door_idx + 2) % 4] = door
        return door, pos

    def remove_wall(self, i: int, j: int, wall_idx: int) -> None:
        room = self.get_room(i, j)
        if room.doors[wall_idx] is not None or room.neighbors[wall_idx] is None:
            raise ValueError(f"room ({i}, {j}) side {wall_idx} has a door or no neighbour")
        (tx, ty), (w, h) = room.top, room.size
        if wall_idx == 0:
            cells = [(tx + w - 1, ty + k) for k in range(1, h - 1)]
        elif wall_idx == 1:
            cells = [(tx + k, ty + h - 1) for k in range(1, w - 1)]
        elif wall_idx == 2:
            cells = [(tx, ty + k) for k in range(1, h - 1)]
        else:
            cells = [(tx + k, ty) for k in range(1, w - 1)]
        for cell in cells:
            self.grid.set(*cell, None)
        room.doors[wall_idx] = True
        room.neighbors[wall_idx].doors[(wall_idx + 2) % 4] = True

    def place_agent_in_room(self, i: int | None = None, j: int | None = None,
                            rand_dir: bool = True) -> Pos:
        """MiniGrid's RoomGrid.place_agent: a random cell of room (i, j) not facing an object."""
        if i is None:
            i = self.rand_int(0, self.params.num_cols)
        if j is None:
            j = self.rand_int(0, self.params.num_rows)
        room = self.room_grid[j][i]
        while True:
            self.place_agent(room.top, room.size, rand_dir, max_tries=1000)
            front = self.grid.get(*self.front_pos)
            if front is None or front.kind == "wall":
                return self.agent_pos

    def connect_all(self, door_colors=COLOR_NAMES, max_itrs: int = 5000) -> list[Door]:
        """Add unlocked doors at random until every room is reachable from the agent's."""
        start = self.room_from_pos(*self.agent_pos)
        added = []
        total = self.params.num_rows * self.params.num_cols
        for _ in range(max_itrs + 1):
            if len(self._reachable_rooms(start)) == total:
                return added
            i, j, k = (self.rand_int(0, self.params.num_cols), self.rand_int(0, self.params.num_rows),
                       self.rand_int(0, 4))
            room = self.get_room(i, j)
            if not room.door_pos[k] or room.doors[k]:
                continue
            if room.locked or room.neighbors[k].locked:
                continue
            door, _ = self.add_door(i, j, k, self.rand_elem(door_colors), False)
            added.append(door)
        raise RecursionError("connect_all failed")

    def _reachable_rooms(self, start: Room) -> set:
        seen, stack = set(), [start]
        while stack:
            room = stack.pop()
            if id(room) in seen:
                continue
            seen.add(id(room))
            stack.extend(room.neighbors[k] for k in range(4) if room.doors[k])
        return seen

    def add_distractors(self, i: int | None = None, j: int | None = None, num_distractors: int = 10,
                        all_unique: bool = True) -> list[WorldObj]:
        objs = [(o.kind, o.color) for row in self.room_grid for room in row for o in room.objs]
        dists = []
        while len(dists) < num_distractors:
            color = self.rand_elem(COLOR_NAMES)
            kind = self.rand_elem(list(PORTABLE))
            if all_unique and (kind, color) in objs:
                continue
            room_i = self.rand_int(0, self.params.num_cols) if i is None else i
            room_j = self.rand_int(0, self.params.num_rows) if j is None else j
            dist, _ = self.add_object(room_i, room_j, kind, color)
            objs.append((kind, color))
            dists.append(dist)
        return dists


class PickupTask(RoomGridTask):
    """A room-grid level won by picking up ``self.obj``, the object the mission names (MiniGrid's
    step compares ``carrying == obj``); picking up anything else does not end the episode."""

    rewards = ("picking up the {target_kind} named in the mission gives 1 - {decay:g} x (turns used "
               "/ {max_turns}); running out of time gives 0.")
    ends = "when you pick up the {target_kind} named in the mission"
    target_kind: ClassVar[str] = "object"      # what the prompt calls the object to pick up

    def family_fields(self) -> dict:
        return {"target_kind": self.target_kind}

    def _act(self, action: int) -> None:
        super()._act(action)
        if action == PICKUP and self.carrying is self.obj:
            self.succeed("That was the mission.")
