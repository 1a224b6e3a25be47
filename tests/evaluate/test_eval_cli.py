import json
import math
import signal
import subprocess
import sys
import time

import pytest

from glyphbench_rl.cli import eval as cli
from glyphbench_rl.evaluate import job, summarize
from glyphbench_rl.evaluate import summary as summary_mod

from eval_helpers import LIGHTS, SNAKE, TASKS, CountingPolicy, lines, records, write_records

RUN = ["--tasks", ",".join(TASKS), "--backend", "random", "--episodes", "3", "--max-episodes-at-once", "1"]


def test_end_to_end_in_a_subprocess(tmp_path):
    out = tmp_path / "job"
    cmd = [sys.executable, "-m", "glyphbench_rl.cli.eval", "--tasks", "glyphbench/classics-snake-*",
           "--backend", "random", "--episodes", "2", "--out", str(out)]
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert "glyphbench/classics-snake-hard-v0" in done.stdout and "overall" in done.stdout
    assert "6 episodes saved" in done.stderr
    assert len(records(out / "episodes.jsonl")) == 6
    again = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    assert again.returncode == 0 and "6 episodes already saved, 0 to run" in again.stderr
    summary = subprocess.run([sys.executable, "-m", "glyphbench_rl.cli.eval", "summary", str(out)],
                             capture_output=True, text=True, timeout=120)
    assert summary.returncode == 0 and summary.stdout == (out / "summary.txt").read_text()


def test_unknown_task_fails_before_the_backend_is_built(tmp_path, monkeypatch, capsys):
    monkeypatch.setattr(job, "make_backend", lambda *a, **k: pytest.fail("backend built"))
    out = tmp_path / "job"
    code = cli.main(["--tasks", "glyphbench/classics-snake-eazy-v0", "--backend", "random",
                     "--episodes", "2", "--out", str(out)])
    err = capsys.readouterr().err.strip()
    assert code == 2 and "\n" not in err and "closest: glyphbench/classics-snake-easy-v0" in err
    assert not out.exists()


def test_only_the_options_given_reach_the_backend(tmp_path, monkeypatch):
    seen = []

    def factory(name, model, **options):
        seen.append((name, model, options))
        return CountingPolicy().backend()

    monkeypatch.setattr(job, "make_backend", factory)
    assert cli.main(RUN + ["--out", str(tmp_path / "a"), "-q"]) == 0
    assert cli.main(RUN + ["--out", str(tmp_path / "b"), "-q", "--model", "m", "--temperature", "0.7",
                           "--top-p", "0.9", "-o", "seed=3", "--history", "2"]) == 0
    assert seen == [("random", None, {}),
                    ("random", "m", {"temperature": 0.7, "top_p": 0.9, "seed": 3})]
    assert json.loads((tmp_path / "b" / "config.json").read_text())["harness"]["history"] == 2


def test_interrupt_keeps_episodes_and_rerun_finishes_each_once(tmp_path, monkeypatch, capsys):
    out = tmp_path / "job"
    log = out / "episodes.jsonl"
    first = CountingPolicy(log, stop_after=2)
    monkeypatch.setattr(job, "make_backend", lambda *a, **k: first.backend())
    assert cli.main(RUN + ["--out", str(out)]) == 130
    err = capsys.readouterr().err.strip().splitlines()
    assert "2 episodes saved" in err[-1] and "rerun the same command to resume" in err[-1]
    assert lines(log) == 2
    assert json.loads((out / "summary.json").read_text())["missing"] == 4
    assert "PARTIAL" in (out / "summary.txt").read_text()

    second = CountingPolicy()
    monkeypatch.setattr(job, "make_backend", lambda *a, **k: second.backend())
    assert cli.main(RUN + ["--out", str(out)]) == 0
    assert len(second.started) == 4
    pairs = [(r["task_id"], r["seed"]) for r in records(log)]
    assert len(pairs) == len(set(pairs)) == 6


