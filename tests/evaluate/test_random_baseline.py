"""tasks/baselines/random.tsv must list exactly the registered tasks (cheap: the file is only read)."""

from pathlib import Path

from glyphbench_rl import get_spec, list_tasks

TSV = Path(__file__).resolve().parents[2] / "tasks" / "baselines" / "random.tsv"
COLUMNS = ["task_id", "suite", "episodes", "mean_return", "ci95", "mean_length"]


def test_random_baseline_lists_every_registered_task():
    lines = TSV.read_text(encoding="utf-8").splitlines()
    assert lines[0].startswith("#") and "scripts/random_baseline.py" in "\n".join(lines[:4])
    body = [line.split("\t") for line in lines if not line.startswith("#")]
    assert body[0] == COLUMNS
    rows = body[1:]
    assert [r[0] for r in rows] == list_tasks(), "rerun: python scripts/random_baseline.py"
    for task_id, suite, episodes, mean, ci, length in rows:
        assert suite == get_spec(task_id).suite and int(episodes) > 0 and float(length) > 0
        if get_spec(task_id).tier == "standard":
            assert -1 <= float(mean) <= 1 and (ci == "" or float(ci) >= 0)
