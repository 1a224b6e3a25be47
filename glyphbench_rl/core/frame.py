"""The observation of one turn and its single text rendering, shared by every task.

A rendered observation reads, top to bottom:

    Step 3/128 | Food 2/10          <- HUD: the turn counter first, then what the grid cannot show
    ██████████
    █··@>>··o█                      <- the grid: one single-width character per cell
    ██████████
    Legend: █ wall, · empty, ...    <- only the glyphs on the grid, in a fixed order
    You ate food.                   <- message, only when something happened

Board games whose actions name cells (``C4``) render with column letters above the grid and row
numbers to its left (``axes=True``); those labels are not part of ``Frame.grid``. Text that is
about the grid but not cells (a nonogram's clues) goes in ``above`` (lines above the board, a
character per column) and ``beside`` (text right of each row), also outside ``Frame.grid``.
"""

from __future__ import annotations

import unicodedata
from dataclasses import dataclass
from typing import Mapping, Sequence


@dataclass(frozen=True, slots=True)
class Frame:
    grid: tuple[str, ...]
    legend: tuple[tuple[str, str], ...]
    hud: str
    message: str = ""
    axes: bool = False
    above: tuple[str, ...] = ()      # lines above the board, character c over column c
    beside: tuple[str, ...] = ()     # per row, text right of it ("" for none); or () for no row

    def render(self) -> str:
        return render(self)

    def legend_dict(self) -> dict[str, str]:
        return dict(self.legend)


def build_frame(grid: Sequence[str], vocab: Mapping[str, str], hud: str, message: str = "",
                axes: bool = False) -> Frame:
    """Make a Frame whose legend lists exactly the glyphs present, in ``vocab`` order."""
    present = set("".join(grid))
    legend = tuple((g, m) for g, m in vocab.items() if g in present)
    if len(legend) != len(present):
        missing = "".join(sorted(present.difference(vocab)))
        raise RuntimeError(f"glyphs {missing!r} are on the grid but have no legend entry")
    return Frame(tuple(grid), legend, hud, message, axes)


def render(frame: Frame) -> str:
    lines = [frame.hud]
    if frame.axes:
        width = len(str(len(frame.grid)))
        lines.extend(" " * (width + 1) + line for line in frame.above)
        lines.append(" " * (width + 1) + "".join(chr(65 + c) for c in range(len(frame.grid[0]))))
        rows = [f"{r + 1:>{width}} {row}" for r, row in enumerate(frame.grid)]
    else:
        lines.extend(frame.above)
        rows = frame.grid
    if frame.beside:
        rows = [f"{row} {note}" if note else row for row, note in zip(rows, frame.beside)]
    lines.extend(rows)
    lines.append("Legend: " + ", ".join(f"{g} {m}" for g, m in frame.legend))
    if frame.message:
        lines.append(frame.message)
    return "\n".join(lines)


def is_single_width(ch: str) -> bool:
    """One visible codepoint that a monospace terminal draws in exactly one column (no spaces)."""
    if len(ch) != 1 or not ch.isprintable() or ch.isspace():
        return False
    if unicodedata.combining(ch) or unicodedata.east_asian_width(ch) in ("W", "F"):
        return False
    return unicodedata.category(ch) not in ("Cc", "Cf", "Mn", "Me", "Zl", "Zp")


def check_frame(frame: Frame) -> list[str]:
    """Every way ``frame`` breaks the rendering contract (empty when it keeps it)."""
    problems = []
    grid = frame.grid
    if not grid or not grid[0]:
        return ["empty grid"]
    if len({len(row) for row in grid}) != 1:
        problems.append(f"grid is not rectangular: row lengths {sorted({len(r) for r in grid})}")
    glyphs = set("".join(grid))
    for ch in sorted(glyphs):
        if not is_single_width(ch):
            problems.append(f"glyph {ch!r} (U+{ord(ch):04X}) is not a single-width character")
    keys = [g for g, _ in frame.legend]
    if len(keys) != len(set(keys)):
        problems.append("legend repeats a glyph")
    if set(keys) != glyphs:
        problems.append(f"legend keys {sorted(set(keys))} != glyphs on grid {sorted(glyphs)}")
    if any(not m or "\n" in m for _, m in frame.legend):
        problems.append("a legend meaning is empty or spans lines")
    if "\n" in frame.hud or "\n" in frame.message:
        problems.append("HUD and message must be one line each")
    if frame.beside and len(frame.beside) != len(grid):
        problems.append(f"{len(frame.beside)} beside notes for {len(grid)} rows")
    if any("\n" in line for line in (*frame.above, *frame.beside)):
        problems.append("a line above or beside the grid spans lines")
    return problems
