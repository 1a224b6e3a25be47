import pytest

from pathlib import Path

import glyphbench_rl
from glyphbench_rl.core import resolve_tasks
from glyphbench_rl.train.config import FIELDS, ConfigError, TrainConfig, config_from_dict, load_config

pytest.importorskip("yaml")


def _write(tmp_path, text):
    p = tmp_path / "c.yaml"
    p.write_text(text)
    return p


def test_defaults_and_overrides(tmp_path):
    cfg = load_config(_write(tmp_path, "tasks: glyphbench/classics-snake-easy-v0\nlr: 2.0e-6\n"),
                      ["group_size=8", "harness.history=2", "loss=default"])
    assert (cfg.lr, cfg.group_size, cfg.loss, cfg.harness_config().history) == (2e-6, 8, "default", 2)
    assert cfg.betas == [0.9, 0.95] and cfg.weight_decay == 0 and cfg.grad_clip == 1


@pytest.mark.parametrize("text, overrides, match", [
    ("lrr: 1\n", [], "unknown config key 'lrr'; did you mean 'lr'"),
    ("group_size: 0\n", [], "group_size must be an int >= 2"),
    ("group_size: 2.5\n", [], "group_size must be an int"),
    ("loss: ppo\n", [], "loss must be one of"),
    ("lr: fast\n", [], "lr must be a number"),
    ("harness: {histry: 2}\n", [], "unknown config key 'harness.histry'"),
    ("harness: {legend: maybe}\n", [], "harness.legend must be one of"),
    ("[1, 2]\n", [], "mapping"),
    ("lr: [\n", [], "not valid YAML at line"),
    ("", ["steps"], "not key=value"),
    ("", ["lr.x=1"], "lr has no sub-keys"),
    ("", ["betas=[0.9]"], "betas must be two numbers"),
])
def test_bad_configs_name_the_key(tmp_path, text, overrides, match):
    with pytest.raises(ConfigError, match=match):
        load_config(_write(tmp_path, text), overrides)


@pytest.mark.parametrize("text, message", [
    ("tasks: [1, 2]\n", "tasks must be a task-list file, glob or comma list, or a non-empty list of "
                        "task IDs, got [1, 2]"),
    ("lr: 0\n", "lr must be a number in (0, 1], got 0"),
    ("group_size: 1\n", "group_size must be an int >= 2, got 1"),
    ("steps: true\n", "steps must be an int >= 1, got True"),
    ("steps: '5'\n", "steps must be an int >= 1, got '5'"),
    ("betas: [0.9, 1]\n", "betas.1 must be a number in [0, 1), got 1"),
    ("harness: {history: -1}\n", "harness.history must be an int >= 0, got -1"),
    ("harness: 3\n", "harness must be a mapping, got 3"),
    ("wandb_name: ' '\n", "wandb_name must be a non-empty string or null, got ' '"),
    ("lr: 1.0e-6\nsteps: 3\nlr: 2.0e-6\n", "c.yaml: duplicate key 'lr' at line 3"),
    ("harness:\n  history: 2\n  history: 3\n", "c.yaml: duplicate key 'history' at line 3"),
])
def test_bad_values_are_one_line_errors(tmp_path, text, message):
    with pytest.raises(ConfigError) as e:
        load_config(_write(tmp_path, text))
    assert str(e.value).endswith(message) and "\n" not in str(e.value)


def test_numbers_as_yaml_1_2_writes_them_and_ints_for_floats(tmp_path):
    cfg = load_config(_write(tmp_path, "lr: 5e-6\nformat_reward: 1\n"), ["kl_coef=1e-4"])
    assert (cfg.lr, cfg.kl_coef, cfg.format_reward) == (5e-6, 1e-4, 1.0)
    assert isinstance(cfg.format_reward, float)


def test_yaml_anchors_may_override_merged_keys(tmp_path):
    cfg = load_config(_write(tmp_path, "harness: &h {history: 2, legend: changed}\n"), [])
    assert cfg.harness == {"history": 2, "legend": "changed"}
    from glyphbench_rl.train.config import read_yaml
    p = tmp_path / "anchors.yaml"
    p.write_text("a: &a {x: 1, y: 2}\nb:\n  <<: *a\n  x: 3\n")
    assert read_yaml(p) == {"a": {"x": 1, "y": 2}, "b": {"x": 3, "y": 2}}


def test_missing_file(tmp_path):
    with pytest.raises(ConfigError, match="does not exist"):
        load_config(tmp_path / "nope.yaml")


def test_unreadable_config_files_are_one_line_errors(tmp_path):
    binary = tmp_path / "model.bin"
    binary.write_bytes(b"\x89PNG\r\n\x1a\n\x00\xff\xfe")
    with pytest.raises(ConfigError, match=r"^\S*model\.bin: not a text file \(byte 0 is not UTF-8\)$"):
        load_config(binary)
    with pytest.raises(ConfigError, match=r"^config file \S+ is a directory, not a YAML file$"):
        load_config(tmp_path)


def test_default_task_list_resolves_against_the_project(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)                         # no tasks/ folder here
    cfg = load_config(None)
    project = Path(glyphbench_rl.__file__).resolve().parents[1]
    assert cfg.tasks == "tasks/standard.txt"            # kept as written; read from the project
    assert resolve_tasks(cfg.tasks) == resolve_tasks(str(project / "tasks" / "standard.txt"))
    (tmp_path / "tasks").mkdir()                        # a task list of one's own comes first
    (tmp_path / "tasks" / "standard.txt").write_text("glyphbench/classics-snake-easy-v0\n")
    assert resolve_tasks(load_config(None).tasks) == ["glyphbench/classics-snake-easy-v0"]


def test_train_cli_with_an_empty_config_runs_from_another_directory(tmp_path):
    """glyphbench-train on an empty config, run elsewhere, trains on the project's standard list
    (rendered for Prime-RL here, which reads every task and loads no model)."""
    import os
    import subprocess
    import sys
    import tomllib
    (tmp_path / "empty.yaml").write_text("")
    env = {**os.environ, "PATH": str(tmp_path / "nowhere")}             # no `rl` to launch
    done = subprocess.run([sys.executable, "-m", "glyphbench_rl.cli.train", "empty.yaml", "--backend",
                           "prime-rl", "--out", "run"], cwd=tmp_path, env=env, capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    taskset = tomllib.loads((tmp_path / "run" / "prime_rl.toml").read_text())["orchestrator"]["train"]
    project_list = str(Path(glyphbench_rl.__file__).resolve().parents[1] / "tasks" / "standard.txt")
    assert taskset["source"][0]["env"]["taskset"]["tasks"] == resolve_tasks(project_list)


def test_to_dict_round_trips_and_assignment_is_checked():
    cfg = TrainConfig(lr=1, harness={"history": 2})
    assert cfg.lr == 1.0 and cfg.to_dict()["harness"] == {"history": 2} and cfg.to_dict()["lr"] == 1.0
    assert set(cfg.to_dict()) == FIELDS
    with pytest.raises(ConfigError, match=r"^lr must be a number in \(0, 1\], got 0$"):
        cfg.lr = 0                                      # assignment is checked too
    assert config_from_dict(cfg.to_dict()) == cfg


def test_shipped_configs_load():
    from pathlib import Path
    import yaml

    from glyphbench_rl.train.sweep import expand
    for path in sorted(Path(__file__).resolve().parents[2].joinpath("configs").glob("*.yaml")):
        data = yaml.safe_load(path.read_text())
        if "grid" in data:              # a sweep file
            assert expand(data)
        else:
            assert isinstance(load_config(path), TrainConfig)
