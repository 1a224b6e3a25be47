"""Per-task, per-suite and overall results of an evaluation, as JSON and as a readable table.

Aggregates weight TASKS equally, as the paper does ("returns are averaged within tasks and tasks
receive equal weight"): a suite's score is the mean of its task means and its 95% interval is a
t-interval across those task means, so a task with more finished episodes does not count more.
The standard-tier aggregate leaves out extended tasks (uncapped horizons, unbounded returns).
"""

from __future__ import annotations

from collections import defaultdict
from typing import Any, Iterable, Sequence

from ..core.registry import SUITES, UnknownTaskError, get_spec
from .stats import fmean, mean_ci

SUMMARY_SCHEMA = 1


def task_info(task_id: str) -> tuple[str, str]:
    """(suite, tier) of a task; '?' for one no longer registered (a renamed or removed game)."""
    try:
        spec = get_spec(task_id)
    except UnknownTaskError:
        return "?", "?"
    return spec.suite, spec.tier


def task_row(task_id: str, records: Sequence[dict[str, Any]]) -> dict[str, Any]:
    suite, tier = task_info(task_id)
    ret = mean_ci(r["return"] for r in records)
    turns = sum(r["length"] for r in records)
    return {
        "task_id": task_id, "suite": suite, "tier": tier, "episodes": len(records),
        "return_mean": ret.mean, "return_ci95": ret.ci95, "return_sd": ret.sd,
        "length_mean": fmean(r["length"] for r in records),
        # pooled over turns: the share of all decisions that named no valid action
        "forfeit_rate": sum(r["forfeits"] for r in records) / turns if turns else 0.0,
        "win_rate": fmean(r["won"] is True for r in records),
        "prompt_tokens_mean": fmean(r["prompt_tokens"] for r in records),
        "completion_tokens_mean": fmean(r["completion_tokens"] for r in records),
    }


def group_row(name: str, rows: Sequence[dict[str, Any]]) -> dict[str, Any]:
    """Equal-weight aggregate over task rows: mean of task means, t-interval across tasks."""
    ret = mean_ci(r["return_mean"] for r in rows)
    return {
        "name": name, "tasks": len(rows), "episodes": sum(r["episodes"] for r in rows),
        "return_mean": ret.mean, "return_ci95": ret.ci95,
        **{k: fmean(r[k] for r in rows) for k in ("length_mean", "forfeit_rate", "win_rate",
                                                  "prompt_tokens_mean", "completion_tokens_mean")},
    }


def ordered_tasks(task_ids: Iterable[str], order: Sequence[str] | None = None) -> list[str]:
    """``order`` first (a job's task list), then the rest by suite as the registry sorts them."""
    present = set(task_ids)
    first = [t for t in (order or ()) if t in present]
    rest = sorted(present - set(first), key=lambda t: (_suite_index(task_info(t)[0]), t))
    return first + rest


def _suite_index(suite: str) -> int:
    return SUITES.index(suite) if suite in SUITES else len(SUITES)


def summarize(records: Iterable[dict[str, Any]], *, order: Sequence[str] | None = None,
              planned: int | None = None, missing: int | None = None,
              config: dict[str, Any] | None = None) -> dict[str, Any]:
    """``planned``/``missing``: the job's (task, seed) pairs and how many have no record yet."""
    by_task: dict[str, list[dict[str, Any]]] = defaultdict(list)
    for r in records:
        by_task[r["task_id"]].append(r)
    rows = [task_row(t, by_task[t]) for t in ordered_tasks(by_task, order)]
    suites = sorted({r["suite"] for r in rows}, key=_suite_index)
    return {
        "schema": SUMMARY_SCHEMA,
        "episodes": sum(r["episodes"] for r in rows),
        "planned": planned,
        "missing": missing,
        "config": config,
        "weighting": "tasks weighted equally: mean of task means, 95% t-interval across tasks",
        "tasks": rows,
        "suites": [group_row(s, [r for r in rows if r["suite"] == s]) for s in suites],
        "overall": group_row("overall", rows),
        "standard": group_row("standard tier", [r for r in rows if r["tier"] == "standard"]),
    }


# -- the readable table --------------------------------------------------------------------------
def _num(x: float | None, spec: str, none: str = "-") -> str:
    return none if x is None else format(x, spec)


def _cells(r: dict[str, Any]) -> list[str]:
    return [_num(r["return_mean"], "+.3f"), _num(r["return_ci95"], ".3f"), _num(r["length_mean"], ".1f"),
            _num(None if r["forfeit_rate"] is None else 100 * r["forfeit_rate"], ".1f") + "%",
            _num(r["prompt_tokens_mean"], ",.0f"), _num(r["completion_tokens_mean"], ",.0f")]


_HEAD = ["mean return", "±95%", "mean len", "forfeit", "prompt tok", "compl tok"]
_WIDTHS = [11, 6, 8, 7, 10, 9]


def _line(name: str, width: int, mid: list[str], cells: list[str]) -> str:
    group, count = mid
    return (f"{name:<{width}} {group:<12} {count:>5} "
            + " ".join(f"{c:>{w}}" for c, w in zip(cells, _WIDTHS))).rstrip()


def format_summary(summary: dict[str, Any], title: str | None = None) -> str:
    rows = summary["tasks"]
    width = max([44] + [len(r["task_id"]) for r in rows])
    out = [title] if title else []
    planned, missing = summary.get("planned"), summary.get("missing") or 0
    done = f"{summary['episodes']} episodes"
    if planned:
        done += f"; {planned - missing} of the job's {planned} (task, seed) pairs done"
    if missing:
        done += " (PARTIAL: rerun the job to finish it)"
    out += [done, "", _line("task", width, ["suite", "eps"], _HEAD)]
    for r in rows:
        out.append(_line(r["task_id"], width, [r["suite"], str(r["episodes"])], _cells(r)))
    out += ["", f"aggregates: {summary['weighting']}",
            _line("suite", width, ["", "tasks"], _HEAD)]
    # the standard-tier row always: it is the paper's headline number, even when every task is
    # standard and it repeats the overall row
    for g in summary["suites"] + [summary["overall"], summary["standard"]]:
        if g["tasks"]:
            out.append(_line(g["name"], width, ["", str(g["tasks"])], _cells(g)))
    return "\n".join(out) + "\n"
