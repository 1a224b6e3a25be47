"""ObstructedMaze against MiniGrid's registered envs (-v1 where MiniGrid has one): same levels,
same episodes and views for the same actions, the clearing solver wins every variant on several
seeds, and the ways of not winning (the green ball, a key, a box, time) give nothing."""

from __future__ import annotations

import os

import gymnasium as gym
import pytest

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
pytest.importorskip("minigrid.envs")
import minigrid  # noqa: E402, F401  (registers MiniGrid's IDs with gymnasium)
from minigrid.envs import ObstructedMaze_Full  # noqa: E402

from glyphbench_rl.games.minigrid import obstructedmaze, solver  # noqa: E402, F401
from glyphbench_rl.games.minigrid.engine import PICKUP, TOGGLE  # noqa: E402
from glyphbench_rl.games.minigrid.obstructedmaze import CORNERS  # noqa: E402

import roomgrid_twin as twin  # noqa: E402

MINIGRID_ID = {
    "obstructedmaze-1dl": "MiniGrid-ObstructedMaze-1Dl-v0",
    "obstructedmaze-1dlh": "MiniGrid-ObstructedMaze-1Dlh-v0",
    "obstructedmaze-1dlhb": "MiniGrid-ObstructedMaze-1Dlhb-v0",
    "obstructedmaze-2dl": "MiniGrid-ObstructedMaze-2Dl-v0",
    "obstructedmaze-2dlh": "MiniGrid-ObstructedMaze-2Dlh-v0",
    "obstructedmaze-2dlhb": "MiniGrid-ObstructedMaze-2Dlhb-v1",
    "obstructedmaze-1q": "MiniGrid-ObstructedMaze-1Q-v1",
    "obstructedmaze-2q": "MiniGrid-ObstructedMaze-2Q-v1",
    "obstructedmaze-full": "MiniGrid-ObstructedMaze-Full-v1",
}
NAMES = sorted(MINIGRID_ID)


def reference(name: str):
    """MiniGrid's env with its horizon capped at 512, as ours."""
    horizon = gym.make(MINIGRID_ID[name]).unwrapped.max_steps
    return gym.make(MINIGRID_ID[name], max_steps=min(horizon, 512)).unwrapped


@pytest.mark.parametrize("name", NAMES)
def test_same_level_as_minigrid(name):
    twin.same_levels(name, reference(name), seeds=(0, 1, 2, 3, 4, 5, 1_000_000))


@pytest.mark.parametrize("name", NAMES)
def test_same_actions_same_episode_and_view(name):
    twin.random_then_solver(name, reference(name))


@pytest.mark.parametrize("name", NAMES)
def test_solver_wins(name):
    twin.solver_wins(name, seeds=(0, 1, 2, 3, 4, 1_000_000, 1_000_001))


@pytest.mark.parametrize("name", NAMES)
def test_layout(name):
    """Every locked door has its key (in a grey box when hidden), a green ball in front of it
    when blocked; the blue ball is in a corner room; MiniGrid's -v1 guarantee holds: no key lost."""
    task = twin.make(name)
    p = task.params
    for seed in range(8):
        task.reset(seed=seed)
        doors = [task.grid.get(*d) for d in solver.find(task, "door")]
        locked = [d for d in doors if d.is_locked]
        assert len(doors) == (1 if p.quarters == 0 else 3 * p.quarters)
        assert len(locked) == (1 if p.quarters == 0 else 2 * p.quarters)
        keys = [o for o in task.grid.objects() if o.kind == "key"]
        boxes = [o for o in task.grid.objects() if o.kind == "box"]
        hidden = [b.contains for b in boxes]
        assert sorted(k.color for k in keys + hidden) == sorted(d.color for d in locked)
        assert (not keys) == p.key_in_box and all(b.color == "grey" for b in boxes)
        green = [o for o in task.grid.objects() if o.kind == "ball" and o.color == "green"]
        assert len(green) == (len(locked) if p.blocked else 0)
        target = task.pickup_target
        assert (target.kind, target.color) == ("ball", "blue") and task.mission == "pick up the blue ball"
        room = task.room_from_pos(*target.pos)
        corners = [(1, 0)] if p.quarters == 0 else CORNERS[:p.quarters]
        assert room in [task.get_room(*c) for c in corners]
        assert solver.plan(task, target.pos, face=True) is None      # never free for the taking


def test_keys_first_is_minigrid_v0_which_can_lose_a_key():
    """keys_last=False builds MiniGrid's -v0 level (why the IDs follow -v1): there a blocking
    ball can be written over a key's box, leaving a locked door without its key."""
    task = obstructedmaze.ObstructedMaze(keys_last=False, max_turns=512)
    env = ObstructedMaze_Full(max_steps=512)            # MiniGrid-ObstructedMaze-Full-v0
    lost = []
    for seed in range(40):
        task.reset(seed=seed)
        env.reset(seed=seed)
        twin.same_state(task, env)
        if len(solver.find(task, "box")) < 8:
            lost.append(seed)
    assert lost


def test_other_pickups_and_boxes_do_not_end_the_episode():
    """Carry the green ball aside, open the box, carry the key: MiniGrid agrees step by step and
    nothing ends or pays."""
    name = "obstructedmaze-1dlhb"

    def script(task):
        green = next(o for o in task.grid.objects() if o.color == "green")
        assert solver.pick_up(task, green) and not task.done
        assert solver.drop_beside(task) and task.carrying is None
        box = solver.find(task, "box")[0]
        key = task.grid.get(*box).contains
        solver.reach(task, box)
        task.step(TOGGLE)
        assert task.grid.get(*box) is key
        task.step(PICKUP)
        assert task.carrying is key and not task.done
    probe, actions = twin.record(name, 5, script)
    task = twin.mirror(name, reference(name), 5, actions)
    assert task.carrying.kind == "key" and not task.done and task.episode_return == 0


def test_the_blue_ball_wins_wherever_it_is_picked_up():
    task = twin.make("obstructedmaze-1dl")
    task.reset(seed=2)
    while task.grid.get(*task.front_pos) is not None:
        task.step(0)                                                   # TURN_LEFT
    ball = task.pickup_target
    task.grid.set(*ball.pos, None)
    task.grid.set(*task.front_pos, ball)
    _, reward, term, trunc, _ = task.step(PICKUP)
    assert term and not trunc and task.won and reward == pytest.approx(1 - 0.9 * task.turn / task.max_turns)


@pytest.mark.parametrize("name", ["obstructedmaze-1dl", "obstructedmaze-full"])
def test_time_out_gives_nothing(name):
    twin.time_out_gives_nothing(name)


def test_bad_params():
    with pytest.raises(ValueError):
        twin.make("obstructedmaze-full").__class__(quarters=5)
    with pytest.raises(ValueError):
        twin.make("obstructedmaze-full").__class__(quarters=0)     # needs the 2x1 room grid
