"""`glyphbench-train --backend prime-rl`: the rendered TOML against Prime-RL's schema (transcribed
in glyphbench_rl/integrations/prime_rl/schema.py), values carried over, the taskset's training
rows, the sweep's configs, and the launch."""

import math
import os
import stat
import tomllib
from pathlib import Path

import pytest
import yaml

from glyphbench_rl.core.seeding import HELDOUT_SEEDS, TRAIN_SEEDS
from glyphbench_rl.integrations import prime_rl
from glyphbench_rl.integrations.prime_rl import PrimeRLConfigError, render_toml
from glyphbench_rl.integrations.prime_rl.render import dumps
from glyphbench_rl.integrations.prime_rl.schema import PRIME_RL_COMMIT, check, tasksets
from glyphbench_rl.cli.train import main
from glyphbench_rl.train.config import config_from_dict, load_config

TASKS = ["glyphbench/classics-snake-easy-v0", "glyphbench/classics-maze-easy-v0"]


def render(tmp_path, resume=False, **keys) -> dict:
    cfg = config_from_dict({"tasks": TASKS, **keys})
    return tomllib.loads(render_toml(cfg, run_dir=tmp_path, resume=resume))


@pytest.mark.parametrize("resume, keys", [
    (False, {}),
    (False, {"loss": "default", "gradient_checkpointing": True}),
    (False, {"eval_every": 5, "harness": {"max_context_tokens": 2000}}),
    (False, {"model": "Qwen/Qwen3.5-4B", "tasks": "tasks/standard.txt", "eval_every": 50}),
    (True, {"wandb_project": "glyph", "wandb_entity": "lab", "wandb_name": "run-1", "tensorboard": False}),
])
def test_rendered_toml_uses_only_schema_keys(tmp_path, resume, keys):
    """The one check of every rendered key: an unknown or misplaced key, or a wrong type, fails."""
    assert prime_rl.PRIME_RL_COMMIT == PRIME_RL_COMMIT       # the renderer uses the schema's commit
    text = render_toml(config_from_dict({"tasks": TASKS, **keys}), run_dir=tmp_path, resume=resume)
    assert f"prime-rl@{PRIME_RL_COMMIT[:12]}" in text
    assert check(tomllib.loads(text)) == []


def test_schema_check_catches_wrong_keys_and_types(tmp_path):
    doc = render(tmp_path)
    doc["trainer"]["loss"]["kl_coef"] = 1e-3                  # our name, not Prime-RL's
    doc["orchestrator"]["batch_size"] = "32"
    doc["trainer"]["optim"]["type"] = "adam"
    doc["orchestrator"]["filter_zero_advantages"] = False      # misplaced: it is orchestrator.train's
    doc["trainer"]["model"]["ac"] = "off"
    assert check(doc) == ["trainer.model.ac should be a table or \"None\"",
                          "unknown key trainer.loss.kl_coef",
                          "trainer.optim.type = 'adam': not one of ['adamw']",
                          "orchestrator.batch_size = '32' has the wrong type (want <class 'int'>)",
                          "unknown key orchestrator.filter_zero_advantages"]


def test_schema_refuses_the_keys_of_the_previous_layout(tmp_path):
    """What the renderer wrote for Prime-RL 004274ec, refused at the targeted commit (issue 14)."""
    doc = render(tmp_path, eval_every=5)
    orch = doc["orchestrator"]
    orch["train"]["env"] = orch["train"].pop("source")
    orch["eval"]["env"] = orch["eval"].pop("source")
    orch["algorithms"] = ["grpo"]
    orch["post_batch_filters"] = [{"type": "zero_advantage", "enforce": False}]
    doc["ckpt"]["resume_step"] = -1
    doc["wandb"] = {"project": "glyph"}
    assert sorted(check(doc)) == sorted([
        "unknown key orchestrator.train.env", "unknown key orchestrator.eval.env",
        "unknown key orchestrator.algorithms", "unknown key orchestrator.post_batch_filters",
        "unknown key ckpt.resume_step", "unknown key wandb"])


