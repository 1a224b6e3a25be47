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
from functools import lru_cache
from typing import Mapping, NamedTuple, Sequence


class Frame(NamedTuple):
    """One turn's observation. A named tuple: a step makes one, and a tuple is made in one C
    call (``new_frame``), several times faster than a frozen dataclass's ``__init__``."""
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


_tuple_new = tuple.__new__


def new_frame(grid: tuple[str, ...], legend: tuple[tuple[str, str], ...], hud: str, message: str,
              axes: bool) -> Frame:
    """``Frame(grid, legend, hud, message, axes)`` made by ``tuple.__new__`` directly (the
    named tuple's own ``__new__`` is a Python function around that call): the one Frame every
    step makes. ``above`` and ``beside`` get their default, empty (checked below)."""
    return _tuple_new(Frame, (grid, legend, hud, message, axes, (), ()))


assert Frame._fields[5:] == ("above", "beside") and Frame._field_defaults["above"] == () == \
    Frame._field_defaults["beside"], "new_frame sets every Frame field"


def build_frame(grid: Sequence[str], vocab: Mapping[str, str], hud: str, message: str = "",
                axes: bool = False, *, hint: tuple[tuple[str, str], ...] = ()) -> Frame:
    """Make a Frame whose legend lists exactly the glyphs present, in ``vocab`` order.

    ``hint`` is an earlier legend drawn from the same ``vocab``: when the grid holds exactly its
    glyphs (the usual case from one turn to the next) it is the legend, found by a count per
    glyph on the grid instead of a test per vocabulary entry."""
    grid = tuple(grid)
    return Frame(grid, legend_of("".join(grid), vocab_entries(vocab), hint), hud, message, axes)


def vocab_entries(vocab: Mapping[str, str]) -> tuple[tuple[str, str], ...]:
    """The ``(glyph, meaning)`` pairs of ``vocab`` that can be on a grid (one character each)."""
    return tuple((g, m) for g, m in vocab.items() if len(g) == 1)


def legend_of(text: str, entries: Sequence[tuple[str, str]],
              hint: tuple[tuple[str, str], ...] = ()) -> tuple[tuple[str, str], ...]:
    """The ``(glyph, meaning)`` pairs of ``entries`` (``vocab_entries(vocab)``) whose glyph occurs
    in ``text``, in their order; RuntimeError when ``text`` holds a character none names.

    Counting each glyph with ``str.count`` is a C scan; a set of the text's characters would make
    a string object per cell (characters beyond Latin-1 are not cached), which was the largest
    cost of a step on a large board. The counts of the legend's glyphs add up to the length of
    the text exactly when every character is one of them."""
    if hint:
        counted = 0
        for g, _ in hint:
            n = text.count(g)
            if not n:
                break
            counted += n
        else:
            if counted == len(text):
                return hint
    legend = []
    counted, size = 0, len(text)
    for entry in entries:   # (the legend holds the entries themselves: equal legends compare fast)
        g = entry[0]
        if g in text:
            legend.append(entry)
            counted += text.count(g)
            if counted == size:   # every character is accounted for: no later glyph occurs
                break
    if counted != size:
        missing = "".join(sorted(set(text).difference(g for g, _ in entries)))
        raise RuntimeError(f"glyphs {missing!r} are on the grid but have no legend entry")
    return tuple(legend)


ROW_MEMO = 8192   # rows a Legends remembers before it starts again


