"""The built-in trainer end to end on a tiny random model (CPU, seconds)."""

import json

import pytest

torch = pytest.importorskip("torch")

from glyphbench_rl.rollout.trajectory import Step, Trajectory  # noqa: E402
from glyphbench_rl.cli.train import main as train_main  # noqa: E402
from glyphbench_rl.train.config import TrainConfig  # noqa: E402
from glyphbench_rl.train.samples import micro_batches, trajectory_samples  # noqa: E402
from glyphbench_rl.train.trainer import Trainer, latest_checkpoint  # noqa: E402


def _step(prompt, comp):
    return Step(turn=1, observation="", reply="", action=None, forfeit_reason=None, reward=0.0,
                prompt_ids=prompt, completion_ids=comp, logprobs=[-0.5] * len(comp))


def test_turns_that_extend_share_a_sequence():
    t = Trajectory("t", 0, steps=[_step([1, 2], [3]), _step([1, 2, 3, 9], [4, 5]),
                                  _step([1, 7], [8])])          # the window slid: a new sequence
    samples, skipped = trajectory_samples(t, 0.5, seq_len=100)
    assert [s.ids for s in samples] == [[1, 2, 3, 9, 4, 5], [1, 7, 8]]
    assert samples[0].mask == [0, 0, 1, 0, 1, 1] and samples[1].mask == [0, 0, 1]
    assert samples[0].sampling_logprobs == [0, 0, -0.5, 0, -0.5, -0.5]
    assert skipped == 0 and all(s.advantage == 0.5 for s in samples)
    samples, skipped = trajectory_samples(t, 0.5, seq_len=5)      # too long turns are skipped
    assert skipped == 2 and [s.ids for s in samples] == [[1, 2, 3], [1, 7, 8]]
    with pytest.raises(ValueError, match="token-in/token-out"):
        trajectory_samples(Trajectory("t", 0, steps=[Step(1, "", "", None, None, 0.0)]), 1.0, 10)


def test_micro_batches_bound_padded_tokens():
    from glyphbench_rl.train.samples import Sample
    samples = [Sample(ids=[0] * n, mask=[1] * n) for n in (5, 1, 9, 3, 30)]
    batches = list(micro_batches(samples, 10))
    assert sorted(len(s) for b in batches for s in b) == [1, 3, 5, 9, 30]
    assert all(len(b) == 1 or max(map(len, b)) * len(b) <= 10 for b in batches)


def _cfg(**kw):
    base = dict(model="tiny", tasks="glyphbench/classics-snake-easy-v0", steps=2, group_size=3,
                groups_per_update=2, max_new_tokens=6, lr=1e-3, harness={"history": 2},
                checkpoint_every=1, micro_batch_tokens=2048, logprob_chunk=64, max_turns=6)
    base.update(kw)
    return TrainConfig(**base)


def _model(tiny_model_dir):
    from glyphbench_rl.models import load_model
    return load_model(str(tiny_model_dir))


def test_two_steps_write_metrics_rollouts_and_checkpoints(tiny_model_dir, tmp_path):
    model, tok = _model(tiny_model_dir)
    before = [p.detach().clone() for p in model.parameters()]
    tr = Trainer(_cfg(), tmp_path / "run", model=model, tokenizer=tok, log=lambda m: None)
    tr.run()
    lines = [json.loads(x) for x in (tmp_path / "run" / "metrics.jsonl").read_text().splitlines()]
    assert [m["step"] for m in lines] == [1, 2]
    for m in lines:
        assert -1 <= m["train/return_mean"] <= 1 and m["train/trainable_tokens"] >= 0
        assert set(m["train/return_by_task"]) == {"glyphbench/classics-snake-easy-v0"}
    rollouts = (tmp_path / "run" / "rollouts" / "step_000001.jsonl").read_text().splitlines()
    assert len(rollouts) == 6      # 2 groups of 3
    assert latest_checkpoint(tmp_path / "run").name == "step_000002"
    if any(m["train/trainable_tokens"] for m in lines):
        assert any(not torch.equal(a, b) for a, b in zip(before, model.parameters()))


