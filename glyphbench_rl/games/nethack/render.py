"""From NLE's observation arrays to a glyph grid, its vocabulary and the HUD text.

Light: numpy only (no ``nle``), so the rules here are testable on synthetic arrays.

- **Grid.** NetHack draws on a 21x79 map. We show the bounding box of every cell seen so far in
  the episode; a box wider or taller than the window (``VIEW``)
  is shown as a window of that size around the hero, and the HUD then says where the window is.
- **Glyphs.** NetHack reuses characters (``.`` is floor and doorway, ``d`` a jackal and a coyote).
  A :class:`Glyphs` assigns each (character, description) pair one grid character for the whole
  episode: NetHack's own character while it is free, else one from a pool of spare symbols. So
  the legend never maps one character to two meanings, and a meaning keeps its character.
- **HUD.** Hit points, armour class, hunger and conditions from ``blstats``; the inventory as
  ``letter name`` pairs, shortened (articles, "uncursed", and the long "(weapon in hand)" forms).
"""

from __future__ import annotations

import re
import numpy as np

ROWS, COLS = 21, 79
VIEW = (21, 41)           # (rows, cols): the largest area shown; bigger levels scroll with the hero
BLANK = "░"               # a visible glyph: the grid holds no spaces
BLANK_MEANING = "unexplored, dark or solid rock"
HERO = "you"

# blstats indices (nle.nethack.NLE_BL_*), written out so this module needs no nle import
BL_X, BL_Y, BL_HP, BL_HPMAX, BL_DEPTH, BL_AC, BL_TIME, BL_HUNGER, BL_CONDITION = 0, 1, 10, 11, 12, 16, 20, 21, 25
BL_GOLD, BL_ENERGY, BL_ENERGYMAX, BL_XP = 13, 14, 15, 18
HUNGER = ("Satiated", "", "Hungry", "Weak", "Fainting", "Fainted", "Starved")   # NetHack's u.uhs
# NLE's condition bits (BL_MASK_*), in NetHack's order
CONDITIONS = ((0x1, "Stone"), (0x2, "Slime"), (0x4, "Strangled"), (0x8, "FoodPois"), (0x10, "Ill"),
              (0x20, "Blind"), (0x40, "Deaf"), (0x80, "Stun"), (0x100, "Conf"), (0x200, "Hallu"),
              (0x400, "Lev"), (0x800, "Fly"), (0x1000, "Ride"))

# features whose NetHack character is shared with a commoner one get their own, always
PREFERRED = {"doorway": "·", "broken door": "·", "open door": "'", "dark part of a room": ",",
             "tree": "τ", "water": "~", "molten lava": "≈", "iron bars": "¦"}
# spare single-width symbols for a meaning whose NetHack character is taken
SPARE = "¤§µøßðþæ¢£¥ΩΣΔΘΛΞΠΦΨλπφψ±×÷¬¿¡ÆØÞ"

_SHORTEN = ((re.compile(r"^(?:an?|the) "), ""), (re.compile(r"\buncursed "), ""),
            (re.compile(r" \(weapons? in hands?\)"), " (wielded)"),
            (re.compile(r" \(being worn\)"), " (worn)"),
            (re.compile(r" \(alternate weapon; not wielded\)"), " (alternate)"),
            (re.compile(r" \(in quiver(?: pouch)?\)"), " (quivered)"),
            (re.compile(r" \(on (?:left|right) hand\)"), " (worn)"))


def text(row: np.ndarray) -> str:
    """A NUL-padded byte row as text."""
    return row.tobytes().split(b"\0", 1)[0].decode("latin-1").strip()


def item_name(s: str) -> str:
    for pattern, repl in _SHORTEN:
        s = pattern.sub(repl, s)
    return s


def inventory(letters: np.ndarray, strs: np.ndarray) -> list[tuple[str, str]]:
    """``(letter, short name)`` for each inventory slot in use."""
    out = []
    for letter, s in zip(letters.tolist(), strs):
        if not letter:
            break
        out.append((chr(letter), item_name(text(s))))
    return out


def status(blstats: np.ndarray, hp_only: bool = False) -> str:
    """HUD fields from blstats: ``HP 12/12 AC 7 Lev`` (hunger and conditions only when set)."""
    b = blstats.tolist()
    parts = [f"HP {b[BL_HP]}/{b[BL_HPMAX]}"]
    if not hp_only:
        parts.append(f"AC {b[BL_AC]}")
    hunger = b[BL_HUNGER]
    if 0 <= hunger < len(HUNGER) and HUNGER[hunger]:
        parts.append(HUNGER[hunger])
    cond = b[BL_CONDITION]
    parts.extend(name for bit, name in CONDITIONS if cond & bit)
    return " ".join(parts)


def describe(description: str, hero: bool) -> str:
    """The legend text of a cell's screen description."""
    if hero:
        return HERO
    return description or BLANK_MEANING


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

    def see(self, chars: np.ndarray) -> None:
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
    """The shown rows, each NetHack (glyph, description) drawn as the episode's character for it."""
    y0, y1, x0, x1 = bounds
    ids = glyphs[y0:y1, x0:x1]
    uniq, first, inverse = np.unique(ids, return_index=True, return_inverse=True)
    width = x1 - x0
    hy, hx = hero[1] - y0, hero[0] - x0
    codes = np.empty(len(uniq), dtype=np.uint32)
    sub_chars = chars[y0:y1, x0:x1]
    for k, flat in enumerate(first.tolist()):
        y, x = divmod(flat, width)
        nh = int(sub_chars[y, x])
        meaning = describe(text(descriptions[y0 + y, x0 + x]), (y, x) == (hy, hx)) if nh != 32 else BLANK_MEANING
        codes[k] = ord(assign.char(nh, meaning))
    cells = codes[inverse.reshape(ids.shape)]
    return [row.tobytes().decode("utf-32-le") for row in np.ascontiguousarray(cells)]

