import json
import math
import re

import pytest

import glyphbench_rl
from glyphbench_rl.core.seeding import heldout_seeds
from glyphbench_rl.evaluate import EpisodeLogError, EvalConfig, EvalError, run_job
from glyphbench_rl.evaluate.job import EPISODES, rebuild_summary
from glyphbench_rl.rollout.trajectory import read_jsonl

from eval_helpers import LIGHTS, SNAKE, TASKS, CountingPolicy, lines, records


def config(episodes=3, **kw):
    return EvalConfig(tasks=list(TASKS), backend="scripted", episodes=episodes, **kw)


def replay_return(record) -> float:
    """Independent check: play the recorded actions on a fresh task from the recorded seed."""
    task = glyphbench_rl.make(record["task_id"])
    task.reset(seed=record["seed"])
    for step in record["steps"]:
        if step["action"] is None:
            task.forfeit(step["forfeit_reason"])
        else:
            task.step(step["action"])
    assert task.done
    return task.episode_return


def test_job_records_and_summary_match_hand_computed_values(tmp_path):
    policy = CountingPolicy()
    result = run_job(config(), tmp_path, backend=policy.backend(), log=None)
    assert (result.saved, result.new, result.missing, result.interrupted) == (6, 6, 0, False)

    recs = records(tmp_path / EPISODES)
    seeds = heldout_seeds(3)
    assert sorted((r["task_id"], r["seed"]) for r in recs) == sorted((t, s) for t in TASKS for s in seeds)
    for r in recs:
        assert r["length"] == len(r["steps"]) and r["meta"]["backend"] == "scripted"
        assert r["return"] == pytest.approx(sum(s["reward"] for s in r["steps"]))
        assert r["return"] == pytest.approx(replay_return(r))
    # the records are valid replay trajectories
    assert len(list(read_jsonl(tmp_path / EPISODES))) == 6

    rows = {row["task_id"]: row for row in result.summary["tasks"]}
    lights = rows[LIGHTS]      # always forfeits: nothing changes until the 50-turn horizon
    assert (lights["episodes"], lights["return_mean"], lights["return_ci95"]) == (3, 0.0, 0.0)
    assert (lights["length_mean"], lights["forfeit_rate"]) == (50.0, 1.0)
    snake_returns = [r["return"] for r in recs if r["task_id"] == SNAKE]
    mean = sum(snake_returns) / 3
    sd = math.sqrt(sum((x - mean) ** 2 for x in snake_returns) / 2)
    assert rows[SNAKE]["return_mean"] == pytest.approx(mean)
    assert rows[SNAKE]["return_ci95"] == pytest.approx(4.3027 * sd / math.sqrt(3), abs=1e-4)
    assert rows[SNAKE]["forfeit_rate"] == 0.0
    overall = result.summary["overall"]   # tasks weighted equally
    assert overall["return_mean"] == pytest.approx((mean + 0.0) / 2)
    assert overall["return_ci95"] == pytest.approx(12.7062 * abs(mean) / math.sqrt(2) / math.sqrt(2), abs=1e-3)
    assert result.summary["standard"]["tasks"] == 2
    text = (tmp_path / "summary.txt").read_text()
    assert SNAKE in text and "Classics" in text and "PARTIAL" not in text
    assert "\nstandard tier " in text and "\noverall " in text    # the README's standard-tier row
    saved = json.loads((tmp_path / "summary.json").read_text())
    assert saved["overall"]["return_mean"] == pytest.approx(overall["return_mean"])
    cfg = json.loads((tmp_path / "config.json").read_text())
    assert cfg["seed_range"] == {"first": 1_000_000, "last": 1_000_002, "count": 3}
    assert cfg["harness"]["history"] == 8 and "context" not in cfg


def test_tokens_flag_keeps_token_fields(tmp_path):
    run_job(config(1, tokens=True), tmp_path, backend=CountingPolicy().backend(), log=None)
    assert all("prompt_ids" in step and "logprobs" in step for r in records(tmp_path / EPISODES)
               for step in r["steps"])
    run_job(config(1), tmp_path / "plain", backend=CountingPolicy().backend(), log=None)
    assert all("prompt_ids" not in step for r in records(tmp_path / "plain" / EPISODES)
               for step in r["steps"])


def test_rerun_skips_finished_pairs_and_extends(tmp_path):
    run_job(config(2), tmp_path, backend=CountingPolicy().backend(), log=None)
    before = (tmp_path / EPISODES).read_bytes()
    again = CountingPolicy()
    built = []
    result = run_job(config(2), tmp_path, backend_factory=lambda *a, **k: built.append(a), log=None)
    assert (result.new, result.saved, built) == (0, 4, [])   # nothing to do: no backend built
    assert (tmp_path / EPISODES).read_bytes() == before
    with pytest.raises(EvalError, match=r"episodes was 2, now 3"):     # more is another job ...
        run_job(config(3), tmp_path, backend_factory=pytest.fail, log=None)
    assert (tmp_path / EPISODES).read_bytes() == before
    result = run_job(config(3), tmp_path, backend=again.backend(), log=None, force_config=True)
    assert sorted(again.started) == sorted(TASKS) and (result.new, result.saved) == (2, 6)   # ... unless asked


def test_cut_short_last_line_is_moved_aside(tmp_path):
    run_job(config(2), tmp_path, backend=CountingPolicy().backend(), log=None)
    log = tmp_path / EPISODES
    data = log.read_bytes()
    last_start = data.rstrip(b"\n").rfind(b"\n") + 1
    cut = data[:last_start + 100]                 # a crash in the middle of the last write
    log.write_bytes(cut)
    lost = json.loads(data[last_start:])
    messages = []
    policy = CountingPolicy()
    result = run_job(config(2), tmp_path, backend=policy.backend(), log=messages.append)
    assert policy.started == [lost["task_id"]] and result.saved == 4
    aside = tmp_path / "episodes.jsonl.partial-1"
    assert aside.read_bytes() == cut[last_start:]
    assert any("partial-1" in m for m in messages)
    recs = records(log)
    assert len({(r["task_id"], r["seed"]) for r in recs}) == len(recs) == 4


