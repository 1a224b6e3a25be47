"""Episode frames as images: one step drawn with Pillow, an episode as an animated GIF or a PNG.

A frame shows, top to bottom: a header (task, seed, model), the HUD line, the glyph grid in a
monospace font with one colour per glyph class (agent, hazard, goal, item, water, wall, empty,
other), the legend, the message, and a caption strip ("turn k · action NAME · reward r · return
R", or the forfeit reason). Frame ``i`` of an episode is the observation the model answered at
step ``i``; frame ``len(steps)`` is the final observation. The observations are split and their
glyphs classed by ``view.EpisodeView``, exactly as the HTML page and the terminal viewer do;
this module only picks the colours and draws. An observation sent without its legend (the
``legend="changed"`` harness) is drawn with the latest legend before it, marked as such.

Fonts: DejaVu Sans Mono as shipped inside matplotlib (it covers the box-drawing, block, arrow and
shape glyphs), else the system's copy. A character that font lacks is drawn, in order of
preference, as an enclosed letter built from its base letter (MiniGrid's ⓑ and ⒠: the letter in
a circle or a box), from DejaVu Sans or STIX (matplotlib), or as an outlined box; the last case
is never silent: a ``MissingGlyphWarning`` names the characters.

Every frame of a GIF has the same size (sections are laid out over all frames at once) and the
same fixed palette (the drawing colours blended into the background), so files stay small.
"""

from __future__ import annotations

import math
import os
import unicodedata
import warnings
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Iterable, Sequence

from ..rollout.trajectory import Trajectory
from .view import EpisodeView, FrameView, TurnView, glyph_class, parse_observation

try:
    from PIL import Image, ImageDraw, ImageFont
except ImportError:          # reported when an image is asked for, not at import
    Image = ImageDraw = ImageFont = None

# glyph_class and parse_observation are view.py's, named here too for callers of this module
__all__ = ["BAD", "CLASS_COLOURS", "DIM", "NAMED_COLOURS", "ImageExportError", "MissingGlyphWarning",
           "class_colour", "export_episode", "glyph_class", "glyph_colour", "grid_segments",
           "parse_observation", "render_step", "write_gif", "write_png"]

RGB = tuple[int, int, int]


class ImageExportError(ValueError):
    """An episode image that cannot be made as asked; the message is one line."""


class MissingGlyphWarning(UserWarning):
    """Characters no available font can draw; they appear as outlined boxes."""


# -- colours -------------------------------------------------------------------------------------
BACKGROUND: RGB = (24, 26, 31)
TEXT: RGB = (222, 225, 230)
DIM: RGB = (128, 134, 146)
RULE: RGB = (58, 62, 72)
GOOD: RGB = (96, 208, 128)
BAD: RGB = (240, 96, 96)
NOTE: RGB = (240, 184, 64)

CLASS_COLOURS: dict[str, RGB] = {
    "agent": (255, 200, 40), "hazard": (240, 88, 88), "goal": (96, 214, 128), "item": (96, 176, 250),
    "water": (64, 140, 230), "wall": (150, 160, 182), "empty": (84, 90, 102), "other": TEXT,
}
NAMED_COLOURS: dict[str, RGB] = {
    "red": (236, 96, 96), "green": (96, 204, 112), "blue": (96, 152, 250), "yellow": (240, 214, 84),
    "purple": (184, 128, 244), "grey": (168, 168, 168), "orange": (246, 152, 64),
}


def class_colour(cls: str, tint: str) -> RGB:
    """The drawing colour of a glyph class and tint (as ``view.glyph_class`` gives them)."""
    return NAMED_COLOURS[tint] if tint else CLASS_COLOURS[cls]


def glyph_colour(glyph: str, meaning: str) -> RGB:
    """The colour a legend entry is drawn in: its class colour, or the colour its meaning names
    (MiniGrid's "red key", Match-3 gems)."""
    return class_colour(*glyph_class(glyph, meaning))


# -- what a frame says ---------------------------------------------------------------------------
Segment = tuple[str, RGB]


@dataclass(frozen=True)
class _Panel:
    header: str
    frame: FrameView
    caption: tuple[Segment, ...]


def _num(x: float) -> str:
    return f"{x:+.3f}"


