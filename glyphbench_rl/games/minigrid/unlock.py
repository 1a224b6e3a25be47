"""Unlock: open the locked door between two rooms with the key lying in yours (MiniGrid
``UnlockEnv``). unlock is MiniGrid-Unlock-v0: two 6x6 rooms side by side (an 11x6 grid), the
door in their shared wall locked and its key in the agent's (left) room; horizon 8 x 6^2 = 288.

As in MiniGrid the episode is won by the TOGGLE that opens the door (1 - 0.9 x turns/288) and
otherwise runs to the horizon with 0; nothing else ends it.
"""

from __future__ import annotations

import numpy as np

from ...core import register_variants
from .engine import TOGGLE, capped
from .rooms import RoomGridTask, TwoRoomParams
from .solver import open_door, win_script


class Unlock(RoomGridTask):
    title = "MiniGrid Unlock"
    about = ("Two rooms of {room_size}x{room_size} cells (walls included) are joined by a locked "
             "door; its key, of the door's colour, lies in your room.")
    rewards = ("opening the door gives 1 - {decay:g} x (turns used / {max_turns}); running out of "
               "time gives 0.")
    ends = "when you open the door"
    Params = TwoRoomParams
    kinds = ("door", "key")
    mission = "open the door"

    def _gen(self, rng: np.random.Generator) -> None:
        super()._gen(rng)
        self.door, _ = self.add_door(0, 0, 0, locked=True)
        self.add_object(0, 0, "key", self.door.color)
        self.place_agent_in_room(0, 0)
        self.mission = "open the door"

    def _act(self, action: int) -> None:
        super()._act(action)
        if action == TOGGLE and self.door.is_open:     # MiniGrid's UnlockEnv.step
            self.succeed("The door is open.")


@win_script(Unlock)
def _open_the_door(task: Unlock) -> None:
    open_door(task, task.door.pos)


register_variants(Unlock, "MiniGrid", {
    "glyphbench/minigrid-unlock-v0": dict(max_turns=capped(8 * 6 * 6)),
})
