"""Without the ``nethack`` extra, making a MiniHack or NetHack task fails with one line naming
the extra, from Python and from the CLI (simulated: the engine packages are blocked in a fresh
interpreter, as if not installed)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]
EXTRA = "pip install 'glyphbench_rl[nethack]'"


def run_without(module: str, code: str) -> subprocess.CompletedProcess:
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]))
    block = f"import sys\nsys.modules[{module!r}] = None   # import {module} now fails as if absent\n"
    return subprocess.run([sys.executable, "-c", block + code], cwd=ROOT, env=env,
                          capture_output=True, text=True, timeout=120)


@pytest.mark.parametrize("module", ["nle", "minihack"])
def test_make_names_the_extra_in_one_line(module):
    proc = run_without(module, """
import glyphbench_rl
from glyphbench_rl.core import MissingExtraError
assert "glyphbench/minihack-eat-v0" in glyphbench_rl.list_tasks()   # listed all the same
for task_id in ("glyphbench/minihack-eat-v0", "glyphbench/nethack-full-v0"):
    try:
        glyphbench_rl.make(task_id)
    except MissingExtraError as e:
        assert isinstance(e, ModuleNotFoundError)
        print("ERROR " + repr(str(e)))
""")
    assert proc.returncode == 0, proc.stderr[-2000:]
    errors = [eval(line[6:]) for line in proc.stdout.splitlines() if line.startswith("ERROR ")]
    assert len(errors) == 2
    for message in errors:
        assert "\n" not in message and EXTRA in message and module in message


def test_the_cli_prints_it_as_one_line():
    proc = run_without("nle", """
import runpy
sys.argv = ["glyphbench", "show", "glyphbench/minihack-eat-v0"]
runpy.run_module("glyphbench_rl.cli", run_name="__main__")
""")
    assert proc.returncode == 2
    lines = [line for line in proc.stderr.splitlines() if line.strip()]
    assert len(lines) == 1, proc.stderr[-2000:]
    assert lines[0].startswith("glyphbench: error: ") and EXTRA in lines[0]
    assert proc.stdout == ""


@pytest.mark.parametrize("argv", [
    ["glyphbench-eval", "--tasks", "glyphbench/minihack-eat-v0", "--backend", "random", "--episodes", "1",
     "--out", "{tmp}/eval"],
    ["glyphbench-train", "{tmp}/config.yaml", "--out", "{tmp}/run"],
])
def test_eval_and_train_stop_before_any_work_with_one_line(argv, tmp_path):
    (tmp_path / "config.yaml").write_text("tasks: [glyphbench/minihack-eat-v0]\nsteps: 1\n")
    argv = [a.format(tmp=tmp_path) for a in argv]
    module = {"glyphbench-eval": "glyphbench_rl.cli.eval", "glyphbench-train": "glyphbench_rl.cli.train"}[argv[0]]
    proc = run_without("nle", f"""
sys.argv = {argv!r}
import importlib
sys.exit(importlib.import_module({module!r}).main())
""")
    assert proc.returncode == 2, proc.stderr[-2000:]
    lines = [line for line in proc.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and EXTRA in lines[0], proc.stderr[-2000:]
    assert not (tmp_path / "run").exists() or not any((tmp_path / "run").iterdir())
