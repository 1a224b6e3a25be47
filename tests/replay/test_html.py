"""The self-contained HTML replay page and `glyphbench replay --html`."""

from __future__ import annotations

import json
import re

import pytest
from replay_helpers import BATTLESHIP, EMPTY, FORFEIT_REPLY, INJECTION, MEMORY, SNAKE, play, write_jsonl

from glyphbench_rl.cli.main import main
from glyphbench_rl.replay.html import script_json, write_html
from glyphbench_rl.replay.index import EpisodeIndex

DATA = re.compile(r'<script type="application/json" id="replay-data">(.*?)</script>', re.S)


@pytest.fixture(scope="module")
def episodes_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("replay") / "episodes.jsonl"
    return write_jsonl(path, play((SNAKE, EMPTY, BATTLESHIP), (1, 2)))


def page_data(page: str) -> dict:
    found = DATA.findall(page)
    assert len(found) == 1
    return json.loads(found[0])


def test_script_json_cannot_end_the_script_element():
    value = {"reply": "</script><script>alert(1)</script><!-- & \u2028\u2029 >", "n": [1.5, None]}
    text = script_json(value)
    assert not set("<>&\u2028\u2029") & set(text)
    assert json.loads(text) == value


def test_page_embeds_every_episode_with_frames_turns_and_marks(tmp_path, episodes_file):
    out = tmp_path / "replay.html"
    index = EpisodeIndex(episodes_file)
    assert write_html(index, out) == 6
    page = out.read_text(encoding="utf-8")
    data = page_data(page)
    assert data["total"] == data["selected"] == 6 and data["note"] == ""
    assert data["suites"] == ["Classics", "MiniGrid"]
    assert [e["task"] for e in data["episodes"]] == [e.task_id for e in index.entries]
    for k, ep in enumerate(data["episodes"]):
        traj = index.load(k)
        assert ep["i"] == k and ep["seed"] == traj.seed and ep["ret"] == traj.episode_return
        assert len(ep["frames"]) == len(ep["turns"]) + 1 == traj.length + 1
        assert [t["reply"] for t in ep["turns"]] == [s.reply for s in traj.steps]
        assert data["prompts"][ep["prompt"]] == traj.system_prompt
        first, second = ep["turns"][:2]
        assert INJECTION in first["reply"] and first["memory"] == MEMORY and first["action"]
        assert second["reply"] == FORFEIT_REPLY and second["action"] is None
        assert second["forfeit"] and second["change"] == "forfeit"
        assert ep["frames"][0]["hud"].startswith("Step 0/") and ep["frames"][0]["legend"]
    assert len(data["prompts"]) == 3                        # one system prompt per task, shared
    board = next(e for e in data["episodes"] if e["task"] == BATTLESHIP)
    assert board["frames"][0]["axes"] and len(board["frames"][0]["grid"]) == 10


def test_page_is_self_contained_and_never_parses_data_as_markup(tmp_path, episodes_file):
    out = tmp_path / "replay.html"
    write_html(EpisodeIndex(episodes_file), out)
    page = out.read_text(encoding="utf-8")
    assert page.count("<script") == 2 and page.count("</script>") == 2
    assert "<img" not in page and "\\u003cimg src=x onerror=" in page     # the reply, as inert data
    code = DATA.sub("", page)          # the page without its data: nothing loads from elsewhere
    assert not re.search(r"(src|href)\s*=|https?://|@import|url\(", code)
    for sink in ("innerHTML", "outerHTML", "insertAdjacentHTML", "document.write", "eval("):
        assert sink not in code
    nonce = re.search(r"script-src 'nonce-([^']+)'", page).group(1)
    assert f'<script nonce="{nonce}">' in page


def test_non_finite_numbers_still_make_a_valid_page(tmp_path, episodes_file):
    lines = episodes_file.read_text(encoding="utf-8").splitlines()
    record = json.loads(lines[0])
    record["return"], record["steps"][0]["reward"] = float("nan"), float("inf")
    path = tmp_path / "nan.jsonl"
    path.write_text(json.dumps(record) + "\n", encoding="utf-8")
    write_html(EpisodeIndex(path), tmp_path / "nan.html")
    episode = page_data((tmp_path / "nan.html").read_text(encoding="utf-8"))["episodes"][0]
    assert episode["ret"] == "nan" and episode["turns"][0]["reward"] == "inf"


