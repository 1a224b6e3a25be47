"""EpisodeIndex: one pass over a trajectory file, lenient about bad lines, episodes on demand."""

from __future__ import annotations

import json
import tracemalloc
import warnings

import pytest
from replay_helpers import EMPTY, SNAKE, play, write_jsonl

from glyphbench_rl.rollout.trajectory import TrajectoryFormatError, read_jsonl
from glyphbench_rl.replay import index as index_module
from glyphbench_rl.replay.index import CorruptLineWarning, EpisodeIndex


@pytest.fixture(scope="module")
def trajs():
    return play((SNAKE, EMPTY), (1, 2))


def test_index_summaries_and_loads_match_the_file(tmp_path, trajs):
    path = write_jsonl(tmp_path / "episodes.jsonl", trajs)
    index = EpisodeIndex(path)
    assert len(index) == 4 and index.warnings == []
    for i, (entry, traj) in enumerate(zip(index.entries, read_jsonl(path))):
        assert (entry.task_id, entry.seed, entry.episode_return, entry.length, entry.forfeits, entry.won) == (
            traj.task_id, traj.seed, traj.episode_return, traj.length, traj.forfeits, traj.won)
        assert entry.model == "scripted-test" and entry.line == i + 1
        assert entry.suite == {SNAKE: "Classics", EMPTY: "MiniGrid"}[traj.task_id]
        assert index.load(i).to_dict() == traj.to_dict()
    assert index.view(3).source == f"{path}:4"
    assert index.select("*snake*") == [0, 1] and index.select(EMPTY) == [2, 3] and index.select("x") == []


def test_job_and_run_directories(tmp_path, trajs):
    job = tmp_path / "job"
    job.mkdir()
    write_jsonl(job / "episodes.jsonl", trajs[:1])
    assert [e.seed for e in EpisodeIndex(job).entries] == [1]
    rollouts = tmp_path / "run" / "rollouts"
    rollouts.mkdir(parents=True)
    write_jsonl(rollouts / "step_000002.jsonl", trajs[2:])
    write_jsonl(rollouts / "step_000001.jsonl", trajs[:2])
    for source in (tmp_path / "run", rollouts):
        index = EpisodeIndex(source)
        assert [(e.file.name, e.line) for e in index.entries] == [
            ("step_000001.jsonl", 1), ("step_000001.jsonl", 2), ("step_000002.jsonl", 1), ("step_000002.jsonl", 2)]
        assert index.load(2).to_dict() == trajs[2].to_dict()
    with pytest.raises(FileNotFoundError, match="without episodes.jsonl"):
        EpisodeIndex(tmp_path)
    with pytest.raises(FileNotFoundError, match="no such file"):
        EpisodeIndex(tmp_path / "missing.jsonl")


def test_bad_lines_are_skipped_with_a_warning_naming_the_line(tmp_path, trajs):
    good = [json.dumps(t.to_dict()) for t in trajs]
    wrong_type = trajs[0].to_dict()
    wrong_type["steps"][0]["reward"] = "lots"
    no_task = {k: v for k, v in trajs[0].to_dict().items() if k != "task_id"}
    path = tmp_path / "mixed.jsonl"
    path.write_bytes(b"\n".join([
        good[0].encode(), b"{not json", json.dumps(no_task).encode(), b"", good[1].encode(),
        b"\xff\xfe garbage", json.dumps(wrong_type).encode(), good[2].encode(), good[3][:200].encode()]))
    seen: list[str] = []
    index = EpisodeIndex(path, on_warning=seen.append)
    assert [e.line for e in index.entries] == [1, 5, 8]
    assert seen == index.warnings and len(seen) == 5
    for line, words in zip((2, 3, 6, 7, 9), ("not valid JSON", "missing field 'task_id'", "not UTF-8",
                                             "step 1: a field has the wrong type", "cut short")):
        message = next(m for m in seen if m.startswith(f"{path}:{line}:"))
        assert words in message and "\n" not in message
    assert index.load(2).to_dict() == trajs[2].to_dict()     # nothing readable was lost


def test_warnings_go_to_the_warnings_module_by_default(tmp_path, trajs):
    path = tmp_path / "e.jsonl"
    path.write_text(json.dumps(trajs[0].to_dict()) + "\n[1, 2]\n", encoding="utf-8")
    with pytest.warns(CorruptLineWarning, match=r"e\.jsonl:2: expected a JSON object"):
        EpisodeIndex(path)


def test_no_readable_episode_is_a_one_line_error(tmp_path):
    empty = tmp_path / "empty.jsonl"
    empty.write_text("\n\n", encoding="utf-8")
    with pytest.raises(TrajectoryFormatError, match="the file is empty"):
        EpisodeIndex(empty)
    junk = tmp_path / "junk.jsonl"
    junk.write_text("hello\n{}\n", encoding="utf-8")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", CorruptLineWarning)
        with pytest.raises(TrajectoryFormatError) as err:
            EpisodeIndex(junk)
    assert "no readable episode; 2 line(s) skipped" in str(err.value) and f"{junk}:1" in str(err.value)
    assert "\n" not in str(err.value)


def test_unknown_task_ids_load_with_suite_unknown(tmp_path, trajs):
    record = trajs[0].to_dict()
    record["task_id"] = "glyphbench/classics-notagame-v9"
    path = tmp_path / "u.jsonl"
    path.write_text(json.dumps(record) + "\n", encoding="utf-8")
    index = EpisodeIndex(path)
    assert index.entries[0].suite == "unknown" and index.view(0).suite == "unknown"


def test_load_checks_range_and_that_the_file_did_not_change(tmp_path, trajs):
    path = write_jsonl(tmp_path / "e.jsonl", trajs[:2])
    index = EpisodeIndex(path)
    with pytest.raises(IndexError, match="episode 2 is out of range"):
        index.load(2)
    write_jsonl(path, trajs[2:])
    with pytest.raises(TrajectoryFormatError, match="changed since it was indexed"):
        index.load(0)


def test_ten_thousand_episodes_index_without_holding_them(tmp_path, trajs, monkeypatch):
    record = trajs[0].to_dict()         # a real record cut to two steps keeps the test quick
    record.update(seed=987654321, steps=record["steps"][:2], length=2)
    head, tail = json.dumps(record).split('"seed": 987654321')
    path = tmp_path / "big.jsonl"
    with open(path, "w", encoding="utf-8") as fh:
        fh.writelines(f'{head}"seed": {seed}{tail}\n' for seed in range(10_000))
    size = path.stat().st_size
    tracemalloc.start()
    try:
        index = EpisodeIndex(path)
        held, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert len(index) == 10_000 and index.warnings == []
    # what stays is a small record per episode, far less than the episodes themselves
    assert held < size / 5 and peak < size / 4, (held, peak, size)
    parsed: list[str] = []
    real_parse = index_module.parse_record
    monkeypatch.setattr(index_module, "parse_record",
                        lambda line, where: parsed.append(where) or real_parse(line, where))
    traj = index.load(9_876)
    assert parsed == [f"{path}:9877"] and traj.seed == 9_876 and traj.steps == trajs[0].steps[:2]
