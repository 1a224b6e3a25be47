"""``view`` compiled: the 9 x 11 window's cell codes drawn from the packed state (``packed``).

``codes`` fills a (ROWS, COLS) uint8 array with the codes ``view.cell_codes`` gives for the
state the arrays pack (see ``view``'s module docstring for what a cell shows); ``rows`` decodes
them with ``view``'s table into ``view.rows``' 9 strings. The codes, the glyph table and the
drawing order are ``view``'s own (imported, not copied).
``tests/games/craftax/test_craftax_kernel_view.py`` checks both against ``view`` on many
states.

``view`` keeps bands of bytes between steps to draw quickly in Python; here the 99 cells are
simply worked out each call (well under a microsecond compiled; calling costs more) and decoded
with one call.
"""

from __future__ import annotations

from codecs import charmap_decode

import numpy as np
from numba import njit, typeof

from ...core.frame import vocab_entries

from .kernel_mobs import is_boss_vulnerable
from .packed import (ALIVE, COL, DIRECTION, KILLED, LEVEL, MELEE, MOB_COL, MOB_ROW, MOB_SHOTS,
                     PASSIVE, PLAYER_SHOTS, RANGED, ROW, SLEEPING, SLOTS, TYPE, Packed)
from .state import Settings
from .tables import BOSS_LEVEL, BlockType, ItemType
from .view import (_DARK, _DECODING, _ITEM0, _MOB0, _NEWLINE, _PLAYER0, _ROW_STARTS,
                   _VISIBLE_LIGHT32, COLS, HALF_C, HALF_R, KILLS_TO_OPEN_LADDER, ROWS, VOCAB)

_OFF_MAP = int(BlockType.OUT_OF_BOUNDS)
_NECROMANCER = int(BlockType.NECROMANCER)
_NECROMANCER_VULNERABLE = int(BlockType.NECROMANCER_VULNERABLE)
_LADDER_DOWN = int(ItemType.LADDER_DOWN)
_LADDER_DOWN_BLOCKED = int(ItemType.LADDER_DOWN_BLOCKED)
_ITEM_TYPES = len(ItemType)
# the packed groups in view's drawing order (its class k, codes _MOB0 + 8k + type): melee,
# passive and ranged mobs, the mobs' projectiles, the player's (a later one drawn over)
_DRAWN = np.array((MELEE, PASSIVE, RANGED, MOB_SHOTS, PLAYER_SHOTS), np.int64)
# a code with no glyph (decoding it raises): what a value off view's tables shows here, where
# ``view`` raises at once (an item past ``ItemType``, a mob or player code past a byte)
_NO_GLYPH = _DECODING.index("\ufffe")


@njit(cache=True)
def _byte(code):
    """The code, or ``_NO_GLYPH`` when it does not fit a byte."""
    return code if 0 <= code < 256 else _NO_GLYPH


@njit(cache=True)
def codes(map, item_map, mob_map, light_map, ints, mobs, out):
    """``view.cell_codes``: the window's codes into ``out`` (uint8, ROWS x COLS): off the map its
    code; an unlit cell (light <= 0.05 in float32) dark; else the item (a down ladder locked
    below 8 kills on the floor) or the block (a block or item by its low byte, as ``view``
    reads them), the necromancer vulnerable on the graveyard when ``is_boss_vulnerable``; the
    player in the middle by facing (asleep: 0); then mobs and projectiles of the floor on cells
    not dark and not the player's. (``mob_map`` is not read.)"""
    _draw(map, item_map, light_map, ints, mobs, out)


@njit(cache=True)
def _draw(map, item_map, light_map, ints, mobs, out):
    """``codes`` without the mob map (the drawing ``codes`` and ``draw_window`` share)."""
    level = ints[LEVEL]
    r0, c0 = ints[ROW] - HALF_R, ints[COL] - HALF_C
    rows, cols = map.shape[1], map.shape[2]
    ladder_open = ints[KILLED + level] >= KILLS_TO_OPEN_LADDER
    vulnerable = level == BOSS_LEVEL and is_boss_vulnerable(ints, mobs)
    for r in range(ROWS):
        row = r0 + r
        for c in range(COLS):
            col = c0 + c
            if not (0 <= row < rows and 0 <= col < cols):
                code = _OFF_MAP
            elif light_map[level, row, col] <= _VISIBLE_LIGHT32:
                code = _DARK
            else:
                item = item_map[level, row, col] & 255
                if item == 0:
                    code = map[level, row, col] & 255
                    if code == _NECROMANCER and vulnerable:
                        code = _NECROMANCER_VULNERABLE
                elif item == _LADDER_DOWN and not ladder_open:
                    code = _ITEM0 + _LADDER_DOWN_BLOCKED
                elif item < _ITEM_TYPES:
                    code = _ITEM0 + item
                else:
                    code = _NO_GLYPH
            out[r, c] = code
    out[HALF_R, HALF_C] = _byte(_PLAYER0 + (0 if ints[SLEEPING] else ints[DIRECTION]))
    for k in range(5):
        group = _DRAWN[k]
        for slot in range(SLOTS):
            if mobs[group, level, slot, ALIVE]:
                r = mobs[group, level, slot, MOB_ROW] - r0
                c = mobs[group, level, slot, MOB_COL] - c0
                if 0 <= r < ROWS and 0 <= c < COLS and out[r, c] != _DARK \
                        and not (r == HALF_R and c == HALF_C):
                    out[r, c] = _byte(_MOB0 + 8 * k + mobs[group, level, slot, TYPE])


