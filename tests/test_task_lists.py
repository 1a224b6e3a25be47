import subprocess
import sys
from pathlib import Path

import pytest

from glyphbench_rl.core import list_tasks, read_task_file, resolve_tasks
from glyphbench_rl.core.registry import UnknownTaskError
from glyphbench_rl.core.tasklist import task_list_text

ROOT = Path(__file__).resolve().parents[1]


@pytest.mark.parametrize("tier", ["standard", "extended"])
def test_task_list_files_match_the_registry(tier):
    path = ROOT / "tasks" / f"{tier}.txt"
    assert path.read_text(encoding="utf-8") == task_list_text(tier), \
        "run: python scripts/gen_task_lists.py"
    assert read_task_file(path) == list_tasks(tier=tier)


def test_check_mode_of_the_generator():
    out = subprocess.run([sys.executable, str(ROOT / "scripts" / "gen_task_lists.py"), "--check"],
                         capture_output=True, text=True)
    assert out.returncode == 0, out.stderr


def test_resolve_tasks_forms(tmp_path):
    ids = list_tasks(pattern="*snake*")
    assert len(ids) == 3
    assert resolve_tasks("glyphbench/classics-snake-*-v0") == ids
    assert resolve_tasks(",".join(ids[:2])) == ids[:2]
    f = tmp_path / "mine.txt"
    f.write_text(f"# my tasks\n{ids[0]}\n\n{ids[1]}  # trailing comment\n{ids[0]}\n")
    assert resolve_tasks(str(f)) == ids[:2]
    with pytest.raises(UnknownTaskError, match="closest: glyphbench/classics-snake-easy-v0"):
        resolve_tasks("glyphbench/classics-snake-eazy-v0")
    with pytest.raises(ValueError, match="no registered task matches"):
        resolve_tasks("glyphbench/nothing-*")


def test_multitask100_is_the_paper_mixture():
    from collections import Counter
    from pathlib import Path
    root = Path(__file__).resolve().parents[1] / "tasks"
    ids = [l for l in (root / "multitask100.txt").read_text().splitlines() if l and not l.startswith("#")]
    rows = [l.split("\t") for l in (root / "catalog.tsv").read_text().splitlines()[1:]]
    assert ids == [r[2] for r in rows if r[4] == "yes"]
    assert Counter(r[0] for r in rows if r[4] == "yes") == {
        "Classics": 18, "Craftax": 18, "MiniAtari": 18, "MiniGrid": 18, "MiniHack": 19, "Procgen": 9}
