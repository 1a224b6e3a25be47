"""Episode frames as images: layout, colours, GIF/PNG files and their errors, on real episodes."""

import warnings

import pytest

PIL = pytest.importorskip("PIL")
from PIL import Image  # noqa: E402

from glyphbench_rl.evaluate import EvalConfig, run_job  # noqa: E402
from glyphbench_rl.evaluate.job import EPISODES  # noqa: E402
from glyphbench_rl.replay import view  # noqa: E402
from glyphbench_rl.replay.image import (  # noqa: E402
    BAD, CLASS_COLOURS, DIM, NAMED_COLOURS, ImageExportError, MissingGlyphWarning, export_episode,
    glyph_class, glyph_colour, grid_segments, parse_observation, render_step, write_gif, write_png)
from glyphbench_rl.rollout.trajectory import Step, Trajectory, read_jsonl  # noqa: E402
from glyphbench_rl.rollout import ScriptedBackend  # noqa: E402

SNAKE = "glyphbench/classics-snake-easy-v0"
EMPTY = "glyphbench/minigrid-empty-5x5-v0"


def policy(request):
    """Forfeits its first turn, then heads UP in Snake (a crash within a few turns) and turns
    left in MiniGrid."""
    if request.turn == 0:
        return "I pass."
    names = request.actions.names
    return names.index("UP") if "UP" in names else 0


@pytest.fixture(scope="module")
def episodes(tmp_path_factory):
    out = tmp_path_factory.mktemp("job")
    run_job(EvalConfig(tasks=[SNAKE], backend="scripted", episodes=1), out,
            backend=ScriptedBackend(policy), log=None)
    run_job(EvalConfig(tasks=[EMPTY], backend="random", episodes=1), out / "mg", log=None)
    trajs = list(read_jsonl(out / EPISODES)) + list(read_jsonl(out / "mg" / EPISODES))
    return {t.task_id: t for t in trajs}


def pixels(im) -> set:
    return {colour for _, colour in im.convert("RGB").getcolors(1 << 24)}


def test_colours_follow_the_shared_glyph_classes():
    assert (glyph_class, parse_observation) == (view.glyph_class, view.parse_observation)
    assert tuple(CLASS_COLOURS) == view.GLYPH_CLASSES and tuple(NAMED_COLOURS) == view.TINTS
    assert len(set(CLASS_COLOURS.values())) == len(CLASS_COLOURS)
    for glyph, meaning, cls in [("▶", "you facing east", "agent"), ("●", "body", "agent"),
                                ("█", "wall", "wall"), ("≈", "lava", "hazard"), ("◎", "goal", "goal"),
                                ("*", "food", "item"), ("~", "water", "water"), ("·", "floor", "empty"),
                                ("·", "no mine around", "empty"), ("*", "mine", "hazard"),
                                ("1", "1 mine around", "other")]:
        assert glyph_colour(glyph, meaning) == CLASS_COLOURS[cls], (glyph, meaning)
    assert glyph_colour("ⓑ", "blue ball") == NAMED_COLOURS["blue"]
    assert glyph_colour("E", "red enemy") == CLASS_COLOURS["hazard"]       # a hazard keeps its colour


def test_grid_segments_colour_glyphs_and_dim_the_board_axes():
    board = parse_observation("Step 0/60\n  ABC\n1 ■■■\n2 ■1■\nLegend: ■ hidden, 1 1 mine around")
    rows = grid_segments(board)
    assert rows[0] == [("  ABC", DIM)]
    assert rows[1] == [("1 ", DIM), ("■■■", CLASS_COLOURS["wall"])]
    assert rows[2] == [("2 ", DIM), ("■", CLASS_COLOURS["wall"]), ("1", CLASS_COLOURS["other"]),
                       ("■", CLASS_COLOURS["wall"])]