def _panels(view: EpisodeView, indices: Sequence[int]) -> list[_Panel]:
    """The panels for frame indices (0..view.length)."""
    header = f"{view.task_id} · seed {view.seed} · model {view.model}"
    return [_Panel(header, view.frames[i], _step_caption(view.turns[i]) if i < view.length
                   else _final_caption(view)) for i in indices]


_CHANGE_NOTES = {"unchanged": "no change", "forfeit": "world unchanged"}
_OUTCOME_COLOURS = {"won": GOOD, "lost": BAD, "truncated": NOTE, "ended": TEXT, "unfinished": NOTE}


def _step_caption(turn: TurnView) -> tuple[Segment, ...]:
    sep = (" · ", DIM)
    act = (f"action {turn.action}", TEXT) if turn.action is not None else \
        (f"FORFEIT: {turn.forfeit_reason or 'no valid action'}", BAD)
    reward_colour = GOOD if turn.reward > 0 else BAD if turn.reward < 0 else TEXT
    out = [(f"turn {turn.turn}", TEXT), sep, act, sep, ("reward ", DIM), (_num(turn.reward), reward_colour),
           sep, ("return ", DIM), (_num(turn.return_so_far), TEXT)]
    if turn.change is not None:
        out += [sep, (_CHANGE_NOTES[turn.change], NOTE)]
    return tuple(out)


def _final_caption(view: EpisodeView) -> tuple[Segment, ...]:
    return ((f"end after {view.length} turns", TEXT), (" · ", DIM), ("return ", DIM),
            (_num(view.episode_return), TEXT), (" · ", DIM), (view.outcome, _OUTCOME_COLOURS[view.outcome]))


def _legend_segments(frame: FrameView) -> list[Segment]:
    out: list[Segment] = []
    for n, (glyph, meaning, cls, tint) in enumerate(frame.legend):
        if n:
            out.append((", ", DIM))
        out += [(glyph, class_colour(cls, tint)), (f" {meaning}", DIM)]
    if frame.legend_carried:
        out.append(("  (legend from an earlier step)", DIM))
    return out


def _runs(chars: Iterable[tuple[str, RGB]]) -> list[Segment]:
    """Characters with colours as runs of one colour each (one drawing call per run)."""
    runs: list[Segment] = []
    for ch, colour in chars:
        if runs and runs[-1][1] == colour:
            runs[-1] = (runs[-1][0] + ch, colour)
        else:
            runs.append((ch, colour))
    return runs


def _wrap(segments: Sequence[Segment], width: int) -> list[list[Segment]]:
    """Greedy word wrap of coloured text to ``width`` characters (long words are cut)."""
    chars = [(ch, colour) for text, colour in segments for ch in text]
    lines: list[list[tuple[str, RGB]]] = []
    while chars:
        if len(chars) <= width:
            cut = len(chars)
        else:
            spaces = [i for i in range(width, 0, -1) if chars[i][0] == " "]
            cut = spaces[0] if spaces else width
        lines.append(chars[:cut])
        chars = chars[cut:]
        while chars and chars[0][0] == " ":
            chars = chars[1:]
    return [_runs(line) for line in lines] or [[]]


def grid_segments(frame: FrameView) -> list[list[Segment]]:
    """The grid as drawn: per line, coloured runs; axis labels dim, each glyph in its legend
    entry's colour (a glyph the legend does not name in the plain text colour)."""
    colours = {entry[0]: class_colour(entry[2], entry[3]) for entry in frame.legend}
    return [_runs([*((ch, DIM) for ch in label), *((ch, colours.get(ch, TEXT)) for ch in cells),
                   *((ch, DIM) for ch in note)])
            for label, cells, note in frame.shown_rows()]


# -- fonts ---------------------------------------------------------------------------------------
def _font_dirs() -> list[Path]:
    dirs = []
    try:
        import matplotlib
        dirs.append(Path(matplotlib.get_data_path()) / "fonts" / "ttf")
    except ImportError:
        pass
    return dirs + [Path("/usr/share/fonts/truetype/dejavu"), Path("/usr/share/fonts/TTF"),
                   Path("/Library/Fonts"), Path(os.environ.get("WINDIR", "C:/Windows")) / "Fonts"]


def _find_font(name: str) -> Path | None:
    return next((d / name for d in _font_dirs() if (d / name).is_file()), None)


