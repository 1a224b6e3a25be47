"""The HTML page, the terminal viewer and the GIF/PNG export class every glyph of a real
observation alike: one colour per (class, tint) in each, and the agent and the walls as such."""

from __future__ import annotations

import json
import re

import pytest
from replay_helpers import play, write_jsonl

from glyphbench_rl.replay.html import write_html
from glyphbench_rl.replay.index import EpisodeIndex
from glyphbench_rl.replay.terminal import CLASS_STYLES, TINT_STYLES, grid_text
from glyphbench_rl.replay.view import GLYPH_CLASSES, TINTS

PIL = pytest.importorskip("PIL")
from glyphbench_rl.replay.image import CLASS_COLOURS, NAMED_COLOURS, grid_segments, render_step  # noqa: E402

SOKOBAN = "glyphbench/classics-sokoban-easy-v0"     # █ wall, · floor, ◎ goal, $ box, @ you
DOORKEY = "glyphbench/minigrid-doorkey-5x5-v0"      # █ wall, ░ unseen, ▼ you facing south, yellow key...
DATA = re.compile(r'<script type="application/json" id="replay-data">(.*?)</script>', re.S)


@pytest.fixture(scope="module")
def episodes(tmp_path_factory):
    folder = tmp_path_factory.mktemp("agree")
    index = EpisodeIndex(write_jsonl(folder / "episodes.jsonl", play((SOKOBAN, DOORKEY), (1,))))
    page = folder / "replay.html"
    write_html(index, page)
    data = json.loads(DATA.findall(page.read_text(encoding="utf-8"))[0])
    return index, data["episodes"]


def terminal_styles(frame) -> dict[str, str]:
    """glyph -> the style the terminal grid gives its cells (one style per glyph, checked)."""
    text, rows = grid_text(frame), frame.shown_rows()
    assert text.plain == "\n".join("".join(row) for row in rows)
    style_at = [""] * len(text.plain)
    for span in text.spans:
        style_at[span.start:span.end] = [str(span.style)] * (span.end - span.start)
    out: dict[str, str] = {}
    offset = 0
    for label, cells, note in rows:
        for i, ch in enumerate(cells, offset + len(label)):
            assert out.setdefault(ch, style_at[i]) == style_at[i], ch
        offset += len(label) + len(cells) + len(note) + 1
    return out


def image_colours(frame) -> dict[str, tuple[int, int, int]]:
    """glyph -> the colour the image export draws its cells in (label columns skipped)."""
    out: dict[str, tuple[int, int, int]] = {}
    for (label, cells, _), runs in zip(frame.shown_rows(), grid_segments(frame)):
        drawn = [colour for text, colour in runs for _ in text][len(label):]
        for ch, colour in zip(cells, drawn):
            assert out.setdefault(ch, colour) == colour, ch
    return out


def seen_as(value, table: dict) -> str | None:
    """The key of ``table`` whose value ``value`` is (None when none is)."""
    keys = [k for k, v in table.items() if v == value]
    return keys[0] if len(keys) == 1 else None


@pytest.mark.parametrize("task", [SOKOBAN, DOORKEY])
def test_three_renderers_agree_on_glyph_classes(episodes, task):
    index, page_episodes = episodes
    k = next(i for i, e in enumerate(index.entries) if e.task_id == task)
    frame = index.view(k).frames[0]                   # the first observation the model read
    page_legend = {e[0]: (e[2], e[3]) for e in page_episodes[k]["frames"][0]["legend"]}
    styles, colours = terminal_styles(frame), image_colours(frame)
    assert set(page_legend) == set(styles) == set(colours) == set("".join(frame.grid))
    agreed: dict[str, str] = {}
    for glyph, (cls, tint) in page_legend.items():
        assert cls in GLYPH_CLASSES and tint in ("", *TINTS)
        if tint:          # a colour word wins over the class in every renderer
            assert styles[glyph] == TINT_STYLES[tint] and colours[glyph] == NAMED_COLOURS[tint], glyph
        else:
            assert seen_as(styles[glyph], CLASS_STYLES) == cls, glyph
            assert seen_as(colours[glyph], CLASS_COLOURS) == cls, glyph
        agreed[glyph] = cls
    assert agreed["█"] == "wall"
    agent = [g for g, m, _, _ in frame.legend if m == "you" or m.startswith("you facing")]
    assert len(agent) == 1 and agreed[agent[0]] == "agent"
    if task == DOORKEY:
        assert page_legend["y"] == ("item", "yellow")            # the yellow key
    pixels = {c for _, c in render_step(index.load(k), 0).convert("RGB").getcolors(1 << 24)}
    assert CLASS_COLOURS["agent"] in pixels and CLASS_COLOURS["wall"] in pixels
