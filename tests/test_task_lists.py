import subprocess
import sys
from collections import Counter
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


def test_missing_task_list_file_says_it_does_not_exist(tmp_path):
    missing = tmp_path / "nope.txt"
    with pytest.raises(ValueError, match=r"^task-list file '.*nope\.txt' does not exist$"):
        resolve_tasks(str(missing))
    with pytest.raises(ValueError, match=r"^task-list file '/no/such/list' does not exist$"):
        resolve_tasks(["glyphbench/classics-snake-easy-v0", "/no/such/list"])
    with pytest.raises(ValueError, match="is a directory"):
        resolve_tasks(str(tmp_path))
    with pytest.raises(UnknownTaskError, match="closest"):     # a mistyped ID is still an ID
        resolve_tasks("glyphbench/classics-snake-eazy-v0")


def test_binary_task_list_file_is_one_line_naming_the_file(tmp_path):
    binary = tmp_path / "tasks.bin"
    binary.write_bytes(b"glyphbench/classics-snake-easy-v0\n\xff\xfe\x00garbage\n")
    with pytest.raises(ValueError) as e:
        resolve_tasks(str(binary))
    message = str(e.value)
    assert str(binary) in message and "not UTF-8 text" in message and "\n" not in message


def test_non_string_task_entries_are_one_line_errors():
    for bad, named in (([1, 2], "got 1 (int)"), (["glyphbench/classics-snake-easy-v0", None], "got None")):
        with pytest.raises(ValueError) as e:
            resolve_tasks(bad)
        assert "\n" not in str(e.value) and "task IDs" in str(e.value) and named in str(e.value)


def test_unimplemented_catalog_tasks_are_counted_by_suite():
    """The paper's 100-task mixture names tasks not implemented yet: one line says how many, of
    which suites, and an example (not the first one alone, as if it were the only one)."""
    path = ROOT / "tasks" / "multitask100.txt"
    ids = read_task_file(path)
    registered = set(list_tasks())
    missing = [t for t in ids if t not in registered]
    if not missing:
        pytest.skip("every task of the mixture is implemented")
    with pytest.raises(UnknownTaskError) as e:
        resolve_tasks(str(path))
    message = str(e.value)
    rows = [line.split("\t") for line in (ROOT / "tasks" / "catalog.tsv").read_text().splitlines()[1:]]
    suite_of = {r[2]: r[0] for r in rows}
    counts = Counter(suite_of[t] for t in missing)
    assert message.startswith(f"{len(missing)} of the {len(ids)} tasks are not implemented in this version yet (")
    for suite, n in counts.items():
        assert f"{suite} {n}" in message
    assert f"e.g. {missing[0]}" in message and "glyphbench list --counts" in message and "\n" not in message


def test_train_cli_names_the_unimplemented_count(tmp_path, capsys):
    from glyphbench_rl.cli.train import main
    if all(t in set(list_tasks()) for t in read_task_file(ROOT / "tasks" / "multitask100.txt")):
        pytest.skip("every task of the mixture is implemented")
    assert main([str(ROOT / "configs" / "multitask.yaml"), "--backend", "prime-rl",
                 "--out", str(tmp_path / "run")]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("glyphbench-train: error: ") and "of the 100 tasks are not implemented" in err
    assert "\n" not in err


def test_shipped_task_lists_resolve_from_any_directory(tmp_path, monkeypatch):
    """`tasks/standard.txt` names the shipped list wherever the command runs (vf-eval,
    glyphbench-eval and configs alike); a file of that name here still wins."""
    from glyphbench_rl.core import resolve_tasks
    monkeypatch.chdir(tmp_path)
    assert resolve_tasks(["tasks/standard.txt"]) == list_tasks(tier="standard")
    (tmp_path / "tasks").mkdir()
    (tmp_path / "tasks" / "standard.txt").write_text("glyphbench/classics-snake-easy-v0\n")
    assert resolve_tasks("tasks/standard.txt") == ["glyphbench/classics-snake-easy-v0"]
