"""``glyphbench plot``: training curves, paired comparison and sweep grid figures, and bad input."""

import json
import math
import sys

import pytest

pytest.importorskip("matplotlib")
yaml = pytest.importorskip("yaml")
from PIL import Image  # noqa: E402

from glyphbench_rl.cli.main import main  # noqa: E402
from glyphbench_rl.evaluate import EvalConfig, run_job  # noqa: E402
from glyphbench_rl.replay.plots import (  # noqa: E402
    PlotError, load_sweep, plot_comparison, plot_sweep, plot_training, read_metrics, trailing_mean)
from glyphbench_rl.train.sweep import expand, write_conditions  # noqa: E402

PNG, PDF = b"\x89PNG\r\n\x1a\n", b"%PDF"
TASKS = ["glyphbench/classics-snake-easy-v0", "glyphbench/classics-lightsout-easy-v0",
         "glyphbench/minigrid-empty-5x5-v0"]


def write_metrics(run, steps, evals=(), forfeit=True):
    run.mkdir(parents=True, exist_ok=True)
    with open(run / "metrics.jsonl", "w") as fh:
        for s in range(1, steps + 1):
            m = {"step": s, "train/return_mean": math.tanh(s / 10) + 0.1 * math.sin(s)}
            if forfeit:
                m["train/forfeit_rate"] = 0.5 / s
            if s in evals:
                m.update({"eval/return_mean": math.tanh(s / 10), "eval/return_ci95": 0.1})
            fh.write(json.dumps(m) + "\n")
    return run


def image_size(path):
    with Image.open(path) as im:
        return im.size


def run_cli(argv, capsys):
    code = main(argv)
    out, err = capsys.readouterr()
    return code, out, err


def test_trailing_mean_counts_the_window_in_x_units_and_skips_gaps():
    assert trailing_mean([1, 2, 3, 4], [1, 2, 3, 4], 2) == [1, 1.5, 2.5, 3.5]
    assert trailing_mean([32, 64, 96], [0, 1, 2], 64) == [0, 0.5, 1.5]      # 64 rollouts = 2 steps
    gap = trailing_mean([1, 2, 3], [1, math.nan, 3], 3)
    assert gap == [1, 1, 2]


def test_training_figure_png_pdf_and_overlay(tmp_path, capsys):
    a = write_metrics(tmp_path / "a", 40, evals=(10, 20, 30, 40))
    b = write_metrics(tmp_path / "b", 25, forfeit=False)
    one = plot_training(a, tmp_path / "a.png", window=5)
    assert one.read_bytes()[:8] == PNG
    w, h = image_size(one)
    assert w > 600 and h > 400
    assert plot_training([a, b], tmp_path / "ab.pdf").read_bytes()[:4] == PDF
    code, out, err = run_cli(["plot", "training", str(a), str(b), "--out", str(tmp_path / "cli.png"),
                              "--window", "3"], capsys)
    assert code == 0 and "wrote" in out and not err
    assert (tmp_path / "cli.png").read_bytes()[:8] == PNG
    assert one.read_bytes() != (tmp_path / "cli.png").read_bytes()


def test_training_figure_leaves_pyplot_alone(tmp_path):
    before = "matplotlib.pyplot" in sys.modules
    plot_training(write_metrics(tmp_path / "r", 5), tmp_path / "r.png")
    assert before or "matplotlib.pyplot" not in sys.modules


def test_metrics_errors_name_file_and_line(tmp_path, capsys):
    run = write_metrics(tmp_path / "run", 5)
    path = run / "metrics.jsonl"
    lines = path.read_text().splitlines()
    path.write_text("\n".join(lines[:2] + ['{"step": 3, "train/ret'] + lines[3:]) + "\n")
    code, _, err = run_cli(["plot", "training", str(run), "--out", str(tmp_path / "x.png")], capsys)
    assert code == 2 and err.count("\n") == 1
    assert err.startswith("glyphbench: error: ") and f"{path}:3: not valid JSON" in err
    assert not (tmp_path / "x.png").exists()
    # a cut-short LAST line is a run still writing: left out, with a warning
    path.write_text("\n".join(lines) + '\n{"step": 6, "train/re')
    assert len(read_metrics(path)) == 5
    code, _, err = run_cli(["plot", "training", str(run), "--out", str(tmp_path / "x.png")], capsys)
    assert code == 0 and f"{path}:6: cut-short last line" in err

    (tmp_path / "empty").mkdir()
    (tmp_path / "empty" / "metrics.jsonl").write_text("\n")
    path.write_text('{"step": 1}\n')
    for target, match in [(tmp_path / "nowhere", "does not exist"),
                          (tmp_path, "metrics.jsonl does not exist"),
                          (tmp_path / "empty", "holds no metrics yet"),
                          (run, "'train/return_mean' is missing")]:
        with pytest.raises(PlotError, match=match):
            plot_training(target, tmp_path / "x.png")
    with pytest.raises(PlotError, match="figure type"):
        plot_training(write_metrics(tmp_path / "ok", 3), tmp_path / "x.jpg")
    with pytest.raises(PlotError, match="window must be at least 1"):
        plot_training(tmp_path / "ok", tmp_path / "x.png", window=0)


@pytest.fixture(scope="module")
def jobs(tmp_path_factory):
    """Two real random-policy evaluation jobs on the same (task, seed) pairs, policies differing."""
    root = tmp_path_factory.mktemp("jobs")
    for name, options in (("a", {}), ("b", {"seed": 5})):
        run_job(EvalConfig(tasks=TASKS, backend="random", episodes=3, backend_options=options),
                root / name, log=None)
    return root / "a", root / "b"


