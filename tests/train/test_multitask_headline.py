"""The headline command: ``glyphbench-train configs/multitask.yaml`` on the paper's 100-task
mixture, every task of which exists. ``--backend prime-rl`` renders the paper's run for a GPU
cluster; on this CPU the same config runs one step through command-line overrides (the README
gives the command with the embedded model; here a tiny random model stands in)."""

from __future__ import annotations

import json
import tomllib
from pathlib import Path

import pytest

pytest.importorskip("torch")

from glyphbench_rl.cli.train import main  # noqa: E402
from glyphbench_rl.core import list_tasks, read_task_file  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
CONFIG = ROOT / "configs" / "multitask.yaml"
MIXTURE = ROOT / "tasks" / "multitask100.txt"


def test_every_task_of_the_mixture_exists():
    ids = read_task_file(MIXTURE)
    assert len(ids) == 100 and set(ids) <= set(list_tasks())


def test_prime_rl_renders_the_paper_run(tmp_path, capsys):
    assert main([str(CONFIG), "--backend", "prime-rl", "--out", str(tmp_path / "run")]) == 0
    toml = tomllib.loads((tmp_path / "run" / "prime_rl.toml").read_text())
    text = json.dumps(toml)
    assert "Qwen/Qwen3.5-4B" in text
    assert all(task in text for task in read_task_file(MIXTURE)[:3] + read_task_file(MIXTURE)[-3:])


def test_one_cpu_step_through_overrides(tiny_model_dir, tmp_path, capsys):
    out = tmp_path / "cpu"
    args = [str(CONFIG), "--out", str(out), f"model={tiny_model_dir}", "steps=1", "group_size=2",
            "groups_per_update=2", "max_episodes_at_once=4", "max_new_tokens=4", "max_turns=2",
            "eval_every=0", "seq_len=2048", "gradient_checkpointing=false", "tensorboard=false"]
    assert main(args) == 0
    metrics = [json.loads(line) for line in (out / "metrics.jsonl").read_text().splitlines()]
    assert metrics[-1]["step"] == 1
    assert "step 1/1: update" in capsys.readouterr().out
