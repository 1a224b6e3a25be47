"""`glyphbench-train --backend prime-rl`: the rendered TOML against Prime-RL's schema (transcribed
in prime_rl_schema.py), values carried over, the taskset's training rows, and the launch."""

import math
import os
import stat
import tomllib

import pytest
import yaml

from prime_rl_schema import PRIME_RL_COMMIT, check, tasksets

from glyphbench_rl.core.seeding import HELDOUT_SEEDS, TRAIN_SEEDS
from glyphbench_rl.integrations import prime_rl
from glyphbench_rl.integrations.prime_rl import PrimeRLConfigError, render_toml
from glyphbench_rl.integrations.prime_rl.render import dumps
from glyphbench_rl.cli.train import main
from glyphbench_rl.train.config import config_from_dict, load_config

TASKS = ["glyphbench/classics-snake-easy-v0", "glyphbench/classics-maze-easy-v0"]


def render(tmp_path, **keys) -> dict:
    cfg = config_from_dict({"tasks": TASKS, **keys})
    return tomllib.loads(render_toml(cfg, run_dir=tmp_path))


@pytest.mark.parametrize("keys", [
    {},
    {"loss": "default", "gradient_checkpointing": True},
    {"eval_every": 5, "harness": {"max_context_tokens": 2000}},
    {"model": "Qwen/Qwen3.5-4B"},
    {"wandb_project": "glyph", "wandb_entity": "lab", "wandb_name": "run-1", "tensorboard": False},
])
def test_rendered_toml_uses_only_schema_keys(tmp_path, keys):
    assert prime_rl.PRIME_RL_COMMIT == PRIME_RL_COMMIT       # code and schema copy name one version
    doc = render(tmp_path, **keys)
    assert check(doc) == []


def test_schema_check_catches_wrong_keys_and_types(tmp_path):
    doc = render(tmp_path)
    doc["trainer"]["loss"]["kl_coef"] = 1e-3                  # our name, not Prime-RL's
    doc["orchestrator"]["batch_size"] = "32"
    doc["trainer"]["optim"]["type"] = "adam"
    assert check(doc) == ["unknown key trainer.loss.kl_coef",
                          "trainer.optim.type = 'adam': not one of ['adamw']",
                          "orchestrator.batch_size = '32' has the wrong type (want <class 'int'>)"]


def test_values_round_trip(tmp_path):
    doc = render(tmp_path, steps=12, group_size=8, groups_per_update=4, lr=2e-6, seq_len=4096,
                 max_new_tokens=512, threshold=0.05, kl_coef=2e-3, adv_tau=0.5, betas=[0.8, 0.9],
                 weight_decay=0.01, grad_clip=0.5, temperature=0.7, checkpoint_every=3,
                 keep_checkpoints=5, logprob_chunk=512, eval_every=4, eval_episodes=3,
                 harness={"history": 2, "legend": "changed", "max_context_tokens": 3000})
    assert (doc["max_steps"], doc["seq_len"]) == (12, 4096)
    assert doc["model"] == {"name": "HuggingFaceTB/SmolLM2-135M-Instruct"}
    assert doc["output_dir"] == str(tmp_path.resolve() / "outputs")
    assert doc["ckpt"] == {"interval": 3, "keep_last": 5}
    assert "wandb" not in doc
    assert render(tmp_path, wandb_project="glyph")["wandb"] == {"project": "glyph"}
    trainer, orch = doc["trainer"], doc["orchestrator"]
    assert trainer["loss"] == {"type": "ipo", "ipo_threshold": 0.05, "adv_tau": 0.5, "kl_tau": 2e-3}
    assert trainer["optim"] == {"type": "adamw", "lr": 2e-6, "betas1": 0.8, "betas2": 0.9,
                                "weight_decay": 0.01, "max_norm": 0.5}
    assert trainer["scheduler"] == {"type": "constant"}
    assert trainer["model"] == {"fused_lm_head_token_chunk_size": 512}
    assert (orch["batch_size"], orch["group_size"], orch["algorithms"]) == (32, 8, ["grpo"])
    assert orch["train"]["sampling"] == {"temperature": 0.7, "max_completion_tokens": 512}
    assert {f["type"]: f["enforce"] for f in orch["post_batch_filters"]}["zero_advantage"] is False
    [env] = orch["train"]["env"]
    prompt = {"history": 2, "legend": "changed", "max_context_tokens": 3000}
    # 12 steps x 4 groups over 2 tasks: 24 training rows per task, as many as built-in groups
    assert env["taskset"] == {"id": "glyphbench-rl", "tasks": TASKS, "split": "train", "episodes": 24,
                              "seed_start": 0, "harness": prompt}
    ev = orch["eval"]
    assert (ev["interval"], ev["group_size"], ev["skip_first_step"]) == (4, 1, True)
    assert ev["sampling"] == {"temperature": 0.7, "max_completion_tokens": 512}
    assert ev["env"][0]["taskset"] == {**env["taskset"], "split": "heldout", "episodes": 3}


