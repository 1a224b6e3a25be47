"""ObstructedMaze: pick up the blue ball in a maze of 6x6 rooms whose doors are locked, with the
keys hidden in grey boxes and green balls standing in front of the doors (MiniGrid
``ObstructedMazeEnv``). Picking up the blue ball wins; the horizon is MiniGrid's
4 x rooms-to-visit x 36, capped at 512.

IDs -> MiniGrid envs (horizon):
  obstructedmaze-1dl    MiniGrid-ObstructedMaze-1Dl-v0     2x1 rooms, key on the floor     (288)
  obstructedmaze-1dlh   MiniGrid-ObstructedMaze-1Dlh-v0    key in a box                    (288)
  obstructedmaze-1dlhb  MiniGrid-ObstructedMaze-1Dlhb-v0   key in a box, door blocked      (288)
  obstructedmaze-2dl    MiniGrid-ObstructedMaze-2Dl-v0     3x3 rooms, one quarter, start in
                                                           the east room, key on the floor (512)
  obstructedmaze-2dlh   MiniGrid-ObstructedMaze-2Dlh-v0    keys in boxes                   (512)
  obstructedmaze-2dlhb  MiniGrid-ObstructedMaze-2Dlhb-v1   keys in boxes, doors blocked    (512)
  obstructedmaze-1q     MiniGrid-ObstructedMaze-1Q-v1      as 2dlhb, start in the middle   (512)
  obstructedmaze-2q     MiniGrid-ObstructedMaze-2Q-v1      two quarters                    (512)
  obstructedmaze-full   MiniGrid-ObstructedMaze-Full-v1    all four quarters               (512)

Which MiniGrid version: -v1 (``ObstructedMaze_Full_V1``) places the keys after all doors and
blocking balls; in -v0 a blocking ball could be written over a key's box and leave the level
unsolvable. MiniGrid registers -v1 only for 2Dlhb, 1Q, 2Q and Full, the levels where that can
happen, and those follow -v1 here; the others exist only as -v0 (no blocking ball, or the
only one is placed before its key) and follow -v0.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param, require
from .engine import PICKUP, capped
from .rooms import RoomGridParams, RoomGridTask
from .solver import pick_up, win_script
from .world import COLOR_NAMES, DIR_VEC, Ball, Box, Key

TARGET, BLOCKER, BOX = COLOR_NAMES[0], COLOR_NAMES[1], COLOR_NAMES[2]   # blue, green, grey
SIDE_ROOMS = ((2, 1), (1, 2), (0, 1), (1, 0))
CORNERS = ((2, 0), (2, 2), (0, 2), (0, 0))


@dataclass(frozen=True)
class ObstructedMazeParams(RoomGridParams):
    room_size: int = 6
    num_rows: int = 3
    num_cols: int = 3
    quarters: int = param(4, 0, 4)      # 0: MiniGrid's 1Dl* (two rooms, one locked door); 1-4: the 3x3 maze
    agent_room: tuple[int, int] = param((1, 1), 0, 2)   # the 3x3 maze's start room (column, row)
    key_in_box: bool = param(True)
    blocked: bool = param(True)
    keys_last: bool = param(True)       # MiniGrid's -v1: keys placed after all doors and blocking balls

    def check(self) -> None:
        shape = (1, 2) if self.quarters == 0 else (3, 3)
        require((self.num_rows, self.num_cols, self.room_size) == (*shape, 6), "num_rows, num_cols, room_size",
                f"{shape[0]}, {shape[1]}, 6 for quarters={self.quarters}",
                (self.num_rows, self.num_cols, self.room_size))


class ObstructedMaze(RoomGridTask):
    title = "MiniGrid ObstructedMaze"
    about = ("The world is {num_cols}x{num_rows} rooms ({room_size}x{room_size} cells, walls "
             "included) joined by doors; the blue ball is in {where}. Locked doors open only for the "
             "key of their colour, which lies on the near side of its door{hidden}.{blocked_text} "
             "You carry one object at a time.")
    rewards = ("picking up the blue ball gives 1 - {decay:g} x (turns used / {max_turns}); running out "
               "of time gives 0.")
    ends = "when you pick up the blue ball"
    Params = ObstructedMazeParams
    kinds = ("door", "key", "ball", "box")
    mission = f"pick up the {TARGET} ball"

    def family_fields(self) -> dict:
        p = self.params
        return {"where": "the other room" if p.quarters == 0 else "one of the corner rooms",
                "hidden": " inside a grey box (TOGGLE opens a box)" if p.key_in_box else "",
                "blocked_text": " A green ball stands in front of each locked door: move it away first."
                                if p.blocked else ""}

    def _gen(self, rng: np.random.Generator) -> None:
        super()._gen(rng)
        p = self.params
        self.door_colors = self.rand_subset(COLOR_NAMES, len(COLOR_NAMES))
        if p.quarters == 0:                              # ObstructedMaze_1Dlhb
            self._door(0, 0, 0, self.door_colors[0], locked=True)
            self.pickup_target, _ = self.add_object(1, 0, "ball", TARGET)
            self.place_agent_in_room(0, 0)
            return
        for i, side in enumerate(SIDE_ROOMS[:p.quarters]):   # ObstructedMaze_Full (_V1)
            self._door(1, 1, i, self.door_colors[i], locked=False)
            sides = [((i + k) % 4, self.door_colors[(i + k) % len(self.door_colors)]) for k in (-1, 1)]
            for idx, color in sides:
                self._door(*side, idx, color, locked=True, with_key=not p.keys_last)
            if p.keys_last:
                for _, color in sides:
                    self._add_key(*side, color)
        ball_room = self.rand_elem(CORNERS[:p.quarters])
        self.pickup_target, _ = self.add_object(*ball_room, "ball", TARGET)
        self.place_agent_in_room(*p.agent_room)

    def _door(self, i: int, j: int, idx: int, color: str, locked: bool, with_key: bool = True) -> None:
        """MiniGrid's ObstructedMazeEnv.add_door: the door, the blocking ball in front of it on
        room (i, j)'s side, then (unless keys come last) the key, in a box if hidden."""
        p = self.params
        _, (x, y) = self.add_door(i, j, idx, color, locked=locked)
        blocked = locked and p.blocked
        if blocked:
            dx, dy = DIR_VEC[idx]
            self.put_obj(Ball(BLOCKER), x - dx, y - dy)
        if locked and with_key:
            self._add_key(i, j, color)

    def _add_key(self, i: int, j: int, color: str) -> None:
        key = Key(color)
        self.place_in_room(i, j, Box(BOX, contains=key) if self.params.key_in_box else key)

    def _act(self, action: int) -> None:
        super()._act(action)
        if action == PICKUP and self.carrying is self.pickup_target:
            self.succeed("You picked up the blue ball.")