class Legends:
    """The legends of grids drawn from one vocabulary (its ``vocab_entries``), found row by row.

    A row's glyphs are worked out once, as a bit per entry (``mask``); a grid's legend is then
    the union of its rows' bits, a dictionary lookup per row (rows repeat from turn to turn, and
    a row already hashed costs nothing to hash again), and each union's legend and legend line
    are made once (``legend``). Counting glyphs over the whole grid each turn cost a few times
    more. One Legends serves every task with the same entries; being a cache of facts about
    strings, it is shared, not copied, by ``copy`` and ``deepcopy``, and pickles empty."""
    __slots__ = ("entries", "rows", "legends", "_bit")

    def __init__(self, entries: tuple[tuple[str, str], ...]) -> None:
        self.entries = entries
        self.rows: dict[str, int] = {}
        self.legends: dict[int, tuple[tuple[tuple[str, str], ...], str]] = {}
        self._bit = {g: 1 << i for i, (g, _) in enumerate(entries)}

    def mask(self, row: str) -> int:
        """The bits of the entries whose glyph is in ``row`` (remembered); RuntimeError when
        ``row`` holds a character no entry names. (Found from the row's distinct characters:
        a row is short, a vocabulary can be long.)"""
        bit = self._bit
        bits = 0
        for ch in set(row):
            b = bit.get(ch)
            if b is None:
                missing = "".join(sorted(set(row).difference(bit)))
                raise RuntimeError(f"glyphs {missing!r} are on the grid but have no legend entry")
            bits |= b
        if len(self.rows) >= ROW_MEMO:
            self.rows.clear()
        self.rows[row] = bits
        return bits

    def grid_bits(self, grid: Sequence[str]) -> int:
        """The union of the rows' bits (``mask`` for a row not seen yet)."""
        known = self.rows
        bits = 0
        for row in grid:
            b = known.get(row)
            bits |= self.mask(row) if b is None else b
        return bits

    def legend(self, bits: int) -> tuple[tuple[tuple[str, str], ...], str]:
        """The legend (the entries themselves, in order) of the union ``bits``, and its line."""
        seen = self.legends.get(bits)
        if seen is None:
            legend = tuple(e for i, e in enumerate(self.entries) if bits >> i & 1)
            seen = self.legends[bits] = (legend, legend_line(legend))
        return seen

    def __copy__(self) -> "Legends":
        return self

    def __deepcopy__(self, memo: dict) -> "Legends":
        return self

    def __reduce__(self):
        return legends_for, (self.entries,)


_LEGENDS: dict[tuple[tuple[str, str], ...], Legends] = {}


def legends_for(entries: tuple[tuple[str, str], ...]) -> Legends:
    """The one ``Legends`` of ``entries`` in this process."""
    memo = _LEGENDS.get(entries)
    if memo is None:
        memo = _LEGENDS[entries] = Legends(entries)
    return memo


@lru_cache(maxsize=4096)
def legend_line(legend: tuple[tuple[str, str], ...]) -> str:
    """``Legend: g meaning, ...`` of a legend (a tuple of pairs), remembered per legend (a game
    shows few distinct ones)."""
    return _legend_text(legend)


def _legend_text(legend: Sequence[Sequence[str]]) -> str:
    return "Legend: " + ", ".join([f"{g} {m}" for g, m in legend])


@lru_cache(maxsize=256)
def _axes(height: int, width: int) -> str:
    """A ``height`` x ``width`` board with its column letters above and row numbers left, as a
    ``%`` template taking the rows (one formatting call draws the labelled board)."""
    digits = len(str(height))
    header = " " * (digits + 1) + "".join(chr(65 + c) for c in range(width))
    return "\n".join([header, *(f"{r + 1:>{digits}} %s" for r in range(height))])


def _render_around(frame: Frame, legend_text: str) -> str:
    """``render`` for a board with text above or beside it (a nonogram's clues)."""
    lines = [frame.hud]
    if frame.axes:
        header, *rows = _axes(len(frame.grid), len(frame.grid[0])).split("\n")
        pad = " " * (len(str(len(frame.grid))) + 1)
        lines.extend(pad + line for line in frame.above)
        lines.append(header)
        rows = [label % row for label, row in zip(rows, frame.grid)]
    else:
        lines.extend(frame.above)
        rows = list(frame.grid)
    if frame.beside:
        rows = [f"{row} {note}" if note else row for row, note in zip(rows, frame.beside)]
    lines.extend(rows)
    lines.append(legend_text)
    if frame.message:
        lines.append(frame.message)
    return "\n".join(lines)


def render(frame: Frame, legend_text: str | None = None) -> str:
    """The observation text of ``frame``; ``legend_text`` is ``legend_line(frame.legend)`` when the
    caller already has it."""
    if legend_text is None:
        try:
            legend_text = legend_line(frame.legend)
        except TypeError:   # a legend built of lists by hand
            legend_text = _legend_text(frame.legend)
    if frame.above or frame.beside:
        return _render_around(frame, legend_text)
    if frame.axes:
        lines = [frame.hud, _axes(len(frame.grid), len(frame.grid[0])) % tuple(frame.grid), legend_text]
    else:
        lines = [frame.hud, *frame.grid, legend_text]
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