def test_default_loss_and_options(tmp_path):
    doc = render(tmp_path, loss="default", mask_low=0.1, mask_high=0.3, gradient_checkpointing=True,
                 model="Qwen/Qwen3.5-4B")
    assert doc["trainer"]["loss"] == {"type": "default", "dppo_mask_low": 0.1, "dppo_mask_high": 0.3,
                                      "adv_tau": 1.0, "kl_tau": 1e-3}
    assert doc["trainer"]["model"]["ac"] == {}
    assert doc["model"]["name"] == "Qwen/Qwen3.5-4B" and "renderer" not in doc["orchestrator"]
    assert "eval" not in doc["orchestrator"] and doc["inference"] == {}


def test_resume_renders_resume_step(tmp_path):
    cfg = config_from_dict({"tasks": TASKS})
    assert tomllib.loads(render_toml(cfg, run_dir=tmp_path, resume=True))["ckpt"]["resume_step"] == -1


def test_model_names(tmp_path):
    local = tmp_path / "ckpt"
    local.mkdir()
    (local / "config.json").write_text("{}")
    doc = render(tmp_path, model=str(local))
    assert doc["model"]["name"] == str(local.resolve())
    assert doc["orchestrator"]["renderer"] == {"name": "default"}   # its own chat template
    gguf_only = tmp_path / "gguf"
    gguf_only.mkdir()
    for bad in (str(gguf_only), str(tmp_path / "m.gguf"), str(tmp_path / "missing")):
        with pytest.raises(PrimeRLConfigError):
            render(tmp_path, model=bad)


def test_every_train_config_field_has_a_prime_rl_decision():
    from glyphbench_rl.integrations.prime_rl import render as r
    from glyphbench_rl.train.config import FIELDS

    listed = [*r.CARRIED, *r.ONLY_AT_DEFAULT, *r.NOT_CARRIED]
    assert sorted(listed) == sorted(FIELDS), "classify new TrainConfig fields in prime_rl/render.py"


@pytest.mark.parametrize("keys, named", [
    ({"top_p": 0.9}, "top_p=0.9"), ({"std_normalize": True}, "std_normalize=true"),
    ({"include_truncated": False}, "include_truncated=false"), ({"max_turns": 8}, "max_turns=8"),
    ({"format_reward": 0.5}, "format_reward=0.5"),
    ({"harness": {"reply_prefix": "<action>"}}, "harness.reply_prefix='<action>'"),
])
def test_inexpressible_values_are_refused(tmp_path, keys, named):
    with pytest.raises(PrimeRLConfigError, match=named) as e:
        render(tmp_path, **keys)
    assert "\n" not in str(e.value)


def test_tasksets_load_training_and_heldout_rows(tmp_path):
    pytest.importorskip("verifiers")
    from glyphbench_rl.integrations.verifiers_v1 import GlyphbenchTaskset, GlyphbenchTasksetConfig

    doc = render(tmp_path, steps=5, groups_per_update=3, eval_every=5, eval_episodes=2)
    train, heldout = (GlyphbenchTasksetConfig.model_validate(t) for t in tasksets(doc))
    rows = [(t.data.task_id, t.data.seed) for t in GlyphbenchTaskset(train)]
    per_task = math.ceil(5 * 3 / len(TASKS))
    assert rows == [(t, s) for t in TASKS for s in range(per_task)]
    assert all(s in TRAIN_SEEDS for _, s in rows)
    assert all(t.data.seed in HELDOUT_SEEDS for t in GlyphbenchTaskset(heldout))


def test_taskset_split_option():
    pytest.importorskip("verifiers")
    from glyphbench_rl.integrations.verifiers_v1 import GlyphbenchTasksetConfig

    base = {"id": "glyphbench-rl", "tasks": TASKS[:1]}
    assert GlyphbenchTasksetConfig(**base, episodes=3, seed_start=5).seeds() == [1_000_005, 1_000_006,
                                                                                 1_000_007]
    assert GlyphbenchTasksetConfig(**base, split="train", episodes=3, seed_start=5).seeds() == [5, 6, 7]
    with pytest.raises(ValueError, match="exceed the training range"):
        GlyphbenchTasksetConfig(**base, split="train", episodes=2, seed_start=999_999)
    with pytest.raises(ValueError, match="split"):
        GlyphbenchTasksetConfig(**base, split="test")