def test_comparison_figure(jobs, tmp_path, capsys):
    a, b = jobs
    png = plot_comparison(a, b, tmp_path / "cmp.png")
    assert png.read_bytes()[:8] == PNG and image_size(png)[0] > 500
    assert plot_comparison(a / "episodes.jsonl", b, tmp_path / "cmp.pdf").read_bytes()[:4] == PDF
    code, out, _ = run_cli(["plot", "compare", str(a), str(b), "--out", str(tmp_path / "c.svg")], capsys)
    assert code == 0 and (tmp_path / "c.svg").read_text().lstrip().startswith("<?xml")


def test_comparison_errors(jobs, tmp_path, capsys):
    a, _ = jobs
    (tmp_path / "other").mkdir()
    run_job(EvalConfig(tasks=TASKS[:1], backend="random", episodes=1, seed_start=50), tmp_path / "other",
            log=None)
    with pytest.raises(PlotError, match="share no"):
        plot_comparison(a, tmp_path / "other", tmp_path / "x.png")
    with pytest.raises(PlotError, match="no episodes.jsonl"):
        plot_comparison(a, tmp_path, tmp_path / "x.png")
    bad = tmp_path / "bad"
    bad.mkdir()
    good = (a / "episodes.jsonl").read_text().splitlines()
    (bad / "episodes.jsonl").write_text("\n".join([good[0], "garbage", good[1]]) + "\n")
    code, _, err = run_cli(["plot", "compare", str(a), str(bad), "--out", str(tmp_path / "x.png")], capsys)
    assert code == 2 and err.count("\n") == 1 and f"{bad / 'episodes.jsonl'}:2" in err
    assert (bad / "episodes.jsonl").read_text().count("\n") == 3        # the log was not touched


@pytest.fixture
def sweep_dir(tmp_path):
    spec = {"base": {"max_turns": 5}, "rollout_budget": 16,
            "grid": {"tasks": ["glyphbench/classics-snake-medium-v0", "glyphbench/classics-snake-easy-v0"],
                     "group_size": [2, 4], "lr": [1.0e-6, 2.0e-6]},
            "variants": {"long": {"grid": {"tasks": ["glyphbench/classics-snake-easy-v0"],
                                           "group_size": [2], "lr": [1.0e-6]}, "rollout_budget": 32}}}
    out = tmp_path / "sweep"
    rows = write_conditions(out, expand(spec))
    (out / "sweep.yaml").write_text(yaml.safe_dump(spec, sort_keys=False))
    for name, cfg, _ in rows[:-1]:                 # the last condition has not run yet
        write_metrics(out / "runs" / name, cfg["steps"])
    return out, [name for name, _, _ in rows]


def test_sweep_figure_and_condition_order(sweep_dir, tmp_path, capsys):
    out, names = sweep_dir
    assert [n for n, _, _ in load_sweep(out)] == names           # the sweep file's order
    assert [n for n, _, _ in load_sweep(out, "long*")] == ["long_snake-easy_g2_lr1e-06"]
    png = plot_sweep(out, tmp_path / "grid.png", window_rollouts=8)
    assert png.read_bytes()[:8] == PNG
    w, h = image_size(png)
    assert w > h > 400                             # columns: 2 tasks x 2 budgets; rows: 2 rates
    code, _, _ = run_cli(["plot", "sweep", str(out), "--out", str(tmp_path / "s.pdf"),
                          "--select", "snake-easy*"], capsys)
    assert code == 0 and (tmp_path / "s.pdf").read_bytes()[:4] == PDF
    (out / "sweep.yaml").unlink()                  # an older sweep directory: configs by name
    assert sorted(n for n, _, _ in load_sweep(out)) == sorted(names)


def test_sweep_errors(sweep_dir, tmp_path):
    out, _ = sweep_dir
    with pytest.raises(PlotError, match="has metrics yet"):
        plot_sweep(out, tmp_path / "x.png", select="long*")
    with pytest.raises(PlotError, match="matches 'nothing"):
        plot_sweep(out, tmp_path / "x.png", select="nothing*")
    with pytest.raises(PlotError, match="not a glyphbench-sweep directory"):
        plot_sweep(tmp_path / "sweep" / "runs", tmp_path / "x.png")
    (out / "sweep.yaml").write_text("grid: {lrr: [1]}\n")
    with pytest.raises(PlotError, match="sweep.yaml: unknown config key 'lrr'"):
        load_sweep(out)


def test_training_figure_ticks_whole_steps(tmp_path, monkeypatch):
    """A short run (4 steps) gets ticks at whole steps only, never at step 2.5."""
    from glyphbench_rl.replay import plots
    run = tmp_path / "short"
    run.mkdir()
    (run / "metrics.jsonl").write_text("".join(
        json.dumps({"step": s, "train/return_mean": 0.1 * s, "train/forfeit_rate": 0.5}) + "\n"
        for s in range(1, 5)))
    figures = []
    monkeypatch.setattr(plots, "_save", lambda fig, out: figures.append(fig) or out)
    plot_training([run], tmp_path / "t.png")
    [fig] = figures
    fig.canvas.draw()
    ticks = [t for ax in fig.axes for t in ax.get_xticks() if 1 <= t <= 4]
    assert ticks and all(float(t).is_integer() for t in ticks), ticks
