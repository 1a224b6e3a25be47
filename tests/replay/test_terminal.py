"""The terminal replay: pure rendering, key handling, plain output and the real key loop on a pty."""

from __future__ import annotations

import fcntl
import os
import pty
import select
import struct
import subprocess
import sys
import termios
import time

import pytest
from replay_helpers import EMPTY, FORFEIT_REPLY, INJECTION, MEMORY, SNAKE, forward, play, write_jsonl

from glyphbench_rl.replay.index import EpisodeIndex
from glyphbench_rl.replay.terminal import Navigator, decode_keys, plain_episode, plain_step, render_step
from glyphbench_rl.replay.view import EpisodeView


@pytest.fixture(scope="module")
def episodes_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("term") / "episodes.jsonl"
    return write_jsonl(path, play((SNAKE,), (1, 2)) + play((EMPTY,), (1,), policy=forward))


@pytest.fixture(scope="module")
def index(episodes_file):
    return EpisodeIndex(episodes_file)


def test_decode_keys_reads_sequences_and_bursts():
    assert decode_keys(b"\x1b[C") == ["right"]
    assert decode_keys(b"\x1b[D\x1b[Cl h") == ["left", "right", "right", "left"]
    assert decode_keys(b"\x1b[H\x1bOF\x1b[1~\x1b[4~gG") == ["home", "end", "home", "end", "home", "end"]
    assert decode_keys(b"npjk\x1b[A\x1b[B\x1b[5~q") == ["next", "prev", "down", "up", "up", "down", "page_up", "quit"]
    assert decode_keys(b"\x1b") == ["quit"] and decode_keys(b"zx\x00") == []


def test_navigator_clamps_and_switches_episodes():
    lengths = [4, 9]
    nav = Navigator(2, lambda slot: lengths[slot], page=3)
    assert nav.press("left") and nav.pos == 0
    for key in ("right", "right", "down", "page_down"):
        nav.press(key)
    assert (nav.pos, nav.scroll) == (2, 4)
    nav.press("end")
    assert (nav.pos, nav.scroll) == (4, 0)
    nav.press("right")
    assert nav.pos == 4
    nav.press("next")
    assert (nav.slot, nav.pos, nav.length) == (1, 0, 9)
    nav.press("next")
    assert nav.slot == 1
    nav.press("end")
    nav.press("prev")
    assert (nav.slot, nav.pos, nav.length) == (0, 0, 4)
    nav.press("up")
    assert nav.scroll == 0
    assert nav.press("quit") is False


def test_plain_step_shows_the_whole_turn(index):
    view = index.view(0)
    first = plain_step(view, 0)
    frame = view.frames[0]
    assert frame.hud in first and all(row in first for row in frame.grid) and "Legend: " in first
    assert "  <think>Plan: " + INJECTION.split("\u2028")[0] in first and MEMORY in first
    assert f"action {view.turns[0].action}  reward" in first
    second = plain_step(view, 1)
    assert FORFEIT_REPLY in second and f"FORFEIT ({view.turns[1].forfeit_reason})" in second
    assert "[world unchanged]" in second
    last = plain_step(view, view.length)
    assert "final observation" in last and f"episode over: {view.outcome}" in last
    whole = plain_episode(view)
    assert whole.count("\n--- step ") == view.length + 1 and "\x1b" not in whole


def test_plain_step_marks_unchanged_steps(index):
    view = index.view(2)
    for i, turn in enumerate(view.turns):
        assert ("[no change]" in plain_step(view, i)) == (turn.change == "unchanged")


def test_control_characters_in_model_text_cannot_drive_the_terminal(index):
    Console = pytest.importorskip("rich.console").Console
    traj = index.load(0)
    traj.steps[0].reply = "think\x1b[2J\x1b]0;title\x07 done\r\nnext\tline \x9b31m"
    traj.steps[0].memory = "mem\x1b[31m"
    view = EpisodeView.from_trajectory(traj)
    text = plain_step(view, 0)
    assert "\x1b" not in text and "\x07" not in text and "\x9b" not in text and "\r" not in text
    assert "think\\x1b[2J\\x1b]0;title\\x07 done\\x0d" in text and "next\tline \\x9b31m" in text
    assert "mem\\x1b[31m" in text
    console = Console(record=True, width=160, color_system=None)
    console.print(render_step(view, 0))
    assert "think\\x1b[2J" in console.export_text()


def test_render_step_is_a_rich_panel_with_the_same_content(index):
    Console = pytest.importorskip("rich.console").Console
    view = index.view(0)
    console = Console(record=True, width=160, color_system=None)
    console.print(render_step(view, 1))
    text = console.export_text()
    assert view.task_id in text and "step 1/" in text and "FORFEIT" in text and FORFEIT_REPLY in text
    assert all(row in text for row in view.frames[1].grid)
    console.print(render_step(view, 0, reply_height=1))
    text = console.export_text()
    assert "<think>Plan: <script>" in text and "above" not in text and "1 line(s) below (↑/↓)" in text
    console.print(render_step(view, 0, reply_offset=1, reply_height=1))
    assert "1 line(s) above (↑/↓)" in console.export_text()
    console.print(render_step(EpisodeIndex(index.path).view(2), 3))
    assert "no change" in console.export_text()


def test_cli_prints_plain_text_when_stdout_is_not_a_terminal(episodes_file, index):
    run = subprocess.run([sys.executable, "-m", "glyphbench_rl.cli", "replay", str(episodes_file),
                          "--task", "*snake*"], capture_output=True, text=True, encoding="utf-8", timeout=120)
    assert run.returncode == 0, run.stderr
    assert "\x1b" not in run.stdout and run.stdout.count("=== episode #") == 2
    steps = index.entries[0].length + index.entries[1].length + 2
    assert run.stdout.count("\n--- step ") == steps


def _read_until(fd: int, needle: bytes, seen: bytearray, deadline: float) -> bool:
    while needle not in seen:
        if time.monotonic() > deadline or not select.select([fd], [], [], 0.5)[0]:
            if time.monotonic() > deadline:
                return False
            continue
        try:
            seen += os.read(fd, 65536)
        except OSError:
            return False
    return True


def test_keys_drive_the_interactive_viewer_on_a_terminal(episodes_file):
    pytest.importorskip("rich")
    master, slave = pty.openpty()
    fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", 40, 150, 0, 0))
    env = {**os.environ, "TERM": "xterm-256color", "COLUMNS": "150", "LINES": "40"}
    proc = subprocess.Popen([sys.executable, "-m", "glyphbench_rl.cli", "replay", str(episodes_file)],
                            stdin=slave, stdout=slave, stderr=slave, env=env, close_fds=True)
    os.close(slave)
    seen = bytearray()
    deadline = time.monotonic() + 60
    try:
        assert _read_until(master, b"step 0/", seen, deadline), bytes(seen)[-500:]
        os.write(master, b"\x1b[C")
        assert _read_until(master, b"step 1/", seen, deadline)
        os.write(master, b"\x1b[F")
        assert _read_until(master, b"episode over", seen, deadline)
        os.write(master, b"n")
        assert _read_until(master, b"seed 2", seen, deadline)
        os.write(master, b"q")
        assert proc.wait(timeout=30) == 0
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
        os.close(master)