def test_resume_continues_and_matches_an_uninterrupted_run(tiny_model_dir, tmp_path):
    m1, tok = _model(tiny_model_dir)
    Trainer(_cfg(steps=3), tmp_path / "a", model=m1, tokenizer=tok, log=lambda m: None).run()
    m2, _ = _model(tiny_model_dir)
    Trainer(_cfg(steps=2), tmp_path / "b", model=m2, tokenizer=tok, log=lambda m: None).run()
    # a torn last line from a kill is dropped with the steps being redone
    with open(tmp_path / "b" / "metrics.jsonl", "a") as fh:
        fh.write('{"step": 3, "train/ret')
    m3, _ = _model(tiny_model_dir)
    tr = Trainer(_cfg(steps=3), tmp_path / "b", model=m3, tokenizer=tok, resume=True, log=lambda m: None)
    assert tr.step == 2
    tr.run()
    a = [json.loads(x) for x in (tmp_path / "a" / "metrics.jsonl").read_text().splitlines()]
    b = [json.loads(x) for x in (tmp_path / "b" / "metrics.jsonl").read_text().splitlines()]
    assert [m["step"] for m in b] == [1, 2, 3]
    assert a[2]["train/return_mean"] == b[2]["train/return_mean"]
    assert a[2]["train/loss"] == pytest.approx(b[2]["train/loss"], rel=1e-4, abs=1e-6)
    kept = sorted((tmp_path / "b" / "checkpoints").glob("step_*"))
    assert len(kept) == 2                                                   # keep_checkpoints
    # optimizer state only where a resume needs it: the latest checkpoint
    assert [(c / "optimizer.pt").exists() for c in kept] == [False, True]
    assert not list((tmp_path / "b" / "checkpoints").glob(".partial-*"))


def test_resume_before_the_first_checkpoint_redoes_the_step_once(tiny_model_dir, tmp_path):
    """A run stopped after step 1's metrics, rollouts and evaluation but before any checkpoint:
    --resume starts over, and each step's records exist once."""
    model, tok = _model(tiny_model_dir)
    cfg = _cfg(steps=1, eval_every=1, eval_episodes=1)
    Trainer(cfg, tmp_path / "r", model=model, tokenizer=tok, log=lambda m: None).run()
    import shutil
    shutil.rmtree(tmp_path / "r" / "checkpoints")            # killed before the checkpoint
    m2, _ = _model(tiny_model_dir)
    tr = Trainer(cfg, tmp_path / "r", model=m2, tokenizer=tok, resume=True, log=lambda m: None)
    assert tr.step == 0
    assert (tmp_path / "r" / "metrics.jsonl").read_text() == ""
    assert not (tmp_path / "r" / "eval" / "step_000001").exists()
    tr.run()
    steps = [json.loads(x)["step"] for x in (tmp_path / "r" / "metrics.jsonl").read_text().splitlines()]
    assert steps == [1]
    records = (tmp_path / "r" / "eval" / "step_000001" / "episodes.jsonl").read_text().splitlines()
    assert len(records) == 1


def test_checkpoints_without_optimizer_state_resume_with_a_fresh_optimizer(tiny_model_dir, tmp_path):
    model, tok = _model(tiny_model_dir)
    logs = []
    Trainer(_cfg(steps=1, save_optimizer=False), tmp_path / "w", model=model, tokenizer=tok,
            log=lambda m: None).run()
    [ckpt] = (tmp_path / "w" / "checkpoints").glob("step_*")
    assert not (ckpt / "optimizer.pt").exists() and (ckpt / "model.safetensors").exists()
    m2, _ = _model(tiny_model_dir)
    tr = Trainer(_cfg(steps=2, save_optimizer=False), tmp_path / "w", model=m2, tokenizer=tok,
                 resume=True, log=logs.append)
    assert tr.step == 1 and any("AdamW starts afresh" in line for line in logs)
    tr.run()
    assert [json.loads(x)["step"] for x in (tmp_path / "w" / "metrics.jsonl").read_text().splitlines()] == [1, 2]


def test_existing_run_needs_resume(tiny_model_dir, tmp_path):
    model, tok = _model(tiny_model_dir)
    Trainer(_cfg(steps=1), tmp_path / "r", model=model, tokenizer=tok, log=lambda m: None).run()
    with pytest.raises(FileExistsError, match="--resume"):
        Trainer(_cfg(steps=1), tmp_path / "r", model=model, tokenizer=tok, log=lambda m: None)


