"""FourRooms: four rooms joined by gaps; agent and goal anywhere (MiniGrid ``FourRoomsEnv``,
MiniGrid-FourRooms-v0: 19x19, horizon 100)."""

from __future__ import annotations

import numpy as np

from ...core import register_variants
from .engine import MiniGridTask
from .world import Goal


class FourRooms(MiniGridTask):
    title = "MiniGrid FourRooms"
    about = ("The 19x19 grid is four rooms joined by one-cell gaps in the walls between them; "
             "get to the green goal square, which may be in any room.")
    mission = "reach the goal"
    kinds = ("goal",)

    def _gen(self, rng: np.random.Generator) -> None:
        size = 19
        grid = self.new_grid(size, size)
        grid.horz_wall(0, 0)
        grid.horz_wall(0, size - 1)
        grid.vert_wall(0, 0)
        grid.vert_wall(size - 1, 0)
        room = size // 2
        for j in range(2):
            for i in range(2):
                left, top = i * room, j * room
                if i == 0:
                    grid.vert_wall(left + room, top, room)
                    grid.set(left + room, self.rand_int(top + 1, top + room), None)
                if j == 0:
                    grid.horz_wall(left, top + room, room)
                    grid.set(self.rand_int(left + 1, left + room), top + room, None)
        self.place_agent()
        self.place_obj(Goal())


register_variants(FourRooms, "MiniGrid", {"glyphbench/minigrid-fourrooms-v0": dict(max_turns=100)})
