"""From NLE's observation arrays to a glyph grid, its vocabulary and the HUD text.

Light: numpy only (no ``nle``), so the rules here are testable on synthetic arrays.

- **Grid.** NetHack draws on a 21x79 map. We show the bounding box of every cell seen so far in
  the episode; a box wider or taller than the window (``VIEW``)
  is shown as a window of that size around the hero, and the HUD then says where the window is.
  Cells NetHack leaves blank (not seen, dark, solid rock) are ``█``: one token, fewer in runs.
  ``grid_rows`` states the drawing; :class:`Painter` keeps it up to date a few cells a turn.
- **Glyphs.** NetHack reuses characters (``.`` is floor and doorway, ``d`` a jackal and a coyote).
  A :class:`Glyphs` assigns each (character, description) pair one grid character for the whole
  episode: NetHack's own character while it is free, else one from a pool of spare symbols. So
  the legend never maps one character to two meanings, and a meaning keeps its character.
  Meanings are NetHack's screen descriptions said short (``floor``, ``stairs down``, ``apple``).
- **HUD.** Hit points, armour class, hunger and conditions from ``blstats``; the inventory as
  ``letter name`` pairs, shortened (articles, "uncursed", and the long "(weapon in hand)" forms);
  tersely (MiniHack) names only, without blessed/uncursed, enchantment and the weapon slots no
  action uses, ``wielded``/``worn`` first.
"""

from __future__ import annotations

import re
from functools import lru_cache

import numpy as np

ROWS, COLS = 21, 79
VIEW = (21, 41)           # (rows, cols): the largest area shown; bigger levels scroll with the hero
BLANK = "█"               # a visible glyph (the grid holds no spaces); one token, fewer in runs
BLANK_MEANING = "unknown"  # (not seen yet, dark, or solid rock: NetHack shows them alike)
HERO = "you"

# blstats indices (nle.nethack.NLE_BL_*), written out so this module needs no nle import
BL_X, BL_Y, BL_HP, BL_HPMAX, BL_DEPTH, BL_AC, BL_TIME, BL_HUNGER, BL_CONDITION = 0, 1, 10, 11, 12, 16, 20, 21, 25
BL_GOLD, BL_ENERGY, BL_ENERGYMAX, BL_XP = 13, 14, 15, 18
HUNGER = ("Satiated", "", "Hungry", "Weak", "Fainting", "Fainted", "Starved")   # NetHack's u.uhs
# NLE's condition bits (BL_MASK_*), in NetHack's order
CONDITIONS = ((0x1, "Stone"), (0x2, "Slime"), (0x4, "Strangled"), (0x8, "FoodPois"), (0x10, "Ill"),
              (0x20, "Blind"), (0x40, "Deaf"), (0x80, "Stun"), (0x100, "Conf"), (0x200, "Hallu"),
              (0x400, "Lev"), (0x800, "Fly"), (0x1000, "Ride"))

# NetHack's screen descriptions said shorter (a legend line is paid for every turn)
MEANINGS = {"floor of a room": "floor", "dark part of a room": "dark floor", "staircase up": "stairs up",
            "staircase down": "stairs down"}
# features whose NetHack character is shared with a commoner one get their own, always
PREFERRED = {"doorway": "·", "broken door": "·", "open door": "'", "dark floor": ",",
             "tree": "τ", "water": "~", "molten lava": "≈"}
# spare single-width symbols for a meaning whose NetHack character is taken
SPARE = "§µøßðæ¢£Δλπφ±×¬¿¤þ¥ΩΣΘΛΞΠΦΨψ÷¡ÆØÞ"   # (one-token symbols first)

_SHORTEN = ((re.compile(r"^(?:an?|the) "), ""), (re.compile(r"\buncursed "), ""),
            (re.compile(r" \(weapons? in hands?\)"), " (wielded)"),
            (re.compile(r" \(being worn\)"), " (worn)"),
            (re.compile(r" \(alternate weapon; not wielded\)"), " (alternate)"),
            (re.compile(r" \(in quiver(?: pouch)?\)"), " (quivered)"),
            (re.compile(r" \(on (?:left|right) hand\)"), " (worn)"))
# and tersely: no blessed/uncursed (cursed stays), enchantments, or weapon slots no action uses;
# "wielded"/"worn" said before the name (fewer tokens than the bracket after it)
_TERSE = ((re.compile(r"\b(?:blessed|uncursed) "), ""), (re.compile(r"(?<![\w+-])[+-]\d+ "), ""),
          (re.compile(r" \((?:alternate weapon; not wielded|in quiver(?: pouch)?)\)"), ""))
_IN_USE = re.compile(r"^(.*) \((wielded|worn)\)$")


