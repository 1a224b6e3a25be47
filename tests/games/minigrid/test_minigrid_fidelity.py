"""Fidelity against Farama's ``minigrid`` package (a test-only dependency; skipped without it).

Our generators draw from the episode generator exactly as MiniGrid's do, and reset(seed) builds
the same numpy generator as gymnasium's seeding, so for every task and seed the level is
MiniGrid's level, cell for cell. Then the same actions give the same positions, facings,
carried objects, grids, rewards and terminations, and the agent sees the same cells: our view
shows exactly what MiniGrid's observation image encodes (unseen cells included).
"""

from __future__ import annotations

import os

import numpy as np
import pytest

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
minigrid_envs = pytest.importorskip("minigrid.envs")
from minigrid.core.constants import COLOR_TO_IDX, OBJECT_TO_IDX  # noqa: E402
from minigrid.core.world_object import Wall as MGWall  # noqa: E402

import glyphbench_rl  # noqa: E402
from glyphbench_rl.games.minigrid import solver  # noqa: E402
from glyphbench_rl.games.minigrid.world import AGENT, FLOOR, UNSEEN  # noqa: E402

E = minigrid_envs
REFERENCE = {   # our task -> MiniGrid env (horizon capped at 512 as ours)
    "empty-5x5": lambda: E.EmptyEnv(size=5),
    "empty-6x6": lambda: E.EmptyEnv(size=6),
    "empty-8x8": lambda: E.EmptyEnv(size=8),
    "empty-16x16": lambda: E.EmptyEnv(size=16, max_steps=512),
    "empty-random-5x5": lambda: E.EmptyEnv(size=5, agent_start_pos=None),
    "empty-random-6x6": lambda: E.EmptyEnv(size=6, agent_start_pos=None),
    "doorkey-5x5": lambda: E.DoorKeyEnv(size=5),
    "doorkey-6x6": lambda: E.DoorKeyEnv(size=6),
    "doorkey-8x8": lambda: E.DoorKeyEnv(size=8, max_steps=512),
    "doorkey-16x16": lambda: E.DoorKeyEnv(size=16, max_steps=512),
    "fourrooms": lambda: E.FourRoomsEnv(),
    "lavagap-s5": lambda: E.LavaGapEnv(size=5),
    "lavagap-s6": lambda: E.LavaGapEnv(size=6),
    "lavagap-s7": lambda: E.LavaGapEnv(size=7),
    **{f"crossing-n{k}": (lambda k=k: E.CrossingEnv(size=9, num_crossings=k)) for k in (1, 2, 3)},
    **{f"crossing-n{k}-safe": (lambda k=k: E.CrossingEnv(size=9, num_crossings=k, obstacle_type=MGWall))
       for k in (1, 2, 3)},
    **{f"simplecrossing-n{k}": (lambda k=k: E.CrossingEnv(size=11, num_crossings=k, obstacle_type=MGWall))
       for k in (1, 2, 3)},
    **{f"simplecrossing-easy-n{k}": (lambda k=k: E.CrossingEnv(size=7, num_crossings=k, obstacle_type=MGWall))
       for k in (1, 2, 3)},
    "dynamic-obstacles-5x5": lambda: E.DynamicObstaclesEnv(size=5, n_obstacles=2),
    "dynamic-obstacles-6x6": lambda: E.DynamicObstaclesEnv(size=6, n_obstacles=3),
    "dynamic-obstacles-8x8": lambda: E.DynamicObstaclesEnv(size=8, n_obstacles=4),
    "dynamic-obstacles-16x16": lambda: E.DynamicObstaclesEnv(size=16, n_obstacles=8, max_steps=512),
    "distshift1": lambda: E.DistShiftEnv(strip2_row=2),
    "distshift2": lambda: E.DistShiftEnv(strip2_row=5),
    "multiroom-n2-s4": lambda: E.MultiRoomEnv(minNumRooms=2, maxNumRooms=2, maxRoomSize=4),
    "multiroom-n4-s5": lambda: E.MultiRoomEnv(minNumRooms=4, maxNumRooms=4, maxRoomSize=5),
    "multiroom-n6": lambda: E.MultiRoomEnv(minNumRooms=6, maxNumRooms=6),
}


