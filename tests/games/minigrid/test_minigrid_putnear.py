"""PutNear (MiniGrid PutNearEnv): same levels and episodes as MiniGrid, wins, and the ways to lose
(a wrong pickup, a drop away from the target, a blocked drop)."""

from __future__ import annotations

import os

import pytest

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
E = pytest.importorskip("minigrid.envs")

import glyphbench_rl  # noqa: E402
from glyphbench_rl.games.minigrid import solver  # noqa: E402
from glyphbench_rl.games.minigrid.engine import DROP, LEFT, PICKUP, RIGHT  # noqa: E402
from minigrid_reference import check_episodes, check_levels, play_both  # noqa: E402

VARIANTS = {"putnear-6x6-n2": (6, 2), "putnear-8x8-n3": (8, 3)}


def make(name):
    return E.PutNearEnv(size=VARIANTS[name][0], numObjs=VARIANTS[name][1])


@pytest.mark.parametrize("name", VARIANTS)
def test_same_levels_and_episodes_as_minigrid(name):
    check_levels(name, make(name))
    check_episodes(name, lambda: make(name))


@pytest.mark.parametrize("name", VARIANTS)
def test_objects_keep_apart_and_differ(name):
    task = glyphbench_rl.make(f"glyphbench/minigrid-{name}-v0")
    for seed in range(20):
        task.reset(seed=seed)
        objs = [o for o in task.grid.objects() if o.kind != "wall"]
        assert len(objs) == VARIANTS[name][1] and len({(o.kind, o.color) for o in objs}) == len(objs)
        assert all(max(abs(a.pos[0] - b.pos[0]), abs(a.pos[1] - b.pos[1])) > 1
                   for a in objs for b in objs if a is not b)
        assert task.move != task.target and task.grid.get(*task.target_pos) is not None


@pytest.mark.parametrize("name", VARIANTS)
def test_picking_up_a_wrong_object_fails(name):
    for seed in range(4):
        task = glyphbench_rl.make(f"glyphbench/minigrid-{name}-v0")
        task.reset(seed=seed)
        path = solver.plan(task, task.target_pos, face=True)
        task, _ = play_both(name, make(name), seed, path + [PICKUP])
        assert task.done and task.won is False and task.episode_return == 0
        assert "not the object to move" in task.frame.message


def test_dropping_away_from_the_target_fails():
    name = "putnear-8x8-n3"
    dropped = 0
    for seed in range(8):
        task = glyphbench_rl.make(f"glyphbench/minigrid-{name}-v0")
        task.reset(seed=seed)
        path = solver.plan(task, task.move_pos, face=True) + [PICKUP]
        solver.run(task, path)
        tx, ty = task.target_pos
        for turn in (RIGHT, LEFT, LEFT):                  # drop where it lay, or beside it
            fx, fy = task.front_pos
            if max(abs(fx - tx), abs(fy - ty)) > 1 and task.grid.get(fx, fy) is None:
                break
            task.step(turn)
            path.append(turn)
        else:
            continue
        task, _ = play_both(name, make(name), seed, path + [DROP])
        assert task.done and task.won is False and task.episode_return == 0
        assert task.carrying is None and "not near" in task.frame.message
        dropped += 1
    assert dropped >= 5


def test_a_blocked_drop_ends_the_episode_too():
    name = "putnear-6x6-n2"
    task = glyphbench_rl.make(f"glyphbench/minigrid-{name}-v0")
    task.reset(seed=0)
    path = solver.plan(task, task.move_pos, face=True) + [PICKUP]
    solver.run(task, path)
    path += solver.plan(task, (0, task.agent_pos[1]), face=True)    # face the west wall
    task, _ = play_both(name, make(name), 0, path + [DROP])
    assert task.done and task.won is False and task.episode_return == 0
    assert task.carrying is not None and task.grid.get(*task.front_pos).kind == "wall"
    assert "could not drop" in task.frame.message
