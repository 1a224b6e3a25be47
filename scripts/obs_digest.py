#!/usr/bin/env python
"""A digest of everything a task shows an agent, to check that a refactor changed none of it.

    python scripts/obs_digest.py [--tasks IDS|GLOB|FILE] [--seeds 4] [--steps 300] [-v]

For every task (default: all registered): the system prompt, then random episodes on a few seeds
(a seeded reset, uniformly random action indices from a fixed stream, one forfeit turn, and a
second seeded episode after the first ends), hashing every observation, reward, flag and the
info fields a game reports. Prints one SHA-256 per task with ``-v`` and always the digest over
all tasks; run it before and after a change that should not alter behaviour and compare.
"""

from __future__ import annotations

import argparse
import hashlib
import sys

import numpy as np

from glyphbench_rl import list_tasks, make
from glyphbench_rl.core import resolve_tasks


def task_digest(task_id: str, seeds: int, steps: int) -> str:
    h = hashlib.sha256()
    task = make(task_id)
    h.update(task.system_prompt().encode())
    n = task.action_space.n
    for seed in range(seeds):
        actions = np.random.Generator(np.random.PCG64(1000 + seed)).integers(n, size=steps)
        obs, info = task.reset(seed=seed)
        h.update(obs.encode())
        h.update(repr(sorted((k, v) for k, v in info.items() if k != "frame")).encode())
        for t, a in enumerate(actions):
            if task.done:
                obs, info = task.reset(seed=10_000 + seed * 100 + t)
                h.update(b"reset" + obs.encode())
                continue
            if t == 3:
                out = task.forfeit("no_tag")
            else:
                out = task.step(int(a))
            obs, reward, term, trunc, info = out
            h.update(obs.encode())
            h.update(repr((round(reward, 12), term, trunc)).encode())
            h.update(repr(sorted((k, v) for k, v in info.items() if k != "frame")).encode())
    return h.hexdigest()


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--tasks", help="task ID, glob, comma list or task-list file (default: all)")
    p.add_argument("--seeds", type=int, default=4)
    p.add_argument("--steps", type=int, default=300)
    p.add_argument("-v", "--verbose", action="store_true", help="one digest per task")
    args = p.parse_args()
    total = hashlib.sha256()
    for task_id in resolve_tasks(args.tasks) if args.tasks else list_tasks():
        d = task_digest(task_id, args.seeds, args.steps)
        total.update(f"{task_id} {d}\n".encode())
        if args.verbose:
            print(f"{task_id} {d}")
    print(f"all {total.hexdigest()}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
