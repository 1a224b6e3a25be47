"""Sweeps (``glyphbench-sweep SWEEP.yaml``, in ``cli/sweep.py``): expand a grid of training runs,
run them, tabulate them.

A sweep file holds ``base`` (training-config keys shared by every condition), ``grid`` (keys
mapped to lists of values; the conditions are their product), optionally ``rollout_budget``
(each condition's steps become budget / (group_size x groups_per_update), the paper's
fixed-interaction-budget comparison) and ``variants`` (named extra sweeps that override any of
those). Every condition's config is validated before anything runs. Conditions run as
``glyphbench-train`` processes, N at a time; a rerun skips finished conditions and resumes
interrupted ones; ``--slurm`` writes an array job script instead of running.
"""

from __future__ import annotations

import itertools
import json
import re
import shlex
import subprocess
import sys
import time
from pathlib import Path
from typing import Annotated, Any, ClassVar

from pydantic import BaseModel, Field

from ..settings import STRICT, Settings
from .config import ConfigError, config_from_dict
from .metrics import MetricsError, read_metrics

SWEEP_KEYS = {"base", "grid", "rollout_budget", "variants"}


class SweepPart(BaseModel):
    """The keys a sweep file and each of its variants set (a variant overrides the ones it sets)."""

    model_config = STRICT

    base: dict[str, Any] | None = None         # training-config keys shared by every condition
    grid: dict[str, Annotated[list[Any], Field(min_length=1)]] | None = None   # key: values
    rollout_budget: Annotated[int, Field(ge=1)] | None = None    # steps = budget / rollouts per step


class SweepSpec(Settings, SweepPart):
    error: ClassVar[type[Exception]] = ConfigError
    kind: ClassVar[str] = "sweep"

    variants: dict[str, SweepPart] | None = None   # name: the keys it changes


def _short(key: str, value: Any) -> str:
    if key == "tasks":
        text = str(value).rsplit("/", 1)[-1].removesuffix("-v0").removeprefix("classics-")
        return re.sub(r"[^A-Za-z0-9.-]+", "-", text)
    abbrev = {"group_size": "g", "lr": "lr", "groups_per_update": "gpu", "loss": ""}.get(key, key)
    return f"{abbrev}{value:g}" if isinstance(value, float) else f"{abbrev}{value}"


def expand(spec: Any) -> list[tuple[str, dict[str, Any]]]:
    """(name, training config dict) for every condition of the sweep and its variants."""
    if not isinstance(spec, dict):
        raise ConfigError(f"a sweep file is a mapping of {', '.join(sorted(SWEEP_KEYS))}, got "
                          f"{type(spec).__name__}")
    sweep = SweepSpec(**{str(k): v for k, v in spec.items()})
    parts = [("", sweep)] + [(name, sweep.model_copy(update=variant.model_dump(exclude_unset=True)))
                             for name, variant in (sweep.variants or {}).items()]
    out: list[tuple[str, dict[str, Any]]] = []
    for prefix, part in parts:
        grid = part.grid or {}
        keys = list(grid)
        for combo in itertools.product(*(grid[k] for k in keys)):
            cfg = {**(part.base or {}), **dict(zip(keys, combo))}
            checked = config_from_dict(cfg)           # every condition valid before any runs
            if part.rollout_budget is not None:
                per_step = checked.group_size * checked.groups_per_update
                if part.rollout_budget % per_step:
                    raise ConfigError(f"rollout_budget {part.rollout_budget} is not a multiple of "
                                      f"group_size x groups_per_update = {per_step}")
                cfg["steps"] = part.rollout_budget // per_step
            name = "_".join(filter(None, [prefix] + [_short(k, v) for k, v in zip(keys, combo)])) or "run"
            out.append((name, cfg))
    names = [n for n, _ in out]
    if len(set(names)) != len(names):
        raise ConfigError("two conditions got the same name; give variants distinct names")
    return out


def _metrics(run_dir: Path) -> list[dict[str, Any]]:
    """A condition's metric records; none when it has not run or its file cannot be read (the
    trainer's --resume drops a torn last line)."""
    try:
        return read_metrics(run_dir / "metrics.jsonl")
    except MetricsError:
        return []


