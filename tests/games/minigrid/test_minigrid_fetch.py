"""Fetch (MiniGrid FetchEnv): same levels and episodes as MiniGrid, wins, and wrong pickups."""

from __future__ import annotations

import os

import pytest

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
E = pytest.importorskip("minigrid.envs")

import glyphbench_rl  # noqa: E402
from glyphbench_rl.games.minigrid import fetch, solver  # noqa: E402
from glyphbench_rl.games.minigrid.engine import PICKUP  # noqa: E402
from minigrid_reference import check_episodes, check_levels, play_both  # noqa: E402

VARIANTS = {"fetch-5x5-n2": (5, 2), "fetch-6x6-n2": (6, 2), "fetch-8x8-n3": (8, 3)}


@pytest.mark.parametrize("name", VARIANTS)
def test_same_levels_and_episodes_as_minigrid(name):
    n, k = VARIANTS[name]
    make = lambda: E.FetchEnv(size=n, numObjs=k)  # noqa: E731
    check_levels(name, make())
    check_episodes(name, make)


@pytest.mark.parametrize("name", VARIANTS)
def test_picking_up_another_object_fails(name):
    n, k = VARIANTS[name]
    failures = 0
    for seed in range(30):
        task = glyphbench_rl.make(f"glyphbench/minigrid-{name}-v0")
        task.reset(seed=seed)
        others = [o for o in task.grid.objects() if o.kind != "wall" and (o.kind, o.color) != task.target]
        paths = [p for p in (solver.plan(task, o.pos, face=True) for o in others) if p is not None]
        if not paths:
            continue
        task, env = play_both(name, E.FetchEnv(size=n, numObjs=k), seed, paths[0] + [PICKUP])
        assert task.done and task.won is False and task.episode_return == 0
        assert task.carrying is not None and "not what the mission asks" in task.frame.message
        failures += 1
    assert failures >= 10


def test_mission_names_the_target_in_one_of_minigrids_phrasings():
    task = glyphbench_rl.make("glyphbench/minigrid-fetch-8x8-n3-v0")
    phrasings = set()
    for seed in range(40):
        task.reset(seed=seed)
        kind, color = task.target
        assert task.mission.endswith(f" a {color} {kind}")
        assert f"Mission: {task.mission}" in task.frame.hud
        phrasings.add(task.mission.rsplit(" ", 2)[0])
    assert phrasings == set(fetch.SYNTAX)
