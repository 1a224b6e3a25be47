"""Fetch: pick up the key or ball the mission names (MiniGrid ``FetchEnv``).

IDs: fetch-5x5-n2 is MiniGrid-Fetch-5x5-N2-v0, fetch-6x6-n2 is MiniGrid-Fetch-6x6-N2-v0,
fetch-8x8-n3 is MiniGrid-Fetch-8x8-N3-v0 (``FetchEnv(size, numObjs)``). Horizon 5 x N^2: 125, 180,
320. ``see_through_walls=True``.

As in MiniGrid: N random keys and balls (repeats allowed) lie in the room, the agent starts
anywhere facing anywhere, and the mission ("get a", "go get a", "fetch a", "go fetch a" or "you
must fetch a" + colour and kind) names one of them. The first pickup ends the episode: the named
kind and colour win (any copy of it), anything else gives 0.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from .engine import PICKUP, MiniGridParams, MiniGridTask, capped
from .solver import find, plan, run, win_script
from .world import COLOR_NAMES, Ball, Key

SYNTAX = ("get a", "go get a", "fetch a", "go fetch a", "you must fetch a")


@dataclass(frozen=True)
class FetchParams(MiniGridParams):
    size: int = param(8, 4, 32)
    objects: int = param(3, 1, lambda p: (p.size - 2) ** 2 - 1)


class Fetch(MiniGridTask):
    title = "MiniGrid Fetch"
    about = ("The {size}x{size} room (walls included) holds {objects} objects, each a key or a ball "
             "of some colour; pick up the one the mission names.")
    rewards = ("picking up an object of the named colour and kind gives 1 - {decay:g} x (turns used "
               "/ {max_turns}); picking up any other object or running out of time gives 0.")
    ends = "when you pick up an object"
    Params = FetchParams
    kinds = ("key", "ball")
    see_through_walls = True

    def _gen(self, rng: np.random.Generator) -> None:
        n = self.params.size
        self.new_grid(n, n).wall_rect(0, 0, n, n)
        objs = []
        while len(objs) < self.params.objects:
            kind = self.rand_elem(["key", "ball"])
            color = self.rand_elem(COLOR_NAMES)
            obj = Key(color) if kind == "key" else Ball(color)
            self.place_obj(obj)
            objs.append(obj)
        self.place_agent()
        target = objs[self.rand_int(0, len(objs))]
        self.target = (target.kind, target.color)
        self.mission = f"{SYNTAX[self.rand_int(0, 5)]} {target.color} {target.kind}"

    def _act(self, action: int) -> None:
        super()._act(action)
        if self.carrying is not None:
            if (self.carrying.kind, self.carrying.color) == self.target:
                self.succeed(f"You fetched the {self.carrying.name}.")
            else:
                self.fail(f"The {self.carrying.name} is not what the mission asks for.")


@win_script(Fetch)
def _win(task: Fetch) -> None:
    kind, color = task.target
    paths = [p for p in (plan(task, pos, face=True) for pos in find(task, kind, color)) if p is not None]
    if paths:
        run(task, min(paths, key=len) + [PICKUP])


register_variants(Fetch, "MiniGrid", {
    f"glyphbench/minigrid-fetch-{n}x{n}-n{k}-v0": dict(size=n, objects=k, max_turns=capped(5 * n * n))
    for n, k in ((5, 2), (6, 2), (8, 3))
})
