"""LockedRoom against MiniGrid's LockedRoomEnv: same levels, same episodes, solver wins; the
locked door stays shut without its key and only the goal ends the episode."""

from __future__ import annotations

import os

import pytest

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
pytest.importorskip("minigrid.envs")
from minigrid.envs import LockedRoomEnv  # noqa: E402

from glyphbench_rl.games.minigrid import lockedroom, solver  # noqa: E402
from glyphbench_rl.games.minigrid.engine import PICKUP, TOGGLE  # noqa: E402

import roomgrid_twin as twin  # noqa: E402

NAME = "lockedroom"


def test_same_level_as_minigrid():
    twin.same_levels(NAME, LockedRoomEnv())


def test_same_actions_same_episode_and_view():
    twin.random_then_solver(NAME, LockedRoomEnv())


def test_solver_wins():
    twin.solver_wins(NAME)


def test_layout_and_mission():
    task = twin.make(NAME)
    for seed in range(6):
        task.reset(seed=seed)
        doors = [task.grid.get(*d) for d in solver.find(task, "door")]
        assert len(doors) == 6 and len({d.color for d in doors}) == 6
        (locked,) = [d for d in doors if d.is_locked]
        (key,) = solver.find(task, "key")
        assert task.grid.get(*key).color == locked.color
        key_room = next(r for r in task.rooms if r.top[0] < key[0] < r.top[0] + r.size[0] - 1
                        and r.top[1] < key[1] < r.top[1] + r.size[1] - 1)
        assert task.mission == (f"get the {locked.color} key from the {key_room.color} room, "
                                f"unlock the {locked.color} door and go to the goal")
        assert 7 < task.agent_pos[0] < 11                               # in the hallway
        assert solver.plan(task, solver.find(task, "goal")[0]) is None  # behind the locked door


def test_locked_door_needs_its_key_and_the_key_does_not_end():
    def script(task):
        door = next(d for d in solver.find(task, "door") if task.grid.get(*d).is_locked)
        solver.run(task, solver.plan(task, door, face=True) + [TOGGLE])
        assert task.grid.get(*door).is_locked and not task.done
        key = solver.find(task, "key")[0]
        solver.run(task, solver.plan(task, key, face=True) + [PICKUP])
        assert task.carrying.kind == "key" and not task.done
    probe, actions = twin.record(NAME, 3, script)
    task = twin.mirror(NAME, LockedRoomEnv(), 3, actions)
    assert not task.done and task.episode_return == 0


def test_time_out_gives_nothing():
    twin.time_out_gives_nothing(NAME)


def test_bad_size():
    for size in (12, 14, 33):
        with pytest.raises(ValueError):
            lockedroom.LockedRoom(size=size)
    task = lockedroom.LockedRoom(size=13, max_turns=130)
    for seed in range(4):
        task.reset(seed=seed)
        solver.solve(task)
        assert task.won
