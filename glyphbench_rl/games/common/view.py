"""Drawing a scrolling course: a long level is generated once as row strings and each frame is
a ``window`` onto it (Flappy's pipes, Ski's slope, the Platformer's camera) with sprites drawn
on top by ``overlay``; ``stamped`` draws the one moving thing over a still picture drawn once (a
maze, a room); ``signed`` writes a HUD velocity with its sign."""

from __future__ import annotations

from typing import Sequence


def signed(value: int) -> str:
    """A HUD integer with an explicit sign: "+2", "-1", "+0"."""
    return f"{value:+d}"


def window(rows: Sequence[str], top: int, left: int, height: int, width: int) -> list[str]:
    """The ``height`` x ``width`` view of a course of equal-length row strings."""
    return [row[left:left + width] for row in rows[top:top + height]]


def stamped(rows: Sequence[str], r: int, c: int, ch: str) -> list[str]:
    """A copy of ``rows`` with ``ch`` drawn at (r, c) (off-view cells are skipped)."""
    out = list(rows)
    overlay(out, r, c, ch)
    return out


def overlay(rows: list[str], r: int, c: int, ch: str) -> None:
    """Draw ``ch`` at (r, c) of a list of row strings, in place (off-view cells are skipped)."""
    if 0 <= r < len(rows) and 0 <= c < len(rows[r]):
        row = rows[r]
        rows[r] = row[:c] + ch + row[c + 1:]