def text(row: np.ndarray) -> str:
    """A NUL-padded byte row as text."""
    return row.tobytes().split(b"\0", 1)[0].decode("latin-1").strip()


@lru_cache(maxsize=4096)
def item_name(s: str, terse: bool = False) -> str:
    """An item's name without article and "uncursed", its slot said short; ``terse``: also
    without "blessed", enchantment, and the alternate-weapon and quiver slots, and "wielded" or
    "worn" first (``wielded short sword``)."""
    if terse:
        for pattern, repl in _TERSE:
            s = pattern.sub(repl, s)
    for pattern, repl in _SHORTEN:
        s = pattern.sub(repl, s)
    return _IN_USE.sub(r"\2 \1", s) if terse else s


def inventory(letters: np.ndarray, strs: np.ndarray, terse: bool = False) -> list[tuple[str, str]]:
    """``(letter, short name)`` for each inventory slot in use."""
    out = []
    for letter, s in zip(letters.tolist(), strs):
        if not letter:
            break
        out.append((chr(letter), item_name(text(s), terse)))
    return out


def status(blstats: np.ndarray, hp_only: bool = False) -> str:
    """HUD fields from blstats: ``HP 12/12 AC 7 Lev`` (hunger and conditions only when set)."""
    b = blstats.tolist()
    key = (b[BL_HP], b[BL_HPMAX], b[BL_AC], b[BL_HUNGER], b[BL_CONDITION], hp_only)
    text = _STATUS.get(key)
    if text is None:
        if len(_STATUS) > 4096:
            _STATUS.clear()
        text = _STATUS[key] = _status(*key)
    return text


_STATUS: dict[tuple, str] = {}   # (the few values a HUD shows repeat: each text made once)


def _status(hp: int, hp_max: int, ac: int, hunger: int, cond: int, hp_only: bool) -> str:
    parts = [f"HP {hp}/{hp_max}"]
    if not hp_only:
        parts.append(f"AC {ac}")
    if 0 <= hunger < len(HUNGER) and HUNGER[hunger]:
        parts.append(HUNGER[hunger])
    parts.extend(name for bit, name in CONDITIONS if cond & bit)
    return " ".join(parts)


def describe(description: str, hero: bool) -> str:
    """The legend text of a cell's screen description."""
    if hero:
        return HERO
    if not description:
        return BLANK_MEANING
    return MEANINGS.get(description) or item_name(description, terse=True)


class Glyphs:
    """The episode's assignment of grid characters to meanings (see the module docstring).

    ``vocab`` is the mapping character -> meaning in order of first sight; it is a new dict each
    time a meaning is added and the same object otherwise (the task base reuses legends while it
    holds)."""

    def __init__(self) -> None:
        self.vocab: dict[str, str] = {BLANK: BLANK_MEANING}     # (the legend lists only what is shown)
        self._by_key: dict[tuple[int, str], str] = {}
        self._spare = iter(SPARE)

    def char(self, nh_char: int, meaning: str) -> str:
        key = (nh_char, meaning)
        ch = self._by_key.get(key)
        if ch is None:
            if meaning == BLANK_MEANING and nh_char == 32:
                ch = BLANK
            else:
                ch = PREFERRED.get(meaning) or (chr(nh_char) if 32 < nh_char < 127 else next(self._spare))
                if ch in self.vocab and self.vocab[ch] != meaning:
                    ch = next(c for c in self._spare if c not in self.vocab)
                if ch not in self.vocab:
                    self.vocab = {**self.vocab, ch: meaning}
            self._by_key[key] = ch
        return ch


class MapView:
    """The shown part of the 21x79 map: the episode's seen bounding box, or a
    window of ``VIEW`` around the hero inside it."""

    def __init__(self, view: tuple[int, int] = VIEW) -> None:
        self.view = view
        self.box: list[int] | None = None   # y0, y1, x0, x1 inclusive, of every cell seen

    def see(self, chars: np.ndarray, cells: np.ndarray | None = None) -> None:
        """Take the cells now drawn into the box: every cell of ``chars``, or only the flat
        indices ``cells`` (those that changed: the others are in the box already)."""
        if cells is not None and self.box is not None:
            b = self.box
            flat = chars.reshape(-1)
            for c in cells:
                y, x = divmod(c, COLS)
                if not (b[0] <= y <= b[1] and b[2] <= x <= b[3]) and flat[c] != 32:
                    b[:] = min(b[0], y), max(b[1], y), min(b[2], x), max(b[3], x)
            return
        ys = np.flatnonzero((chars != 32).any(axis=1))
        if not len(ys):
            return
        xs = np.flatnonzero((chars[ys[0]:ys[-1] + 1] != 32).any(axis=0))
        y0, y1, x0, x1 = int(ys[0]), int(ys[-1]), int(xs[0]), int(xs[-1])
        b = self.box
        self.box = [y0, y1, x0, x1] if b is None else [min(b[0], y0), max(b[1], y1), min(b[2], x0), max(b[3], x1)]

    def window(self, hero: tuple[int, int]) -> tuple[int, int, int, int]:
        """``(y0, y1, x0, x1)`` half-open bounds of the shown area."""
        y0, y1, x0, x1 = self.box if self.box is not None else (hero[1], hero[1], hero[0], hero[0])
        y1, x1 = y1 + 1, x1 + 1
        (y0, y1), (x0, x1) = _fit(y0, y1, hero[1], self.view[0]), _fit(x0, x1, hero[0], self.view[1])
        return y0, y1, x0, x1

    def scrolled(self, bounds: tuple[int, int, int, int]) -> bool:
        y0, y1, x0, x1 = bounds
        b = self.box
        return b is not None and (y0 > b[0] or y1 <= b[1] or x0 > b[2] or x1 <= b[3])


