"""Rollout-engine overhead: everything the engine does per episode-turn except the backend.

Plays batches of episodes with the random backend (whose own time is measured separately and
subtracted) and prints the median over repeats, for a plain and a legend-on-change harness.
Target: <= 1 ms per episode-turn.

    python scripts/bench_rollout.py [--tasks tasks/standard.txt] [--episodes 8] [--repeats 5]
"""

from __future__ import annotations

import argparse
import statistics

from glyphbench_rl.agent import HarnessConfig
from glyphbench_rl.core import resolve_tasks
from glyphbench_rl.rollout import EpisodeSpec, Generation, RandomBackend, RolloutEngine

TARGET_MS = 1.0


class RandomTokenBackend(RandomBackend):
    """Random actions answered as token ids, so the engine's token path (per-message
    tokenisation, prompt assembly) is measured; encoding the reply counts as backend time."""

    def __init__(self, tokenizer, seed=0):
        super().__init__(seed=seed)
        self.tokenizer = tokenizer

    def generate(self, requests):
        gens = super().generate(requests)
        eos = self.tokenizer.eos_token_id
        return [Generation(g.text, self.tokenizer.encode(g.text, add_special_tokens=False) + [eos],
                           None) for g in gens]


def measure(task_ids, episodes, repeats, harness, batch, tokenizer=None):
    per_turn, turns = [], 0
    for r in range(repeats):
        backend = RandomBackend(seed=r) if tokenizer is None else RandomTokenBackend(tokenizer, r)
        eng = RolloutEngine(backend, harness, max_episodes=batch)
        eng.run([EpisodeSpec(t, 1_000_000 + s) for t in task_ids for s in range(episodes)])
        per_turn.append(eng.stats.overhead_ms_per_turn)
        turns = eng.stats.turns
    return statistics.median(per_turn), turns


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tasks", default="tasks/standard.txt")
    ap.add_argument("--episodes", type=int, default=8)
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--batch", type=int, default=64)
    ap.add_argument("--tokenizer", help="also measure the token path: 'smollm2' or a model folder")
    args = ap.parse_args()
    task_ids = resolve_tasks(args.tasks)
    print(f"{len(task_ids)} tasks x {args.episodes} episodes, batch {args.batch}, "
          f"median of {args.repeats} runs")
    ok = True
    cases = [("text, history 8", HarnessConfig(), None),
             ("text, history 8, legend on change", HarnessConfig(legend="changed"), None)]
    if args.tokenizer:
        from glyphbench_rl.models import load_tokenizer
        tok = load_tokenizer(args.tokenizer)
        cases.append((f"tokens ({args.tokenizer}), history 8", HarnessConfig(), tok))
    for label, harness, tokenizer in cases:
        ms, turns = measure(task_ids, args.episodes, args.repeats, harness, args.batch, tokenizer)
        ok &= ms <= TARGET_MS
        print(f"{label:<40} {ms:7.3f} ms per episode-turn ({turns} turns per run)")
    print(f"target <= {TARGET_MS} ms: {'OK' if ok else 'MISSED'}")
    return 0 if ok else 1


if __name__ == "__main__":
    raise SystemExit(main())