def test_values_round_trip(tmp_path):
    doc = render(tmp_path, steps=12, group_size=8, groups_per_update=4, lr=2e-6, seq_len=4096,
                 max_new_tokens=512, threshold=0.05, kl_coef=2e-3, adv_tau=0.5, betas=[0.8, 0.9],
                 weight_decay=0.01, grad_clip=0.5, temperature=0.7, checkpoint_every=3,
                 keep_checkpoints=5, logprob_chunk=512, eval_every=4, eval_episodes=3,
                 harness={"history": 2, "legend": "changed", "max_context_tokens": 3000})
    assert (doc["max_steps"], doc["seq_len"]) == (12, 4096)
    assert doc["model"] == {"name": "HuggingFaceTB/SmolLM2-135M-Instruct"}
    assert doc["output_dir"] == str(tmp_path.resolve())
    assert doc["run"] == {"name": tmp_path.name, "dir": "outputs"}     # Prime-RL: output_dir/outputs
    assert doc["ckpt"] == {"interval": 3, "keep_last": 5}
    assert "monitors" not in doc and "resume" not in doc
    assert render(tmp_path, wandb_project="glyph")["monitors"] == {"wandb": {"project": "glyph"}}
    trainer, orch = doc["trainer"], doc["orchestrator"]
    assert trainer["loss"] == {"type": "ipo", "ipo_threshold": 0.05, "adv_tau": 0.5, "kl_tau": 2e-3}
    assert trainer["optim"] == {"type": "adamw", "lr": 2e-6, "betas1": 0.8, "betas2": 0.9,
                                "weight_decay": 0.01, "max_norm": 0.5}
    assert trainer["scheduler"] == {"type": "constant"}
    # activation checkpointing is on in Prime-RL unless switched off, offloading included
    assert trainer["model"] == {"fused_lm_head_token_chunk_size": 512, "ac": "None", "ac_offloading": "None"}
    assert (orch["batch_size"], orch["group_size"], orch["algo"]) == (32, 8, {"type": "grpo"})
    assert orch["train"]["sampling"] == {"temperature": 0.7, "max_completion_tokens": 512}
    assert orch["train"]["filter_zero_advantages"] is False    # Prime-RL's default drops them
    [source] = orch["train"]["source"]
    prompt = {"history": 2, "legend": "changed", "max_context_tokens": 3000}
    # 12 steps x 4 groups over 2 tasks: 24 training rows per task, as many as built-in groups
    assert source["name"] == "glyphbench-rl"
    assert source["env"] == {"taskset": {"id": "glyphbench-rl", "tasks": TASKS, "split": "train",
                                         "episodes": 24, "seed_start": 0, "harness": prompt}}
    ev = orch["eval"]
    assert (ev["interval"], ev["group_size"], ev["skip_first_step"]) == (4, 1, True)
    assert ev["sampling"] == {"temperature": 0.7, "max_completion_tokens": 512}
    [heldout] = ev["source"]
    assert heldout["env"]["taskset"] == {**source["env"]["taskset"], "split": "heldout", "episodes": 3}
    assert heldout["name"] != source["name"]


def test_default_loss_and_options(tmp_path):
    doc = render(tmp_path, loss="default", mask_low=0.1, mask_high=0.3, gradient_checkpointing=True,
                 model="Qwen/Qwen3.5-4B")
    assert doc["trainer"]["loss"] == {"type": "default", "dppo_mask_low": 0.1, "dppo_mask_high": 0.3,
                                      "adv_tau": 1.0, "kl_tau": 1e-3}
    assert doc["trainer"]["model"]["ac"] == {"mode": "full", "freq": 1}      # every layer
    assert "ac_offloading" not in doc["trainer"]["model"]
    assert doc["model"]["name"] == "Qwen/Qwen3.5-4B" and "renderer" not in doc["orchestrator"]
    assert "eval" not in doc["orchestrator"] and doc["inference"] == {}


def test_resume_finds_the_same_run_directory(tmp_path, monkeypatch):
    fresh, resumed = render(tmp_path / "run-a"), render(tmp_path / "run-a", resume=True)
    assert resumed["resume"] == {}                      # Prime-RL: the latest checkpoint
    assert "resume" not in fresh
    # the run directory does not depend on when or from where the file is rendered
    monkeypatch.chdir(tmp_path)
    relative = render(tmp_path / "x" / ".." / "run-a")
    for doc in (resumed, relative):
        assert (doc["output_dir"], doc["run"]) == (fresh["output_dir"], fresh["run"])
    assert fresh["run"] == {"name": "run-a", "dir": "outputs"}


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
    # round-robin over the tasks: Prime-RL's default sampler cycles through the rows in this
    # order, so group g plays task g mod n, as in the built-in trainer
    assert rows == [(t, s) for s in range(per_task) for t in TASKS]
    assert [t for t, _ in rows[:5 * 3]] == [TASKS[g % len(TASKS)] for g in range(5 * 3)]
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
    assert tomllib.loads((out / "prime_rl.toml").read_text())["resume"] == {}


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


# -- sweeps and documentation ----------------------------------------------------------------------

ROOT = Path(__file__).resolve().parents[2]


def test_every_snake_sweep_condition_renders_to_the_schema(tmp_path, capsys):
    from glyphbench_rl.cli.sweep import main as sweep

    out = tmp_path / "sweep"
    assert sweep([str(ROOT / "configs" / "snake_sweep.yaml"), "--out", str(out), "--prime-rl"]) == 0
    tomls = sorted(out.glob("runs/*/prime_rl.toml"))
    assert len(tomls) == 66
    docs = [tomllib.loads(p.read_text()) for p in tomls]
    assert [check(d) for d in docs] == [[]] * len(docs)
    assert len({(d["output_dir"], d["run"]["name"]) for d in docs}) == len(docs)    # one run dir each
    assert not any("resume" in d for d in docs)
    # a rerun resumes what Prime-RL started (from its latest checkpoint) instead of being refused
    started = tomls[0].parent / "outputs" / "checkpoints"
    started.mkdir(parents=True)
    capsys.readouterr()
    assert sweep([str(ROOT / "configs" / "snake_sweep.yaml"), "--out", str(out), "--prime-rl"]) == 0
    assert [("resume" in tomllib.loads(p.read_text())) for p in tomls] == [True] + [False] * 65


def test_readme_names_the_commit_and_the_command():
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    section = text[text.index("### Training on a cluster with Prime-RL"):]
    section = section[:section.index("\n## ")]
    assert PRIME_RL_COMMIT[:7] in section and "rl @ " in section
    assert "packages/prime-rl-configs" in section and "validate_prime_rl.py" in section