@lru_cache(maxsize=None)
def _cmap(path: Path) -> frozenset[int]:
    from fontTools.ttLib import TTFont   # a matplotlib dependency
    return frozenset(TTFont(str(path), lazy=True)["cmap"].getBestCmap())


# block elements drawn as rectangles: (left, top, right, bottom) as cell fractions, colour share
_BLOCKS = {"█": ((0, 0, 1, 1), 1.0), "▓": ((0, 0, 1, 1), 0.75), "▒": ((0, 0, 1, 1), 0.5),
           "░": ((0, 0, 1, 1), 0.25), "▀": ((0, 0, 1, 0.5), 1.0), "▄": ((0, 0.5, 1, 1), 1.0),
           "▌": ((0, 0, 0.5, 1), 1.0), "▐": ((0.5, 0, 1, 1), 1.0)}


class _Typeface:
    """A monospace font at one size with its fallbacks; draws text on a fixed character grid."""

    def __init__(self, size: int) -> None:
        primary = _find_font("DejaVuSansMono.ttf")
        if primary is None:
            raise ImageExportError("no DejaVu Sans Mono font found (install matplotlib, which ships "
                                   "it, or the fonts-dejavu package)")
        self.font = ImageFont.truetype(str(primary), size)
        self.small = ImageFont.truetype(str(primary), max(6, round(size * 0.62)))
        self.covered = _cmap(primary)
        self.fallbacks = [(ImageFont.truetype(str(p), size), _cmap(p))
                          for p in filter(None, map(_find_font, ("DejaVuSans.ttf", "STIXGeneral.ttf")))]
        self.advance = self.font.getlength("M")
        self.ascent, descent = self.font.getmetrics()
        self.line = self.ascent + descent
        self.missing: set[str] = set()

    def width(self, columns: int) -> int:
        return math.ceil(columns * self.advance)

    def draw(self, draw, x: float, y: float, runs: Sequence[Segment]) -> None:
        """Coloured runs from (x, y) (top left), one character per column."""
        col = 0
        for text, colour in runs:
            start = 0
            for i, ch in enumerate(text + "\0"):
                if i < len(text) and ord(ch) in self.covered and ch not in _BLOCKS:
                    continue
                if i > start:       # a covered stretch: one call, glyphs on the same advance grid
                    draw.text((x + (col + start) * self.advance, y + self.ascent), text[start:i],
                              font=self.font, fill=colour, anchor="ls")
                if i < len(text):
                    self._draw_special(draw, x + (col + i) * self.advance, y, ch, colour)
                start = i + 1
            col += len(text)

    def _draw_special(self, draw, x: float, y: float, ch: str, colour: RGB) -> None:
        if ch in _BLOCKS:        # on whole pixels, so that walls tile without seams
            (left, top, right, bottom), share = _BLOCKS[ch]
            x0, x1 = round(x), round(x + self.advance)
            shade = tuple(round(b + (c - b) * share) for b, c in zip(BACKGROUND, colour))
            draw.rectangle((round(x0 + left * (x1 - x0)), round(y + top * self.line),
                            round(x0 + right * (x1 - x0)) - 1, round(y + bottom * self.line) - 1), fill=shade)
            return
        name = unicodedata.name(ch, "")
        base = unicodedata.normalize("NFKD", ch).strip("()")
        cx, cy, r = x + self.advance / 2, y + self.line / 2, self.advance / 2
        if ("CIRCLED" in name or "PARENTHESIZED" in name) and len(base) == 1 and ord(base) in self.covered:
            box = (cx - r, cy - r, cx + r, cy + r)
            if "CIRCLED" in name:
                draw.ellipse(box, outline=colour, width=1)
            else:
                draw.rounded_rectangle(box, radius=r / 2, outline=colour, width=1)
            draw.text((cx, cy), base, font=self.small, fill=colour, anchor="mm")
            return
        for font, covered in self.fallbacks:
            if ord(ch) in covered:
                draw.text((cx, y + self.ascent), ch, font=font, fill=colour, anchor="ms")
                return
        self.missing.add(ch)
        draw.rectangle((x + 1, y + 3, x + self.advance - 2, y + self.line - 4), outline=colour, width=1)


# -- layout and drawing --------------------------------------------------------------------------
PAD = 14
GAP = 8
GRID_SIZE, TEXT_SIZE = 22, 15
MIN_TEXT_COLUMNS = 64
MAX_CELLS = (320, 200)        # columns, rows: beyond this an observation is not a game grid


