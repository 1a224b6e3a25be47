"""Metric sinks (TensorBoard, W&B) and the progress display, without a model."""

import io
import sys
import types

import pytest

from glyphbench_rl.train.config import ConfigError, TrainConfig
from glyphbench_rl.train.display import PlainDisplay, RichDisplay, make_display, progress_line
from glyphbench_rl.train.sinks import SinkError, WandbSink, flatten, open_sinks

METRICS = {"step": 3, "train/return_mean": 0.25, "train/return_by_task": {"a/b-v0": 0.5, "c": -1.0},
           "train/forfeit_rate": 0.5, "train/episode_length": 4.0, "train/loss": 0.01,
           "train/grad_norm": 0.3, "train/trainable_tokens": 120, "time/rollout_s": 1.0,
           "time/train_s": 2.0, "train/won": True, "note": "x", "train/nan": float("nan")}


def test_flatten_keeps_finite_numbers_under_slash_keys():
    flat = flatten(METRICS)
    assert flat["train/return_by_task/a/b-v0"] == 0.5 and flat["train/return_by_task/c"] == -1.0
    assert "step" not in flat and "note" not in flat and "train/won" not in flat
    assert "train/nan" not in flat and flat["train/trainable_tokens"] == 120.0


class _FakeRun:
    def __init__(self, calls):
        self.calls = calls

    def log(self, data, step):
        self.calls.append(("log", data, step))

    def finish(self):
        self.calls.append(("finish",))


@pytest.fixture
def fake_wandb(monkeypatch):
    calls = []
    mod = types.ModuleType("wandb")
    mod.util = types.SimpleNamespace(generate_id=lambda: "abc123")

    def init(**kw):
        calls.append(("init", kw))
        return _FakeRun(calls)

    mod.init = init
    monkeypatch.setitem(sys.modules, "wandb", mod)
    return calls


def test_wandb_sink_logs_flat_metrics_and_resumes_the_same_run(tmp_path, fake_wandb):
    cfg = TrainConfig(wandb_project="glyph", wandb_entity="lab", tensorboard=False)
    [sink] = open_sinks(tmp_path, cfg)
    sink.log(METRICS, 3)
    sink.close()
    init = fake_wandb[0][1]
    assert (init["project"], init["entity"], init["name"], init["id"], init["resume"]) == \
        ("glyph", "lab", tmp_path.name, "abc123", "allow")
    assert init["config"]["wandb_project"] == "glyph"
    assert fake_wandb[1] == ("log", flatten(METRICS), 3) and fake_wandb[2] == ("finish",)
    # a resumed run reuses the id recorded in the run directory
    sys.modules["wandb"].util.generate_id = lambda: "other"
    WandbSink(tmp_path, project="glyph", entity=None, name=None, config={})
    assert fake_wandb[-1][1]["id"] == "abc123"


def test_missing_sink_packages_are_one_line_errors(tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "wandb", None)          # import wandb raises ImportError
    with pytest.raises(SinkError, match="pip install wandb"):
        open_sinks(tmp_path, TrainConfig(wandb_project="p", tensorboard=False))
    with pytest.raises(ConfigError, match="wandb_project must be a non-empty string"):
        TrainConfig(wandb_project="")
    with pytest.raises(ConfigError, match="tensorboard must be true or false"):
        TrainConfig(tensorboard="yes")


def test_plain_display_logs_phases_progress_and_one_line_per_step():
    """A log file shows what the run is doing between step lines, without a line per episode."""
    lines, now = [], [0.0]
    d = PlainDisplay(10, lines.append, start=2, every=30, clock=lambda: now[0])
    d.phase("rollouts", 0, 8)
    for done in range(1, 8):             # quick episodes: no line each
        now[0] += 1
        d.phase("rollouts", done, 8)
    now[0] += 40
    d.phase("rollouts", 7, 8)            # 30 s since the last line: progress
    d.phase("rollouts", 8, 8)            # the phase's end
    d.phase("update (1,234 trainable tokens)")
    d.step_done(METRICS)
    assert lines[:4] == ["step 3/10: rollouts 0/8", "step 3/10: rollouts 7/8 (47s)",
                         "step 3/10: rollouts 8/8 (47s)", "step 3/10: update (1,234 trainable tokens)"]
    assert lines[4] == progress_line(METRICS, 10) and lines[4].startswith("step 3/10  return +0.250")
    d.phase("rollouts", 0, 8)
    assert lines[5] == "step 4/10: rollouts 0/8"


def test_rich_display_shows_progress_phase_and_first_vs_last(tmp_path):
    buf = io.StringIO()
    d = RichDisplay(10, start=2, title="run", file=buf)
    d.phase("rollouts", 3, 8)
    first = dict(METRICS)
    d.step_done(first)
    d.step_done({**METRICS, "step": 4, "train/forfeit_rate": 0.125, "eval/return_mean": 0.75})
    d.step_done({**METRICS, "step": 5})
    from rich.console import Console
    out = io.StringIO()
    Console(file=out, width=100).print(d)
    text = out.getvalue()
    assert "5/10" in text and "rollouts 3/8" in text
    assert "step 3" in text and "step 5" in text and "50.0%" in text
    assert "held-out return  step 4: +0.750" in text
    assert "step 3/10  return +0.250" in buf.getvalue()      # step lines stay in the scrollback


def test_make_display_is_plain_off_a_terminal():
    assert isinstance(make_display(5), PlainDisplay)            # pytest captures stdout
    assert isinstance(make_display(5, rich=True), RichDisplay)
