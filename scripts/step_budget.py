#!/usr/bin/env python
"""Where a task's step time goes: the grid, the HUD, the game's own turn, the shared frame.

    python scripts/step_budget.py [--tasks IDS|GLOB|FILE] [--runs 3] [--steps 400] [--rounds 2]
    python scripts/step_budget.py --bytecodes [--top 15] [--tasks ...]

Each task is played as ``glyphbench bench`` plays it (random actions on seeds 0 .. runs-1, every
step timed, the median kept) five ways, alternating within each round, the least disturbed round
of each kept:

- ``full``: as it is;
- the grid held: ``_grid`` returns the first frame's rows (the game still plays the same turns);
- the HUD held: ``_hud`` returns the first frame's line;
- both held;
- nothing but the frame: ``_act`` does nothing and both are held (the step every task pays for
  turn counting, the legend, the observation text and the info dict).

and prints per task ``full``, ``grid`` (full - grid held), ``hud`` (full - HUD held), ``turn``
(both held - frame) and ``frame``, then their medians over the tasks. Measured in the running
loop, so each part is charged what it costs there (a part timed alone, with its data in the
caches, comes out cheaper). The parts need not add up to ``full`` exactly.

With ``--bytecodes`` it counts instead of timing: the median number of Python bytecodes a step
executes per task, and the functions that execute the most. Unlike a time, the count is the same
on a busy machine, so it compares two versions of the code run at different moments. It is a
guide, not a time: work done in C counts as the one call that starts it (a numpy call, or a
``reduce(or_, map(...))`` that replaces a loop of seven bytecodes an item, and measured slower
than that loop).
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from collections import Counter
from pathlib import Path

from glyphbench_rl.core import make, resolve_tasks
from glyphbench_rl.evaluate.bench import follow_on_seed, stream_actions

ROOT = Path(__file__).resolve().parents[1]

VARIANTS = ("full", "grid held", "hud held", "both held", "frame only")


def _hold(task, variant: str) -> None:
    """Patch ``task`` (just reset) for ``variant``: its hooks return the first frame's parts."""
    for name in ("_grid", "_hud", "_act"):
        task.__dict__.pop(name, None)
    if variant == "full":
        return
    grid, hud = tuple(type(task)._grid(task)), type(task)._hud(task)
    if variant in ("grid held", "both held", "frame only"):
        task._grid = lambda: grid
    if variant in ("hud held", "both held", "frame only"):
        task._hud = lambda: hud
    if variant == "frame only":
        task._act = lambda action: None


def _play(task, variant: str, runs: int, steps: int, each) -> None:
    """Play ``task`` (patched for ``variant``) as the bench does: ``steps`` random actions from
    each of seeds 0 .. runs-1, an episode that ends followed by another; ``each(step, action)``
    takes each step."""
    for seed in range(runs):
        actions = stream_actions(task, seed, steps)
        task.reset(seed=seed)
        _hold(task, variant)
        episode, step = 0, task.step
        for a in actions:
            if task.done:
                episode += 1
                task.reset(seed=follow_on_seed(seed, episode))
                _hold(task, variant)
            each(step, a)
    _hold(task, "full")


def _median_step(task, variant: str, runs: int, steps: int) -> float:
    clock, times = time.perf_counter, []

    def timed(step, action):
        t0 = clock()
        step(action)
        times.append(clock() - t0)

    _play(task, variant, runs, steps, timed)
    return statistics.median(times) * 1e6


def _bytecodes(task, runs: int, steps: int, by_code: Counter) -> float:
    """The median number of Python bytecodes a step of ``task`` executes (each code object's
    count added to ``by_code``): a measure of the interpreter's work that a busy machine does
    not disturb (work done in C, a numpy call, counts as one call)."""
    counts, total = [], [0]

    def tracer(frame, event, arg):
        frame.f_trace_opcodes = True
        if event == "opcode":
            by_code[frame.f_code] += 1
            total[0] += 1
        return tracer

    def traced(step, action):
        before = total[0]
        sys.settrace(tracer)
        try:
            step(action)
        finally:
            sys.settrace(None)
        counts.append(total[0] - before)

    _play(task, "full", runs, steps, traced)
    return statistics.median(counts)


def _bytecode_table(tasks: dict, runs: int, steps: int, top: int) -> None:
    by_code: Counter = Counter()
    medians = {}
    print(f"{'task':48s}{'bytecodes':>10s}   (median Python bytecodes per step)")
    for task_id, task in tasks.items():
        medians[task_id] = _bytecodes(task, runs, steps, by_code)
        print(f"{task_id:48s}{medians[task_id]:10.0f}")
    if len(medians) > 1:
        print(f"{'median over ' + str(len(medians)) + ' tasks':48s}{statistics.median(medians.values()):10.0f}")
    played = len(tasks) * runs * steps
    print(f"\nthe {top} functions that execute the most (bytecodes per step, all tasks' steps):")
    for code, n in by_code.most_common(top):
        where = Path(code.co_filename)
        where = where.relative_to(ROOT) if where.is_relative_to(ROOT) else where.name
        print(f"{n / played:10.1f}  {where}:{code.co_name}")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tasks", default="glyphbench/craftax-*")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--steps", type=int, default=400)
    parser.add_argument("--rounds", type=int, default=2)
    parser.add_argument("--bytecodes", action="store_true",
                        help="count the Python bytecodes each step executes instead of timing")
    parser.add_argument("--top", type=int, default=15, help="with --bytecodes: functions listed")
    args = parser.parse_args(argv)
    task_ids = resolve_tasks(args.tasks)
    tasks = {task_id: make(task_id) for task_id in task_ids}
    if args.bytecodes:
        _bytecode_table(tasks, args.runs, args.steps, args.top)
        return 0
    best = {task_id: dict.fromkeys(VARIANTS, float("inf")) for task_id in task_ids}
    for _ in range(args.rounds):
        for task_id, task in tasks.items():
            for variant in VARIANTS:
                us = _median_step(task, variant, args.runs, args.steps)
                best[task_id][variant] = min(best[task_id][variant], us)
    columns = ("full", "grid", "hud", "turn", "frame")
    rows = {}
    print(f"{'task':48s}" + "".join(f"{c:>8s}" for c in columns) + "   (median us per step)")
    for task_id, m in best.items():
        rows[task_id] = (m["full"], m["full"] - m["grid held"], m["full"] - m["hud held"],
                         m["both held"] - m["frame only"], m["frame only"])
        print(f"{task_id:48s}" + "".join(f"{x:8.1f}" for x in rows[task_id]))
    if len(rows) > 1:
        medians = [statistics.median(r[i] for r in rows.values()) for i in range(len(columns))]
        print(f"{'median over ' + str(len(rows)) + ' tasks':48s}" + "".join(f"{x:8.1f}" for x in medians))
    return 0


if __name__ == "__main__":
    sys.exit(main())
