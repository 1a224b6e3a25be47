"""scripts/step_budget.py: the five ways it plays a task, and its table (no timing asserted)."""

import importlib.util
import re
import subprocess
import sys
from pathlib import Path

from glyphbench_rl.core import make

ROOT = Path(__file__).resolve().parents[2]
spec = importlib.util.spec_from_file_location("step_budget", ROOT / "scripts" / "step_budget.py")
budget = importlib.util.module_from_spec(spec)
spec.loader.exec_module(budget)


def test_held_parts_stay_as_the_first_frame_and_full_restores_the_hooks():
    task = make("glyphbench/classics-snake-easy-v0")
    first, _ = task.reset(seed=0)
    budget._hold(task, "both held")
    grid, hud = task._grid(), task._hud()
    for action in (1, 1, 2, 2, 0):
        task.step(action)
        assert task._grid() == grid and task._hud() == hud
    turn = task.turn
    budget._hold(task, "frame only")     # the game's turn does nothing: the state stays as it is
    now = type(task)._grid(task)
    obs = task.step(1)[0]
    assert task.turn == turn + 1 and "\n".join(now) in obs and type(task)._grid(task) == now
    budget._hold(task, "full")
    assert not {"_grid", "_hud", "_act"} & set(vars(task))


def test_prints_a_row_per_task_and_the_medians(capsys):
    assert budget.main(["--tasks", "glyphbench/classics-snake-easy-v0,glyphbench/minigrid-empty-5x5-v0",
                        "--runs", "1", "--steps", "20", "--rounds", "1"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[0].split()[:6] == ["task", "full", "grid", "hud", "turn", "frame"]
    assert [line.split()[0] for line in lines[1:3]] == ["glyphbench/classics-snake-easy-v0",
                                                        "glyphbench/minigrid-empty-5x5-v0"]
    assert lines[3].startswith("median over 2 tasks")
    full, grid, hud, turn, frame = map(float, lines[1].split()[1:])
    assert full > 0 and frame > 0


def test_bytecode_counts_are_the_same_in_every_fresh_process():
    command = [sys.executable, str(ROOT / "scripts" / "step_budget.py"), "--bytecodes", "--tasks",
               "glyphbench/classics-snake-easy-v0", "--runs", "1", "--steps", "20", "--top", "3"]
    first, second = (subprocess.run(command, capture_output=True, text=True, check=True, cwd=ROOT).stdout
                     for _ in range(2))
    assert first == second       # a count, not a time: a busy machine does not change it
    lines = first.splitlines()
    assert lines[0].split()[:2] == ["task", "bytecodes"]
    assert lines[1].split()[0] == "glyphbench/classics-snake-easy-v0" and int(lines[1].split()[1]) > 0
    busiest = lines[lines.index("") + 2:]
    assert len(busiest) == 3
    assert all(re.fullmatch(r"\s*\d+\.\d\s+\S+\.py:\S+", line) for line in busiest), busiest
