"""The parsed episode model shared by the HTML page and the terminal viewer."""

from __future__ import annotations

from replay_helpers import BATTLESHIP, EMPTY, FORFEIT_REPLY, MEMORY, SNAKE, forward, play

from glyphbench_rl.agent.harness import HarnessConfig
from glyphbench_rl.core import make
from glyphbench_rl.rollout.trajectory import Step, Trajectory
from glyphbench_rl.replay.view import EpisodeView, glyph_class, parse_legend, parse_observation


def test_parse_observation_splits_a_real_observation():
    task = make(SNAKE)
    task.reset(seed=3)
    frame = parse_observation(task.frame.render())
    assert frame.hud == task.frame.hud
    assert frame.grid == task.frame.grid and not frame.axes
    assert [(g, m) for g, m, _, _ in frame.legend] == list(task.frame.legend)
    assert frame.message == "" and not frame.legend_carried


def test_parse_observation_strips_board_axes_and_shows_them_again():
    task = make(BATTLESHIP)
    task.reset(seed=1)
    text = task.frame.render()
    frame = parse_observation(text)
    assert frame.axes and frame.grid == task.frame.grid
    assert [(g, m) for g, m, _, _ in frame.legend] == list(task.frame.legend)
    shown = frame.shown_rows()
    assert ["".join(row) for row in shown] == text.split("\n")[1:len(shown) + 1]
    assert shown[0][1] == "" and shown[1] == (" 1 ", frame.grid[0], "")


def test_parse_observation_keeps_the_clues_around_a_nonogram():
    task = make("glyphbench/classics-nonogram-easy-v0")
    task.reset(seed=0)
    task.step("B2")
    text = task.frame.render()
    frame = parse_observation(text)
    assert frame.axes and frame.grid == task.frame.grid and frame.hud == task.frame.hud
    assert frame.above == tuple("  " + line for line in task.frame.above)
    assert frame.beside == task.frame.beside and frame.to_json()["beside"] == list(frame.beside)
    assert [(g, m) for g, m, _, _ in frame.legend] == list(task.frame.legend)
    shown = frame.shown_rows()
    assert ["".join(row) for row in shown] == text.split("\n")[1:len(shown) + 1]
    no_legend = "\n".join(line for line in text.split("\n") if not line.startswith("Legend: "))
    assert parse_observation(no_legend).grid == frame.grid


def test_parse_observation_of_hand_written_text():
    frame = parse_observation("Step 2/9 | Score 1\n█·a\n█,·\n"
                              "Legend: █ wall, · floor, a key, red, , comma sign\nYou bumped.\nTwice.")
    assert frame.hud == "Step 2/9 | Score 1" and frame.grid == ("█·a", "█,·") and not frame.axes
    assert frame.legend == (("█", "wall", "wall", ""), ("·", "floor", "empty", ""),
                            ("a", "key, red", "item", "red"), (",", "comma sign", "other", ""))
    assert frame.message == "You bumped.\nTwice."
    board = parse_observation("Step 0/60\n  ABC\n1 ■■■\n2 ■1■\nLegend: ■ hidden, 1 1 mine around")
    assert board.axes and board.grid == ("■■■", "■1■")
    assert board.shown_rows() == [("  ABC", "", ""), ("1 ", "■■■", ""), ("2 ", "■1■", "")]
    # spaces then letters that are not A, B, C... in order are no column header
    assert not parse_observation("Step 0/9\n  AC\n1 ··\nLegend: · empty").axes


def test_parse_observation_without_legend_keeps_the_message_and_carries_the_legend():
    known = {"·": ("·", "empty", "empty", ""), "*": ("*", "food", "goal", ""), "@": ("@", "you", "agent", "")}
    frame = parse_observation("Step 2/9\n·@·\n···\nNo valid action: nothing happened.", known)
    assert frame.grid == ("·@·", "···")
    assert frame.message == "No valid action: nothing happened."
    assert frame.legend == (known["·"], known["@"]) and frame.legend_carried


def test_parse_legend_allows_commas_inside_meanings():
    text = "· empty, █ wall, or rock, ▶ you facing east"
    assert parse_legend(text, {"·", "█", "▶"}) == [("·", "empty"), ("█", "wall, or rock"),
                                                   ("▶", "you facing east")]
    assert parse_legend(", comma glyph, · empty", {",", "·"}) == [(",", "comma glyph"), ("·", "empty")]