def test_cli_errors_are_one_line(tmp_path, capsys):
    cfg = tmp_path / "c.yaml"
    cfg.write_text("tasks: glyphbench/classics-snak-easy-v0\n")
    assert train_main([str(cfg), "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("glyphbench-train: error: unknown task") and "\n" not in err
    assert train_main([str(cfg), "--out", str(tmp_path / "o"), "stepz=3"]) == 2
    assert "did you mean 'steps'" in capsys.readouterr().err


def test_cli_runs_a_tiny_model(tiny_model_dir, tmp_path, capsys):
    cfg = tmp_path / "c.yaml"
    cfg.write_text(f"model: {tiny_model_dir}\ntasks: glyphbench/classics-snake-easy-v0\nsteps: 1\n"
                   f"group_size: 2\nmax_new_tokens: 4\neval_every: 1\neval_episodes: 1\nmax_turns: 4\n")
    assert train_main([str(cfg), "--out", str(tmp_path / "o")]) == 0
    m = json.loads((tmp_path / "o" / "metrics.jsonl").read_text())
    assert "eval/return_mean" in m and (tmp_path / "o" / "eval" / "step_000001" / "summary.json").exists()
    job = json.loads((tmp_path / "o" / "eval" / "step_000001" / "config.json").read_text())
    assert job["backend_options"] == {} and job["context"]["train_step"] == 1   # bookkeeping apart
    out = capsys.readouterr().out
    assert "step 1/1" in out and "step 1/1: rollouts 0/2" in out and "step 1/1: update" in out
    assert "step 1/1: checkpoint" in out and "step 2/1" not in out


def _traj(reasons, ret=0.0, group=0):
    steps = [Step(turn=i + 1, observation="", reply="", action=None if r else "UP", forfeit_reason=r,
                  reward=0.0, prompt_ids=[1, 2], completion_ids=[3], logprobs=[-0.1])
             for i, r in enumerate(reasons)]
    return Trajectory("glyphbench/classics-snake-easy-v0", 0, steps=steps, episode_return=ret,
                      group=group)


def test_format_score_grades_each_turn():
    from glyphbench_rl.train.trainer import format_score
    assert format_score(_traj([None, None])) == 1.0
    assert format_score(_traj(["unknown_name", "no_tag"])) == 0.25     # (0.5 + 0) / 2
    assert format_score(_traj(["empty_tag", None, "unclosed_think", "empty"])) == pytest.approx(1.5 / 4)
    assert format_score(_traj([])) == 0.0


def test_format_reward_gives_flat_return_groups_a_signal(tiny_model_dir, tmp_path):
    """Equal returns: no advantage unless format_reward separates the episodes by format."""
    model, tok = _model(tiny_model_dir)
    group = [_traj(["no_tag"] * 2), _traj([None, "no_tag"]), _traj([None, None])]
    plain = Trainer(_cfg(), tmp_path / "a", model=model, tokenizer=tok, log=lambda m: None)
    samples, _, flat = plain.samples(group)
    assert samples == [] and flat == 1
    shaped = Trainer(_cfg(format_reward=1.0), tmp_path / "b", model=model, tokenizer=tok, log=lambda m: None)
    samples, _, flat = shaped.samples(group)
    # scores 0, 0.5, 1: the middle episode has zero advantage; each other turn is a sample
    assert flat == 0 and sorted(s.advantage for s in samples) == pytest.approx([-0.5, -0.5, 0.5, 0.5])


def test_metrics_reach_tensorboard(tiny_model_dir, tmp_path):
    pytest.importorskip("tensorboard")
    from tensorboard.backend.event_processing.event_accumulator import EventAccumulator
    model, tok = _model(tiny_model_dir)
    Trainer(_cfg(steps=2), tmp_path / "run", model=model, tokenizer=tok, log=lambda m: None).run()
    ea = EventAccumulator(str(tmp_path / "run" / "tensorboard"))
    ea.Reload()
    tags = ea.Tags()["scalars"]
    assert "train/return_by_task/glyphbench/classics-snake-easy-v0" in tags
    lines = [json.loads(x) for x in (tmp_path / "run" / "metrics.jsonl").read_text().splitlines()]
    assert [(e.step, e.value) for e in ea.Scalars("train/return_mean")] == \
        [(m["step"], pytest.approx(m["train/return_mean"])) for m in lines]
