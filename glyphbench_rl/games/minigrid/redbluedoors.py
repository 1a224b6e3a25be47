"""RedBlueDoors: open the red door, then the blue one (MiniGrid ``RedBlueDoorEnv``).

IDs: redbluedoors-6x6 is MiniGrid-RedBlueDoors-6x6-v0, redbluedoors-8x8 is
MiniGrid-RedBlueDoors-8x8-v0 (``RedBlueDoorEnv(size)``). The grid is 2N wide and N high, the
room N x N in its middle; horizon 20 x N^2 (720, 1280), capped at 512.

As in MiniGrid: the agent starts anywhere in the room facing anywhere; a closed red door lies in
the room's west wall and a closed blue door in its east wall. Opening the blue door ends the
episode: with the reward if the red door was open just before, with 0 otherwise.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from .engine import TOGGLE, MiniGridParams, MiniGridTask, capped
from .solver import plan, run, win_script
from .world import Door


@dataclass(frozen=True)
class RedBlueDoorsParams(MiniGridParams):
    size: int = param(8, 4, 32)


class RedBlueDoors(MiniGridTask):
    title = "MiniGrid RedBlueDoors"
    about = ("You are in a {size}x{size} room (walls included) with a closed red door in its west "
             "wall and a closed blue door in its east wall.")
    rewards = ("opening the blue door while the red one is open gives 1 - {decay:g} x (turns used / "
               "{max_turns}); opening it otherwise, or running out of time, gives 0.")
    ends = "when you open the blue door"
    Params = RedBlueDoorsParams
    kinds = ("door",)
    mission = "open the red door then the blue door"

    def _gen(self, rng: np.random.Generator) -> None:
        n = self.params.size
        grid = self.new_grid(2 * n, n)
        grid.wall_rect(0, 0, 2 * n, n)
        grid.wall_rect(n // 2, 0, n, n)
        self.place_agent(top=(n // 2, 0), size=(n, n))
        self.red_door, self.blue_door = Door("red"), Door("blue")
        grid.set(n // 2, self.rand_int(1, n - 1), self.red_door)
        grid.set(n // 2 + n - 1, self.rand_int(1, n - 1), self.blue_door)

    def _act(self, action: int) -> None:
        red_before = self.red_door.is_open
        super()._act(action)
        if self.blue_door.is_open:       # (MiniGrid's "red opened after blue" cannot happen: this ends)
            if red_before:
                self.succeed("You opened the red door, then the blue one.")
            else:
                self.fail("You opened the blue door before the red one.")


@win_script(RedBlueDoors)
def _win(task: RedBlueDoors) -> None:
    blue = task.blue_door.pos
    run(task, plan(task, task.red_door.pos, face=True, blocked=blue.__eq__) + [TOGGLE])
    run(task, plan(task, blue, face=True) + [TOGGLE])


register_variants(RedBlueDoors, "MiniGrid", {
    f"glyphbench/minigrid-redbluedoors-{n}x{n}-v0": dict(size=n, max_turns=capped(20 * n * n)) for n in (6, 8)
})
