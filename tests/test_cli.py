import json
import subprocess
import sys

import pytest

from glyphbench_rl.cli.main import main


def test_list_prints_ids_only_and_counts_on_request(capsys):
    assert main(["list", "--suite", "classics"]) == 0
    out, err = capsys.readouterr()
    assert "glyphbench/classics-snake-easy-v0" in out and "total" not in out
    assert err == ""
    assert main(["list", "--counts"]) == 0
    out, err = capsys.readouterr()
    assert "Classics" in out and "total" in out and "glyphbench/" not in out and err == ""
    assert out.splitlines()[-1].split()[-1] == "362"       # the catalog total beside ours


def test_show_prints_prompt_and_observation(capsys):
    assert main(["show", "glyphbench/classics-maze-easy-v0", "--seed", "4"]) == 0
    out = capsys.readouterr().out
    assert "=== system prompt ===" in out and "Step 0/100" in out and "<action>" in out


def test_unknown_task_is_one_line_error(capsys):
    assert main(["show", "glyphbench/classics-snak-easy-v0"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "closest: glyphbench/classics-snake-easy-v0" in err


def test_random_prints_returns(tmp_path, capsys):
    out_json = tmp_path / "rows.json"
    assert main(["random", "glyphbench/classics-snake-*", "--episodes", "3", "--json", str(out_json)]) == 0
    out = capsys.readouterr().out
    assert "mean over tasks" in out
    rows = json.loads(out_json.read_text())
    assert len(rows) == 3 and all(-1 <= r["mean_return"] <= 1 and r["episodes"] == 3 for r in rows)


def test_bench_table(capsys):
    assert main(["bench", "--tasks", "glyphbench/classics-snake-easy-v0", "--runs", "2", "--steps", "50"]) == 0
    out = capsys.readouterr().out
    assert "median step+render" in out and "glyphbench/classics-snake-easy-v0" in out


def test_play_in_a_terminal_session():
    """A person types names; a wrong name lists the valid ones; the game goes on."""
    script = "left\nsideways\nRIGHT\nquit\n"
    out = subprocess.run([sys.executable, "-m", "glyphbench_rl.cli", "play", "glyphbench/classics-2048-v0"],
                         input=script, capture_output=True, text=True, timeout=60)
    assert out.returncode == 0, out.stderr
    assert "unknown action 'sideways'; valid actions: UP, DOWN, LEFT, RIGHT" in out.stdout
    assert "Step 2/512" in out.stdout


def test_play_takes_arrow_keys():
    """Arrow keys (as a terminal sends them) play the direction actions, MiniGrid's too."""
    script = "\x1b[D\n\x1bOC\nquit\n"
    out = subprocess.run([sys.executable, "-m", "glyphbench_rl.cli", "play", "glyphbench/classics-2048-v0"],
                         input=script, capture_output=True, text=True, timeout=60)
    assert out.returncode == 0 and "unknown action" not in out.stdout and "Step 2/512" in out.stdout
    out = subprocess.run([sys.executable, "-m", "glyphbench_rl.cli", "play", "glyphbench/minigrid-empty-5x5-v0"],
                         input="\x1b[A\n\x1b[D\nquit\n", capture_output=True, text=True, timeout=60)
    assert out.returncode == 0 and "unknown action" not in out.stdout and "Step 2/" in out.stdout


def test_bad_counts_are_refused(capsys):
    assert main(["random", "glyphbench/classics-2048-v0", "--episodes", "0"]) == 2
    assert "--episodes" in capsys.readouterr().err


def test_output_cut_short_by_the_reader_is_quiet():
    """`glyphbench show ... | head`: a reader that has gone away ends the command without a traceback."""
    import subprocess
    import sys
    proc = subprocess.Popen([sys.executable, "-m", "glyphbench_rl.cli", "show", "glyphbench/classics-2048-v0"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    proc.stdout.close()                     # the reader is gone before anything is written
    err = proc.stderr.read().decode()
    assert proc.wait(timeout=120) == 141 and err == ""
