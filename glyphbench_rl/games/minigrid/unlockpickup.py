"""UnlockPickup: unlock the door to the next room and pick up the box there (MiniGrid
``UnlockPickupEnv``). unlockpickup is MiniGrid-UnlockPickup-v0: two 6x6 rooms side by side (an
11x6 grid), a box of random colour in the right room, the shared door locked and its key in the
agent's (left) room; horizon 8 x 6^2 = 288.

As in MiniGrid only picking up that box wins (1 - 0.9 x turns/288); picking up anything else
(the key) does not end the episode, and a box opened with TOGGLE vanishes (it is empty), which
leaves the episode to run out with 0.
"""

from __future__ import annotations

import numpy as np

from ...core import register_variants
from .engine import capped
from .rooms import PickupTask, TwoRoomParams
from .solver import fetch, win_script


class UnlockPickup(PickupTask):
    title = "MiniGrid UnlockPickup"
    about = ("Two rooms of {room_size}x{room_size} cells (walls included) are joined by a locked "
             "door whose key lies in your room; the box to pick up is in the other room. You carry "
             "one object at a time, and opening a box (TOGGLE) destroys it.")
    Params = TwoRoomParams             # the same two-room layout as Unlock
    kinds = ("door", "key", "box")
    target_kind = "box"

    def _gen(self, rng: np.random.Generator) -> None:
        super()._gen(rng)
        self.obj, _ = self.add_object(1, 0, kind="box")
        door, _ = self.add_door(0, 0, 0, locked=True)
        self.add_object(0, 0, "key", door.color)
        self.place_agent_in_room(0, 0)
        self.mission = f"pick up the {self.obj.color} {self.obj.kind}"


@win_script(UnlockPickup)
def _pick_up_the_box(task: UnlockPickup) -> None:
    if task.obj.pos is not None:
        fetch(task, task.obj.pos)


register_variants(UnlockPickup, "MiniGrid", {
    "glyphbench/minigrid-unlockpickup-v0": dict(max_turns=capped(8 * 6 * 6)),
})
