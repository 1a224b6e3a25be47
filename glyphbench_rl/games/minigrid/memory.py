"""Memory: see a green key or ball in the start room, walk the hallway, and go to the matching
object at the split (MiniGrid ``MemoryEnv``).

IDs: memory-sN is MiniGrid-MemorySN-v0, i.e. ``MemoryEnv(size=N)`` with the fixed hallway length
(MiniGrid registers its 17-cell size only as MemoryS17Random-v0, the random-length variant; ours is
the same env with ``random_length=False``, as for the other sizes). Horizon 5 x N^2, capped at 512:
245 (s7), 405 (s9), 512 (s11, s13, s17).

As in MiniGrid: the agent starts facing east in the hallway row; PICKUP acts as TOGGLE (so
nothing can be carried); stepping onto the cell just before the matching object wins, onto the
cell before the other one ends the episode with 0. The cue object is only seen from the start
room (walls block sight), so the agent has to remember it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from .engine import PICKUP, TOGGLE, MiniGridParams, MiniGridTask, capped
from .solver import plan, run, win_script
from .world import Ball, Key, Wall


@dataclass(frozen=True)
class MemoryParams(MiniGridParams):
    size: int = param(13, 7, 31, odd=True)


class Memory(MiniGridTask):
    title = "MiniGrid Memory"
    about = ("In the {size}x{size} level (walls included) a small start room in the west holds a "
             "green key or ball; a hallway leads east to a north-south corridor with a green key at "
             "one end and a green ball at the other. Nothing can be picked up.")
    rewards = ("stepping next to the object matching the start room's gives 1 - {decay:g} x (turns "
               "used / {max_turns}); stepping next to the other one or running out of time gives 0.")
    ends = "when you step next to either object at the corridor's ends"
    Params = MemoryParams
    kinds = ("key", "ball")
    mission = "go to the matching object at the end of the hallway"

    def _gen(self, rng: np.random.Generator) -> None:
        n = self.params.size
        width = height = n
        grid = self.new_grid(width, height)
        grid.wall_rect(0, 0, width, height)
        upper_room_wall, lower_room_wall = height // 2 - 2, height // 2 + 2
        hallway_end = width - 3
        for i in range(1, 5):                          # the start room
            grid.set(i, upper_room_wall, Wall())
            grid.set(i, lower_room_wall, Wall())
        grid.set(4, upper_room_wall + 1, Wall())
        grid.set(4, lower_room_wall - 1, Wall())
        for i in range(5, hallway_end):                # the horizontal hallway
            grid.set(i, upper_room_wall + 1, Wall())
            grid.set(i, lower_room_wall - 1, Wall())
        for j in range(height):                        # the vertical corridor
            if j != height // 2:
                grid.set(hallway_end, j, Wall())
            grid.set(hallway_end + 2, j, Wall())
        self.agent_pos, self.agent_dir = (self.rand_int(1, hallway_end + 1), height // 2), 0
        cue = self.rand_elem([Key, Ball])
        self.cue = cue("green")
        grid.set(1, height // 2 - 1, self.cue)
        others = self.rand_elem([[Ball, Key], [Key, Ball]])
        pos0, pos1 = (hallway_end + 1, height // 2 - 2), (hallway_end + 1, height // 2 + 2)
        grid.set(*pos0, others[0]("green"))
        grid.set(*pos1, others[1]("green"))
        north, south = (pos0[0], pos0[1] + 1), (pos1[0], pos1[1] - 1)
        self.success_pos, self.failure_pos = (north, south) if cue is others[0] else (south, north)

    def _act(self, action: int) -> None:
        super()._act(TOGGLE if action == PICKUP else action)
        if self.agent_pos == self.success_pos:
            self.succeed("You went to the matching object.")
        elif self.agent_pos == self.failure_pos:
            self.fail("That object does not match the one in the start room.")


@win_script(Memory)
def _win(task: Memory) -> None:
    run(task, plan(task, task.success_pos))


register_variants(Memory, "MiniGrid", {
    f"glyphbench/minigrid-memory-s{n}-v0": dict(size=n, max_turns=capped(5 * n * n))
    for n in (7, 9, 11, 13, 17)
})
