"""Figures from runs, evaluation jobs and sweeps (``glyphbench plot``), as PNG, PDF or SVG.

* ``plot_training``: training curves from ``<run>/metrics.jsonl`` (batch mean return pale, a
  trailing mean solid, held-out evaluation points with 95% intervals; forfeit rate below),
  several runs overlaid.
* ``plot_comparison``: two evaluation jobs paired on their common (task, seed) pairs, as in the
  paper's Figure 4a: per suite, the distribution of task-mean returns of A and B (violin, one dot
  per task joined across A and B, interquartile bar, median dot), and the paired per-task gain.
* ``plot_sweep``: a ``glyphbench-sweep`` directory as the paper's Snake grid: rows learning rate,
  columns the other swept keys (task difficulty), colours group size, x rollouts consumed.

Matplotlib is imported only when a figure is drawn, through ``Figure`` objects (no pyplot, so no
global figure state and no backend switch). A metrics file is read strictly: a bad line in the
middle is an error naming file:line; only a cut-short last line (a run still writing) is left out,
with a warning through ``log``.
"""

from __future__ import annotations

import fnmatch
import itertools
import json
import math
import os
from pathlib import Path
from typing import Any, Callable, Iterable, Sequence

from ..evaluate.compare import compare_records
from ..train import metrics as metrics_file
from ..evaluate.job import EPISODES, EvalError, read_config
from ..evaluate.store import scan

Log = Callable[[str], None] | None
FORMATS = (".png", ".pdf", ".svg")
RUN_COLOURS = ("#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b", "#e377c2")
A_COLOUR, B_COLOUR = "#7f8c9d", "#1f6fd1"


class PlotError(ValueError):
    """A figure that cannot be drawn from what was given; the message is one line."""


# -- reading -------------------------------------------------------------------------------------
def read_metrics(path: str | os.PathLike, log: Log = None) -> list[dict[str, Any]]:
    """The records of a run's ``metrics.jsonl`` (``train.metrics.read_metrics``), errors as
    PlotError."""
    try:
        return metrics_file.read_metrics(path, log)
    except metrics_file.MetricsError as e:
        raise PlotError(str(e)) from None


def trailing_mean(xs: Sequence[float], ys: Sequence[float], window: float) -> list[float]:
    """At each point, the mean of the points whose x lies within ``window`` before it (itself
    included): a window of n steps when x counts steps, of n rollouts when x counts rollouts."""
    out, start, total, count = [], 0, 0.0, 0
    for i, x in enumerate(xs):
        if not math.isnan(ys[i]):         # a missing value is a gap, not a zero
            total, count = total + ys[i], count + 1
        while xs[start] <= x - window:
            if not math.isnan(ys[start]):
                total, count = total - ys[start], count - 1
            start += 1
        out.append(total / count if count else math.nan)
    return out