@dataclass(frozen=True)
class _Layout:
    width: int
    height: int
    columns: int              # text characters per line
    y_hud: int
    y_grid: int
    y_legend: int
    y_message: int
    y_rule: int
    y_caption: int


def _texts(panel: _Panel, columns: int) -> dict[str, list[list[Segment]]]:
    return {"header": _wrap([(panel.header, DIM)], columns),
            "hud": _wrap([(panel.frame.hud, TEXT)], columns),
            "legend": _wrap(_legend_segments(panel.frame), columns) if panel.frame.legend else [],
            "message": [line for m in panel.frame.message.split("\n") if m
                        for line in _wrap([(m, TEXT)], columns)],
            "caption": _wrap(panel.caption, columns)}


def _layout(panels: Sequence[_Panel], grid_face: _Typeface, text_face: _Typeface) -> _Layout:
    shown = [p.frame.shown_rows() for p in panels]
    cols = max(max((sum(map(len, row)) for row in rows), default=0) for rows in shown)
    rows = max(len(r) for r in shown)
    if cols > MAX_CELLS[0] or rows > MAX_CELLS[1]:
        raise ImageExportError(f"observation grid of {cols}x{rows} characters is too large to draw "
                               f"(at most {MAX_CELLS[0]}x{MAX_CELLS[1]})")
    width = 2 * PAD + max(grid_face.width(cols), text_face.width(MIN_TEXT_COLUMNS))
    columns = int((width - 2 * PAD) // text_face.advance)
    counts = [{k: len(v) for k, v in _texts(p, columns).items()} for p in panels]
    most = {k: max(c[k] for c in counts) for k in counts[0]}
    line = text_face.line
    y_hud = PAD + most["header"] * line + GAP // 2
    y_grid = y_hud + most["hud"] * line + GAP
    y_legend = y_grid + rows * grid_face.line + GAP
    y_message = y_legend + most["legend"] * line + (GAP // 2 if most["legend"] else 0)
    y_rule = y_message + most["message"] * line + GAP
    y_caption = y_rule + GAP
    height = y_caption + most["caption"] * line + PAD
    return _Layout(width, height, columns, y_hud, y_grid, y_legend, y_message, y_rule, y_caption)


def _draw_panel(panel: _Panel, lay: _Layout, grid_face: _Typeface, text_face: _Typeface):
    im = Image.new("RGB", (lay.width, lay.height), BACKGROUND)
    draw = ImageDraw.Draw(im)
    texts = _texts(panel, lay.columns)

    def lines(key: str, y: int) -> None:
        for n, runs in enumerate(texts[key]):
            text_face.draw(draw, PAD, y + n * text_face.line, runs)

    lines("header", PAD)
    lines("hud", lay.y_hud)
    for r, cells in enumerate(grid_segments(panel.frame)):
        grid_face.draw(draw, PAD, lay.y_grid + r * grid_face.line, cells)
    lines("legend", lay.y_legend)
    lines("message", lay.y_message)
    draw.line((PAD, lay.y_rule, lay.width - PAD, lay.y_rule), fill=RULE, width=1)
    lines("caption", lay.y_caption)
    return im


@lru_cache(maxsize=1)
def _palette():
    """Every drawing colour blended into the background in eight steps: antialiased text maps
    onto it exactly, and all frames share it (no flicker, small deltas)."""
    bases = [TEXT, DIM, RULE, GOOD, BAD, NOTE, *CLASS_COLOURS.values(), *NAMED_COLOURS.values()]
    colours = [BACKGROUND]
    for c in bases:
        for k in range(1, 9):
            blend = tuple(round(b + (x - b) * k / 8) for b, x in zip(BACKGROUND, c))
            if blend not in colours:
                colours.append(blend)
    colours = colours[:256]
    colours += [BACKGROUND] * (256 - len(colours))
    pal = Image.new("P", (1, 1))
    pal.putpalette([v for c in colours for v in c])
    return pal


def _require_pil() -> None:
    if Image is None:
        raise ImageExportError("GIF/PNG export needs Pillow (pip install pillow; matplotlib brings it)")


def _render(traj: Trajectory, indices: Sequence[int]) -> list:
    _require_pil()
    grid_face, text_face = _Typeface(GRID_SIZE), _Typeface(TEXT_SIZE)
    panels = _panels(EpisodeView.from_trajectory(traj), indices)
    lay = _layout(panels, grid_face, text_face)
    images = [_draw_panel(p, lay, grid_face, text_face) for p in panels]
    missing = grid_face.missing | text_face.missing
    if missing:
        listed = " ".join(f"{c} (U+{ord(c):04X})" for c in sorted(missing))
        warnings.warn(f"no font can draw {listed}; drawn as boxes", MissingGlyphWarning, stacklevel=3)
    return images


def _check_index(traj: Trajectory, i: int) -> int:
    n = len(traj.steps)
    if isinstance(i, bool) or not isinstance(i, int) or not -n - 1 <= i <= n:
        raise ImageExportError(f"step {i!r} is out of range: the episode has {n} steps "
                               f"(0..{n - 1}; {n} is the final observation)")
    return i % (n + 1)


# -- public API ----------------------------------------------------------------------------------
def render_step(traj: Trajectory, i: int):
    """Frame ``i`` as an RGB image: the observation of step ``i`` with that step's action,
    reward and return so far; ``i == len(traj.steps)`` (or -1) is the final observation."""
    return _render(traj, [_check_index(traj, i)])[0]


def write_gif(traj: Trajectory, out_path: str | os.PathLike, *, fps: float = 4,
              max_steps: int | None = None) -> Path:
    """An animated GIF of the episode, looping forever: one frame per step (the first
    ``max_steps`` when given), then the final observation held longer."""
    if isinstance(fps, bool) or not isinstance(fps, (int, float)) or not 0 < fps <= 50:
        raise ImageExportError(f"fps must be a number in (0, 50], got {fps!r}")
    if max_steps is not None and (isinstance(max_steps, bool) or not isinstance(max_steps, int)
                                  or max_steps < 0):
        raise ImageExportError(f"max_steps must be an int >= 0, got {max_steps!r}")
    out = _target(out_path, ".gif")
    n = len(traj.steps)
    indices = list(range(n if max_steps is None else min(n, max_steps))) + [n]
    frames = [im.quantize(palette=_palette(), dither=Image.Dither.NONE) for im in _render(traj, indices)]
    frame_ms = round(1000 / fps)
    durations = [frame_ms] * (len(frames) - 1) + [max(3 * frame_ms, 2000)]
    return _save(out, lambda tmp: frames[0].save(
        tmp, format="GIF", save_all=True, append_images=frames[1:], duration=durations, loop=0))


def write_png(traj: Trajectory, out_path: str | os.PathLike, step: int | None = None) -> Path:
    """One frame as a palette PNG: step ``step``, or the final observation when None."""
    out = _target(out_path, ".png")
    i = len(traj.steps) if step is None else _check_index(traj, step)
    frame = render_step(traj, i).quantize(palette=_palette(), dither=Image.Dither.NONE)
    return _save(out, lambda tmp: frame.save(tmp, format="PNG", optimize=True))


def export_episode(traj: Trajectory, out_path: str | os.PathLike, *, step: int | None = None,
                   fps: float = 4, max_steps: int | None = None) -> Path:
    """GIF or PNG by the extension of ``out_path`` (``step`` applies to PNG only)."""
    suffix = Path(out_path).suffix.lower()
    if suffix == ".gif":
        if step is not None:
            raise ImageExportError("a step number applies to a PNG frame, not to a GIF")
        return write_gif(traj, out_path, fps=fps, max_steps=max_steps)
    if suffix == ".png":
        return write_png(traj, out_path, step=step)
    raise ImageExportError(f"cannot tell the image type of {str(out_path)!r}: use a .gif or .png name")


def _target(out_path: str | os.PathLike, suffix: str) -> Path:
    """The output path, checked before any drawing: its extension and its directory."""
    out = Path(out_path)
    if out.suffix.lower() != suffix:
        raise ImageExportError(f"{str(out)!r} should end in {suffix} (the file is written as "
                               f"{suffix[1:].upper()})")
    if not out.parent.is_dir():
        raise ImageExportError(f"directory {str(out.parent)!r} does not exist")
    return out


def _save(out: Path, write) -> Path:
    """Write beside the target, then rename, so a failure never leaves half an image."""
    tmp = out.with_name(f".{out.name}.tmp")
    try:
        write(tmp)
        os.replace(tmp, out)
    finally:
        tmp.unlink(missing_ok=True)
    return out
