"""``glyphbench``: list, show, play, random-agent runs and the environment benchmark."""

from __future__ import annotations

import argparse
import json
import os
import statistics
import sys
from collections import Counter
from pathlib import Path
from typing import Sequence

from ..core import list_tasks, make, resolve_tasks, seeding
from ..core.registry import SUITES, MissingExtraError, UnknownTaskError, get_spec
from .replay import register as _register_replay

CATALOG = Path(__file__).resolve().parents[2] / "tasks" / "catalog.tsv"


def _catalog_counts() -> Counter:
    counts: Counter = Counter()
    if CATALOG.exists():
        for line in CATALOG.read_text(encoding="utf-8").splitlines()[1:]:
            counts[line.split("\t", 1)[0]] += 1
    return counts


def cmd_list(args) -> int:
    ids = list_tasks(suite=args.suite, pattern=args.pattern, tier=args.tier)
    if not args.counts:
        for task_id in ids:
            print(task_id)
        return 0
    out = sys.stdout
    planned = _catalog_counts()
    have = Counter(get_spec(t).suite for t in ids)
    print(f"{'suite':<12} {'tasks':>5}" + (f" {'of':>4}" if planned else ""), file=out)
    for suite in SUITES:
        if have[suite] or (planned and args.suite is None and args.pattern is None):
            line = f"{suite:<12} {have[suite]:>5}" + (f" {planned[suite]:>4}" if planned else "")
            print(line, file=out)
    print(f"{'total':<12} {len(ids):>5}" + (f" {sum(planned.values()):>4}" if planned else ""), file=out)
    return 0


def cmd_show(args) -> int:
    task = make(args.task)
    obs, _ = task.reset(seed=args.seed)
    print("=== system prompt ===")
    print(task.system_prompt())
    print(f"=== observation (seed {args.seed}) ===")
    print(obs)
    return 0


# what a terminal sends for the arrow keys (normal and application cursor mode), and the
# actions an arrow stands for, first match wins (MiniGrid moves forward and turns)
ARROW_KEYS = {"\x1b[A": "UP", "\x1bOA": "UP", "\x1b[B": "DOWN", "\x1bOB": "DOWN",
              "\x1b[C": "RIGHT", "\x1bOC": "RIGHT", "\x1b[D": "LEFT", "\x1bOD": "LEFT"}
ARROW_ACTIONS = {"UP": ("UP", "FORWARD"), "DOWN": ("DOWN",), "RIGHT": ("RIGHT", "TURN_RIGHT"),
                 "LEFT": ("LEFT", "TURN_LEFT")}


def cmd_play(args) -> int:
    task = make(args.task)
    obs, _ = task.reset(seed=args.seed)
    print(task.system_prompt(), end="\n\n")
    print(obs)
    print("(type an action name or press an arrow key, then Enter; 'help' lists them, 'quit' stops)")
    while not task.done:
        try:
            line = input("action> ").strip()
        except EOFError:
            print()
            break
        if line.lower() in ("quit", "exit", "q"):
            break
        if not line:
            continue
        if line.lower() in ("help", "?"):
            print("\n".join(task.actions.prompt_lines()))
            continue
        index = task.actions.lookup(ARROW_KEYS.get(line, line))
        if index is None and line in ARROW_KEYS:
            index = next((i for name in ARROW_ACTIONS[ARROW_KEYS[line]]
                          if (i := task.actions.lookup(name)) is not None), None)
        if index is None:
            print(f"unknown action {line!r}; valid actions: {', '.join(task.actions.names)}")
            continue
        obs, reward, term, trunc, _ = task.step(index)
        print(f"\n{obs}\nreward {reward:+.3f}  return {task.episode_return:+.3f}")
    if task.done:
        how = "won" if task.won else "lost" if task.won is False else "truncated" if task._truncated else "ended"
        print(f"episode {how} after {task.turn} turns, return {task.episode_return:+.3f}")
    return 0


def cmd_random(args) -> int:
    task_ids = resolve_tasks(args.tasks)
    seeds = list(range(args.seed, args.seed + args.episodes))  # distinct game instances, one each
    rows = []
    print(f"{'task':<44} {'episodes':>8} {'mean return':>11} {'min':>7} {'max':>7} {'mean len':>8} {'won':>4}")
    for task_id in task_ids:
        task = make(task_id)
        returns, lengths, wins = [], [], 0
        for seed in seeds:
            task.reset(seed=seed)
            rng = seeding.generator(seed, "random-agent", task_id)
            while not task.done:
                task.step(int(rng.integers(task.action_space.n)))
            returns.append(task.episode_return)
            lengths.append(task.turn)
            wins += bool(task.won)
            if args.verbose:
                print(f"  {task_id} seed {seed}: return {task.episode_return:+.3f} length {task.turn}")
        row = dict(task_id=task_id, episodes=len(seeds), mean_return=statistics.fmean(returns),
                   min_return=min(returns), max_return=max(returns),
                   mean_length=statistics.fmean(lengths), wins=wins)
        rows.append(row)
        print(f"{task_id:<44} {row['episodes']:>8} {row['mean_return']:>+11.3f} {row['min_return']:>+7.3f} "
              f"{row['max_return']:>+7.3f} {row['mean_length']:>8.1f} {wins:>4}")
    if len(rows) > 1:
        print(f"{'mean over tasks':<44} {'':>8} {statistics.fmean(r['mean_return'] for r in rows):>+11.3f}")
    if args.json:
        Path(args.json).write_text(json.dumps(rows, indent=1))
    return 0


