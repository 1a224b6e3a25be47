"""`glyphbench bench` on NetHack-engine tasks: the engine alone on the same turns beside ours,
memory per live episode, and the engine's keys recorded turn by turn (no timing asserted)."""

from __future__ import annotations

import glyphbench_rl
from glyphbench_rl.evaluate import bench

TASK = "glyphbench/minihack-eat-distract-v0"


def test_engine_tasks_get_the_engine_alone_beside_ours():
    maze, eat = bench.bench(["glyphbench/classics-maze-easy-v0", TASK], runs=1, steps=30, rounds=1,
                            count_tokens=lambda text: len(text.split()))
    assert maze.raw_step_us is None and maze.raw_ratio is None      # other suites as before
    assert eat.raw_step_us > 0 and eat.raw_ratio == eat.step_us / eat.raw_step_us
    memory = {"live": 64, "tasks": 1, "stepped": 64, "rss_mib": 1.0, "shared_mib": 3.0, "per_episode_mib": 4.0}
    table = bench.format_table([maze, eat], memory)
    head = table.splitlines()[0].split()
    assert "raw" in head and "x" in head
    assert "median ratio ours / engine alone:" in table and "target <= 1.3" in table
    assert "median obs tokens:" in table and "memory per live episode: 4.00 MiB" in table
    assert "engine alone" not in bench.format_table([maze])


def test_replay_records_each_turns_keys_and_times_them_on_upstreams_env():
    task = glyphbench_rl.make(TASK)
    replay = task.raw_replay()
    times, _, _ = bench._run(task, 0, 25, recorder=replay)
    replay.stop_recording()
    turns = [keys for kind, keys in replay.plan if kind == "turn"]
    assert len(turns) == len(times) == 25 and all(len(keys) >= 1 for keys in turns)
    assert replay.plan[0] == ("reset", 0)
    assert len(replay.times()) == 25
    assert type(replay._env) is not type(task.env) and isinstance(task.env, type(replay._env))   # upstream's own
    replay.close()
    task.close()


def test_memory_per_live_episode_in_a_fresh_process():
    m = bench.live_memory([TASK, "glyphbench/minihack-room-5x5-v0"], live=4)
    assert m["live"] == 4 and m["stepped"] == 4 and m["tasks"] == 2
    assert m["shared_mib"] > 1 and m["per_episode_mib"] == m["rss_mib"] + m["shared_mib"]