def test_toml_writer_round_trips_awkward_values():
    doc = {"plain key": "tab\tquote\" backslash\\ newline\n bell\x07 é ▶", "n": -3, "x": 1e-300,
           "flags": [True, False], "long": [f"glyphbench/task-{i:03d}-v0" for i in range(20)],
           "empty": [], "t": {"u": {}, "arr": [{"a": 1, "sub": {"b": [1.5]}}, {"a": 2}]}}
    assert tomllib.loads(dumps(doc)) == doc
    with pytest.raises(ValueError):
        dumps({"x": float("nan")})
    with pytest.raises(TypeError):
        dumps({"x": None})


# -- the command line ------------------------------------------------------------------------------

@pytest.fixture
def config_file(tmp_path):
    path = tmp_path / "run.yaml"
    path.write_text(yaml.safe_dump({"tasks": TASKS, "group_size": 4, "steps": 3, "lr": 5e-6}))
    return path


@pytest.fixture
def fake_rl(tmp_path, monkeypatch):
    """An `rl` on an otherwise empty PATH that records its argv and exits with $FAKE_RL_EXIT."""
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    script = bin_dir / "rl"
    script.write_text('#!/bin/sh\nprintf \'%s\\n\' "$@" > "$FAKE_RL_ARGV"\nexit "${FAKE_RL_EXIT:-0}"\n')
    script.chmod(script.stat().st_mode | stat.S_IXUSR)
    monkeypatch.setenv("PATH", str(bin_dir))
    monkeypatch.setenv("FAKE_RL_ARGV", str(tmp_path / "argv.txt"))
    return tmp_path / "argv.txt"


def test_cli_prints_the_command_without_rl(tmp_path, config_file, monkeypatch, capsys):
    monkeypatch.setenv("PATH", str(tmp_path / "nowhere"))
    out = tmp_path / "run"
    assert main([str(config_file), "--backend", "prime-rl", "--out", str(out), "lr=3.0e-6"]) == 0
    toml_path = (out / "prime_rl.toml").resolve()
    assert f"  rl @ {toml_path}" in capsys.readouterr().out.splitlines()
    doc = tomllib.loads(toml_path.read_text())
    assert check(doc) == [] and doc["trainer"]["optim"]["lr"] == 3e-6
    assert load_config(out / "config.yaml").lr == 3e-6           # the resolved config beside it
    assert not (out / "metrics.jsonl").exists()                  # nothing trained here


def test_cli_launches_rl_and_returns_its_status(tmp_path, config_file, fake_rl, monkeypatch):
    out = tmp_path / "run"
    args = [str(config_file), "--backend", "prime-rl", "--out", str(out)]
    assert main(args) == 0
    assert fake_rl.read_text().splitlines() == ["@", str((out / "prime_rl.toml").resolve())]
    monkeypatch.setenv("FAKE_RL_EXIT", "3")
    assert main([*args, "--resume"]) == 3                         # an unedited file is re-rendered
    assert tomllib.loads((out / "prime_rl.toml").read_text())["ckpt"]["resume_step"] == -1


def test_cli_refuses_to_overwrite_an_edited_toml(tmp_path, config_file, fake_rl, capsys):
    out = tmp_path / "run"
    args = [str(config_file), "--backend", "prime-rl", "--out", str(out)]
    assert main(args) == 0
    path = out / "prime_rl.toml"
    edited = path.read_text().replace("[inference]", "[inference]\ngpu_memory_utilization = 0.5")
    path.write_text(edited)
    os.remove(fake_rl)
    capsys.readouterr()
    assert main(args) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "was edited after glyphbench-train wrote it" in err
    assert path.read_text() == edited and not fake_rl.exists()   # untouched, nothing launched


def test_cli_one_line_error_for_inexpressible_config(tmp_path, config_file, fake_rl, capsys):
    out = tmp_path / "run"
    assert main([str(config_file), "--backend", "prime-rl", "--out", str(out), "top_p=0.5"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("glyphbench-train: error: no Prime-RL equivalent for top_p=0.5") and err.count("\n") == 1
    assert not out.exists() and not fake_rl.exists()
