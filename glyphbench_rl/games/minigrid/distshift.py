"""DistShift: walk past lava strips to the goal in the top-right corner (MiniGrid
``DistShiftEnv``): distshift1 is MiniGrid-DistShift1-v0 (second strip on row 2), distshift2 is
MiniGrid-DistShift2-v0 (second strip on row 5). 9x7, horizon 252, ``see_through_walls=True``."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from .engine import MiniGridParams, MiniGridTask, capped
from .world import Goal, Lava


@dataclass(frozen=True)
class DistShiftParams(MiniGridParams):
    strip2_row: int = param(2, 1, 5)      # the row of the second lava strip (the first is on row 1)


class DistShift(MiniGridTask):
    title = "MiniGrid DistShift"
    about = ("The {width}x{height} room (walls included) holds strips of lava between you and "
             "the green goal square.")
    Params = DistShiftParams
    kinds = ("goal", "lava")
    has_lava = True
    see_through_walls = True
    WIDTH, HEIGHT = 9, 7

    def family_fields(self) -> dict:
        return {"width": self.WIDTH, "height": self.HEIGHT}

    def _gen(self, rng: np.random.Generator) -> None:
        w, h = self.WIDTH, self.HEIGHT
        self.new_grid(w, h).wall_rect(0, 0, w, h)
        self.put_obj(Goal(), w - 2, 1)
        for i in range(w - 6):
            self.grid.set(3 + i, 1, Lava())
            self.grid.set(3 + i, self.params.strip2_row, Lava())
        self.agent_pos, self.agent_dir = (1, 1), 0


register_variants(DistShift, "MiniGrid", {
    "glyphbench/minigrid-distshift1-v0": dict(strip2_row=2, max_turns=capped(4 * 9 * 7)),
    "glyphbench/minigrid-distshift2-v0": dict(strip2_row=5, max_turns=capped(4 * 9 * 7)),
})
