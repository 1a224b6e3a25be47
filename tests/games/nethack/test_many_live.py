"""64 MiniHack episodes open at once in one process (the rollout engine's default), each as it
would be alone; and the rollout engine's handling of these tasks: a fresh task per episode, none
reused or closed while it plays, each freed (its NetHack with it) as soon as it finishes."""

from __future__ import annotations

import gc
import weakref

import numpy as np

import glyphbench_rl
from glyphbench_rl.rollout import RandomBackend, RolloutEngine
from glyphbench_rl.rollout.engine import EpisodeSpec

LIVE = 64
TURNS = 12
# a mix of the kinds of level: rooms, corridors, mazes, rivers, skills, monsters, Boxoban
TASKS = [f"glyphbench/minihack-{name}-v0" for name in (
    "room-5x5", "room-monster-15x15", "corridor-r3", "keyroom-s5", "mazewalk-9x9", "river",
    "eat-distract", "wield", "lavacross-levitate-ring-inv", "memento-short", "hidenseek",
    "boxoban-medium", "corridorbattle-dark", "wod-easy", "room-trap-5x5", "sink")]


def _actions(task_id: str, seed: int, n: int, count: int) -> list[int]:
    rng = np.random.default_rng([seed, TASKS.index(task_id)])
    return [int(a) for a in rng.integers(count, size=n)]


def _alone(task, seed: int, actions: list[int]) -> list:
    """The episode played on its own: every observation and reward."""
    seen = [task.reset(seed=seed)[0]]
    for a in actions:
        if task.done:
            break
        obs, reward, *_ = task.step(a)
        seen.append((obs, reward))
    return seen


def test_64_episodes_open_at_once_play_as_alone():
    episodes = [(TASKS[i % len(TASKS)], 1000 + i) for i in range(LIVE)]
    tasks = [glyphbench_rl.make(task_id) for task_id, _ in episodes]
    plans = [_actions(task_id, seed, TURNS, task.action_space.n) for (task_id, seed), task in zip(episodes, tasks)]
    seen = [[task.reset(seed=seed)[0]] for task, (_, seed) in zip(tasks, episodes)]
    assert len({id(task.env) for task in tasks}) == LIVE and len({id(task.env.nethack) for task in tasks}) == LIVE
    for turn in range(TURNS):                      # all of them a turn at a time, in turns
        for task, plan, record in zip(tasks, plans, seen):
            if not task.done:
                obs, reward, *_ = task.step(plan[turn])
                record.append((obs, reward))
    assert sum(len(record) > 1 for record in seen) == LIVE
    solo = {task_id: glyphbench_rl.make(task_id) for task_id in TASKS}   # one at a time, reused
    for (task_id, seed), plan, record in zip(episodes, plans, seen):
        assert _alone(solo[task_id], seed, plan) == record, f"{task_id} seed {seed} differs when not alone"
    for task in [*tasks, *solo.values()]:
        task.close()


def test_rollout_engine_gives_each_episode_its_own_task_and_frees_it_when_done():
    made: list[weakref.ref] = []
    engine = RolloutEngine(RandomBackend(seed=3))
    start = engine._start

    def start_and_watch(spec):                     # every episode's task and NetHack, weakly
        driver = start(spec)
        made.append((weakref.ref(driver.task), weakref.ref(driver.task.env), weakref.ref(driver.task.env.nethack)))
        return driver
    engine._start = start_and_watch
    specs = [EpisodeSpec(TASKS[i % len(TASKS)], 2000 + i, overrides={"max_turns": 6}, group=i // 8)
             for i in range(LIVE + 8)]             # more than fit at once: slots are refilled
    freed_while_running = []
    gc.disable()                                   # freed by reference counting, not by a sweep
    try:
        trajectories = engine.run(specs, on_episode=lambda traj: freed_while_running.append(
            sum(task() is None for task, _, _ in made)))
    finally:
        gc.enable()
    assert engine.max_episodes == LIVE and len(trajectories) == len(specs) == len(made)
    assert len({id(env()) for _, env, _ in made if env() is not None}) == sum(env() is not None for _, env, _ in made)
    assert freed_while_running[-1] >= len(specs) - LIVE   # finished episodes' tasks go at once
    assert all(task() is None and env() is None and nethack() is None for task, env, nethack in made)
    solo = {task_id: glyphbench_rl.make(task_id, max_turns=6) for task_id in TASKS}
    for spec, traj in zip(specs, trajectories):
        assert (traj.task_id, traj.seed) == (spec.task_id, spec.seed)
        task = solo[spec.task_id]
        obs = task.reset(seed=spec.seed)[0]
        assert obs == traj.initial_observation
        for step in traj.steps:                    # what it saw (HUD and grid), what it got
            assert obs.split("\nLegend:")[0] in step.observation
            obs, reward, term, trunc, _ = task.step(step.action)
            assert (reward, term, trunc) == (step.reward, step.terminated, step.truncated)
        assert task.done and obs == traj.final_observation
    for task in solo.values():
        task.close()
