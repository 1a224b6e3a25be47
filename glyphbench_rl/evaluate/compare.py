"""Paired comparison of two evaluation runs (the paper's Figure 4): B − A per task, then across tasks.

Only (task, seed) pairs that both runs finished count, so an unfinished run compares fairly on
what it has. Within a task the difference is the mean of per-seed differences (a paired
t-interval over seeds); across tasks every task weighs the same and the mean paired gain gets a
t-interval over the task differences.
"""

from __future__ import annotations

from collections import defaultdict
from typing import Any

from .stats import fmean, mean_ci
from .summary import _suite_index, ordered_tasks, task_info

TIE = 1e-12   # task means this close count as tied (float noise, not a difference)


def compare_records(a: list[dict[str, Any]], b: list[dict[str, Any]]) -> dict[str, Any]:
    ra = {(r["task_id"], r["seed"]): r["return"] for r in a}
    rb = {(r["task_id"], r["seed"]): r["return"] for r in b}
    common = sorted(set(ra) & set(rb))
    by_task: dict[str, list[tuple[float, float]]] = defaultdict(list)
    for key in common:
        by_task[key[0]].append((ra[key], rb[key]))
    rows = []
    for task_id in ordered_tasks(by_task):
        pairs = by_task[task_id]
        diff = mean_ci(y - x for x, y in pairs)
        suite, tier = task_info(task_id)
        rows.append({"task_id": task_id, "suite": suite, "tier": tier, "pairs": len(pairs),
                     "mean_a": fmean(x for x, _ in pairs), "mean_b": fmean(y for _, y in pairs),
                     "diff": diff.mean, "diff_ci95": diff.ci95})
    suites = sorted({r["suite"] for r in rows}, key=_suite_index)
    return {
        "pairs": len(common), "tasks": len(rows),
        "unpaired": {"only_a": len(set(ra) - set(rb)), "only_b": len(set(rb) - set(ra))},
        "task_rows": rows,
        "suites": [_group(s, [r for r in rows if r["suite"] == s]) for s in suites],
        "overall": _group("overall", rows),
        "standard": _group("standard tier", [r for r in rows if r["tier"] == "standard"]),
    }


def _group(name: str, rows: list[dict[str, Any]]) -> dict[str, Any]:
    gain = mean_ci(r["diff"] for r in rows)
    return {"name": name, "tasks": len(rows),
            "improved": sum(r["diff"] > TIE for r in rows),
            "worse": sum(r["diff"] < -TIE for r in rows),
            "tied": sum(abs(r["diff"]) <= TIE for r in rows),
            "mean_a": fmean(r["mean_a"] for r in rows), "mean_b": fmean(r["mean_b"] for r in rows),
            "mean_gain": gain.mean, "gain_ci95": gain.ci95}


def _f(x: float | None, spec: str) -> str:
    return "-" if x is None else format(x, spec)


def format_comparison(c: dict[str, Any], name_a: str = "A", name_b: str = "B") -> str:
    width = max([44] + [len(r["task_id"]) for r in c["task_rows"]])
    out = ["paired comparison, B − A on the (task, seed) pairs both runs finished",
           f"  A: {name_a}", f"  B: {name_b}",
           f"{c['pairs']} pairs on {c['tasks']} tasks; unpaired episodes: "
           f"{c['unpaired']['only_a']} only in A, {c['unpaired']['only_b']} only in B", "",
           f"{'task':<{width}} {'pairs':>5} {'mean A':>7} {'mean B':>7} {'B − A':>7} {'±95%':>6}"]
    for r in c["task_rows"]:
        out.append(f"{r['task_id']:<{width}} {r['pairs']:>5} {r['mean_a']:>+7.3f} {r['mean_b']:>+7.3f} "
                   f"{r['diff']:>+7.3f} {_f(r['diff_ci95'], '.3f'):>6}")
    out += ["", "across tasks (each task weighs the same; 95% t-interval over task differences)",
            f"{'group':<{width}} {'tasks':>5} {'better':>6} {'worse':>5} {'tied':>4} "
            f"{'mean A':>7} {'mean B':>7} {'gain':>7} {'±95%':>6}"]
    groups = c["suites"] + [c["overall"]]
    if c["standard"]["tasks"] != c["overall"]["tasks"]:
        groups.append(c["standard"])
    for g in groups:
        if g["tasks"]:
            out.append(f"{g['name']:<{width}} {g['tasks']:>5} {g['improved']:>6} {g['worse']:>5} "
                       f"{g['tied']:>4} {g['mean_a']:>+7.3f} {g['mean_b']:>+7.3f} "
                       f"{g['mean_gain']:>+7.3f} {_f(g['gain_ci95'], '.3f'):>6}")
    o = c["overall"]
    if o["tasks"]:
        ci = "" if o["gain_ci95"] is None else f" ± {o['gain_ci95']:.3f}"
        out += ["", f"B is better on {o['improved']} of {o['tasks']} tasks, worse on {o['worse']}, "
                    f"tied on {o['tied']}; mean paired gain {o['mean_gain']:+.3f}{ci} (95%)"]
    return "\n".join(out) + "\n"
