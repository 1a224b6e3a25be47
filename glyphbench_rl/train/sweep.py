"""``glyphbench-sweep SWEEP.yaml``: expand a grid of training runs, run them, tabulate them.

A sweep file holds ``base`` (training-config keys shared by every condition), ``grid`` (keys
mapped to lists of values; the conditions are their product), optionally ``rollout_budget``
(each condition's steps become budget / (group_size x groups_per_update), the paper's
fixed-interaction-budget comparison) and ``variants`` (named extra sweeps that override any of
those). Every condition's config is validated before anything runs. Conditions run as
``glyphbench-train`` processes, N at a time; a rerun skips finished conditions and resumes
interrupted ones; ``--slurm`` writes an array job script instead of running.
"""

from __future__ import annotations

import argparse
import itertools
import json
import re
import shlex
import subprocess
import sys
import time
from pathlib import Path
from typing import Annotated, Any, ClassVar, Sequence

from pydantic import BaseModel, Field

from ..settings import STRICT, Settings
from .config import ConfigError, config_from_dict

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
    from ..plots import PlotError, read_metrics
    try:
        return read_metrics(run_dir / "metrics.jsonl")
    except PlotError:
        return []


def status(run_dir: Path, steps: int) -> str:
    if not (run_dir / "metrics.jsonl").exists():
        return "todo"
    last = max((m["step"] for m in _metrics(run_dir)), default=0)
    return "done" if last >= steps else "partial"


def _train_cmd(cfg_path: Path, run_dir: Path, resume: bool) -> list[str]:
    cmd = [sys.executable, "-m", "glyphbench_rl.train.cli", str(cfg_path), "--out", str(run_dir)]
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


def write_prime_rl(out: Path, rows) -> list[Path]:
    """Each condition as a Prime-RL config, ``runs/<name>/prime_rl.toml``."""
    from ..integrations.prime_rl import write_toml
    return [write_toml(config_from_dict(cfg), out / "runs" / name) for name, cfg, _ in rows]


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


def main(argv: Sequence[str] | None = None) -> int:
    import yaml

    ap = argparse.ArgumentParser(prog="glyphbench-sweep", description=__doc__.splitlines()[0])
    ap.add_argument("sweep", help="sweep YAML (base, grid, rollout_budget, variants)")
    ap.add_argument("--out", help="sweep directory (default: runs/<sweep name>)")
    ap.add_argument("--parallel", type=int, default=1, help="conditions run at once (local)")
    ap.add_argument("--slurm", action="store_true", help="write sweep.sbatch (an array job) instead of running")
    ap.add_argument("--sbatch-extra", default="", help="extra #SBATCH lines for --slurm")
    ap.add_argument("--prime-rl", action="store_true",
                    help="render each condition as runs/<name>/prime_rl.toml and write prime_rl.sh "
                         "(with --slurm: an array job running Prime-RL's rl) instead of running")
    ap.add_argument("--dry-run", action="store_true", help="list the conditions and stop")
    ap.add_argument("--table", action="store_true", help="only tabulate what has run")
    args = ap.parse_args(argv)
    out = Path(args.out or Path("runs") / Path(args.sweep).stem)
    try:
        spec = yaml.safe_load(Path(args.sweep).read_text(encoding="utf-8"))
        conditions = expand(spec)
    except (OSError, yaml.YAMLError, ConfigError) as e:
        print(f"glyphbench-sweep: error: {str(e).splitlines()[0]}", file=sys.stderr)
        return 2
    if args.dry_run:
        for name, cfg in conditions:
            print(f"{name}: steps {config_from_dict(cfg).steps}")
        print(f"{len(conditions)} conditions")
        return 0
    rows = write_conditions(out, conditions)
    (out / "sweep.yaml").write_text(Path(args.sweep).read_text(encoding="utf-8"), encoding="utf-8")
    if args.prime_rl:
        from ..integrations.prime_rl import PrimeRLConfigError
        try:
            tomls = write_prime_rl(out, rows)
        except (PrimeRLConfigError, FileExistsError, ValueError) as e:
            print(f"glyphbench-sweep: error: {str(e).splitlines()[0]}", file=sys.stderr)
            return 2
        (out / "logs").mkdir(parents=True, exist_ok=True)
        if args.slurm:
            path = out / "prime_rl.sbatch"
            path.write_text(slurm_script(out, rows, args.sbatch_extra, prime_rl=tomls))
            print(f"wrote {len(tomls)} Prime-RL configs and {path}; submit with: sbatch {path}")
        else:
            path = out / "prime_rl.sh"
            path.write_text("#!/bin/bash\nset -e\n" + "".join(f"rl @ {shlex.quote(str(t))}\n" for t in tomls))
            path.chmod(0o755)
            print(f"wrote {len(tomls)} Prime-RL configs and {path} (runs them one after another)")
        return 0
    if args.slurm:
        (out / "logs").mkdir(parents=True, exist_ok=True)
        path = out / "sweep.sbatch"
        path.write_text(slurm_script(out, rows, args.sbatch_extra))
        print(f"wrote {path} ({len(rows)} array tasks); submit with: sbatch {path}")
        return 0
    failed = 0 if args.table else run_local(out, rows, max(1, args.parallel))
    print(table(out, rows))
    from ..plots import PlotError, plot_sweep
    try:
        print(f"learning curves: {plot_sweep(out, out / 'curves.png')}")
    except PlotError as e:          # nothing has metrics yet, or no matplotlib
        print(f"(no figure: {e})")
    return 1 if failed else 0


if __name__ == "__main__":
    raise SystemExit(main())
