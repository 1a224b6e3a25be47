"""DynamicObstacles: reach the goal while blue balls wander the room (MiniGrid
``DynamicObstaclesEnv``; dynamic-obstacles-NxN is MiniGrid-Dynamic-Obstacles-NxN-v0).

As in MiniGrid: only the three movement actions; every turn each ball first moves to a random
free cell among its eight neighbours (or stays, after 100 failed draws); moving FORWARD when the
cell in front held anything but the goal before the balls moved (a ball or a wall) ends the
episode with -1. ``see_through_walls=True``; horizon 4 x N^2, capped at 512.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from .engine import FORWARD, NAV_ACTIONS, MiniGridParams, MiniGridTask, capped
from .world import Ball, Goal

COLLISION_PENALTY = 1.0


@dataclass(frozen=True)
class DynamicObstaclesParams(MiniGridParams):
    size: int = param(8, 4, 32)
    obstacles: int = param(4, 0, lambda p: p.size // 2 + 1)


class DynamicObstacles(MiniGridTask):
    title = "MiniGrid DynamicObstacles"
    about = ("You are in the {size}x{size} room (walls included) with {obstacles} blue balls that "
             "move to a random neighbouring cell every turn; get to the green goal square.")
    rewards = ("reaching the goal gives 1 - {decay:g} x (turns used / {max_turns}); moving "
               "forward into a ball or a wall gives -{penalty:g} and ends the episode.")
    ends = "when you reach the goal or collide"
    Params = DynamicObstaclesParams
    kinds = ("goal", "ball")
    ACTIONS = NAV_ACTIONS
    see_through_walls = True

    def family_fields(self) -> dict:
        return {"penalty": COLLISION_PENALTY}

    def _gen(self, rng: np.random.Generator) -> None:
        n = self.params.size
        self.new_grid(n, n).wall_rect(0, 0, n, n)
        self.grid.set(n - 2, n - 2, Goal())
        self.agent_pos, self.agent_dir = (1, 1), 0
        self.obstacles = [Ball() for _ in range(self.params.obstacles)]
        for ball in self.obstacles:
            self.place_obj(ball, max_tries=100)
        self.mission = "get to the green goal square"

    def _act(self, action: int) -> None:
        front = self.grid.get(*self.front_pos)
        blocked = front is not None and front.kind != "goal"
        for ball in self.obstacles:
            old = ball.pos
            try:
                self.place_obj(ball, top=(old[0] - 1, old[1] - 1), size=(3, 3), max_tries=100)
            except RecursionError:
                continue
            self.grid.set(*old, None)
        super()._act(action)
        if action == FORWARD and blocked:
            self.fail("You collided with an obstacle.", penalty=COLLISION_PENALTY)


register_variants(DynamicObstacles, "MiniGrid", {
    f"glyphbench/minigrid-dynamic-obstacles-{n}x{n}-v0": dict(size=n, obstacles=k, max_turns=capped(4 * n * n))
    for n, k in ((5, 2), (6, 3), (8, 4), (16, 8))
})
