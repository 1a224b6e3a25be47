"""GoToDoor (MiniGrid GoToDoorEnv) and GoToObject (GoToObjectEnv): same levels and episodes as
MiniGrid, wins with DONE beside the target, and the ways to lose (DONE elsewhere, TOGGLE)."""

from __future__ import annotations

import os

import pytest

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
E = pytest.importorskip("minigrid.envs")

import glyphbench_rl  # noqa: E402
from glyphbench_rl.games.minigrid import gotodoor, solver  # noqa: E402
from glyphbench_rl.games.minigrid.engine import DONE, LEFT, TOGGLE  # noqa: E402
from minigrid_reference import check_episodes, check_levels, play_both  # noqa: E402

REFERENCE = {
    "gotodoor-5x5": lambda: E.GoToDoorEnv(size=5),
    "gotodoor-6x6": lambda: E.GoToDoorEnv(size=6),
    "gotodoor-8x8": lambda: E.GoToDoorEnv(size=8),
    "gotoobject-6x6-n2": lambda: E.GoToObjectEnv(size=6, numObjs=2),
}


@pytest.mark.parametrize("name", REFERENCE)
def test_same_levels_and_episodes_as_minigrid(name):
    check_levels(name, REFERENCE[name]())
    check_episodes(name, REFERENCE[name])


def test_rooms_vary_in_size_and_have_four_doors_of_four_colours():
    task = glyphbench_rl.make("glyphbench/minigrid-gotodoor-8x8-v0")
    sizes = set()
    for seed in range(40):
        task.reset(seed=seed)
        doors = [task.grid.get(*p) for p in solver.find(task, "door")]
        assert len(doors) == 4 and len({d.color for d in doors}) == 4
        assert not any(d.is_open or d.is_locked for d in doors)
        assert task.target_color in {d.color for d in doors} and task.mission.endswith(task.target_color + " door")
        sizes.add(max(x for x, _ in solver.find(task, "door")) + 1)
    assert sizes == {5, 6, 7, 8}


@pytest.mark.parametrize("name", REFERENCE)
def test_done_beside_another_door_or_object_fails(name):
    failures = 0
    for seed in range(8):
        task = glyphbench_rl.make(f"glyphbench/minigrid-{name}-v0")
        task.reset(seed=seed)
        other = next(o.pos for o in task.grid.objects() if o.kind != "wall" and o.pos != task.target_pos)
        path = solver.plan(task, other, face=True, blocked=lambda p: p == task.target_pos)
        task, _ = play_both(name, REFERENCE[name](), seed, path + [DONE])
        assert task.done and task.turn == len(path) + 1
        if gotodoor.beside(task.agent_pos, task.target_pos):    # beside both: still a win
            assert task.won
            continue
        assert task.won is False and task.episode_return == 0 and "not beside" in task.frame.message
        failures += 1
    assert failures >= 4


@pytest.mark.parametrize("name", REFERENCE)
def test_toggle_ends_the_episode_even_at_the_target(name):
    task = glyphbench_rl.make(f"glyphbench/minigrid-{name}-v0")
    task.reset(seed=5)
    path = solver.plan(task, task.target_pos, face=True)
    task, _ = play_both(name, REFERENCE[name](), 5, path + [TOGGLE])
    assert task.done and task.won is False and task.episode_return == 0


def test_done_wins_beside_the_door_whatever_the_facing_and_fails_elsewhere():
    task = glyphbench_rl.make("glyphbench/minigrid-gotodoor-6x6-v0")
    task.reset(seed=2)
    assert not gotodoor.beside(task.agent_pos, task.target_pos)
    _, reward, term, _, _ = task.step(DONE)
    assert term and reward == 0 and task.won is False
    task.reset(seed=2)
    solver.run(task, solver.plan(task, task.target_pos, face=True) + [LEFT])
    assert task.front_pos != task.target_pos                    # turned away from the door
    _, reward, term, _, _ = task.step(DONE)
    assert term and task.won and reward == pytest.approx(1 - 0.9 * task.turn / task.max_turns)