def test_every_task_has_a_reference():
    ours = {t.split("/minigrid-", 1)[1][:-3] for t in glyphbench_rl.list_tasks(suite="MiniGrid")}
    assert set(REFERENCE) <= ours


def encode(obj) -> tuple[int, int, int]:
    if obj is None:
        return OBJECT_TO_IDX["empty"], 0, 0
    state = (0 if obj.is_open else 2 if obj.is_locked else 1) if obj.kind == "door" else 0
    return OBJECT_TO_IDX[obj.kind], COLOR_TO_IDX[obj.color], state


def grid_code(task) -> np.ndarray:
    g = task.grid
    return np.array([[encode(g.get(x, y)) for y in range(g.height)] for x in range(g.width)], dtype="uint8")


def same_state(task, env) -> None:
    assert task.agent_pos == tuple(int(v) for v in env.agent_pos)
    assert task.agent_dir == env.agent_dir
    assert np.array_equal(grid_code(task), env.grid.encode())
    carried, theirs = task.carrying, env.carrying
    assert (carried is None) == (theirs is None)
    if carried is not None:
        assert (carried.kind, carried.color) == (theirs.type, theirs.color)


def same_view(task, env) -> None:
    """Every cell of MiniGrid's observation image against the cell our view draws there."""
    image = env.gen_obs()["image"]
    view = task.frame.grid
    cells = {(vx, vy): task.grid.view_cell(task.agent_pos, task.agent_dir, vx, vy)
             for vx in range(7) for vy in range(7)}
    x0 = min(x for x, _ in cells.values())
    y0 = min(y for _, y in cells.values())
    for (vx, vy), (x, y) in cells.items():
        drawn = view[y - y0][x - x0]
        theirs = tuple(int(v) for v in image[vx, vy])
        if (vx, vy) == (3, 6):           # MiniGrid puts the carried object where the agent stands
            assert drawn == AGENT[task.agent_dir]
            assert theirs == (encode(task.carrying) if task.carrying else encode(None))
        elif theirs[0] == OBJECT_TO_IDX["unseen"]:
            assert drawn == UNSEEN
        else:
            obj = task.grid.get(x, y)   # beyond the edge this is wall, as in MiniGrid's slice
            assert theirs == encode(obj)
            assert drawn == (FLOOR if obj is None else obj.glyph)


@pytest.mark.parametrize("name", sorted(REFERENCE))
def test_same_level_as_minigrid(name):
    task = glyphbench_rl.make(f"glyphbench/minigrid-{name}-v0")
    env = REFERENCE[name]()
    assert env.max_steps == task.max_turns
    for seed in (0, 1, 2, 1_000_000):
        task.reset(seed=seed)
        env.reset(seed=seed)
        same_state(task, env)
        assert task.mission == env.mission


def step_both(task, env, action) -> None:
    _, reward, term, trunc, _ = task.step(action)
    _, their_reward, their_term, their_trunc, _ = env.step(action)
    assert reward == pytest.approx(float(their_reward)) and term == their_term
    assert trunc == (their_trunc and not their_term)
    same_state(task, env)
    if not task.done:
        same_view(task, env)


@pytest.mark.parametrize("name", sorted(REFERENCE))
def test_same_actions_same_episode_and_view(name):
    """Random actions, then the solver's actions (pickups, doors, the goal) fed to both."""
    task = glyphbench_rl.make(f"glyphbench/minigrid-{name}-v0")
    env = REFERENCE[name]()
    rng = np.random.default_rng(7)
    task.reset(seed=3)
    env.reset(seed=3)
    same_view(task, env)
    for _ in range(40):
        step_both(task, env, int(rng.integers(task.action_space.n)))
        if task.done:
            break
    task.reset(seed=1_000_001)
    env.reset(seed=1_000_001)
    actions = []
    probe = glyphbench_rl.make(f"glyphbench/minigrid-{name}-v0")
    probe.reset(seed=1_000_001)
    probe.step = lambda a, _step=probe.step: (actions.append(a), _step(a))[1]
    solver.solve(probe, dynamic="dynamic" in name)
    assert probe.won
    for action in actions:
        step_both(task, env, action)
    assert task.won and env.step_count == task.turn
