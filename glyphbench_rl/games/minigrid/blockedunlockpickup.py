"""BlockedUnlockPickup: move the ball blocking the locked door, unlock it and pick up the box
behind it (MiniGrid ``BlockedUnlockPickupEnv``). blockedunlockpickup is
MiniGrid-BlockedUnlockPickup-v0: UnlockPickup's two 6x6 rooms with a ball of random colour on
the cell in front of the door on the agent's side; horizon 16 x 6^2 = 576 in MiniGrid, capped
at 512 here (so the win reward is 1 - 0.9 x turns/512).

As in MiniGrid only picking up the box wins; picking up the ball or the key does not end the
episode, and a box opened with TOGGLE vanishes, leaving the episode to run out with 0.
"""

from __future__ import annotations

import numpy as np

from ...core import register_variants
from .engine import capped
from .rooms import PickupTask, TwoRoomParams
from .solver import drop_beside, fetch, win_script
from .world import Ball


class BlockedUnlockPickup(PickupTask):
    title = "MiniGrid BlockedUnlockPickup"
    about = ("Two rooms of {room_size}x{room_size} cells (walls included) are joined by a locked "
             "door whose key lies in your room, and a ball blocks the door on your side; the box to "
             "pick up is in the other room. You carry one object at a time, and opening a box "
             "(TOGGLE) destroys it.")
    Params = TwoRoomParams             # UnlockPickup's two rooms
    kinds = ("door", "key", "ball", "box")
    target_kind = "box"

    def _gen(self, rng: np.random.Generator) -> None:
        super()._gen(rng)                              # the two rooms, then MiniGrid's order
        self.obj, _ = self.add_object(1, 0, kind="box")
        door, (x, y) = self.add_door(0, 0, 0, locked=True)
        self.ball = Ball(self.rand_color())
        self.grid.set(x - 1, y, self.ball)
        self.add_object(0, 0, "key", door.color)
        self.place_agent_in_room(0, 0)
        self.mission = f"pick up the {self.obj.color} {self.obj.kind}"


@win_script(BlockedUnlockPickup)
def _move_the_ball_then_pick_up_the_box(task: BlockedUnlockPickup) -> None:
    if task.ball.pos is not None and fetch(task, task.ball.pos):
        drop_beside(task)       # to the side: the cell in front of the door stays free
    if task.obj.pos is not None:
        fetch(task, task.obj.pos)


register_variants(BlockedUnlockPickup, "MiniGrid", {
    "glyphbench/minigrid-blockedunlockpickup-v0": dict(max_turns=capped(16 * 6 * 6)),
})
