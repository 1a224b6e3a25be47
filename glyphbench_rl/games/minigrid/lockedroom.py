"""LockedRoom: fetch the key from the room the mission names, unlock the locked room and reach
the goal inside (MiniGrid ``LockedRoomEnv``). lockedroom is MiniGrid-LockedRoom-v0: a 19x19
grid, a north-south hallway down the middle (where the agent starts) and three rooms on each
side behind closed doors of six different colours; one room is locked and holds the goal, the
key of its colour lies in another room, which the mission names by its door's colour.
Horizon 10 x 19 = 190.

As in MiniGrid, entering the goal wins (1 - 0.9 x turns/190); nothing else ends the episode.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from .engine import MiniGridParams, MiniGridTask, capped
from .world import COLOR_NAMES, Door, Goal, Key, Wall


@dataclass(frozen=True)
class LockedRoomParams(MiniGridParams):
    # the grid is size x size; odd, so the six rooms fit MiniGrid's layout
    size: int = param(19, 13, 31, odd=True)


@dataclass
class _Room:            # MiniGrid's LockedRoom (a room of the level)
    top: tuple[int, int]
    size: tuple[int, int]
    door_pos: tuple[int, int]
    color: str = ""
    locked: bool = False


class LockedRoom(MiniGridTask):
    title = "MiniGrid LockedRoom"
    about = ("A hallway runs north-south through the middle of the {size}x{size} grid (walls "
             "included), with three rooms on each side behind closed doors of six different "
             "colours. One room is locked and holds the green goal square; the key that opens it "
             "lies in the room the mission names. You carry one object at a time.")
    Params = LockedRoomParams
    kinds = ("goal", "door", "key")

    def _gen(self, rng: np.random.Generator) -> None:
        width = height = self.params.size
        grid = self.new_grid(width, height)
        for i in range(width):
            grid.set(i, 0, Wall())
            grid.set(i, height - 1, Wall())
        for j in range(height):
            grid.set(0, j, Wall())
            grid.set(width - 1, j, Wall())
        left, right = width // 2 - 2, width // 2 + 2      # the hallway's walls
        for j in range(height):
            grid.set(left, j, Wall())
            grid.set(right, j, Wall())
        rooms = []
        for n in range(3):
            j = n * (height // 3)
            for i in range(left):
                grid.set(i, j, Wall())
            for i in range(right, width):
                grid.set(i, j, Wall())
            size = (left + 1, height // 3 + 1)
            rooms.append(_Room((0, j), size, (left, j + 3)))
            rooms.append(_Room((right, j), size, (right, j + 3)))
        locked = self.rand_elem(rooms)
        locked.locked = True
        grid.set(*self._room_pos(locked), Goal())
        colors = set(COLOR_NAMES)
        for room in rooms:
            room.color = self.rand_elem(sorted(colors))
            colors.remove(room.color)
            grid.set(*room.door_pos, Door(room.color, is_locked=room.locked))
        while True:
            key_room = self.rand_elem(rooms)
            if key_room is not locked:
                break
        grid.set(*self._room_pos(key_room), Key(locked.color))
        self.place_agent(top=(left, 0), size=(right - left, height))
        self.rooms = rooms
        self.mission = (f"get the {locked.color} key from the {key_room.color} room, "
                        f"unlock the {locked.color} door and go to the goal")

    def _room_pos(self, room: _Room) -> tuple[int, int]:
        """MiniGrid's LockedRoom.rand_pos: a random cell inside the room's walls."""
        (x, y), (w, h) = room.top, room.size
        return self.rand_pos(x + 1, x + w - 1, y + 1, y + h - 1)


register_variants(LockedRoom, "MiniGrid", {
    "glyphbench/minigrid-lockedroom-v0": dict(max_turns=capped(10 * 19)),
})