def cmd_bench(args) -> int:
    from ..evaluate import bench
    task_ids = resolve_tasks(args.tasks) if args.tasks else list_tasks()
    counter = bench.load_token_counter(args.tokenizer) if args.tokenizer else None
    progress = (lambda line: print(f"  {line}", file=sys.stderr)) if args.progress else None
    results = bench.bench(task_ids, runs=args.runs, steps=args.steps, rounds=args.rounds,
                          count_tokens=counter, progress=progress)
    engine_ids = [r.task_id for r in results if r.raw_step_us is not None]
    memory = bench.live_memory(engine_ids, args.live) if engine_ids and args.live else None
    print(bench.format_table(results, memory))
    if args.json:
        rows = bench.to_json(results)
        for row in rows:            # (the memory figure belongs to the engine tasks together)
            if memory and row["task_id"] in engine_ids:
                row["live_memory"] = memory
        Path(args.json).write_text(json.dumps(rows, indent=1))
    return 0


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="glyphbench", description=__doc__)
    sub = p.add_subparsers(dest="command", required=True)

    s = sub.add_parser("list", help="registered task IDs and counts per suite")
    s.add_argument("--suite", help="one suite, e.g. Classics")
    s.add_argument("--tier", choices=["standard", "extended"])
    s.add_argument("--pattern", help="glob over IDs, e.g. '*snake*'")
    s.add_argument("--counts", action="store_true", help="only the counts")
    s.set_defaults(func=cmd_list)

    s = sub.add_parser("show", help="system prompt and first observation of a task")
    s.add_argument("task")
    s.add_argument("--seed", type=int, default=0)
    s.set_defaults(func=cmd_show)

    s = sub.add_parser("play", help="play a task in the terminal by typing action names")
    s.add_argument("task")
    s.add_argument("--seed", type=int, default=0)
    s.set_defaults(func=cmd_play)

    s = sub.add_parser("random", help="a uniform random agent over a task list; prints returns")
    s.add_argument("tasks", help="task ID, glob, comma list or task-list file")
    s.add_argument("--episodes", type=int, default=5)
    s.add_argument("--seed", type=int, default=seeding.HELDOUT_SEEDS.start,
                   help="first episode seed (default: the first held-out seed)")
    s.add_argument("--json", help="also write the per-task rows to this file")
    s.add_argument("-v", "--verbose", action="store_true", help="one line per episode")
    s.set_defaults(func=cmd_random)

    s = sub.add_parser("bench", help="step+render time and observation size per task, "
                                      "against the reference implementation's figures")
    s.add_argument("--tasks", help="task ID, glob, comma list or task-list file (default: all)")
    s.add_argument("--runs", type=int, default=3, help="episode streams, on seeds 0..runs-1 (default 3)")
    s.add_argument("--steps", type=int, default=400, help="random actions per run (default 400)")
    s.add_argument("--rounds", type=int, default=3,
                   help="repeats of the whole measurement; the least disturbed is kept (default 3)")
    s.add_argument("--tokenizer", help="'smollm2', a tokenizer.json path or a HF tokenizer name")
    s.add_argument("--live", type=int, default=64,
                   help="engine tasks (NetHack, MiniHack): memory per episode with this many open "
                        "at once, in a fresh process (default 64; 0: skip)")
    s.add_argument("--json", help="also write the results to this file")
    s.add_argument("--progress", action="store_true")
    s.set_defaults(func=cmd_bench)

    _register_replay(sub)
    from .plot import register as register_plot
    register_plot(sub)
    return p


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    for name in ("episodes", "runs", "steps", "rounds"):
        if getattr(args, name, 1) < 1:
            print(f"glyphbench: error: --{name} must be at least 1", file=sys.stderr)
            return 2
    try:
        return args.func(args)
    except (UnknownTaskError, MissingExtraError, ValueError, FileNotFoundError) as e:
        print(f"glyphbench: error: {e}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        return 130
    except BrokenPipeError:
        # the reader went away (`glyphbench show ... | head`): stop quietly, as Unix tools do
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 141


if __name__ == "__main__":
    sys.exit(main())