def test_render_step_shows_state_action_and_colours(episodes):
    snake = episodes[SNAKE]
    assert snake.steps[0].action is None and snake.steps[1].action == "UP"
    first, second = render_step(snake, 0), render_step(snake, 1)
    final = render_step(snake, len(snake.steps))
    assert first.mode == "RGB" and first.width >= 400 and first.height >= 250
    assert first.size == second.size and first.tobytes() != second.tobytes()
    assert first.tobytes() != final.tobytes()
    assert render_step(snake, -1).tobytes() == final.tobytes()
    assert BAD in pixels(first) and BAD not in pixels(second)     # the FORFEIT caption is red
    grid = render_step(episodes[EMPTY], 0)
    seen = pixels(grid)
    assert CLASS_COLOURS["agent"] in seen and CLASS_COLOURS["wall"] in seen and CLASS_COLOURS["goal"] in seen
    with pytest.raises(ImageExportError, match="out of range"):
        render_step(snake, len(snake.steps) + 1)


def test_gif_frames_same_size_loop_and_final_hold(episodes, tmp_path):
    snake = episodes[SNAKE]
    out = write_gif(snake, tmp_path / "ep.gif", fps=5)
    assert out.read_bytes()[:6] == b"GIF89a"
    with Image.open(out) as im:
        assert im.n_frames == len(snake.steps) + 1 and im.info["loop"] == 0
        sizes, durations, frames = set(), [], []
        for k in range(im.n_frames):
            im.seek(k)
            sizes.add(im.size)
            durations.append(im.info["duration"])
            frames.append(im.convert("RGB").tobytes())
    assert len(sizes) == 1
    assert durations[0] == 200 and durations[-1] > durations[0]
    assert len(set(frames)) == len(frames)                  # every turn shows something new
    assert out.stat().st_size < 100_000
    with Image.open(write_gif(snake, tmp_path / "two.gif", max_steps=2)) as im:
        assert im.n_frames == 3


def test_png_and_export_by_extension(episodes, tmp_path):
    snake = episodes[SNAKE]
    png = write_png(snake, tmp_path / "final.png")
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    with Image.open(png) as im:
        assert im.mode == "P" and im.size == render_step(snake, -1).size
    assert export_episode(snake, tmp_path / "one.PNG", step=0).read_bytes()[:4] == b"\x89PNG"
    assert export_episode(snake, tmp_path / "all.gif").read_bytes()[:3] == b"GIF"
    for bad, kw, match in [("x.jpg", {}, "use a .gif or .png"), ("x.gif", {"step": 1}, "PNG frame"),
                           ("x.png", {"step": 99}, "out of range"),
                           ("missing/x.png", {}, "does not exist")]:
        with pytest.raises(ImageExportError, match=match):
            export_episode(snake, tmp_path / bad, **kw)
    with pytest.raises(ImageExportError, match="should end in .gif"):
        write_gif(snake, tmp_path / "x.jpg")
    with pytest.raises(ImageExportError, match="fps"):
        write_gif(snake, tmp_path / "x.gif", fps=0)
    with pytest.raises(ImageExportError, match="max_steps"):
        write_gif(snake, tmp_path / "x.gif", max_steps=-1)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["all.gif", "final.png", "one.PNG"]


def _one_step(grid: str, legend: str) -> Trajectory:
    obs = f"Step 0/3\n{grid}\nLegend: {legend}"
    return Trajectory(task_id="glyphbench/test-v0", seed=7, final_observation=obs, episode_return=0.5,
                      steps=[Step(turn=1, observation=obs, reply="<action>A</action>", action="A",
                                  forfeit_reason=None, reward=0.5)])


def test_glyphs_no_font_has_are_never_silent():
    with warnings.catch_warnings():
        warnings.simplefilter("error")          # enclosed letters are drawn, not boxed
        render_step(_one_step("ⓑ⒠·", "ⓑ blue ball, ⒠ grey box, · floor"), 0)
    with pytest.warns(MissingGlyphWarning, match="U\\+E123"):
        render_step(_one_step("\ue123·", "\ue123 thing, · floor"), 0)