# the legend's entries (``core.frame.vocab_entries`` of view's vocabulary) and each code's entry
# (-1: a code with no glyph, or the row end), as its bit in the legend's two words (``_LOW``,
# ``_HIGH``) and whether it has none (``_UNKNOWN``)
ENTRIES = vocab_entries(VOCAB)
_ENTRY_OF = np.array([next((i for i, (g, _) in enumerate(ENTRIES) if g == _DECODING[code]), -1)
                      for code in range(256)], np.int64)
assert len(ENTRIES) <= 128      # (two 64-bit words of entry bits)
_LOW = np.array([1 << e if 0 <= e < 64 else 0 for e in _ENTRY_OF.tolist()], np.uint64)
_HIGH = np.array([1 << (e - 64) if e >= 64 else 0 for e in _ENTRY_OF.tolist()], np.uint64)
_UNKNOWN = np.array([e < 0 for e in _ENTRY_OF.tolist()], np.uint64)
# ``draw_window``'s answer: what changed since the window drawn before
LINES_CHANGED, WORDS_CHANGED = 1, 2


@njit(cache=True)
def draw_window(map, item_map, light_map, ints, mobs, out, lines, words):
    """``codes`` into ``out``, and copied into ``lines`` (uint8, ROWS * (COLS + 1) - 1): the
    rows one after another, each but the last followed by view's row end (``_NEWLINE``); the
    legend entries on show as bits of ``words`` (uint64: entries 0-63, 64-127, and 1 when a code
    has no entry). Returns what changed: ``LINES_CHANGED``, ``WORDS_CHANGED`` (bits)."""
    _draw(map, item_map, light_map, ints, mobs, out)
    low = high = unknown = np.uint64(0)
    changed = 0
    for r in range(ROWS):
        at = r * (COLS + 1)
        for c in range(COLS):
            code = out[r, c]
            if lines[at + c] != code:
                lines[at + c] = code
                changed = LINES_CHANGED
            low |= _LOW[code]
            high |= _HIGH[code]
            unknown |= _UNKNOWN[code]
    if words[0] != low or words[1] != high or words[2] != unknown:
        words[0], words[1], words[2] = low, high, unknown
        changed |= WORDS_CHANGED
    return changed


class Window:
    """A task's window: the buffers the compiled drawing writes, the packed state's (``codes``:
    the cell codes, uint8 ROWS x COLS; ``lines``: the rows' bytes; ``words``: the legend's bits)
    and the rows last decoded (decoded anew unless the codes are the last ones: remembering more
    windows measured slower, as the player or a mob moves on most steps). ``rows`` draws and
    decodes; ``shown`` decodes what was drawn last (by ``rows``, or by the compiled step, which
    draws the window it leaves)."""

    __slots__ = ("codes", "lines", "words", "_key", "_shown", "bits")

    def __init__(self, p: Packed) -> None:
        self.codes, self.lines, self.words = p.codes, p.lines, p.words
        self.lines[:] = _NEWLINE
        self._key = self._shown = None
        # the legend bits (``ENTRIES``' order) of the rows ``shown`` gave last (they follow from
        # the codes); None when one of its codes has no entry
        self.bits: int | None = None

    @property
    def last(self) -> tuple[str, ...]:
        """The rows ``shown`` or ``rows`` gave last (for a window drawn again the same)."""
        return self._shown

    def rows(self, p: Packed) -> tuple[str, ...]:
        """``view.rows``: the 9 rows of 11 glyphs around the player, from ``codes`` decoded with
        ``view``'s table (a code with no glyph raises ``UnicodeDecodeError``, as ``view.rows``
        does)."""
        draw = _entry or _compile()
        draw(p.map, p.item_map, p.light_map, p.ints, p.mobs, self.codes, self.lines, self.words)
        return self.shown()

    def shown(self, legend: bool = True) -> tuple[str, ...]:
        """The rows of the window drawn last (``legend`` False: its legend's bits are those of
        the window decoded before, as the drawing found)."""
        key = self.lines.tobytes()
        if key != self._key:
            shown = tuple(charmap_decode(key, "strict", _DECODING)[0].split("\n"))
            if len(shown) != ROWS:      # (a cell's code is the row end's: cut the rows by place)
                text = charmap_decode(self.codes.tobytes(), "strict", _DECODING)[0]
                shown = tuple([text[i:i + COLS] for i in _ROW_STARTS])
            self._key, self._shown = key, shown
            if legend:
                low, high, unknown = self.words.tolist()
                self.bits = None if unknown else low | high << 64
        return self._shown


_entry = None       # ``draw_window``'s entry point for the packed arrays' types (as kernel's)


def _compile():
    global _entry
    p = Packed(Settings())
    _entry = draw_window.compile(tuple(typeof(a) for a in (
        p.map, p.item_map, p.light_map, p.ints, p.mobs, p.codes, p.lines, p.words)))
    return _entry


def rows(p: Packed, out: np.ndarray | None = None) -> tuple[str, ...]:
    """``view.rows`` of the packed state (drawn into its window's buffers; ``out``, if given,
    gets the cell codes)."""
    window = Window(p)
    shown = window.rows(p)
    if out is not None:
        out[...] = window.codes
    return shown
