"""GoToDoor: stand next to the door the mission names and say DONE (MiniGrid ``GoToDoorEnv``).

IDs: gotodoor-5x5 is MiniGrid-GoToDoor-5x5-v0, gotodoor-6x6 is MiniGrid-GoToDoor-6x6-v0,
gotodoor-8x8 is MiniGrid-GoToDoor-8x8-v0 (``GoToDoorEnv(size)``). Horizon 4 x N^2: 100, 144, 256.
``see_through_walls=True``.

As in MiniGrid: in an N x N grid the room measures a random 5..N cells a side (walls included)
from the north-west corner, the rest of the grid stays empty floor; each wall holds one closed
door, the four of different colours. DONE ends the episode, with the reward when the agent
stands beside the named door (sharing an edge, whichever way it faces) and with 0 elsewhere;
TOGGLE ends it with 0 (the door in front still opens, as in MiniGrid).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from .engine import DONE, TOGGLE, MiniGridParams, MiniGridTask, beside, capped
from .solver import find, plan, run, win_script
from .world import COLOR_NAMES, Door


@dataclass(frozen=True)
class GoToDoorParams(MiniGridParams):
    size: int = param(5, 5, 32)


class GoToDoor(MiniGridTask):
    title = "MiniGrid GoToDoor"
    about = ("You are in a room of at most {size}x{size} cells (walls included) with a closed door "
             "of a different colour in each of its four walls.")
    rewards = ("DONE while standing beside the door the mission names gives 1 - {decay:g} x (turns "
               "used / {max_turns}); DONE anywhere else, TOGGLE, or running out of time gives 0.")
    ends = "when you use DONE or TOGGLE"
    Params = GoToDoorParams
    kinds = ("door",)
    see_through_walls = True

    def _gen(self, rng: np.random.Generator) -> None:
        n = self.params.size
        self.new_grid(n, n)
        width, height = self.rand_int(5, n + 1), self.rand_int(5, n + 1)
        self.grid.wall_rect(0, 0, width, height)
        door_pos = [(self.rand_int(2, width - 2), 0), (self.rand_int(2, width - 2), height - 1),
                    (0, self.rand_int(2, height - 2)), (width - 1, self.rand_int(2, height - 2))]
        colors: list[str] = []
        while len(colors) < len(door_pos):
            color = self.rand_elem(COLOR_NAMES)
            if color not in colors:
                colors.append(color)
        for pos, color in zip(door_pos, colors):
            self.grid.set(*pos, Door(color))
        self.place_agent(size=(width, height))
        k = self.rand_int(0, len(door_pos))
        self.target_pos, self.target_color = door_pos[k], colors[k]
        self.mission = f"go to the {self.target_color} door"

    def _act(self, action: int) -> None:
        super()._act(action)
        if action == DONE and beside(self.agent_pos, self.target_pos):
            self.succeed(f"You are at the {self.target_color} door.")
        elif action == DONE:
            self.fail(f"You are not beside the {self.target_color} door.")
        elif action == TOGGLE:
            self.fail("Doors are not to be opened here.")


@win_script(GoToDoor)
def _win(task: GoToDoor) -> None:
    doors = set(find(task, "door"))
    run(task, plan(task, task.target_pos, face=True, blocked=doors.__contains__) + [DONE])


register_variants(GoToDoor, "MiniGrid", {
    f"glyphbench/minigrid-gotodoor-{n}x{n}-v0": dict(size=n, max_turns=capped(4 * n * n)) for n in (5, 6, 8)
})
