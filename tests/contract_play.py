"""Seeded random play used by the contract tests (also run in a subprocess for determinism)."""

from __future__ import annotations

import hashlib
import json
import sys

import numpy as np

import glyphbench_rl
from glyphbench_rl.core import seeding


def play(task_id: str, seed: int, max_steps: int | None = None, forfeit_every: int = 0):
    """Random actions (from a derived, reproducible stream) until the episode ends."""
    task = glyphbench_rl.make(task_id)
    obs, info = task.reset(seed=seed)
    rng = seeding.generator(seed, "contract-actions", task_id)
    trace = [obs]
    steps = 0
    while not task.done and (max_steps is None or steps < max_steps):
        steps += 1
        if forfeit_every and steps % forfeit_every == 0:
            obs, r, term, trunc, info = task.forfeit("test")
        else:
            obs, r, term, trunc, info = task.step(int(rng.integers(task.action_space.n)))
        trace.append(f"{obs}|{r!r}|{term}|{trunc}")
    return task, trace


def digest(task_ids, seeds=(0, 7), max_steps=60) -> dict[str, str]:
    out = {}
    for task_id in task_ids:
        h = hashlib.sha256()
        for seed in seeds:
            _, trace = play(task_id, seed, max_steps=max_steps, forfeit_every=5)
            h.update("\n".join(trace).encode())
        out[task_id] = h.hexdigest()
    return out


if __name__ == "__main__":
    print(json.dumps(digest(glyphbench_rl.list_tasks() if len(sys.argv) < 2 else sys.argv[1:])))
