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
from typing import Any, Sequence

from .config import FIELDS, ConfigError, config_from_dict

SWEEP_KEYS = {"base", "grid", "rollout_budget", "variants"}


def _short(key: str, value: Any) -> str:
    if key == "tasks":
        text = str(value).rsplit("/", 1)[-1].removesuffix("-v0").removeprefix("classics-")
        return re.sub(r"[^A-Za-z0-9.-]+", "-", text)
    abbrev = {"group_size": "g", "lr": "lr", "groups_per_update": "gpu", "loss": ""}.get(key, key)
    return f"{abbrev}{value:g}" if isinstance(value, float) else f"{abbrev}{value}"


def expand(spec: dict[str, Any]) -> list[tuple[str, dict[str, Any]]]:
    """(name, training config dict) for every condition of the sweep and its variants."""
    if not isinstance(spec, dict) or set(spec) - SWEEP_KEYS:
        bad = sorted(set(spec) - SWEEP_KEYS) if isinstance(spec, dict) else [type(spec).__name__]
        raise ConfigError(f"unknown sweep key {bad[0]!r}; sweep keys: {', '.join(sorted(SWEEP_KEYS))}")
    out: list[tuple[str, dict[str, Any]]] = []
    runs = [("", spec)] + [(name, {**spec, **v, "variants": {}})
                           for name, v in (spec.get("variants") or {}).items()]
    for prefix, part in runs:
        grid = part.get("grid") or {}
        for key, values in grid.items():
            if key not in FIELDS:
                raise ConfigError(f"unknown config key {key!r} in grid")
            if not isinstance(values, list) or not values:
                raise ConfigError(f"grid.{key} must be a non-empty list")
        keys = list(grid)
        for combo in itertools.product(*(grid[k] for k in keys)):
            cfg = {**(part.get("base") or {}), **dict(zip(keys, combo))}
            budget = part.get("rollout_budget")
            if budget is not None:
                per_step = cfg.get("group_size", 32) * cfg.get("groups_per_update", 1)
                if budget % per_step:
                    raise ConfigError(f"rollout_budget {budget} is not a multiple of "
                                      f"group_size x groups_per_update = {per_step}")
                cfg["steps"] = budget // per_step
            name = "_".join(filter(None, [prefix] + [_short(k, v) for k, v in zip(keys, combo)])) or "run"
            config_from_dict(cfg)                       # every condition valid before any runs
            out.append((name, cfg))
    names = [n for n, _ in out]
    if len(set(names)) != len(names):
        raise ConfigError("two conditions got the same name; give variants distinct names")
    return out


def status(run_dir: Path, steps: int) -> str:
    metrics = run_dir / "metrics.jsonl"
    if not metrics.exists():
        return "todo"
    last = 0
    for line in metrics.read_text(encoding="utf-8").splitlines():
        try:
            last = max(last, int(json.loads(line)["step"]))
        except (ValueError, KeyError, TypeError):
            continue
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


def slurm_script(out: Path, rows, extra: str = "") -> str:
    lines = ["#!/bin/bash", f"#SBATCH --array=0-{len(rows) - 1}", "#SBATCH --job-name=glyphbench-sweep",
             f"#SBATCH --output={out}/logs/%a.out", *([extra] if extra else []), "", "case $SLURM_ARRAY_TASK_ID in"]
    for i, (name, _, path) in enumerate(rows):
        run_dir = out / "runs" / name
        cmd = " ".join(shlex.quote(c) for c in _train_cmd(path, run_dir, False))
        # --resume when a previous attempt left a run behind
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
        path = out / "runs" / name / "metrics.jsonl"
        metrics = [json.loads(x) for x in path.read_text().splitlines() if x.strip()] if path.exists() else []
        tail = metrics[-last:]
        ret = sum(m["train/return_mean"] for m in tail) / len(tail) if tail else float("nan")
        forfeit = sum(m["train/forfeit_rate"] for m in tail) / len(tail) if tail else float("nan")
        summary.append({"condition": name, "steps": len(metrics), "final_return": ret, "forfeit_rate": forfeit})
        lines.append(f"{name:<40} {len(metrics):>5} {ret:>+12.3f} {forfeit:>8.1%}")
    (out / "summary.json").write_text(json.dumps(summary, indent=1) + "\n")
    text = "\n".join(lines) + f"\n(final return: mean train return over each run's last {last} steps)\n"
    (out / "summary.txt").write_text(text)
    return text