@win_script(ObstructedMaze)
def _clear_the_way_to_the_blue_ball(task: ObstructedMaze) -> None:
    pick_up(task, task.pickup_target)


def _variant(quarters: int, agent_room=(1, 1), key_in_box=True, blocked=True, keys_last=True, rooms=2):
    shape = dict(num_rows=1, num_cols=2) if quarters == 0 else {}
    return dict(quarters=quarters, agent_room=agent_room, key_in_box=key_in_box, blocked=blocked,
                keys_last=keys_last, **shape, max_turns=capped(4 * rooms * 6 * 6))


register_variants(ObstructedMaze, "MiniGrid", {
    "glyphbench/minigrid-obstructedmaze-1dl-v0": _variant(0, key_in_box=False, blocked=False,
                                                          keys_last=False),
    "glyphbench/minigrid-obstructedmaze-1dlh-v0": _variant(0, blocked=False, keys_last=False),
    "glyphbench/minigrid-obstructedmaze-1dlhb-v0": _variant(0, keys_last=False),
    "glyphbench/minigrid-obstructedmaze-2dl-v0": _variant(1, (2, 1), False, False, False, rooms=4),
    "glyphbench/minigrid-obstructedmaze-2dlh-v0": _variant(1, (2, 1), True, False, False, rooms=4),
    "glyphbench/minigrid-obstructedmaze-2dlhb-v0": _variant(1, (2, 1), rooms=4),
    "glyphbench/minigrid-obstructedmaze-1q-v0": _variant(1, (1, 1), rooms=5),
    "glyphbench/minigrid-obstructedmaze-2q-v0": _variant(2, (2, 1), rooms=11),
    "glyphbench/minigrid-obstructedmaze-full-v0": _variant(4, rooms=25),
})
