import json

import pytest

yaml = pytest.importorskip("yaml")

from glyphbench_rl.train.config import ConfigError  # noqa: E402
from glyphbench_rl.cli.sweep import main  # noqa: E402
from glyphbench_rl.train.sweep import expand, slurm_script, status, write_conditions  # noqa: E402


def test_snake_sweep_expands_to_the_papers_conditions():
    spec = yaml.safe_load(open("configs/snake_sweep.yaml"))
    conds = expand(spec)
    main_grid = [c for n, c in conds if not n.startswith("long")]
    long = [c for n, c in conds if n.startswith("long")]
    assert len(main_grid) == 60 and len(long) == 6
    assert {c["group_size"]: c["steps"] for c in main_grid} == {32: 192, 64: 96, 128: 48, 256: 24, 512: 12}
    assert {c["group_size"]: c["steps"] for c in long} == {32: 800, 512: 50}
    assert all(c["loss"] == "ipo" and c["max_new_tokens"] == 4096 for _, c in conds)
    names = [n for n, _ in conds]
    assert "snake-easy_g32_lr1e-06" in names and len(set(names)) == len(names)


@pytest.mark.parametrize("spec, match", [
    ({"grid": {"lrr": [1]}}, "unknown config key 'lrr'"),
    ({"grid": {"lr": 1}}, "must be a non-empty list"),
    ({"base": {}, "grids": {}}, "unknown sweep key 'grids'"),
    ({"grid": {"group_size": [3]}, "rollout_budget": 10}, "not a multiple"),
    ({"grid": {"group_size": [0]}}, "group_size must be an int >= 2"),
    ({"grid": {"lr": [0]}}, r"^lr must be a number in \(0, 1\], got 0$"),
    ({"base": {"tasks": [1, 2]}}, r"^tasks must be a task-list file, .* got \[1, 2\]$"),
    ({"base": [1]}, r"^base must be a mapping or null, got \[1\]$"),
    ({"grid": {"lr": []}}, r"^grid\.lr must be a non-empty list, got \[\]$"),
    ({"rollout_budget": "6144"}, r"^rollout_budget must be an int >= 1 or null, got '6144'$"),
    ({"variants": [1]}, r"^variants must be a mapping or null, got \[1\]$"),
    ({"variants": {"long": {"grids": {}}}},
     r"^unknown sweep key 'variants\.long\.grids'; did you mean 'variants\.long\.grid'\?$"),
    ({"variants": {"long": {"rollout_budget": True}}},
     r"^variants\.long\.rollout_budget must be an int >= 1 or null, got True$"),
    ({"variants": {"long": {"variants": {}}}}, r"^unknown sweep key 'variants\.long\.variants'"),
    ([{"grid": {}}], r"^a sweep file is a mapping of base, grid, rollout_budget, variants, got list$"),
])
def test_bad_sweeps(spec, match):
    with pytest.raises(ConfigError, match=match):
        expand(spec)


def test_variants_override_only_what_they_set():
    conds = dict(expand({"base": {"group_size": 4}, "grid": {"lr": [1e-6]}, "rollout_budget": 8,
                         "variants": {"big": {"base": {"group_size": 8}}, "plain": {"rollout_budget": None}}}))
    assert conds == {"lr1e-06": {"group_size": 4, "lr": 1e-6, "steps": 2},
                     "big_lr1e-06": {"group_size": 8, "lr": 1e-6, "steps": 1},
                     "plain_lr1e-06": {"group_size": 4, "lr": 1e-6}}


def test_slurm_script_and_dry_run(tmp_path, capsys):
    rows = write_conditions(tmp_path, expand({"grid": {"lr": [1e-6, 2e-6]}}))
    text = slurm_script(tmp_path, rows, "#SBATCH --gres=gpu:1")
    assert "#SBATCH --array=0-1" in text and "#SBATCH --gres=gpu:1" in text
    assert text.count("glyphbench_rl.cli.train") == 4 and "--resume" in text
    sweep = tmp_path / "s.yaml"
    sweep.write_text("grid: {lr: [1.0e-6, 2.0e-6]}\n")
    assert main([str(sweep), "--dry-run"]) == 0
    assert "2 conditions" in capsys.readouterr().out


def test_runs_skip_finished_and_tabulate(tmp_path, tiny_model_dir, capsys):
    sweep = tmp_path / "s.yaml"
    sweep.write_text(f"base: {{model: {tiny_model_dir}, tasks: glyphbench/classics-snake-easy-v0, "
                     f"max_new_tokens: 4, max_turns: 3, checkpoint_every: 1}}\n"
                     f"grid: {{group_size: [2, 4]}}\nrollout_budget: 4\n")
    out = tmp_path / "sweep"
    assert main([str(sweep), "--out", str(out), "--parallel", "2"]) == 0
    for name, steps in (("g2", 2), ("g4", 1)):
        assert status(out / "runs" / name, steps) == "done"
    summary = json.loads((out / "summary.json").read_text())
    assert [r["steps"] for r in summary] == [2, 1]
    if __import__("importlib").util.find_spec("matplotlib"):
        assert (out / "curves.png").stat().st_size > 1000
    capsys.readouterr()
    assert main([str(sweep), "--out", str(out)]) == 0          # rerun: nothing left to do
    assert capsys.readouterr().out.count("done, skipped") == 2


def test_prime_rl_sweep_renders_one_config_per_condition(tmp_path, capsys):
    import tomllib
    sweep = tmp_path / "s.yaml"
    sweep.write_text("base: {tasks: glyphbench/classics-snake-easy-v0}\n"
                     "grid: {group_size: [4, 8], lr: [1.0e-6, 2.0e-6]}\nrollout_budget: 32\n")
    out = tmp_path / "out"
    assert main([str(sweep), "--out", str(out), "--prime-rl"]) == 0
    tomls = sorted(out.glob("runs/*/prime_rl.toml"))
    assert len(tomls) == 4
    docs = {p.parent.name: tomllib.loads(p.read_text()) for p in tomls}
    for doc in docs.values():     # equal interaction: steps x group size = the rollout budget
        assert doc["max_steps"] * doc["orchestrator"]["group_size"] == 32
    assert {d["trainer"]["optim"]["lr"] for d in docs.values()} == {1e-6, 2e-6}
    script = (out / "prime_rl.sh").read_text()
    assert script.count("rl @ ") == 4 and all(str(p) in script for p in tomls)
    assert main([str(sweep), "--out", str(out), "--prime-rl", "--slurm"]) == 0
    assert (out / "prime_rl.sbatch").read_text().count("rl @ ") == 4
    bad = tmp_path / "bad.yaml"
    bad.write_text("base: {tasks: glyphbench/classics-snake-easy-v0, top_p: 0.9}\ngrid: {lr: [1.0e-6]}\n")
    capsys.readouterr()
    assert main([str(bad), "--out", str(tmp_path / "o2"), "--prime-rl"]) == 2
    assert "no Prime-RL equivalent for top_p" in capsys.readouterr().err
