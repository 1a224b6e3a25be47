import pytest

from glyphbench_rl.train.config import ConfigError, TrainConfig, load_config

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
    ("group_size: 0\n", [], "group_size must be an int >= 1"),
    ("group_size: 2.5\n", [], "group_size must be an int"),
    ("loss: ppo\n", [], "loss must be one of"),
    ("lr: fast\n", [], "lr must be a number"),
    ("harness: {histry: 2}\n", [], "unknown key harness.histry"),
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


def test_missing_file(tmp_path):
    with pytest.raises(ConfigError, match="does not exist"):
        load_config(tmp_path / "nope.yaml")


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
