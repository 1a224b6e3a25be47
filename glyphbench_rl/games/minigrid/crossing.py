"""Crossing: rivers of lava (or wall) across the room, each with one crossing point (MiniGrid
``CrossingEnv``; start top-left facing east, goal bottom-right, horizon 4 x size^2).

Our IDs map onto MiniGrid's as follows (N = the number of rivers, each with one crossing):

    crossing-nN            MiniGrid-LavaCrossingS9NN-v0    9x9, lava
    crossing-nN-safe       MiniGrid-SimpleCrossingS9NN-v0  9x9, wall: the same layouts (same seed),
                                                           but a wrong step costs nothing
    simplecrossing-nN      CrossingEnv(size=11, N, Wall)   11x11, wall: the size of MiniGrid's
                                                           SimpleCrossingS11N5, with N rivers
    simplecrossing-easy-nN CrossingEnv(size=7, N, Wall)    7x7, wall: a smaller room, shorter paths
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from .engine import MiniGridParams, MiniGridTask, capped
from .world import Goal, Lava, Wall

_OBSTACLES = {"lava": Lava, "wall": Wall}


@dataclass(frozen=True)
class CrossingParams(MiniGridParams):
    size: int = param(9, 5, 31, odd=True)     # rivers run along even rows and columns
    crossings: int = param(1, 1, lambda p: 2 * ((p.size - 3) // 2))   # rivers, each crossable at one cell
    obstacle: str = param("lava", choices=("lava", "wall"))          # "lava" (deadly) or "wall"


class Crossing(MiniGridTask):
    title = "MiniGrid Crossing"
    about = ("The {size}x{size} room (walls included) is cut by {rivers}; a path from your "
             "corner to the green goal square in the opposite corner always exists.")
    Params = CrossingParams
    kinds = ("goal", "lava")

    def family_fields(self) -> dict:
        n, lava = self.params.crossings, self.params.obstacle == "lava"
        thing = ("river" if n == 1 else "rivers") + " of lava" if lava else ("wall" if n == 1 else "walls")
        each = "passable at exactly one cell" if n == 1 else "each passable at exactly one cell"
        return {"rivers": f"{n} straight {thing} running across it, {each}"}

    def _init(self) -> None:
        self.has_lava = lava = self.params.obstacle == "lava"
        self.mission = ("avoid the lava and get to the green goal square" if lava
                        else "find the opening and get to the green goal square")

    def _gen(self, rng: np.random.Generator) -> None:
        n, obstacle = self.params.size, _OBSTACLES[self.params.obstacle]
        grid = self.new_grid(n, n)
        grid.wall_rect(0, 0, n, n)
        self.agent_pos, self.agent_dir = (1, 1), 0
        self.put_obj(Goal(), n - 2, n - 2)
        # Candidate rivers, shuffled and cut as MiniGrid does (vertical ones first).
        rivers = [("v", i) for i in range(2, n - 2, 2)] + [("h", j) for j in range(2, n - 2, 2)]
        rng.shuffle(rivers)
        rivers = rivers[:self.params.crossings]
        rivers_v = sorted(p for d, p in rivers if d == "v")
        rivers_h = sorted(p for d, p in rivers if d == "h")
        for i, j in itertools.chain(itertools.product(range(1, n - 1), rivers_h),
                                    itertools.product(rivers_v, range(1, n - 1))):
            self.put_obj(obstacle(), i, j)
        # One opening per river, along a monotone path of rooms from the start to the goal.
        path = ["h"] * len(rivers_v) + ["v"] * len(rivers_h)
        rng.shuffle(path)
        limits_v, limits_h = [0, *rivers_v, n - 1], [0, *rivers_h, n - 1]
        room_i = room_j = 0
        for direction in path:
            if direction == "h":
                i = limits_v[room_i + 1]
                j = int(rng.choice(range(limits_h[room_j] + 1, limits_h[room_j + 1])))
                room_i += 1
            else:
                i = int(rng.choice(range(limits_v[room_i] + 1, limits_v[room_i + 1])))
                j = limits_h[room_j + 1]
                room_j += 1
            grid.set(i, j, None)


register_variants(Crossing, "MiniGrid", {
    **{f"glyphbench/minigrid-crossing-n{k}-v0": dict(size=9, crossings=k, obstacle="lava", max_turns=capped(4 * 81))
       for k in (1, 2, 3)},
    **{f"glyphbench/minigrid-crossing-n{k}-safe-v0": dict(size=9, crossings=k, obstacle="wall", max_turns=capped(4 * 81))
       for k in (1, 2, 3)},
    **{f"glyphbench/minigrid-simplecrossing-n{k}-v0": dict(size=11, crossings=k, obstacle="wall",
                                                           max_turns=capped(4 * 121)) for k in (1, 2, 3)},
    **{f"glyphbench/minigrid-simplecrossing-easy-n{k}-v0": dict(size=7, crossings=k, obstacle="wall",
                                                                max_turns=capped(4 * 49)) for k in (1, 2, 3)},
})