def test_corrupt_middle_line_is_a_one_line_error(tmp_path, capsys):
    write_records(tmp_path / "episodes.jsonl", [(SNAKE, 1_000_000, 0.0), (SNAKE, 1_000_001, 0.0),
                                                (SNAKE, 1_000_002, 0.0)])
    path = tmp_path / "episodes.jsonl"
    data = path.read_text().splitlines(keepends=True)
    data[1] = "{oops\n"
    path.write_text("".join(data))
    before = path.read_bytes()
    assert cli.main(RUN + ["--out", str(tmp_path)]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and f"{path}:2: not valid JSON" in err
    assert path.read_bytes() == before and not (tmp_path / "config.json").exists()


def test_compare_two_runs_with_a_known_difference(tmp_path, capsys):
    a, b = tmp_path / "a", tmp_path / "b"
    s = [1_000_000, 1_000_001, 1_000_002]
    write_records(a / "episodes.jsonl", [(SNAKE, s[0], 0.0), (SNAKE, s[1], 0.0), (SNAKE, s[2], 0.0),
                                         (LIGHTS, s[0], 1.0), (LIGHTS, s[1], 1.0), (LIGHTS, s[2], 0.5)])
    # B misses (LIGHTS, s[2]) so only the pairs both have count
    write_records(b / "episodes.jsonl", [(SNAKE, s[0], 0.5), (SNAKE, s[1], 0.5), (SNAKE, s[2], 0.2),
                                         (LIGHTS, s[0], 0.0), (LIGHTS, s[1], 0.0)])
    report = tmp_path / "cmp.json"
    assert cli.main(["compare", str(a), str(b), "--json", str(report)]) == 0
    out = capsys.readouterr().out
    assert "better on 1 of 2 tasks, worse on 1, tied on 0" in out
    c = json.loads(report.read_text())
    assert (c["pairs"], c["unpaired"]) == (5, {"only_a": 1, "only_b": 0})
    rows = {r["task_id"]: r for r in c["task_rows"]}
    assert rows[SNAKE]["diff"] == pytest.approx(0.4) and rows[LIGHTS]["diff"] == pytest.approx(-1.0)
    assert rows[LIGHTS]["pairs"] == 2
    o = c["overall"]
    assert (o["improved"], o["worse"], o["tied"]) == (1, 1, 0)
    assert o["mean_gain"] == pytest.approx(-0.3)
    sd = abs(0.4 - -1.0) / math.sqrt(2)      # two task differences
    assert o["gain_ci95"] == pytest.approx(12.7062 * sd / math.sqrt(2), abs=1e-3)
    assert cli.main(["compare", str(a), str(tmp_path / "none")]) == 2


def test_standard_aggregate_leaves_out_extended_tasks(monkeypatch):
    tiers = {SNAKE: "standard", LIGHTS: "extended"}
    monkeypatch.setattr(summary_mod, "task_info", lambda t: ("Classics", tiers[t]))
    recs = [{"task_id": t, "seed": i, "return": r, "length": 4, "forfeits": 1, "won": r > 0,
             "prompt_tokens": 100, "completion_tokens": 10 * i}
            for t, rs in ((SNAKE, [1.0, 0.0, 0.5]), (LIGHTS, [0.2, 0.4])) for i, r in enumerate(rs)]
    s = summarize(recs, order=[SNAKE])
    assert [r["task_id"] for r in s["tasks"]] == [SNAKE, LIGHTS]
    snake = s["tasks"][0]
    assert (snake["return_mean"], snake["forfeit_rate"], snake["prompt_tokens_mean"]) == (0.5, 0.25, 100)
    assert snake["completion_tokens_mean"] == 10 and snake["win_rate"] == pytest.approx(2 / 3)
    assert s["overall"]["return_mean"] == pytest.approx(0.4)            # (0.5 + 0.3) / 2
    assert s["overall"]["return_ci95"] == pytest.approx(12.7062 * 0.2 / math.sqrt(2) / math.sqrt(2), abs=1e-4)
    assert (s["standard"]["tasks"], s["standard"]["return_mean"]) == (1, 0.5)
    assert s["standard"]["return_ci95"] is None


def test_ctrl_c_in_a_real_process(tmp_path):
    """SIGINT to a running job: exit 130, one line saying what is saved; a rerun resumes."""
    out = tmp_path / "job"
    log = out / "episodes.jsonl"
    cmd = [sys.executable, "-m", "glyphbench_rl.cli.eval", "--tasks", "glyphbench/classics-maze-hard-v0",
           "--backend", "random", "--episodes", "2000", "--max-episodes-at-once", "2", "--out", str(out)]
    # a shell that starts a job in the background (`... &`) leaves SIGINT ignored for it and its
    # children; give the child the disposition a terminal's Ctrl-C meets
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    deadline = time.monotonic() + 60
    while lines(log) < 1 and proc.poll() is None and time.monotonic() < deadline:
        time.sleep(0.01)
    proc.send_signal(signal.SIGINT)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == 130, err
    # the interrupt waits while a record is written: no cut-short line, and every line counted
    assert log.read_bytes().endswith(b"\n")
    last = err.strip().splitlines()[-1]
    assert "interrupted:" in last and "rerun the same command to resume" in last
    assert f"{len(records(log))} episodes saved" in last
    assert json.loads((out / "summary.json").read_text())["missing"] > 0