def test_complete_last_line_without_newline_is_kept(tmp_path):
    run_job(config(1), tmp_path, backend=CountingPolicy().backend(), log=None)
    log = tmp_path / EPISODES
    log.write_bytes(log.read_bytes().rstrip(b"\n"))   # e.g. an editor dropped the final newline
    policy = CountingPolicy()
    run_job(config(2), tmp_path, backend=policy.backend(), log=None, force_config=True)
    assert len(policy.started) == 2 and len(records(log)) == 4
    assert not list(tmp_path.glob("*.partial-*"))


def test_corrupt_middle_line_is_an_error_and_nothing_changes(tmp_path):
    run_job(config(2), tmp_path, backend=CountingPolicy().backend(), log=None)
    log = tmp_path / EPISODES
    lines_ = log.read_bytes().splitlines(keepends=True)
    lines_[1] = lines_[1][:40] + b"\n"
    log.write_bytes(b"".join(lines_))
    snapshot = {p.name: p.read_bytes() for p in tmp_path.iterdir()}
    with pytest.raises(EpisodeLogError, match=rf"episodes\.jsonl:2: not valid JSON") as e:
        run_job(config(3), tmp_path, backend_factory=pytest.fail, log=None)
    assert "\n" not in str(e.value)
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir()} == snapshot


def test_other_settings_in_the_same_directory_are_refused(tmp_path):
    run_job(config(1), tmp_path, backend=CountingPolicy().backend(), log=None)
    with pytest.raises(EvalError, match=r"harness\.history was 8, now 2.*--force-config"):
        run_job(config(2, harness={"history": 2}), tmp_path, backend_factory=pytest.fail, log=None)
    with pytest.raises(EvalError, match=r"backend_options\.temperature"):
        run_job(config(2, backend_options={"temperature": 0.5}), tmp_path, log=None)
    assert lines(tmp_path / EPISODES) == 2
    # where the model is served is not part of what the episodes are
    run_job(config(1, backend_options={"base_url": "http://elsewhere"}), tmp_path, log=None)
    result = run_job(config(2, harness={"history": 2}), tmp_path, force_config=True,
                     backend=CountingPolicy().backend(), log=None)
    assert result.saved == 4


@pytest.mark.parametrize("first, again, differs", [
    (dict(episodes=2), dict(episodes=1), r"episodes was 2, now 1"),
    (dict(episodes=1), dict(episodes=2), r"episodes was 1, now 2"),
    (dict(episodes=1), dict(episodes=1, seed_start=5), r"seed_start was 0, now 5"),
])
def test_other_episodes_or_seeds_in_the_same_directory_are_refused(tmp_path, first, again, differs):
    run_job(config(**first), tmp_path, backend=CountingPolicy().backend(), log=None)
    before = {p.name: p.read_bytes() for p in tmp_path.iterdir()}
    with pytest.raises(EvalError, match=rf"^{re.escape(str(tmp_path))} holds another evaluation "
                                        rf"\({differs}\); use a new --out, or --force-config to add "
                                        rf"to it anyway$"):
        run_job(config(**again), tmp_path, backend_factory=pytest.fail, log=None)
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir()} == before   # config.json untouched


@pytest.mark.parametrize("kw, message", [
    (dict(episodes=0), "episodes must be an int >= 1, got 0"),
    (dict(episodes=True), "episodes must be an int >= 1, got True"),
    (dict(episodes="3"), "episodes must be an int >= 1, got '3'"),
    (dict(seed_start=1.0), "seed_start must be an int, got 1.0"),
    (dict(tokens="yes"), "tokens must be true or false, got 'yes'"),
    (dict(harness={"history": -1}), "harness.history must be an int >= 0, got -1"),
    (dict(harness={"histroy": 3}), "unknown config key 'harness.histroy'; did you mean 'harness.history'?"),
    (dict(episodez=3), "unknown config key 'episodez'; did you mean 'episodes'?"),
])
def test_bad_values_are_one_line_eval_errors(kw, message):
    with pytest.raises(EvalError) as e:
        EvalConfig(**{"tasks": [SNAKE], "backend": "random", "episodes": 1, **kw})
    assert str(e.value) == message


def test_bad_settings_fail_before_anything(tmp_path):
    with pytest.raises(glyphbench_rl.UnknownTaskError, match="closest"):
        EvalConfig(tasks=["glyphbench/classics-snak-easy-v0"], backend="random", episodes=1)
    with pytest.raises(EvalError, match="held-out range"):
        EvalConfig(tasks=[SNAKE], backend="random", episodes=5, seed_start=999_999)
    with pytest.raises(EvalError, match="harness"):
        EvalConfig(tasks=[SNAKE], backend="random", episodes=1, harness={"histroy": 3})
    with pytest.raises(ValueError, match="legend"):
        EvalConfig(tasks=[SNAKE], backend="random", episodes=1, harness={"legend": "never"})


def test_summary_is_rebuilt_from_the_log(tmp_path):
    run_job(config(2), tmp_path, backend=CountingPolicy().backend(), log=None)
    first = json.loads((tmp_path / "summary.json").read_text())
    (tmp_path / "summary.json").unlink()
    (tmp_path / "summary.txt").unlink()
    summary, text = rebuild_summary(tmp_path, log=None)
    assert summary == first and SNAKE in text
