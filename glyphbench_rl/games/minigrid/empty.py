"""Empty: reach the goal in the far corner of an empty room (MiniGrid ``EmptyEnv``).

IDs: empty-5x5 / 6x6 / 8x8 / 16x16 are MiniGrid-Empty-NxN-v0 (start in the top-left corner
facing east); empty-random-5x5 / 6x6 are MiniGrid-Empty-Random-NxN-v0 (random start and
facing). MiniGrid gives these rooms ``see_through_walls=True``, and so do we.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from .engine import MiniGridParams, MiniGridTask, capped
from .world import Goal


@dataclass(frozen=True)
class EmptyParams(MiniGridParams):
    size: int = param(8, 4, 32)               # the room with its walls is size x size
    random_start: bool = param(False)         # False: start at (1, 1) facing east


class Empty(MiniGridTask):
    title = "MiniGrid Empty"
    about = "You are in the empty {size}x{size} room (walls included); get to the green goal square."
    Params = EmptyParams
    kinds = ("goal",)
    see_through_walls = True

    def _gen(self, rng: np.random.Generator) -> None:
        n = self.params.size
        self.new_grid(n, n).wall_rect(0, 0, n, n)
        self.put_obj(Goal(), n - 2, n - 2)
        if self.params.random_start:
            self.place_agent()
        else:
            self.agent_pos, self.agent_dir = (1, 1), 0
        self.mission = "get to the green goal square"


register_variants(Empty, "MiniGrid", {
    f"glyphbench/minigrid-empty-{rand}{n}x{n}-v0": dict(size=n, random_start=bool(rand), max_turns=capped(4 * n * n))
    for rand, sizes in (("", (5, 6, 8, 16)), ("random-", (5, 6))) for n in sizes
})
