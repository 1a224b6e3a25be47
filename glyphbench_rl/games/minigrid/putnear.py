"""PutNear: pick up the object the mission names and drop it next to another (MiniGrid
``PutNearEnv``).

IDs: putnear-6x6-n2 is MiniGrid-PutNear-6x6-N2-v0, putnear-8x8-n3 is MiniGrid-PutNear-8x8-N3-v0
(``PutNearEnv(size, numObjs)``). Horizon 5 x N (MiniGrid's, not N^2): 30 and 40.
``see_through_walls=True``.

As in MiniGrid: N distinct objects (key, ball or box of some colour) lie in the room, none within
one cell of another; the agent starts anywhere facing anywhere. Picking up any other object than
the one to move ends the episode with 0. DROP while carrying ends the episode: with the reward if
the object landed on one of the eight cells around the target object's starting cell, with 0
otherwise (also when the drop was blocked).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from .engine import DROP, PICKUP, MiniGridParams, MiniGridTask, capped
from .solver import plan, run, win_script


@dataclass(frozen=True)
class PutNearParams(MiniGridParams):
    size: int = param(6, 5, 32)
    # objects keep a cell apart: a room of side m always fits ceil(m / 3) ** 2 of them
    objects: int = param(2, 2, lambda p: min(18, (-(-(p.size - 2) // 3)) ** 2))


class PutNear(MiniGridTask):
    title = "MiniGrid PutNear"
    about = ("The {size}x{size} room (walls included) holds {objects} different objects (keys, "
             "balls, boxes).")
    rewards = ("dropping the object the mission names on a cell touching the other named object "
               "(diagonals count) gives 1 - {decay:g} x (turns used / {max_turns}); picking up a "
               "wrong object, dropping anywhere else, or running out of time gives 0.")
    ends = "when you use DROP while carrying something or pick up a wrong object"
    Params = PutNearParams
    kinds = ("key", "ball", "box")
    see_through_walls = True

    def _gen(self, rng: np.random.Generator) -> None:
        n = self.params.size
        self.new_grid(n, n).wall_rect(0, 0, n, n)
        objs, positions = self.place_distinct_objects(self.params.objects, apart=True)
        self.place_agent()
        k = self.rand_int(0, len(objs))
        self.move, self.move_pos = objs[k], positions[k]
        while (t := self.rand_int(0, len(objs))) == k:
            pass
        self.target, self.target_pos = objs[t], positions[t]
        self.mission = f"put the {self.move[1]} {self.move[0]} near the {self.target[1]} {self.target[0]}"

    def _act(self, action: int) -> None:
        carried = self.carrying
        super()._act(action)
        held = self.carrying
        if action == PICKUP and held is not None and (held.kind, held.color) != self.move:
            self.fail(f"The {held.name} is not the object to move.")
        elif action == DROP and carried is not None:
            fx, fy = self.front_pos
            tx, ty = self.target_pos
            near = f"near the {self.target[1]} {self.target[0]}"
            if self.grid.get(fx, fy) is not carried:
                self.fail(f"You could not drop the {carried.name} there.")
            elif abs(fx - tx) <= 1 and abs(fy - ty) <= 1:
                self.succeed(f"You put the {carried.name} {near}.")
            else:
                self.fail(f"The {carried.name} is not {near}.")


@win_script(PutNear)
def _win(task: PutNear) -> None:
    run(task, plan(task, task.move_pos, face=True) + [PICKUP])
    tx, ty = task.target_pos
    cells = [(tx + dx, ty + dy) for dx in (-1, 0, 1) for dy in (-1, 0, 1)]
    paths = [p for p in (plan(task, c, face=True) for c in cells
                         if task.grid.get(*c) is None and c != task.agent_pos) if p is not None]
    run(task, min(paths, key=len) + [DROP])


register_variants(PutNear, "MiniGrid", {
    f"glyphbench/minigrid-putnear-{n}x{n}-n{k}-v0": dict(size=n, objects=k, max_turns=capped(5 * n))
    for n, k in ((6, 2), (8, 3))
})
