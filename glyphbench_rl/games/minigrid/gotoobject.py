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
from .engine import DONE, TOGGLE, MiniGridParams, MiniGridTask, capped, check_int
from .gotodoor import beside
from .solver import plan, run, win_script
from .world import COLOR_NAMES, Ball, Box, Key

MAKERS = {"key": Key, "ball": Ball, "box": Box}


def place_distinct_objects(task: MiniGridTask, count: int, *, apart: bool = False
                           ) -> tuple[list[tuple[str, str]], list[tuple[int, int]]]:
    """``count`` objects of distinct (kind, colour) on random cells, drawn as MiniGrid's
    GoToObject and PutNear draw them; ``apart`` keeps each off the 8 cells around earlier ones."""
    objs: list[tuple[str, str]] = []
    positions: list[tuple[int, int]] = []

    def near(_task: MiniGridTask, p1: tuple[int, int]) -> bool:
        return any(abs(p1[0] - p2[0]) <= 1 and abs(p1[1] - p2[1]) <= 1 for p2 in positions)

    while len(objs) < count:
        kind = task.rand_elem(list(MAKERS))
        color = task.rand_elem(COLOR_NAMES)
        if (kind, color) in objs:
            continue
        positions.append(task.place_obj(MAKERS[kind](color), reject_fn=near if apart else None))
        objs.append((kind, color))
    return objs, positions


@dataclass(frozen=True)
class GoToObjectParams(MiniGridParams):
    size: int = 6
    objects: int = 2

    def __post_init__(self) -> None:
        super().__post_init__()
        check_int("size", self.size, 4, 32)
        check_int("objects", self.objects, 1, min(18, (self.size - 2) ** 2 - 1))


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
        objs, positions = place_distinct_objects(self, self.params.objects)
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