def _fit(lo: int, hi: int, centre: int, size: int) -> tuple[int, int]:
    if hi - lo <= size:
        return lo, hi
    start = min(max(lo, centre - size // 2), hi - size)
    return start, start + size


def grid_rows(chars: np.ndarray, glyphs: np.ndarray, descriptions: np.ndarray, bounds: tuple[int, int, int, int],
              hero: tuple[int, int], assign: Glyphs) -> list[str]:
    """The shown rows, each cell drawn as the episode's character for its NetHack character and
    screen description (the hero's cell: for ``you``). Meanings new to ``assign`` are taken in
    order of NetHack glyph id, then position. The plain statement of what :class:`Painter` keeps
    up to date step by step (a cell at a time, so slow: for tests)."""
    y0, y1, x0, x1 = bounds
    ids = glyphs[y0:y1, x0:x1].astype(np.int64)
    order = np.argsort(ids, axis=None, kind="stable")
    width = x1 - x0
    codes = np.empty(ids.size, dtype=np.uint32)
    for flat in order.tolist():
        y, x = divmod(flat, width)
        codes[flat] = ord(assign.char(*_meaning(chars, descriptions, y0 + y, x0 + x, hero)))
    return [row.tobytes().decode("utf-32-le") for row in codes.reshape(ids.shape)]


def _meaning(chars: np.ndarray, descriptions: np.ndarray, y: int, x: int, hero: tuple[int, int]) -> tuple[int, str]:
    """(NetHack character, meaning) of map cell (y, x)."""
    nh = int(chars[y, x])
    return nh, HERO if (x, y) == hero and nh != 32 else _cell_meaning(nh, descriptions[y, x])


def _cell_meaning(nh: int, description: np.ndarray) -> str:
    """The meaning of a cell other than the hero's: its NetHack character and description."""
    return BLANK_MEANING if nh == 32 else describe(text(description), False)


class Painter:
    """The episode's grid, kept up to date cell by cell: what ``grid_rows`` draws, at the cost
    of the cells that changed.

    NetHack redraws a few cells a turn. A cell's character is worked out again when its glyph
    id changed, when it holds the hero (or held it), when it comes into view, and every turn
    when its glyph is one whose description can differ between cells and turns (``varies``:
    monsters, objects, traps, altars, doorways; "peaceful", "2 apples", "broken door"). Other
    glyphs (walls, floor, water, stairs ...) mean the same wherever they are, so their character
    is remembered per glyph id. A row is decoded again only when one of its cells changed.
    ``varies`` is a boolean per glyph id (None: every glyph varies)."""

    def __init__(self, assign: Glyphs, varies: np.ndarray | None = None, view: tuple[int, int] = VIEW) -> None:
        self.assign = assign
        self.view = MapView(view)
        size = 1 << 15 if varies is None else len(varies)
        self._varies = bytes(size * [1]) if varies is None else bytes(np.asarray(varies, np.uint8))
        self._glyphs: np.ndarray | None = None         # the glyph map drawn last, flat
        self._glyph_bytes = b""
        self._codes = np.zeros(ROWS * COLS, np.uint32)  # each cell's character; 0: to work out
        self._lut = np.zeros(size, np.uint32)           # glyph id -> character, glyphs that do not vary (0: none yet)
        self._by_look: dict[tuple, int] = {}            # (glyph id, NetHack char, description) -> character
        self._varying: dict[int, bytes] = {}            # cells in view showing a varying glyph: their text
        self._hero = -1
        self._hero_codes: dict[int, int] = {}           # the hero's NetHack char -> character
        self._rows: dict[int, str] = {}                 # decoded rows of the columns of ``bounds``
        self._shown: list[str] | None = None            # the rows of ``bounds`` (None: to redo)
        self.bounds = (0, 0, 0, 0)

    def update(self, chars: np.ndarray, glyphs: np.ndarray, descriptions: np.ndarray,
               hero: tuple[int, int]) -> tuple[int, int, int, int]:
        """Take NetHack's arrays of this turn; returns the shown bounds ``(y0, y1, x0, x1)``."""
        flat = glyphs.reshape(-1)
        codes = self._codes
        changed: list[int] = []
        now = flat.tobytes()
        if self._glyphs is None:
            self._glyphs = flat.copy()
            self.view.see(chars)
        elif now != self._glyph_bytes:
            diff = (flat != self._glyphs).nonzero()[0]
            self._glyphs[:] = flat
            codes[diff] = 0
            changed = diff.tolist()
            self.view.see(chars, changed)
        self._glyph_bytes = now
        cell = hero[1] * COLS + hero[0]
        if cell != self._hero:
            for c in (self._hero, cell):
                if c >= 0 and codes[c]:
                    codes[c] = 0
                    changed.append(c)
            self._hero = cell
        bounds = self.view.window(hero)
        y0, y1, x0, x1 = bounds
        if bounds != self.bounds:
            if bounds[2:] != self.bounds[2:]:
                self._rows = {}
            self.bounds = bounds
            self._shown = None
            ys, xs = (codes.reshape(ROWS, COLS)[y0:y1, x0:x1] == 0).nonzero()
            pending = ((ys + y0) * COLS + xs + x0).tolist()
        else:
            pending = [c for c in changed if y0 <= c // COLS < y1 and x0 <= c % COLS < x1]
        todo = []
        descs = descriptions.reshape(ROWS * COLS, -1)
        if self._varying:                  # the same glyph: worked out again if its text changed
            keep = {}
            for c, seen in self._varying.items():
                if not (y0 <= c // COLS < y1 and x0 <= c % COLS < x1):
                    codes[c] = 0           # out of view: worked out again on its return
                elif codes[c]:             # (0: its glyph changed, it is pending)
                    if descs[c].tobytes() == seen:
                        keep[c] = seen
                    else:
                        todo.append(c)
            self._varying = keep
        if pending:
            rows, hero_cell = self._rows, self._hero
            if len(pending) > 32:          # (a new or moved window: a table look-up at once)
                cells = np.array(pending)
                known = self._lut[flat[cells]]
                known[cells == hero_cell] = 0
                codes[cells] = known
                todo.extend(cells[known == 0].tolist())
                for y in set((cells // COLS).tolist()):
                    rows.pop(y, None)
            else:
                lut = self._lut
                for c, g in zip(pending, flat[pending].tolist()):
                    code = int(lut[g]) or None if c != hero_cell else self._hero_codes.get(int(chars.flat[c]))
                    if code is None:
                        todo.append(c)
                    else:
                        codes[c] = code
                    rows.pop(c // COLS, None)
            self._shown = None
        if todo:
            if len(todo) > 1:
                todo = sorted(set(todo), key=lambda c: (int(flat[c]), c))
            self._work_out(todo, flat, chars, descs)
        return bounds

    def _work_out(self, cells: list[int], flat: np.ndarray, chars: np.ndarray, descs: np.ndarray) -> None:
        codes, varies, lut, by_look = self._codes, self._varies, self._lut, self._by_look
        nh_flat = chars.reshape(-1)
        for c in cells:
            g = int(flat[c])
            nh = int(nh_flat[c])
            if c == self._hero:
                code = self._hero_codes.get(nh)
                if code is None:
                    code = self._hero_codes[nh] = ord(self.assign.char(nh, HERO if nh != 32 else BLANK_MEANING))
            elif varies[g]:
                seen = descs[c].tobytes()
                key = (g, nh, seen)
                code = by_look.get(key)
                if code is None:
                    code = by_look[key] = ord(self.assign.char(nh, _cell_meaning(nh, descs[c])))
                self._varying[c] = seen
            else:
                code = int(lut[g])
                if not code:
                    code = lut[g] = ord(self.assign.char(nh, _cell_meaning(nh, descs[c])))
            if codes[c] != code:
                codes[c] = code
                self._rows.pop(c // COLS, None)
                self._shown = None

    def rows(self) -> list[str]:
        """The shown rows (of the bounds the last ``update`` returned)."""
        if self._shown is None:
            y0, y1, x0, x1 = self.bounds
            rows, grid = self._rows, self._codes.reshape(ROWS, COLS)
            out = []
            for y in range(y0, y1):
                row = rows.get(y)
                if row is None:
                    row = rows[y] = grid[y, x0:x1].tobytes().decode("utf-32-le")
                out.append(row)
            self._shown = out
        return self._shown