def figure(out: Path, rows, spec_grid_keys: Sequence[str], smooth: int = 15) -> Path | None:
    """Learning curves like the paper's Snake figure: one panel per combination of the grid keys
    other than group size (rows: the second key, e.g. lr; columns: the first, e.g. task), one
    colour per group size, train return against rollouts used (pale: per step; solid: trailing
    mean over ``smooth`` steps)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    panel_keys = [k for k in spec_grid_keys if k != "group_size"]
    col_key = panel_keys[0] if panel_keys else None
    row_key = panel_keys[1] if len(panel_keys) > 1 else None
    cols = sorted({str(c.get(col_key)) for _, c, _ in rows}) if col_key else ["all"]
    row_vals = sorted({c.get(row_key) for _, c, _ in rows}) if row_key else [None]
    sizes = sorted({c.get("group_size", 32) for _, c, _ in rows})
    colours = plt.get_cmap("viridis")
    fig, axes = plt.subplots(len(row_vals), len(cols), squeeze=False, sharex=True, sharey=True,
                             figsize=(3.2 * len(cols), 2.4 * len(row_vals)))
    drawn = False
    for name, cfg, _ in rows:
        path = out / "runs" / name / "metrics.jsonl"
        if not path.exists():
            continue
        metrics = [json.loads(x) for x in path.read_text().splitlines() if x.strip()]
        if not metrics:
            continue
        r = row_vals.index(cfg.get(row_key)) if row_key else 0
        c = cols.index(str(cfg.get(col_key))) if col_key else 0
        g = cfg.get("group_size", 32)
        per_step = g * cfg.get("groups_per_update", 1)
        x = [m["step"] * per_step for m in metrics]
        y = [m["train/return_mean"] for m in metrics]
        trail = [sum(y[max(0, i - smooth + 1):i + 1]) / len(y[max(0, i - smooth + 1):i + 1]) for i in range(len(y))]
        colour = colours(sizes.index(g) / max(1, len(sizes) - 1))
        ax = axes[r][c]
        ax.plot(x, y, color=colour, alpha=0.25, linewidth=0.8)
        ax.plot(x, trail, color=colour, linewidth=1.6, label=f"G={g}")
        drawn = True
    if not drawn:
        plt.close(fig)
        return None
    for c, col in enumerate(cols):
        axes[0][c].set_title(_short(col_key, col) if col_key else col, fontsize=9)
        axes[-1][c].set_xlabel("rollouts")
    for r, val in enumerate(row_vals):
        axes[r][0].set_ylabel(f"{row_key} {val:g}\nreturn" if row_key else "return", fontsize=9)
    handles, labels = axes[0][0].get_legend_handles_labels()
    uniq = dict(zip(labels, handles))
    fig.legend(uniq.values(), uniq.keys(), loc="upper right", fontsize=8)
    fig.tight_layout()
    path = out / "curves.png"
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def main(argv: Sequence[str] | None = None) -> int:
    import yaml

    ap = argparse.ArgumentParser(prog="glyphbench-sweep", description=__doc__.splitlines()[0])
    ap.add_argument("sweep", help="sweep YAML (base, grid, rollout_budget, variants)")
    ap.add_argument("--out", help="sweep directory (default: runs/<sweep name>)")
    ap.add_argument("--parallel", type=int, default=1, help="conditions run at once (local)")
    ap.add_argument("--slurm", action="store_true", help="write sweep.sbatch (an array job) instead of running")
    ap.add_argument("--sbatch-extra", default="", help="extra #SBATCH lines for --slurm")
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
    if args.slurm:
        (out / "logs").mkdir(parents=True, exist_ok=True)
        path = out / "sweep.sbatch"
        path.write_text(slurm_script(out, rows, args.sbatch_extra))
        print(f"wrote {path} ({len(rows)} array tasks); submit with: sbatch {path}")
        return 0
    failed = 0 if args.table else run_local(out, rows, max(1, args.parallel))
    print(table(out, rows))
    try:
        png = figure(out, rows, list((spec.get("grid") or {}).keys()))
    except ImportError:
        print("(no figure: pip install matplotlib)")
    else:
        if png is not None:
            print(f"learning curves: {png}")
    return 1 if failed else 0


if __name__ == "__main__":
    raise SystemExit(main())