def test_glyph_classes_follow_the_legend_words():
    assert glyph_class("▶", "head moving right") == ("agent", "")
    assert glyph_class("●", "body") == ("agent", "")
    assert glyph_class("e", "opponent trail") == ("hazard", "")
    assert glyph_class("o", "your trail") == ("agent", "")
    assert glyph_class("≈", "lava") == ("hazard", "")
    assert glyph_class("◎", "empty home") == ("goal", "")
    assert glyph_class("R", "red door") == ("item", "red")
    assert glyph_class("·", "no mine around") == ("empty", "")
    assert glyph_class("2", "2 mines around") == ("other", "")
    assert glyph_class("█", "solid ground") == ("wall", "")
    assert glyph_class("#", "something new") == ("wall", "")
    assert glyph_class("Q", "something new") == ("other", "")
    # the cases the two former rule sets (web/terminal and image export) disagreed on
    assert glyph_class("@", "falling piece") == ("agent", "")
    assert glyph_class("<", "car driving left") == ("hazard", "")
    assert glyph_class("X", "red car") == ("item", "red")
    assert glyph_class("E", "red enemy") == ("hazard", "")          # hazards keep the hazard colour
    assert glyph_class("e", "gray key") == ("item", "grey")
    assert glyph_class("*", "food") == ("item", "") and glyph_class("o", "coin") == ("item", "")
    assert glyph_class("~", "water") == ("water", "") and glyph_class("≈", "pond") == ("water", "")
    assert glyph_class("·", "ground") == ("empty", "") and glyph_class("=", "ground") == ("wall", "")
    assert glyph_class("▒", "crate") == ("wall", "") and glyph_class("■", "face down") == ("wall", "")
    assert glyph_class("●", "light on") == ("item", "") and glyph_class("·", "light off") == ("empty", "")
    assert glyph_class("◉", "source") == ("goal", "") and glyph_class("S", "sunk ship") == ("other", "")


def test_episode_view_aligns_frames_turns_rewards_and_memory():
    traj = play((SNAKE,), (1,))[0]
    view = EpisodeView.from_trajectory(traj, index=4, source="f.jsonl:5", suite="Classics")
    assert len(view.frames) == view.length + 1 == len(traj.steps) + 1
    assert view.frames[-1] == parse_observation(traj.final_observation)
    running = 0.0
    for step, turn in zip(traj.steps, view.turns):
        running += step.reward
        assert turn.return_so_far == running and turn.reply == step.reply and turn.action == step.action
    assert abs(view.turns[-1].return_so_far - traj.episode_return) < 1e-9
    assert view.turns[0].memory == MEMORY and view.turns[1].memory is None
    assert view.turns[1].reply == FORFEIT_REPLY and view.turns[1].change == "forfeit"
    assert view.turns[1].forfeit_reason
    assert (view.index, view.source, view.model, view.outcome) == (4, "f.jsonl:5", "scripted-test", "lost")


def test_unchanged_marks_exactly_the_steps_whose_grid_stayed_the_same():
    view = EpisodeView.from_trajectory(play((EMPTY,), (1,), policy=forward)[0])
    changes = [t.change for t in view.turns]
    assert "unchanged" in changes and None in changes
    for i, turn in enumerate(view.turns):
        same = view.frames[i].grid == view.frames[i + 1].grid
        assert (turn.change == "unchanged") == same


def test_changed_legend_harness_shows_the_last_legend():
    terse = EpisodeView.from_trajectory(play((SNAKE,), (1,), harness=HarnessConfig(legend="changed"))[0])
    full = EpisodeView.from_trajectory(play((SNAKE,), (1,))[0])     # the same game, every legend sent
    assert [f.grid for f in terse.frames] == [f.grid for f in full.frames]
    assert any(f.legend_carried for f in terse.frames)
    for shown, sent in zip(terse.frames, full.frames):
        assert set(shown.legend) == set(sent.legend)


def test_an_episode_without_steps_has_one_frame():
    task = make(SNAKE)
    obs, _ = task.reset(seed=0)
    view = EpisodeView.from_trajectory(Trajectory(SNAKE, 0, initial_observation=obs))
    assert len(view.frames) == 1 and view.length == 0 and view.outcome == "unfinished"
    step = Step(1, obs, "", None, "no action tag", 0.0)
    unfinished = EpisodeView.from_trajectory(Trajectory(SNAKE, 0, steps=[step], initial_observation=obs))
    assert unfinished.frames[-1].grid == () and unfinished.turns[0].change == "forfeit"
