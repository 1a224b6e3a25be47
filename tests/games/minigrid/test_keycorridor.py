"""KeyCorridor against MiniGrid's KeyCorridorEnv: same levels, same episodes, solver wins, and
picking up the key (not the mission's object) does not end the episode."""

from __future__ import annotations

import os

import pytest

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
pytest.importorskip("minigrid.envs")
from minigrid.envs import KeyCorridorEnv  # noqa: E402

from glyphbench_rl.games.minigrid import solver  # noqa: E402
from glyphbench_rl.games.minigrid.engine import PICKUP  # noqa: E402

import roomgrid_twin as twin  # noqa: E402

SIZES = ((3, 1), (3, 2), (3, 3), (4, 3), (5, 3), (6, 3))
REFERENCE = {f"keycorridor-s{s}r{r}": (lambda s=s, r=r: KeyCorridorEnv(room_size=s, num_rows=r,
                                                                       max_steps=min(30 * s * s, 512)))
             for s, r in SIZES}


@pytest.mark.parametrize("name", sorted(REFERENCE))
def test_same_level_as_minigrid(name):
    twin.same_levels(name, REFERENCE[name]())


@pytest.mark.parametrize("name", sorted(REFERENCE))
def test_same_actions_same_episode_and_view(name):
    twin.random_then_solver(name, REFERENCE[name]())


@pytest.mark.parametrize("name", sorted(REFERENCE))
def test_solver_wins(name):
    twin.solver_wins(name)


def pick_up_the_key(task):
    key = solver.find(task, "key")[0]
    solver.run(task, solver.plan(task, key, face=True) + [PICKUP])


@pytest.mark.parametrize("name", ["keycorridor-s3r3", "keycorridor-s5r3"])
def test_picking_up_the_key_does_not_end_the_episode(name):
    probe, actions = twin.record(name, 4, pick_up_the_key)
    assert probe.carrying.kind == "key" and not probe.done and probe.episode_return == 0
    task = twin.mirror(name, REFERENCE[name](), 4, actions)   # MiniGrid agrees step by step
    assert task.carrying.kind == "key" and not task.done


def test_layout():
    task = twin.make("keycorridor-s4r3")
    for seed in range(6):
        task.reset(seed=seed)
        assert task.obj.kind == "ball" and task.mission == f"pick up the {task.obj.name}"
        locked = [d for d in solver.find(task, "door") if task.grid.get(*d).is_locked]
        assert len(locked) == 1 and locked[0][0] == 6                 # east side of the hallway
        door = task.grid.get(*locked[0])
        assert task.room_from_pos(*task.obj.pos).top[0] == 6
        (key,) = solver.find(task, "key", door.color)
        assert key[0] < 3 and 3 < task.agent_pos[0] < 6                # key west, agent in the hallway
        assert solver.plan(task, task.obj.pos, face=True) is None     # the locked door is in the way


def test_time_out_gives_nothing():
    twin.time_out_gives_nothing("keycorridor-s3r1")


def test_bad_params():
    with pytest.raises(ValueError):
        twin.make("keycorridor-s3r1").__class__(num_cols=2)
    with pytest.raises(ValueError):
        twin.make("keycorridor-s3r1").__class__(obj_type="goal")
