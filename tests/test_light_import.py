"""Heavy engines stay out of the import: ``import glyphbench_rl`` and ``glyphbench list`` load
none of them, and a task registered as ``"module:Class"`` imports its module only when made.

Each check runs in a fresh interpreter and reads ``sys.modules`` from an ``atexit`` hook, so
whatever the command imported on its way out counts too.
"""

from __future__ import annotations

import importlib.util
import json
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
HEAVY = ("jax", "nle", "minihack", "torch", "transformers")
MARK = "LOADED-TOP-LEVEL-PACKAGES "

PROBE = """
import atexit, json, sys
def _report():
    sys.stderr.write({mark!r} + json.dumps(sorted({{m.split(".")[0] for m in list(sys.modules)}})) + "\\n")
atexit.register(_report)
"""


def run_python(code: str, extra_path: Path | None = None) -> tuple[subprocess.CompletedProcess, set[str]]:
    env = dict(os.environ)
    paths = [str(ROOT)] + ([str(extra_path)] if extra_path else []) + [env.get("PYTHONPATH", "")]
    env["PYTHONPATH"] = os.pathsep.join(p for p in paths if p)
    proc = subprocess.run([sys.executable, "-c", PROBE.format(mark=MARK) + textwrap.dedent(code)],
                          cwd=ROOT, env=env, capture_output=True, text=True, timeout=120)
    lines = [line for line in proc.stderr.splitlines() if line.startswith(MARK)]
    assert len(lines) == 1, proc.stderr[-3000:]
    return proc, set(json.loads(lines[0][len(MARK):]))


def test_the_probe_sees_what_was_imported():
    proc, loaded = run_python("import glyphbench_rl, json\n")
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert {"glyphbench_rl", "gymnasium", "numpy"} <= loaded
    installed = [name for name in HEAVY if importlib.util.find_spec(name) is not None]
    if installed:                                   # a heavy import would be seen
        _, loaded = run_python(f"import {installed[0]}\n")
        assert installed[0] in loaded


def test_import_glyphbench_rl_loads_no_heavy_engine():
    proc, loaded = run_python("import glyphbench_rl\nglyphbench_rl.list_tasks()\n")
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert not loaded & set(HEAVY), sorted(loaded & set(HEAVY))


def test_glyphbench_list_loads_no_heavy_engine():
    proc, loaded = run_python("""
        import runpy, sys
        sys.argv = ["glyphbench", "list"]
        runpy.run_module("glyphbench_rl.cli", run_name="__main__")
    """)
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert "glyphbench/classics-snake-easy-v0" in proc.stdout
    assert not loaded & set(HEAVY), sorted(loaded & set(HEAVY))


LAZY_GAME = '''
from dataclasses import dataclass
from glyphbench_rl.core import ActionSet, GlyphTask
from glyphbench_rl.core.params import param

@dataclass(frozen=True)
class ProbeParams:
    size: int = param(3, 1, 9)

class LazyProbe(GlyphTask):
    title = "Lazy probe"
    rules = "Nothing happens on a row of {size} cells."
    Params = ProbeParams
    ACTIONS = ActionSet([("WAIT", "wait")])
    glyphs = {"·": "floor"}

    def _setup(self, rng):
        pass

    def _act(self, action):
        pass

    def _grid(self):
        return ["·" * self.params.size]
'''


def test_a_module_class_spec_is_imported_only_when_made(tmp_path):
    (tmp_path / "lazy_probe_game.py").write_text(LAZY_GAME, encoding="utf-8")
    proc, loaded = run_python("""
        import sys
        import gymnasium
        import glyphbench_rl
        from glyphbench_rl.core import get_spec, register_variants

        ID = "glyphbench/classics-lazyprobe-v0"
        register_variants("lazy_probe_game:LazyProbe", "Classics", {ID: dict(size=4, max_turns=5)})
        assert "lazy_probe_game" not in sys.modules
        assert ID in glyphbench_rl.list_tasks() and ID in gymnasium.registry
        assert get_spec(ID).game_name == "LazyProbe"
        assert "lazy_probe_game" not in sys.modules, "listing or naming the task imported it"
        task = glyphbench_rl.make(ID)
        assert "lazy_probe_game" in sys.modules
        assert task.reset(seed=0)[0].splitlines()[1] == "····"
        print("made", type(task).__name__)
    """, extra_path=tmp_path)
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert "made LazyProbe" in proc.stdout
    assert "lazy_probe_game" in loaded


@pytest.mark.parametrize("module", ["glyphbench_rl.core", "glyphbench_rl.games"])
def test_core_and_games_never_import_heavy_engines_at_module_level(module):
    proc, loaded = run_python(f"import {module}\n")
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert not loaded & set(HEAVY)
