"""HFBackend rollout wall time with and without the cross-turn prefix (KV) cache.

Plays the same episodes (greedy, so both settings sample the same ids) with a fresh backend per
run and prints the median wall time of each setting, the ratio, how many prompt ids the cache
served, and whether both settings produced identical replies.

    python scripts/bench_prefix_cache.py [--model smollm2] [--task glyphbench/classics-2048-v0]
        [--episodes 8] [--turns 6] [--history 8] [--max-new-tokens 8] [--repeats 3]
"""

from __future__ import annotations

import argparse
import statistics
import time

from glyphbench_rl.agent import HarnessConfig
from glyphbench_rl.models import load_model
from glyphbench_rl.rollout import EpisodeSpec, RolloutEngine
from glyphbench_rl.rollout.hf_backend import HFBackend


def rollout(model, tokenizer, args, prefix_cache: bool) -> tuple[float, HFBackend, list[list[int]]]:
    backend = HFBackend(model, tokenizer=tokenizer, temperature=0.0, max_new_tokens=args.max_new_tokens,
                        batch_size=args.episodes, prefix_cache=prefix_cache)
    engine = RolloutEngine(backend, HarnessConfig(history=args.history), max_episodes=args.episodes)
    specs = [EpisodeSpec(args.task, seed, {"max_turns": args.turns}) for seed in range(args.episodes)]
    t0 = time.perf_counter()
    trajs = engine.run(specs)
    return time.perf_counter() - t0, backend, [s.completion_ids for t in trajs for s in t.steps]


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--model", default="smollm2")
    ap.add_argument("--task", default="glyphbench/classics-2048-v0")
    ap.add_argument("--episodes", type=int, default=8)
    ap.add_argument("--turns", type=int, default=6)
    ap.add_argument("--history", type=int, default=8)
    ap.add_argument("--max-new-tokens", type=int, default=8)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--device")
    args = ap.parse_args()
    model, tokenizer = load_model(args.model, device=args.device)
    rollout(model, tokenizer, args, prefix_cache=False)          # warm-up (first calls are slow)
    times: dict[bool, list[float]] = {False: [], True: []}
    replies: dict[bool, list[list[int]]] = {}
    for _ in range(args.repeats):
        for cached in (False, True):
            wall, backend, replies[cached] = rollout(model, tokenizer, args, cached)
            times[cached].append(wall)
    print(f"{args.model} on {args.task}: {args.episodes} episodes x {args.turns} turns, history "
          f"{args.history}, max_new_tokens {args.max_new_tokens}, median of {args.repeats}")
    full, cached = statistics.median(times[False]), statistics.median(times[True])
    print(f"full prefill      {full:7.2f} s   runs: {', '.join(f'{t:.2f}' for t in times[False])}")
    print(f"prefix cache      {cached:7.2f} s   runs: {', '.join(f'{t:.2f}' for t in times[True])}")
    print(f"speed-up          {full / cached:7.2f} x")
    print(f"prompt ids served from the cache: {backend.reused_tokens} of {backend.prompt_tokens} "
          f"({backend.reused_tokens / max(1, backend.prompt_tokens):.0%})")
    same = replies[False] == replies[True]
    print(f"identical greedy replies: {'yes' if same else 'NO'}")
    return 0 if same else 1


if __name__ == "__main__":
    raise SystemExit(main())