def _number(value: Any) -> float:
    """A metric value as a float; NaN when absent or not a number (a gap in the curve)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return math.nan
    return float(value)


# -- figures -------------------------------------------------------------------------------------
def _check_out(out: str | os.PathLike) -> Path:
    out = Path(out)
    if out.suffix.lower() not in FORMATS:
        raise PlotError(f"cannot tell the figure type of {str(out)!r}: use a name ending in "
                        f"{', '.join(FORMATS)}")
    if not out.parent.is_dir():
        raise PlotError(f"directory {str(out.parent)!r} does not exist")
    return out


def _new_figure(width: float, height: float):
    try:
        from matplotlib.figure import Figure
    except ImportError:
        raise PlotError("plots need matplotlib: pip install matplotlib "
                        "(or the glyphbench_rl[train] extra)") from None
    return Figure(figsize=(width, height), layout="constrained")


def _save(fig, out: Path) -> Path:
    """Write beside the target, then rename, so a failure never leaves half a file."""
    tmp = out.with_name(f".{out.name}.tmp")
    try:
        fig.savefig(tmp, format=out.suffix.lower()[1:], dpi=150, bbox_inches="tight", pad_inches=0.08)
        os.replace(tmp, out)
    finally:
        tmp.unlink(missing_ok=True)
    return out


def _check_window(value: float, name: str) -> None:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not value >= 1:
        raise PlotError(f"{name} must be at least 1, got {value!r}")


def plot_training(run_dirs: str | os.PathLike | Iterable[str | os.PathLike], out: str | os.PathLike,
                  *, window: int = 10, log: Log = None) -> Path:
    """Return and forfeit rate against step for one or more training runs (overlaid)."""
    out = _check_out(out)
    _check_window(window, "window")
    dirs = [Path(run_dirs)] if isinstance(run_dirs, (str, os.PathLike)) else [Path(d) for d in run_dirs]
    if not dirs:
        raise PlotError("no run directory given")
    runs = []
    for d in dirs:
        if not d.is_dir():
            raise PlotError(f"run directory {str(d)!r} does not exist")
        runs.append(read_metrics(d / "metrics.jsonl", log))
    names = _labels(dirs)
    fig = _new_figure(7.5, 5.6)
    ret_ax, ff_ax = fig.subplots(2, 1, sharex=True, height_ratios=[2.2, 1])
    any_eval = False
    for metrics, name, colour in zip(runs, names, itertools.cycle(RUN_COLOURS)):
        steps = [m["step"] for m in metrics]
        ret = [_number(m["train/return_mean"]) for m in metrics]
        ret_ax.plot(steps, ret, color=colour, alpha=0.25, linewidth=0.9)
        ret_ax.plot(steps, trailing_mean(steps, ret, window), color=colour, linewidth=1.8,
                    label=name if len(runs) > 1 else "batch return, trailing mean")
        evals = [m for m in metrics if isinstance(m.get("eval/return_mean"), (int, float))]
        if evals:
            any_eval = True
            ci = [_number(m.get("eval/return_ci95")) for m in evals]
            ret_ax.errorbar([m["step"] for m in evals], [m["eval/return_mean"] for m in evals],
                            yerr=[0 if math.isnan(c) else c for c in ci], fmt="o", color=colour,
                            markeredgecolor="black", markersize=5, capsize=3, linewidth=1)
        forfeit = [_number(m.get("train/forfeit_rate")) for m in metrics]
        ff_ax.plot(steps, forfeit, color=colour, alpha=0.25, linewidth=0.9)
        ff_ax.plot(steps, trailing_mean(steps, forfeit, window), color=colour, linewidth=1.6)
    ret_ax.set_ylabel("mean return")
    title = f"training: pale per step, solid trailing {window}-step mean"
    if any_eval:
        title += ", dots held-out eval (95% CI)"
    ret_ax.set_title(title if len(runs) > 1 else f"{names[0]}\n{title}", fontsize=9)
    ret_ax.legend(fontsize=8, loc="best")
    ret_ax.grid(alpha=0.3)
    ff_ax.set_ylabel("forfeit rate")
    ff_ax.set_xlabel("step")
    from matplotlib.ticker import MaxNLocator
    ff_ax.xaxis.set_major_locator(MaxNLocator(integer=True))   # steps are whole numbers
    ff_ax.yaxis.set_major_formatter(_percent())
    ff_ax.grid(alpha=0.3)
    return _save(fig, out)


def _labels(dirs: Sequence[Path]) -> list[str]:
    """Short distinct names for run directories (the last path parts that tell them apart)."""
    for depth in range(1, 6):
        names = ["/".join(d.resolve().parts[-depth:]) for d in dirs]
        if len(set(names)) == len(names):
            return names
    return [str(d) for d in dirs]


def _percent():
    from matplotlib.ticker import PercentFormatter
    return PercentFormatter(1.0, decimals=0)


# -- paired comparison ---------------------------------------------------------------------------
def load_job(path: str | os.PathLike, log: Log = None) -> tuple[list[dict[str, Any]], str]:
    """An evaluation job's episode records (scalar fields) and a short name for it. ``path`` is
    the job directory or its ``episodes.jsonl``."""
    path = Path(path)
    if not path.exists():
        raise PlotError(f"{path} does not exist")
    episodes = path / EPISODES if path.is_dir() else path
    if not episodes.is_file():
        raise PlotError(f"{path} has no {EPISODES} (not an evaluation job directory?)")
    result = scan(episodes)
    if result.partial is not None and log:
        log(f"{episodes}:{result.partial.line}: cut-short last line left out")
    job_dir = episodes.parent
    try:
        cfg = read_config(job_dir) or {}
    except EvalError:
        cfg = {}
    who = cfg.get("model") or cfg.get("backend")
    name = job_dir.name + (f" ({who})" if who else "")
    return result.records, name


def plot_comparison(job_a: str | os.PathLike, job_b: str | os.PathLike, out: str | os.PathLike,
                    *, log: Log = None) -> Path:
    """Per-suite task-mean return distributions of A and B, and the paired per-task gain B − A."""
    out = _check_out(out)
    (a, name_a), (b, name_b) = load_job(job_a, log), load_job(job_b, log)
    if name_a == name_b:
        name_a, name_b = str(job_a), str(job_b)
    c = compare_records(a, b)
    if not c["pairs"]:
        raise PlotError(f"{job_a} and {job_b} share no (task, seed) pair")
    groups = [(g["name"], [r for r in c["task_rows"] if r["suite"] == g["name"]], g) for g in c["suites"]]
    if len(groups) > 1:
        groups.append(("all tasks", c["task_rows"], c["overall"]))
    fig = _new_figure(max(6.0, 1.25 * len(groups) + 2.5), 7.0)
    dist_ax, gain_ax = fig.subplots(2, 1, sharex=True, height_ratios=[1.5, 1])
    for k, (_, rows, _) in enumerate(groups):
        _paired_distributions(dist_ax, k, [r["mean_a"] for r in rows], [r["mean_b"] for r in rows])
        _gains(gain_ax, k, [r["diff"] for r in rows])
    for k, (_, _, g) in enumerate(groups):
        gain_ax.errorbar([k], [g["mean_gain"]], yerr=[g["gain_ci95"] or 0], fmt="D", color="black",
                         markersize=5, capsize=4, linewidth=1.2, zorder=4)
    o = c["overall"]
    dist_ax.set_title(f"(a) task-mean return per suite, {c['pairs']} paired episodes on {c['tasks']} "
                      f"tasks\nviolin and dots: tasks; bar: interquartile range; white dot: median",
                      fontsize=9)
    dist_ax.set_ylabel("task-mean return")
    from matplotlib.patches import Patch
    fig.legend(handles=[Patch(color=A_COLOUR, label=f"A: {name_a}"),
                        Patch(color=B_COLOUR, label=f"B: {name_b}")],
               loc="outside upper center", ncols=2, fontsize=8)
    gain_ax.axhline(0, color="black", linewidth=0.8)
    gain_ax.set_title(f"(b) paired per-task gain B − A, diamond: mean ± 95% CI\nB better on "
                      f"{o['improved']} of {o['tasks']} tasks, worse on {o['worse']}, tied on {o['tied']}",
                      fontsize=9)
    gain_ax.set_ylabel("B − A")
    gain_ax.set_xticks(range(len(groups)), [f"{name}\n({_count(len(rows), 'task')})" for name, rows, _ in groups],
                       fontsize=8)
    for ax in (dist_ax, gain_ax):
        ax.grid(axis="y", alpha=0.3)
    return _save(fig, out)


def _spread(n: int, width: float, seed: int) -> list[float]:
    """Horizontal offsets for n dots (fixed generator: the same figure every time)."""
    import numpy as np
    return list(np.random.default_rng(seed).uniform(-width, width, n))


def _quartiles(values: Sequence[float]) -> tuple[float, float, float]:
    import numpy as np
    q1, med, q3 = np.percentile(values, [25, 50, 75])
    return float(q1), float(med), float(q3)


def _paired_distributions(ax, k: int, a: Sequence[float], b: Sequence[float]) -> None:
    from matplotlib.patches import Rectangle
    xa, xb = k - 0.2, k + 0.2
    for x, values, colour in ((xa, a, A_COLOUR), (xb, b, B_COLOUR)):
        if len(set(values)) > 1:
            body = ax.violinplot([values], positions=[x], widths=0.36, showextrema=False)["bodies"][0]
            body.set_facecolor(colour)
            body.set_alpha(0.25)
            lo, hi = min(values), max(values)   # no density drawn beyond the data
            body.set_clip_path(Rectangle((x - 0.5, lo), 1.0, hi - lo, transform=ax.transData))
    ja, jb = _spread(len(a), 0.06, 2 * k), _spread(len(b), 0.06, 2 * k + 1)
    for ya, yb, da, db in zip(a, b, ja, jb):
        ax.plot([xa + da, xb + db], [ya, yb], color="0.6", alpha=0.35, linewidth=0.6, zorder=1)
    ax.scatter([xa + d for d in ja], a, s=10, color=A_COLOUR, alpha=0.8, zorder=2, linewidths=0)
    ax.scatter([xb + d for d in jb], b, s=10, color=B_COLOUR, alpha=0.8, zorder=2, linewidths=0)
    for x, values, colour in ((xa, a, A_COLOUR), (xb, b, B_COLOUR)):
        q1, med, q3 = _quartiles(values)
        ax.vlines(x, q1, q3, color=colour, linewidth=5, zorder=3)
        ax.scatter([x], [med], s=18, color="white", edgecolors=colour, zorder=4)


def _gains(ax, k: int, diffs: Sequence[float]) -> None:
    colours = ["#2e9e4f" if d > 0 else "#d64545" if d < 0 else "0.55" for d in diffs]
    ax.scatter([k + d for d in _spread(len(diffs), 0.18, 1000 + k)], diffs, s=10, c=colours,
               alpha=0.75, linewidths=0, zorder=2)


# -- sweep grid ----------------------------------------------------------------------------------
def load_sweep(sweep_dir: str | os.PathLike, select: str | None = None
               ) -> list[tuple[str, dict[str, Any], Path]]:
    """(name, resolved config dict, run dir) of each condition of a ``glyphbench-sweep``
    directory, in the sweep file's order when the directory holds it (``sweep.yaml``), else the
    ``configs/*.yaml`` by name; optionally only names matching the glob ``select``."""
    try:
        import yaml  # noqa: F401  (read_yaml's)
    except ImportError:
        raise PlotError("reading a sweep needs pyyaml: pip install pyyaml") from None
    from ..train.config import ConfigError, config_from_dict, read_yaml
    from ..train.sweep import expand

    root = Path(sweep_dir)
    if not root.is_dir():
        raise PlotError(f"sweep directory {str(root)!r} does not exist")
    spec_path = root / "sweep.yaml"
    try:
        if spec_path.is_file():
            where = spec_path
            named = expand(read_yaml(spec_path, "sweep"))
        else:
            named = []
            for path in sorted((root / "configs").glob("*.yaml")):
                where = path
                named.append((path.stem, read_yaml(path) or {}))
        if not named:
            raise PlotError(f"{root} holds no sweep.yaml or configs/*.yaml (not a glyphbench-sweep "
                            f"directory?)")
        out = [(name, config_from_dict(cfg).to_dict(), root / "runs" / name) for name, cfg in named
               if not select or fnmatch.fnmatchcase(name, select)]
    except (OSError, ConfigError, TypeError, AttributeError) as e:
        msg = str(e).splitlines()[0]
        raise PlotError(msg if str(where) in msg else f"{where}: {msg}") from None
    if not out:
        raise PlotError(f"no condition of {root} matches {select!r}")
    return out


def _value_label(key: str, value: Any) -> str:
    if key == "tasks":
        return str(value).rsplit("/", 1)[-1].removesuffix("-v0")
    return f"{key} {value:g}" if isinstance(value, float) else f"{key} {value}"


def plot_sweep(sweep_dir: str | os.PathLike, out: str | os.PathLike, *, window_rollouts: int = 512,
               select: str | None = None, log: Log = None) -> Path:
    """Rows: learning rate; columns: every other key that varies across conditions (e.g. the
    task), split by rollout budget when variants differ in it; colours: group size. Pale: batch
    mean return per step; solid: trailing mean over ``window_rollouts`` rollouts; dot: final."""
    out = _check_out(out)
    _check_window(window_rollouts, "window_rollouts")
    conditions = load_sweep(sweep_dir, select)
    curves = []
    for name, cfg, run in conditions:
        if not (run / "metrics.jsonl").exists():
            continue                       # not run yet
        per_step = cfg["group_size"] * cfg["groups_per_update"]
        curves.append((name, cfg, per_step * cfg["steps"], read_metrics(run / "metrics.jsonl", log)))
    if not curves:
        raise PlotError(f"no condition of {sweep_dir} has metrics yet")
    varying = [k for k in curves[0][1] if k != "steps"
               and len({json.dumps(c[k], sort_keys=True) for _, c, _, _ in curves}) > 1]
    row_key = "lr" if "lr" in varying else None
    col_keys = [k for k in varying if k not in ("lr", "group_size")]
    split_budget = len({budget for _, _, budget, _ in curves}) > 1

    def col_of(cfg: dict[str, Any], budget: int) -> str:
        parts = [_value_label(k, cfg[k]) for k in col_keys]
        parts += [f"{budget:,} rollouts"] if split_budget else []
        return " · ".join(parts) or "all conditions"

    cols = list(dict.fromkeys(col_of(c, b) for _, c, b, _ in sorted(curves, key=lambda x: x[2])))
    rows = sorted({c[row_key] for _, c, _, _ in curves}) if row_key else [None]
    sizes = sorted({c["group_size"] for _, c, _, _ in curves})
    fig = _new_figure(max(4.0, 3.0 * len(cols)), max(2.8, 2.3 * len(rows)))
    axes = fig.subplots(len(rows), len(cols), squeeze=False, sharex="col", sharey="col")
    from matplotlib import colormaps
    cmap = colormaps["viridis"]
    used = set()
    for _, cfg, budget, metrics in curves:
        r = rows.index(cfg[row_key]) if row_key else 0
        c = cols.index(col_of(cfg, budget))
        ax = axes[r][c]
        used.add((r, c))
        per_step = cfg["group_size"] * cfg["groups_per_update"]
        x = [m["step"] * per_step for m in metrics]
        y = [_number(m["train/return_mean"]) for m in metrics]
        smooth = trailing_mean(x, y, window_rollouts)
        colour = cmap(0.85 * sizes.index(cfg["group_size"]) / max(1, len(sizes) - 1))
        ax.plot(x, y, color=colour, alpha=0.22, linewidth=0.7)
        ax.plot(x, smooth, color=colour, linewidth=1.5, label=f"G={cfg['group_size']}")
        ax.scatter([x[-1]], [smooth[-1]], color=colour, s=14, zorder=3)
    for r, row in enumerate(rows):
        for c, col in enumerate(cols):
            ax = axes[r][c]
            if (r, c) not in used:
                ax.set_axis_off()
                continue
            ax.grid(alpha=0.3)
            if r == 0 or (r - 1, c) not in used:
                ax.set_title(col, fontsize=9)
            if c == 0 or (r, c - 1) not in used:
                ax.set_ylabel(("" if row is None else f"lr {row:g}\n") + "return", fontsize=9)
            if r == len(rows) - 1 or (r + 1, c) not in used:
                ax.set_xlabel("rollouts", fontsize=9)
                ax.tick_params(axis="x", labelbottom=True)
    handles = {}
    for ax in fig.axes:
        for h, label in zip(*ax.get_legend_handles_labels()):
            handles.setdefault(label, h)
    order = sorted(handles, key=lambda s: int(s[2:]))
    fig.legend([handles[k] for k in order], order, loc="outside right upper", fontsize=8, title="group size",
               title_fontsize=8)
    fig.suptitle(f"sweep {Path(sweep_dir).resolve().name}: batch mean return (pale), trailing "
                 f"{window_rollouts}-rollout mean (solid), final (dot)", fontsize=10)
    return _save(fig, out)


def _count(n: int, noun: str) -> str:
    return f"{n} {noun}" if n == 1 else f"{n} {noun}s"
