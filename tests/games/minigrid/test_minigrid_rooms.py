"""The room-grid helpers (MiniGrid's RoomGrid) build MiniGrid's levels for the same seed."""

from __future__ import annotations

import os
from dataclasses import dataclass

import numpy as np
import pytest

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
roomgrid = pytest.importorskip("minigrid.core.roomgrid")
from minigrid.core.mission import MissionSpace  # noqa: E402
from minigrid.envs import UnlockEnv  # noqa: E402

from glyphbench_rl.games.minigrid import solver  # noqa: E402
from glyphbench_rl.games.minigrid.engine import TOGGLE  # noqa: E402
from glyphbench_rl.games.minigrid.rooms import RoomGridParams, RoomGridTask  # noqa: E402

from test_minigrid_fidelity import same_state  # noqa: E402


@dataclass(frozen=True)
class UnlockParams(RoomGridParams):
    room_size: int = 6
    num_rows: int = 1
    num_cols: int = 2


class Unlock(RoomGridTask):
    """MiniGrid's UnlockEnv, as a family module would write it."""
    Params = UnlockParams
    mission = "open the door"

    def _gen(self, rng):
        super()._gen(rng)
        self.door, _ = self.add_door(0, 0, 0, locked=True)
        self.add_object(0, 0, "key", self.door.color)
        self.place_agent_in_room(0, 0)

    def _act(self, action):
        super()._act(action)
        if action == TOGGLE and self.door.is_open:
            self.succeed()


class Probe(RoomGridTask):
    """Every helper once, in an order a family might use them."""

    def _gen(self, rng):
        super()._gen(rng)
        self.remove_wall(0, 0, 0)
        self.add_door(1, 1)
        self.add_door(2, 1, 3, color="red", locked=True)
        self.add_object(2, 2)
        self.add_distractors(num_distractors=4)
        self.place_agent_in_room()
        self.connect_all()


class MGProbe(roomgrid.RoomGrid):
    def __init__(self):
        super().__init__(mission_space=MissionSpace(mission_func=lambda: "probe"), room_size=5,
                         num_rows=3, num_cols=3, max_steps=100)

    def _gen_grid(self, width, height):
        super()._gen_grid(width, height)
        self.remove_wall(0, 0, 0)
        self.add_door(1, 1)
        self.add_door(2, 1, 3, color="red", locked=True)
        self.add_object(2, 2)
        self.add_distractors(num_distractors=4)
        self.place_agent()
        self.connect_all()


def test_unlock_matches_minigrid_and_is_solvable():
    task, env = Unlock(max_turns=8 * 36), UnlockEnv()
    for seed in range(6):
        task.reset(seed=seed)
        env.reset(seed=seed)
        same_state(task, env)
        key = solver.find(task, "key")[0]
        solver.run(task, solver.plan(task, key, face=True) + [3])
        door = solver.find(task, "door")[0]
        solver.run(task, solver.plan(task, door, face=True) + [TOGGLE])
        assert task.won


def test_every_room_helper_matches_minigrid():
    task, env = Probe(max_turns=100, room_size=5), MGProbe()
    for seed in range(12):
        task.reset(seed=seed)
        env.reset(seed=seed)
        same_state(task, env)
        rooms = {id(r) for row in task.room_grid for r in row}
        assert task._reachable_rooms(task.room_from_pos(*task.agent_pos)) == rooms
        assert np.array_equal([[bool(d) for d in r.doors] for row in task.room_grid for r in row],
                              [[bool(d) for d in r.doors] for row in env.room_grid for r in row])