def status(run_dir: Path, steps: int) -> str:
    if not (run_dir / "metrics.jsonl").exists():
        return "todo"
    last = max((m["step"] for m in _metrics(run_dir)), default=0)
    return "done" if last >= steps else "partial"


def _train_cmd(cfg_path: Path, run_dir: Path, resume: bool) -> list[str]:
    cmd = [sys.executable, "-m", "glyphbench_rl.cli.train", str(cfg_path), "--out", str(run_dir)]
    return cmd + (["--resume"] if resume else [])


def write_conditions(out: Path, conditions) -> list[tuple[str, dict, Path]]:
    import yaml

    rows = []
    for name, cfg in conditions:
        d = out / "configs"
        d.mkdir(parents=True, exist_ok=True)
        path = d / f"{name}.yaml"
        path.write_text(yaml.safe_dump(cfg, sort_keys=False), encoding="utf-8")
        rows.append((name, cfg, path))
    return rows


def slurm_script(out: Path, rows, extra: str = "", prime_rl: list[Path] | None = None) -> str:
    """An array job, one task per condition: the built-in trainer (resuming a run a previous
    attempt left behind), or with ``prime_rl`` (one rendered TOML per row) Prime-RL's ``rl``."""
    lines = ["#!/bin/bash", f"#SBATCH --array=0-{len(rows) - 1}", "#SBATCH --job-name=glyphbench-sweep",
             f"#SBATCH --output={out}/logs/%a.out", *([extra] if extra else []), "", "case $SLURM_ARRAY_TASK_ID in"]
    for i, (name, _, path) in enumerate(rows):
        if prime_rl is not None:
            lines.append(f"  {i}) rl @ {shlex.quote(str(prime_rl[i]))} ;;")
            continue
        run_dir = out / "runs" / name
        cmd = " ".join(shlex.quote(c) for c in _train_cmd(path, run_dir, False))
        lines.append(f"  {i}) if [ -f {shlex.quote(str(run_dir / 'metrics.jsonl'))} ]; then {cmd} --resume; "
                     f"else {cmd}; fi ;;")
    lines.append("esac")
    return "\n".join(lines) + "\n"


def run_local(out: Path, rows, parallel: int, log=print) -> int:
    pending = []
    for name, cfg, path in rows:
        st = status(out / "runs" / name, cfg["steps"] if "steps" in cfg else config_from_dict(cfg).steps)
        if st == "done":
            log(f"{name}: done, skipped")
        else:
            pending.append((name, path, st == "partial"))
    (out / "logs").mkdir(parents=True, exist_ok=True)
    running: list[tuple[str, subprocess.Popen]] = []
    failed = 0
    while pending or running:
        while pending and len(running) < parallel:
            name, path, resume = pending.pop(0)
            log(f"{name}: {'resuming' if resume else 'starting'}")
            fh = open(out / "logs" / f"{name}.log", "a", encoding="utf-8")
            running.append((name, subprocess.Popen(_train_cmd(path, out / "runs" / name, resume),
                                                   stdout=fh, stderr=subprocess.STDOUT)))
        time.sleep(0.2)
        for item in list(running):
            name, proc = item
            if proc.poll() is not None:
                running.remove(item)
                failed += proc.returncode != 0
                log(f"{name}: {'finished' if proc.returncode == 0 else f'failed (exit {proc.returncode}); see logs/{name}.log'}")
    return failed


def table(out: Path, rows, last: int = 5) -> str:
    lines = [f"{'condition':<40} {'steps':>5} {'final return':>12} {'forfeit':>8}"]
    summary = []
    for name, cfg, _ in rows:
        metrics = _metrics(out / "runs" / name)
        tail = metrics[-last:]
        ret = sum(m["train/return_mean"] for m in tail) / len(tail) if tail else float("nan")
        forfeit = sum(m["train/forfeit_rate"] for m in tail) / len(tail) if tail else float("nan")
        summary.append({"condition": name, "steps": len(metrics), "final_return": ret, "forfeit_rate": forfeit})
        lines.append(f"{name:<40} {len(metrics):>5} {ret:>+12.3f} {forfeit:>8.1%}")
    (out / "summary.json").write_text(json.dumps(summary, indent=1) + "\n")
    text = "\n".join(lines) + f"\n(final return: mean train return over each run's last {last} steps)\n"
    (out / "summary.txt").write_text(text)
    return text
