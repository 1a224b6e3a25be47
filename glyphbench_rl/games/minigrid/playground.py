"""Playground: a 19x19 world of 3x3 rooms joined by closed doors of random colours, with twelve
random keys, balls and boxes lying anywhere; there is no mission and nothing to win (MiniGrid
``PlaygroundEnv``; playground is MiniGrid-Playground-v0, horizon 100).

As in MiniGrid every step gives 0 and only the horizon ends the episode: the task measures
nothing but lets an agent explore the object and door mechanics. MiniGrid's mission is the empty
string; the HUD says "none".
"""

from __future__ import annotations

import numpy as np

from ...core import register_variants
from .engine import MiniGridParams, MiniGridTask
from .world import COLOR_NAMES, Ball, Box, Door, Key

SIZE = 19
OBJECTS = 12


class Playground(MiniGridTask):
    title = "MiniGrid Playground"
    about = ("The {size}x{size} world (walls included) is 3x3 rooms joined by closed doors and "
             "holds {objects} keys, balls and boxes. There is no mission: explore freely.")
    rewards = "every turn gives 0; there is nothing to win."
    ends = ""
    Params = MiniGridParams
    kinds = ("door", "key", "ball", "box")
    mission = ""

    def family_fields(self) -> dict:
        return {"size": SIZE, "objects": OBJECTS}

    def _gen(self, rng: np.random.Generator) -> None:
        grid = self.new_grid(SIZE, SIZE)
        grid.horz_wall(0, 0)
        grid.horz_wall(0, SIZE - 1)
        grid.vert_wall(0, 0)
        grid.vert_wall(SIZE - 1, 0)
        room_w = room_h = SIZE // 3
        for j in range(3):
            for i in range(3):
                x_l, y_t = i * room_w, j * room_h
                x_r, y_b = x_l + room_w, y_t + room_h
                if i + 1 < 3:
                    grid.vert_wall(x_r, y_t, room_h)
                    pos = (x_r, self.rand_int(y_t + 1, y_b - 1))
                    grid.set(*pos, Door(self.rand_elem(COLOR_NAMES)))
                if j + 1 < 3:
                    grid.horz_wall(x_l, y_b, room_w)
                    pos = (self.rand_int(x_l + 1, x_r - 1), y_b)
                    grid.set(*pos, Door(self.rand_elem(COLOR_NAMES)))
        self.place_agent()
        makers = {"key": Key, "ball": Ball, "box": Box}
        for _ in range(OBJECTS):
            kind = self.rand_elem(["key", "ball", "box"])
            self.place_obj(makers[kind](self.rand_elem(COLOR_NAMES)))
        self.mission = ""

    def _hud(self) -> str:
        carried = self.carrying.name if self.carrying is not None else "nothing"
        return f"Mission: none | Carrying: {carried}"


register_variants(Playground, "MiniGrid", {
    "glyphbench/minigrid-playground-v0": dict(max_turns=100),
})
