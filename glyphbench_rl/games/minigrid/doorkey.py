"""DoorKey: pick up the key, unlock the door in the dividing wall, reach the goal (MiniGrid
``DoorKeyEnv``; doorkey-NxN is MiniGrid-DoorKey-NxN-v0, horizon 10 x N^2 capped at 512)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from .engine import MiniGridParams, MiniGridTask, capped
from .world import Door, Goal, Key


@dataclass(frozen=True)
class DoorKeyParams(MiniGridParams):
    size: int = param(8, 5, 32)


class DoorKey(MiniGridTask):
    title = "MiniGrid DoorKey"
    about = ("The {size}x{size} room (walls included) is split by a wall with a locked yellow door; "
             "the yellow key lies on your side and the green goal square on the other.")
    Params = DoorKeyParams
    kinds = ("goal", "door", "key")
    mission = "use the key to open the door and then get to the goal"

    def _gen(self, rng: np.random.Generator) -> None:
        n = self.params.size
        grid = self.new_grid(n, n)
        grid.wall_rect(0, 0, n, n)
        self.put_obj(Goal(), n - 2, n - 2)
        split = self.rand_int(2, n - 2)
        grid.vert_wall(split, 0)
        self.place_agent(size=(split, n))
        self.put_obj(Door("yellow", is_locked=True), split, self.rand_int(1, n - 2))
        self.place_obj(Key("yellow"), top=(0, 0), size=(split, n))


register_variants(DoorKey, "MiniGrid", {
    f"glyphbench/minigrid-doorkey-{n}x{n}-v0": dict(size=n, max_turns=capped(10 * n * n)) for n in (5, 6, 8, 16)
})
