"""MiniHack's Boxoban rules on our generated levels (imported only on the engine path).

Upstream ``BoxoHack`` reads a level file at construction; ours takes each episode's level from
``boxoban.generate`` with the episode's generator (``next_level``) and keeps everything else of
upstream's: the level built by ``boxoban.to_des`` exactly as upstream builds it, success when
every boulder stands on a fountain, and the shaping of ``reward_shaping_coefficient`` per boulder
put on (or taken off) a fountain. Upstream pays 1 on success on top of that shaping; we pay
``1 - 3 x shaping`` so that a solved level returns exactly 1, and no time penalty.
"""

from __future__ import annotations

import numpy as np
from minihack import MiniHackNavigation
from minihack.envs.boxohack import BoxoHack

from . import boxoban

SHAPING = 0.1


class GeneratedBoxoban(BoxoHack):
    def __init__(self, *, difficulty: str, **kwargs) -> None:
        # BoxoHack.__init__ loads level files; ours sets the same attributes without them
        self.difficulty = difficulty
        self._time_penalty = kwargs.pop("penalty_time", 0)
        self._flags = tuple(kwargs.pop("flags", []))
        self._reward_shaping_coefficient = SHAPING
        self._level = boxoban.generate(np.random.default_rng(0), difficulty)
        self._des = boxoban.to_des(self._level)
        MiniHackNavigation.__init__(self, des_file=self._des, **kwargs)

    def next_level(self, rng: np.random.Generator) -> None:
        self._level = boxoban.generate(rng, self.difficulty)
        self._des = boxoban.to_des(self._level)

    def update(self, des_file) -> None:
        if des_file != getattr(self, "_installed", None):   # recompiling costs a subprocess
            super().update(des_file)
            self._installed = des_file

    def reset(self, *args, **kwargs):
        self.update(self._des)
        self._goal_pos_set = None            # (read by the end check while NetHack starts)
        obs = MiniHackNavigation.reset(self, *args, **kwargs)
        self._goal_pos_set = self._object_positions(self.last_observation, "{")
        return obs

    def _reward_fn(self, last_observation, action, observation, end_status):
        if end_status == self.StepStatus.TASK_SUCCESSFUL:
            return 1 - (boxoban.BOXES - 1) * SHAPING
        return super()._reward_fn(last_observation, action, observation, end_status)


def builder(difficulty: str):
    def build() -> tuple[type, dict]:
        return GeneratedBoxoban, {"difficulty": difficulty}
    return build


unfiltered, medium, hard = (builder(d) for d in boxoban.DIFFICULTIES)
