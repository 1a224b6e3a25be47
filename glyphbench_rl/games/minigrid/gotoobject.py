"""GoToObject: stand next to the object the mission names and say DONE (MiniGrid
``GoToObjectEnv``).

IDs: gotoobject-6x6-n2 is MiniGrid-GoToObject-6x6-N2-v0 (``GoToObjectEnv(size=6, numObjs=2)``).
Horizon 5 x N^2 = 180. ``see_through_walls=True``.

As in MiniGrid: N distinct objects (key, ball or box of some colour) lie in the room, the agent
starts anywhere facing anywhere. DONE ends the episode, with the reward when the agent stands
beside the cell where the named object was placed (sharing an edge) and with 0 elsewhere; TOGGLE
ends it with 0 (a box in front still opens first). PICKUP works but does not move the target:
MiniGrid checks the object's starting cell.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from .engine import DONE, TOGGLE, MiniGridParams, MiniGridTask, beside, capped
from .solver import plan, run, win_script


@dataclass(frozen=True)
class GoToObjectParams(MiniGridParams):
    size: int = param(6, 4, 32)
    objects: int = param(2, 1, lambda p: min(18, (p.size - 2) ** 2 - 1))


class GoToObject(MiniGridTask):
    title = "MiniGrid GoToObject"
    about = ("The {size}x{size} room (walls included) holds {objects} different objects (keys, "
             "balls, boxes).")
    rewards = ("DONE while standing beside the object the mission names gives 1 - {decay:g} x "
               "(turns used / {max_turns}); DONE anywhere else, TOGGLE, or running out of time "
               "gives 0.")
    ends = "when you use DONE or TOGGLE"
    Params = GoToObjectParams
    kinds = ("key", "ball", "box")
    see_through_walls = True

    def _gen(self, rng: np.random.Generator) -> None:
        n = self.params.size
        self.new_grid(n, n).wall_rect(0, 0, n, n)
        objs, positions = self.place_distinct_objects(self.params.objects)
        self.place_agent()
        k = self.rand_int(0, len(objs))
        self.target, self.target_pos = objs[k], positions[k]
        self.mission = f"go to the {objs[k][1]} {objs[k][0]}"

    def _act(self, action: int) -> None:
        super()._act(action)
        name = f"{self.target[1]} {self.target[0]}"
        if action == DONE and beside(self.agent_pos, self.target_pos):
            self.succeed(f"You are at the {name}.")
        elif action == DONE:
            self.fail(f"You are not beside the {name}.")
        elif action == TOGGLE:
            self.fail("Toggling ends the episode here.")


@win_script(GoToObject)
def _win(task: GoToObject) -> None:
    run(task, plan(task, task.target_pos, face=True) + [DONE])


register_variants(GoToObject, "MiniGrid", {
    "glyphbench/minigrid-gotoobject-6x6-n2-v0": dict(size=6, objects=2, max_turns=capped(5 * 6 * 6)),
})
