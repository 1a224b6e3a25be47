"""LavaGap: cross a wall of lava through its one gap (MiniGrid ``LavaGapEnv``; lavagap-sN is
MiniGrid-LavaGapSN-v0, horizon 4 x N^2)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from .engine import MiniGridParams, MiniGridTask, capped
from .world import Goal, Lava


@dataclass(frozen=True)
class LavaGapParams(MiniGridParams):
    size: int = param(5, 5, 32)


class LavaGap(MiniGridTask):
    title = "MiniGrid LavaGap"
    about = ("The {size}x{size} room (walls included) is crossed from top to bottom by a strip of "
             "lava with one gap; get to the green goal square in the far corner without touching "
             "the lava.")
    Params = LavaGapParams
    kinds = ("goal", "lava")
    has_lava = True
    mission = "avoid the lava and get to the green goal square"

    def _gen(self, rng: np.random.Generator) -> None:
        n = self.params.size
        grid = self.new_grid(n, n)
        grid.wall_rect(0, 0, n, n)
        self.agent_pos, self.agent_dir = (1, 1), 0
        self.put_obj(Goal(), n - 2, n - 2)
        gap = (self.rand_int(2, n - 2), self.rand_int(1, n - 1))
        grid.vert_wall(gap[0], 1, n - 2, Lava)
        grid.set(*gap, None)


register_variants(LavaGap, "MiniGrid", {
    f"glyphbench/minigrid-lavagap-s{n}-v0": dict(size=n, max_turns=capped(4 * n * n)) for n in (5, 6, 7)
})
