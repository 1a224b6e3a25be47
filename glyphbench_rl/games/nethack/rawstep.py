"""The benchmark's raw step of a NetHack task: what its turns cost in NLE alone.

A turn of ours sends one or more NetHack keys (the command, then the answers to what NetHack
asks). ``RawReplay`` records those keys while the task plays, then has upstream's own
environment (the same class and options, built without ``lean``, with NLE's own handling of
``--More--`` and menus) step the same keys from the same seeds, and times each turn's keys
together: no wrapper, no rendering. Resets go through the task, so a level made per episode
(Boxoban) is made from the same generator.
"""

from __future__ import annotations

import time
import warnings
from typing import Callable

from .lean import turn_function, upstream_classes


class RawReplay:
    def __init__(self, task) -> None:
        self.task = task
        self.plan: list[tuple[str, object]] = []     # ("reset", seed) and ("turn", keys)
        self._keys: list[int] = []
        self._env = None

    # -- recording, while the task plays (the benchmark calls these around its own steps) ------
    def on_reset(self, seed: int) -> None:
        self.plan.append(("reset", seed))
        task = self.task
        if "_recorded" not in vars(task):            # record the actions the task steps its env with
            turn, keys = task._turn, self._keys

            def recorded(action: int):
                keys.append(action)
                return turn(action)
            task._turn = task._recorded = recorded

    def on_turn(self) -> None:
        self.plan.append(("turn", tuple(self._keys)))
        self._keys.clear()

    def stop_recording(self) -> None:
        task = self.task
        if vars(task).pop("_recorded", None) is not None:
            task._turn = turn_function(task.env)

    # -- the replay ----------------------------------------------------------------------------------
    def times(self, clock: Callable[[], float] = time.perf_counter) -> list[float]:
        """Seconds of each recorded turn on upstream's environment."""
        task = self.task
        if self._env is None:
            with upstream_classes():
                self._env = task._new_env()
        env, out, over = self._env, [], False
        for kind, value in self.plan:
            if kind == "reset":
                ours, task.env = task.env, env        # the task's own seeding, on upstream's env
                try:
                    with warnings.catch_warnings():
                        warnings.simplefilter("ignore")
                        task.reset(seed=value)
                finally:
                    task.env = ours
                over = False
                continue
            if over:            # (NLE's own menu handling ended the game before ours did: rare)
                continue
            step = env.step
            t0 = clock()
            for key in value:
                if step(key)[2]:
                    over = True
                    break
            out.append(clock() - t0)
        return out

    def close(self) -> None:
        if self._env is not None:
            self._env.close()
            self._env = None
