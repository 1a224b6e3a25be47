"""KeyCorridor: find the key in a side room, unlock the door across the hallway and pick up the
object behind it (MiniGrid ``KeyCorridorEnv``).

IDs: keycorridor-sSrR is MiniGrid-KeyCorridorSSRR-v0, i.e. ``KeyCorridorEnv(room_size=S,
num_rows=R)``: three columns of R rooms of SxS cells (walls included); the middle column is one
hallway where the agent starts, a locked door on its east side hides a ball, and the key of
that door lies in a room of the west column. ``connect_all`` then adds unlocked doors of random
colours until every room is reachable. Horizon 30 x S^2, capped at 512: 270 (s3r1, s3r2, s3r3),
480 (s4r3), 512 (s5r3, s6r3; MiniGrid: 750 and 1080).

As in MiniGrid only picking up that ball wins (1 - 0.9 x turns/max_turns); picking up the key
(or anything else) does not end the episode.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from .engine import capped
from .rooms import PickupTask, RoomGridParams
from .solver import fetch, win_script


@dataclass(frozen=True)
class KeyCorridorParams(RoomGridParams):
    room_size: int = 6
    num_rows: int = 3
    num_cols: int = param(3, choices=(3,))     # MiniGrid's RoomGrid default; the level needs three
    obj_type: str = param("ball", choices=("ball", "key", "box"))   # the object behind the locked door


class KeyCorridor(PickupTask):
    title = "MiniGrid KeyCorridor"
    about = ("Three columns of {num_rows} rooms of {room_size}x{room_size} cells (walls included): "
             "you start in the middle column, an open hallway. A locked door on its east side hides "
             "the {obj_type} to pick up; the key of that door, of the door's colour, lies in one of "
             "the western rooms, behind closed doors. You carry one object at a time.")
    Params = KeyCorridorParams
    kinds = ("door", "key", "ball", "box")

    def _gen(self, rng: np.random.Generator) -> None:
        super()._gen(rng)
        rows = self.params.num_rows
        for j in range(1, rows):                       # the middle column becomes a hallway
            self.remove_wall(1, j, 3)
        room_idx = self.rand_int(0, rows)
        door, _ = self.add_door(2, room_idx, 2, locked=True)
        self.obj, _ = self.add_object(2, room_idx, kind=self.params.obj_type)
        self.add_object(0, self.rand_int(0, rows), "key", door.color)
        self.place_agent_in_room(1, rows // 2)
        self.connect_all()
        self.mission = f"pick up the {self.obj.color} {self.obj.kind}"

    def family_fields(self) -> dict:
        return {"target_kind": self.params.obj_type}


@win_script(KeyCorridor)
def _pick_up_the_object(task: KeyCorridor) -> None:
    if task.obj.pos is not None:
        fetch(task, task.obj.pos)


register_variants(KeyCorridor, "MiniGrid", {
    f"glyphbench/minigrid-keycorridor-s{s}r{r}-v0": dict(room_size=s, num_rows=r, max_turns=capped(30 * s * s))
    for s, r in ((3, 1), (3, 2), (3, 3), (4, 3), (5, 3), (6, 3))
})