def test_page_limit_and_selection(tmp_path, episodes_file):
    index = EpisodeIndex(episodes_file)
    out = tmp_path / "few.html"
    assert write_html(index, out, [5, 1, 3], limit=2) == 2
    data = page_data(out.read_text(encoding="utf-8"))
    assert [e["i"] for e in data["episodes"]] == [5, 1]
    assert data["selected"] == 3 and "first 2 of 3" in data["note"]
    with pytest.raises(ValueError, match="episode 6 is out of range"):
        write_html(index, out, [6])
    with pytest.raises(FileNotFoundError):
        write_html(index, tmp_path / "no" / "such" / "dir.html")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["few.html"]     # no temporary left over


def test_cli_writes_the_page(tmp_path, episodes_file, capsys):
    out = tmp_path / "snake.html"
    assert main(["replay", str(episodes_file), "--task", "*snake*", "--html", str(out)]) == 0
    assert f"wrote {out}: 2 episode(s)" in capsys.readouterr().out
    assert [e["task"] for e in page_data(out.read_text(encoding="utf-8"))["episodes"]] == [SNAKE, SNAKE]
    assert main(["replay", str(episodes_file.parent), "--episode", "2-3,0", "--html", str(out),
                 "--max-episodes", "2"]) == 0
    assert "the first 2 of 3 selected" in capsys.readouterr().out
    assert [e["i"] for e in page_data(out.read_text(encoding="utf-8"))["episodes"]] == [2, 3]


@pytest.mark.parametrize("args, message", [
    (["{missing}"], "no such file or directory"),
    (["{empty}"], "no episodes (the file is empty)"),
    (["{file}", "--episode", "6"], "--episode 6 is out of range"),
    (["{file}", "--episode", "two"], "expected numbers like"),
    (["{file}", "--task", "*tetris*"], "no episode of task '*tetris*'"),
    (["{file}", "--task", SNAKE, "--episode", "4"], "none of --episode 4 is an episode of task"),
    (["{file}", "--html", "{tmp}/absent/x.html"], "does not exist"),
])
def test_cli_errors_are_one_line(tmp_path, episodes_file, capsys, args, message):
    (tmp_path / "empty.jsonl").write_text("", encoding="utf-8")
    names = {"missing": tmp_path / "missing.jsonl", "empty": tmp_path / "empty.jsonl",
             "file": episodes_file, "tmp": tmp_path}
    assert main(["replay", *(a.format(**names) for a in args)]) == 2
    err = capsys.readouterr().err
    assert err.startswith("glyphbench: error: ") and err.count("\n") == 1 and message in err


def test_cli_reports_skipped_lines_and_keeps_going(tmp_path, episodes_file, capsys):
    path = tmp_path / "cut.jsonl"
    path.write_bytes(episodes_file.read_bytes()[:-300])         # the last record cut short
    out = tmp_path / "cut.html"
    assert main(["replay", str(path), "--html", str(out)]) == 0
    err = capsys.readouterr().err
    assert err.startswith(f"glyphbench: warning: {path}:6: not valid JSON") and "cut short" in err
    assert len(page_data(out.read_text(encoding="utf-8"))["episodes"]) == 5


def test_cli_writes_a_gif_of_the_first_selected_episode(tmp_path, episodes_file, capsys):
    pytest.importorskip("PIL")
    out = tmp_path / "snake.gif"
    assert main(["replay", str(episodes_file), "--task", "*battleship*", "--gif", str(out), "--fps", "8"]) == 0
    assert "episode 4 (glyphbench/classics-battleship-v0, seed 1)" in capsys.readouterr().out
    assert out.read_bytes()[:6] == b"GIF89a"


def test_lone_surrogates_written_by_the_episode_writer_are_shown(tmp_path, capsys):
    """A reply holding a lone surrogate (some endpoints send them) is stored by the episode
    writer; every viewer reads it back and shows it, as U+FFFD."""
    from glyphbench_rl.evaluate.store import EpisodeWriter
    traj = play(seeds=(1,))[0]
    traj.steps[0].reply = "half a pair \ud800 here <action>UP</action>"
    traj.system_prompt += " \udfff"
    path = tmp_path / "episodes.jsonl"
    with EpisodeWriter(path) as writer:
        writer.append(traj)
    out = tmp_path / "page.html"
    assert main(["replay", str(path), "--html", str(out)]) == 0
    [episode] = page_data(out.read_text(encoding="utf-8"))["episodes"]
    assert "half a pair \ufffd here" in episode["turns"][0]["reply"]
    capsys.readouterr()
    assert main(["replay", str(path)]) == 0
    assert "half a pair \ufffd here" in capsys.readouterr().out
    assert main(["replay", str(path), "--gif", str(tmp_path / "e.gif")]) == 0
