"""The Craftax observation: the 9 x 11 glyph grid around the player, and the rules text of the
system prompt (the HUD line is ``hud``'s).

What is visible follows upstream's symbolic observation (``render_craftax_symbolic``): the
window is upstream's ``OBS_DIM`` (9 rows, 11 columns) centred on the player; a cell whose
``light_map`` value is at most 0.05 shows nothing (blocks, items and mobs alike) and is drawn as
the darkness glyph. On the overworld the light map is all ones, so night hides nothing there
(upstream's symbolic observation only reports the light level; the HUD says Day or Night).
Two deliberate differences from upstream's window: a cell outside the map has its own glyph
(upstream's padding is unlit, so it shows as darkness), and the player's own cell is always
drawn. Drawing order is upstream's renderer's: block, item over it, mobs, projectiles, and
the two substitutions it makes (a down ladder is shown blocked until the floor's kill count
reaches 8; the necromancer is shown vulnerable when no melee or ranged mob is on its floor and
its summoning wave is over; only on the graveyard, the one floor where upstream lets it be hit).

Every glyph has exactly one meaning (``VOCAB``, glyph -> meaning, in legend order).
Lower-case letters are mobs; upper-case letters and most ASCII symbols are terrain and items;
projectiles are ``/ ) ' (`` and a few non-ASCII symbols; arrows (or ``@`` asleep) are the player.
"""

from __future__ import annotations

import sys
from codecs import charmap_decode as _charmap_decode

import numpy as np

from .hud import TIERS
from .mobs import is_boss_vulnerable
from .state import OBS_DIM, State
from .tables import (BOSS_LEVEL, LIGHT_VISIBLE, MINING, PLACING, RECIPES as CRAFTING, Action,
                     BlockType, ItemType, ProjectileType)
from .tables import MONSTERS_KILLED_TO_CLEAR_LEVEL as KILLS_TO_OPEN_LADDER

ROWS, COLS = OBS_DIM                     # upstream's OBS_DIM
HALF_R, HALF_C = ROWS // 2, COLS // 2
# (the level names, dark levels, the kills that open a ladder and the light a cell needs to be
# seen are tables.py's)

# ---- glyphs ------------------------------------------------------------------------------

BLOCK_GLYPHS: dict[BlockType, tuple[str, str]] = {
    BlockType.INVALID: ("?", "invalid block"),
    BlockType.OUT_OF_BOUNDS: ("%", "outside the map"),
    BlockType.GRASS: (".", "grass"),
    BlockType.WATER: ("~", "water"),
    BlockType.STONE: ("#", "stone"),
    BlockType.TREE: ("T", "tree"),
    BlockType.WOOD: ("W", "wood block"),
    BlockType.PATH: ("_", "path"),
    BlockType.COAL: ("C", "coal"),
    BlockType.IRON: ("I", "iron"),
    BlockType.DIAMOND: ("D", "diamond"),
    BlockType.CRAFTING_TABLE: ("+", "crafting table"),
    BlockType.FURNACE: ("F", "furnace"),
    BlockType.SAND: (":", "sand"),
    BlockType.LAVA: ("L", "lava"),
    BlockType.PLANT: (";", "sapling (unripe)"),
    BlockType.RIPE_PLANT: ("P", "ripe plant"),
    BlockType.WALL: ("=", "wall"),
    BlockType.DARKNESS: ("X", "void (solid)"),
    BlockType.WALL_MOSS: ("&", "mossy wall"),
    BlockType.STALAGMITE: ("^", "stalagmite"),
    BlockType.SAPPHIRE: ("S", "sapphire"),
    BlockType.RUBY: ("R", "ruby"),
    BlockType.CHEST: ("$", "chest"),
    BlockType.FOUNTAIN: ("O", "fountain"),
    BlockType.FIRE_GRASS: (",", "fire grass"),
    BlockType.ICE_GRASS: ("*", "ice grass"),
    BlockType.GRAVEL: ("\"", "gravel"),
    BlockType.FIRE_TREE: ("Y", "fire tree"),
    BlockType.ICE_SHRUB: ("V", "ice shrub"),
    BlockType.ENCHANTMENT_TABLE_FIRE: ("E", "fire enchant table"),
    BlockType.ENCHANTMENT_TABLE_ICE: ("U", "ice enchant table"),
    BlockType.NECROMANCER: ("N", "necromancer (shielded)"),
    BlockType.GRAVE: ("G", "grave"),
    BlockType.GRAVE2: ("H", "grave (cross)"),
    BlockType.GRAVE3: ("J", "grave (tomb)"),
    BlockType.NECROMANCER_VULNERABLE: ("!", "necromancer (vulnerable)"),
}
ITEM_GLYPHS: dict[ItemType, tuple[str, str]] = {
    ItemType.TORCH: ("|", "torch"),
    ItemType.LADDER_DOWN: (">", "ladder down"),
    ItemType.LADDER_UP: ("<", "ladder up"),
    ItemType.LADDER_DOWN_BLOCKED: ("]", "ladder down (locked)"),
}
DARK = ("-", "dark")
PLAYER_GLYPHS: dict[int, tuple[str, str]] = {     # by player_direction; 0 = asleep
    Action.LEFT: ("←", "you (facing left)"),
    Action.RIGHT: ("→", "you (facing right)"),
    Action.UP: ("↑", "you (facing up)"),
    Action.DOWN: ("↓", "you (facing down)"),
    0: ("@", "you (asleep)"),
}
# mobs by class and type_id: upstream's texture lists (melee / passive / ranged)
MELEE_GLYPHS = (("z", "zombie"), ("g", "gnome warrior"), ("o", "orc soldier"), ("l", "lizard"),
                ("n", "knight"), ("t", "troll"), ("p", "pigman"), ("f", "frost troll"))
PASSIVE_GLYPHS = (("c", "cow"), ("b", "bat"), ("s", "snail"))
RANGED_GLYPHS = (("k", "skeleton"), ("a", "gnome archer"), ("m", "orc mage"), ("q", "kobold"),
                 ("r", "knight archer"), ("d", "deep thing"), ("e", "fire elemental"),
                 ("i", "ice elemental"))
# projectiles by owner and kind; upstream draws ARROW/ARROW2, FIREBALL/FIREBALL2 and
# ICEBALL/ICEBALL2 with one texture each, so a kind covers both members of a pair
PROJECTILE_KINDS = ("arrow", "dagger", "fireball", "iceball", "slimeball")
PROJECTILE_KIND = {ProjectileType.ARROW: 0, ProjectileType.ARROW2: 0, ProjectileType.DAGGER: 1,
                   ProjectileType.FIREBALL: 2, ProjectileType.FIREBALL2: 2,
                   ProjectileType.ICEBALL: 3, ProjectileType.ICEBALL2: 3,
                   ProjectileType.SLIMEBALL: 4}
MOB_PROJECTILE_GLYPHS = (("/", "enemy arrow"), (")", "enemy dagger"), ("°", "enemy fireball"),
                         ("×", "enemy iceball"), ("§", "enemy slimeball"))
PLAYER_PROJECTILE_GLYPHS = (("'", "your arrow"), ("(", "your dagger"), ("•", "your fireball"),
                            ("±", "your iceball"), ("·", "your slimeball"))


def _vocabulary() -> dict[str, str]:
    entries = [*PLAYER_GLYPHS.values(), *MELEE_GLYPHS, *PASSIVE_GLYPHS, *RANGED_GLYPHS,
               *MOB_PROJECTILE_GLYPHS, *PLAYER_PROJECTILE_GLYPHS, *ITEM_GLYPHS.values(),
               *BLOCK_GLYPHS.values(), DARK]
    vocab = dict(entries)
    assert len(vocab) == len(entries), "a glyph with two meanings"
    assert len(set(vocab.values())) == len(entries), "two glyphs with one meaning"
    return vocab


VOCAB: dict[str, str] = _vocabulary()     # glyph -> meaning, legend order

# cell codes (one byte per cell)
_ITEM0 = len(BlockType)                               # item i -> _ITEM0 + i
_DARK = _ITEM0 + len(ItemType)
_PLAYER0 = _DARK + 1                                  # direction d -> _PLAYER0 + d (0 asleep)
_MOB0 = _PLAYER0 + 5                                  # class k, type t -> _MOB0 + 8k + t
_CLASSES = 5                                          # melee, passive, ranged, mob/player shots
_NEWLINE = 255                                        # the code of a row's end
assert _MOB0 + 8 * _CLASSES <= _NEWLINE


def _translation() -> dict[int, str]:
    table = {int(b): g for b, (g, _) in BLOCK_GLYPHS.items()}
    table[_NEWLINE] = "\n"
    table.update({_ITEM0 + int(i): g for i, (g, _) in ITEM_GLYPHS.items()})
    table[_DARK] = DARK[0]
    table.update({_PLAYER0 + int(d): g for d, (g, _) in PLAYER_GLYPHS.items()})
    for k, glyphs in enumerate((MELEE_GLYPHS, PASSIVE_GLYPHS, RANGED_GLYPHS)):
        table.update({_MOB0 + 8 * k + t: g for t, (g, _) in enumerate(glyphs)})
    for k, glyphs in ((3, MOB_PROJECTILE_GLYPHS), (4, PLAYER_PROJECTILE_GLYPHS)):
        table.update({_MOB0 + 8 * k + int(t): glyphs[kind][0] for t, kind in PROJECTILE_KIND.items()})
    return table


_TABLE = _translation()
# the same as a 256-character decoding table: codecs' charmap decoder turns the codes into the
# glyphs in one C call (ten times faster than str.translate with a dict); "\ufffe" marks an
# unused code (decoding one raises)
_DECODING = "".join(_TABLE.get(code, "\ufffe") for code in range(256))


# ---- the grid ----------------------------------------------------------------------------
#
# The grid is drawn every step, and numpy's calls cost more than the work on 99 cells, so the
# window is read in as few calls as possible and what did not change is not worked out again.
# The window lies in a band of the player's level (its rows, at full width); the band's blocks,
# items and light are read as three byte strings through memoryviews of the state's arrays
# (no numpy call) and compared with the band read last time. Only when a byte differs are the
# band's cell codes worked out again (items over blocks, darkness over both); the window, the
# player drawn in it, is cut from them and decoded once per column offset and facing. Mobs and
# projectiles are read each time from their slot lists (``_mob_codes``): they move every
# step. What is remembered is a function of the bytes just read (and the ladder's state); the
# views are kept per state (``_kept``) while it holds the same arrays, so a cell edited in
# place, or a whole array replaced, shows at once.

_NECROMANCER = int(BlockType.NECROMANCER)
_NECROMANCER_VULNERABLE = int(BlockType.NECROMANCER_VULNERABLE)
_VISIBLE_LIGHT32 = np.float32(LIGHT_VISIBLE)      # (light_map is float32: compare as upstream)
_LADDER_DOWN = int(ItemType.LADDER_DOWN)


def _item_codes(ladder_open: bool) -> bytes:
    """``codes[item]``: the code an item shows as (a closed floor's down ladder: blocked)."""
    codes = [_ITEM0 + i for i in range(len(ItemType))]
    if not ladder_open:
        codes[ItemType.LADDER_DOWN] = _ITEM0 + ItemType.LADDER_DOWN_BLOCKED
    return bytes(codes)


_ITEM_CODES = (_item_codes(False), _item_codes(True))    # by whether the floor's ladder is open
_OFF_MAP = int(BlockType.OUT_OF_BOUNDS)
_CENTRE = HALF_R * COLS + HALF_C                  # the player's cell in the window
_ROW_STARTS = tuple(range(0, ROWS * COLS, COLS))
_FULL_LIGHT = np.float32(1).tobytes()             # one fully lit cell's light
_LOW = 0 if sys.byteorder == "little" else 3      # (where an int32's low byte is)
_MEMO_SIZE = 4096
# a band's light map (float32 bytes) -> its unlit cells (a byte each, 1: unlit); the light map
# changes only where a torch is placed, and bands recur as the player walks back and forth
_DARKNESS: dict[bytes, bytes] = {}
_NECROMANCER_BYTES = bytes((_NECROMANCER,)), bytes((_NECROMANCER_VULNERABLE,))


def _mark(codes: bytearray, where: bytes, code) -> None:
    """``codes[i] = code[where[i]]`` wherever ``where[i]`` is not 0 (a few cells: found by
    ``bytes.find``, value by value)."""
    for value in set(where):
        if value:
            to = code[value]
            i = where.find(value)
            while i >= 0:
                codes[i] = to
                i = where.find(value, i + 1)


_DARK_CODE = bytes([0] + [_DARK] * 255)      # (``_mark``'s value -> code for a dark cell)


def _overlay(ladder_open: bool) -> bytes:
    """A translation table from ``item << 6 | block`` (an item below 4, a block below 64) to the
    code the cell shows: the block, or the item over it."""
    shown = _ITEM_CODES[ladder_open]
    return bytes(block if item == 0 else shown[item] for item in range(4) for block in range(64))


_OVERLAYS = (_overlay(False), _overlay(True))
_BELOW = {n: bytes(range(n)) for n in (4, 64, 128)}     # (what ``translate`` deletes: values below n)
# code | dark << 7 (a code below 128) -> the code, or darkness where dark
_DARKEN = bytes(range(128)) + bytes((_DARK,)) * 128


def _merge(low: bytes, high: bytes, shift: int) -> bytes:
    """``low[i] | high[i] << shift`` for each byte (no bit carried into the next byte: the
    caller keeps the sum below 256), as one big-int operation in C."""
    return (int.from_bytes(low, "little") | int.from_bytes(high, "little") << shift).to_bytes(
        len(low), "little")


def _is_usual(blocks: np.ndarray, items: np.ndarray, light: np.ndarray) -> bool:
    """Whether the three maps are kept as the state keeps them (int32, int32, float32, one
    shape, C order): then their memory is read as it is."""
    return (blocks.dtype == np.int32 and items.dtype == np.int32 and light.dtype == np.float32
            and blocks.ndim == 3 and blocks.shape == items.shape == light.shape
            and blocks.flags.c_contiguous and items.flags.c_contiguous
            and light.flags.c_contiguous)


def _byte_views(blocks: np.ndarray, items: np.ndarray, light: np.ndarray) -> tuple:
    """Flat byte memoryviews of the three maps (in the usual layout), then rows and columns, and
    a dict for ``_band_views``."""
    return (memoryview(blocks).cast("B"), memoryview(items).cast("B"),
            memoryview(light).cast("B"), *blocks.shape[1:], {})


def _band_views(maps: tuple, level: int, r0: int) -> tuple:
    """Views of the band the window whose top row is ``r0`` lies in (its rows on the map of
    ``level``, at full width) in the three maps, kept in ``maps``' last member: slicing anew
    each step measured slower than looking them up."""
    blocks, items, light, rows, cols, known = maps
    ra, rb = max(r0, 0), min(r0 + ROWS, rows)
    start = end = 0
    if ra < rb:
        start, end = (level * rows + ra) * cols * 4, (level * rows + rb) * cols * 4
    if len(known) >= _MEMO_SIZE:
        known.clear()
    views = known[level, r0] = (blocks[start:end], items[start:end], light[start:end])
    return views


# what the view keeps for a state, by the id of its map array (``_kept``); several states are
# drawn in turn when a process steps many episodes
_KEPT: dict[int, list] = {}
_KEPT_STATES = 64


def _kept(state: State) -> list:
    """What the view keeps for a state: ``[map, item_map, light_map, their _byte_views, the band
    read last]``, kept while the state holds the same
    three maps (the views see every edit in place; a replaced array is another object, and all
    is made anew). Maps in another layout are read through copies in the usual one, made each
    time and not kept: blocks and items as int32 (their low byte, the code, is unchanged), the
    light as 0 where unlit and 1 where lit (all the view reads of it)."""
    blocks, items, light = state.map, state.item_map, state.light_map
    kept = _KEPT.get(id(blocks))       # (an entry keeps its map alive: its id is not reused)
    if kept is not None and kept[1] is items and kept[2] is light:
        return kept
    if _is_usual(blocks, items, light):
        if len(_KEPT) >= _KEPT_STATES:
            _KEPT.clear()
        kept = _KEPT[id(blocks)] = [blocks, items, light, _byte_views(blocks, items, light), None]
        return kept
    lit = np.where(light <= _VISIBLE_LIGHT32, np.float32(0), np.float32(1))
    views = _byte_views(np.ascontiguousarray(blocks, np.int32), np.ascontiguousarray(items, np.int32),
                        np.ascontiguousarray(lit, np.float32))
    return [None, None, None, views, None]


class _Band:
    """The band of the map the window lies in (rows ``ra`` to ``rb`` of the player's level, at
    full width) as last read: its bytes, its cell codes (the block, or the item over it, or
    darkness) and the windows cut from them."""

    __slots__ = ("where", "raw", "ladder", "open", "necromancer", "codes", "windows")

    def __init__(self, where: tuple, raw: tuple[bytes, bytes, bytes], killed: int) -> None:
        self.where, self.raw = where, raw      # where: (r0, rows, cols); raw: blocks, items, light
        blocks, items, light = raw
        codes, items = blocks[_LOW::4], items[_LOW::4]
        self.ladder = _LADDER_DOWN in items    # (its glyph depends on the floor's kills)
        self.open = self.ladder and killed >= KILLS_TO_OPEN_LADDER
        if items.count(0) != len(items):
            if not items.translate(None, _BELOW[4]) and not codes.translate(None, _BELOW[64]):
                codes = _merge(codes, items, 6).translate(_OVERLAYS[self.open])
            else:
                codes = bytearray(codes)
                _mark(codes, items, _ITEM_CODES[self.open])
        if light != _FULL_LIGHT * (len(light) // 4):     # (else fully lit: nothing dark)
            dark = _DARKNESS.get(light)
            if dark is None:
                dark = np.less_equal(np.frombuffer(light, np.float32), _VISIBLE_LIGHT32).tobytes()
                if len(_DARKNESS) >= _MEMO_SIZE:
                    _DARKNESS.clear()
                _DARKNESS[light] = dark
            if 1 in dark:
                if not codes.translate(None, _BELOW[128]):
                    codes = _merge(codes, dark, 7).translate(_DARKEN)
                else:
                    codes = bytearray(codes)
                    _mark(codes, dark, _DARK_CODE)
        self.codes = bytes(codes)
        self.necromancer = _NECROMANCER in self.codes      # (its glyph depends on the fight)
        # (column offset, player's code, necromancer vulnerable) -> the window's codes and rows
        self.windows: dict[tuple[int, int, bool], tuple[bytes, tuple[str, ...] | None]] = {}

    def window(self, c0: int, player: int, vulnerable: bool) -> tuple[bytes, tuple[str, ...] | None]:
        """The window's codes (columns ``c0`` on, the player's code in the middle, the
        necromancer shown vulnerable or not) and its rows of glyphs (None if a code has no
        glyph), kept in ``windows``."""
        codes = self._cut(c0, player)
        if vulnerable:
            codes = codes.replace(*_NECROMANCER_BYTES)
        window = self.windows[c0, player, vulnerable] = (codes, _decode(codes))
        return window

    def _cut(self, c0: int, player: int) -> bytes:
        r0, rows, cols = self.where
        band = self.codes
        if 0 <= c0 <= cols - COLS and len(band) == ROWS * cols:
            # (the usual window, all on the map: its rows cut from the band, nothing to pad)
            codes = bytearray(b"".join([band[i:i + COLS] for i in range(c0, len(band), cols)]))
            codes[_CENTRE] = player
            return bytes(codes)
        ca, cb = max(c0, 0), min(c0 + COLS, cols)
        off = bytes((_OFF_MAP,))
        left, right = off * (ca - c0), off * (c0 + COLS - cb)      # cells off the map: their glyph
        inside = [left + band[i + ca:i + cb] + right for i in range(0, len(band), cols)] \
            if ca < cb else [off * COLS] * (len(band) // cols if cols else 0)
        codes = bytearray(off * (COLS * min(max(0, -r0), ROWS)))
        codes += b"".join(inside)
        codes += off * (ROWS * COLS - len(codes))
        codes[_CENTRE] = player
        return bytes(codes)


def _decode(codes: bytes) -> tuple[str, ...] | None:
    """The rows of glyphs the codes show; None when one has no glyph (decoding raises)."""
    try:
        text = _charmap_decode(codes, "strict", _DECODING)[0]
    except UnicodeDecodeError:
        return None
    return tuple([text[i:i + COLS] for i in _ROW_STARTS])


def _mob_codes(state: State, level: int, r0: int, c0: int) -> list[tuple[int, int, int]]:
    """(row, column, code) in the window whose top left cell is ``(r0, c0)`` of every live mob
    and projectile of the level inside it, in drawing order (melee, passive and ranged mobs,
    the mobs' projectiles, the player's: a later one is drawn over an earlier). The one place
    the view reads the mob slots."""
    marks = []
    base = _MOB0            # the class's first code: 8 codes a class
    for mobs in (state.melee_mobs, state.passive_mobs, state.ranged_mobs,
                 state.mob_projectiles, state.player_projectiles):
        live = mobs.mask[level]
        if True in live:
            positions, types = mobs.position[level], mobs.type_id[level]
            for slot, on in enumerate(live):
                if on:
                    row, col = positions[slot]
                    r, c = row - r0, col - c0
                    if 0 <= r < ROWS and 0 <= c < COLS:
                        marks.append((r, c, base + types[slot]))
        base += 8
    return marks


def _window(state: State) -> tuple[bytes, tuple[str, ...] | None, list[tuple[int, int, int]]]:
    """The window's codes and rows before mobs (blocks, items over them, darkness over both,
    the necromancer as it shows, the player), and the mobs to draw over them (``_mob_codes``)."""
    level = state.player_level
    pr, pc = state.player_position.tolist()
    r0, c0 = pr - HALF_R, pc - HALF_C
    kept = _KEPT.get(id(state.map))
    if kept is None or kept[1] is not state.item_map or kept[2] is not state.light_map:
        kept = _kept(state)
    maps = kept[3]
    band_views = maps[5].get((level, r0))
    if band_views is None:
        band_views = _band_views(maps, level, r0)
    blocks, items, light = band_views
    where = (r0, maps[3], maps[4])
    band = kept[4]
    # (the band as last read, if it is at the same rows and its bytes are the maps' now: each
    # compared where it lies, ``startswith`` of a view as long as the bytes, without a copy)
    if band is None or band.where != where or not (
            band.raw[0].startswith(blocks) and band.raw[1].startswith(items)
            and band.raw[2].startswith(light)) or (
            band.ladder and band.open != (state.monsters_killed.item(level) >= KILLS_TO_OPEN_LADDER)):
        band = kept[4] = _Band(where, (blocks.tobytes(), items.tobytes(), light.tobytes()),
                               state.monsters_killed.item(level))
    key = (c0, _PLAYER0 + (0 if state.is_sleeping else state.player_direction),
           level == BOSS_LEVEL and band.necromancer and is_boss_vulnerable(state))
    window = band.windows.get(key) or band.window(*key)
    return window[0], window[1], _mob_codes(state, level, r0, c0)


def _drawn(codes: bytes, marks: list[tuple[int, int, int]]) -> bytes:
    """The codes with the mobs drawn over them (not on unlit cells, not on the player)."""
    shown = bytearray(codes)
    for r, c, code in marks:
        i = r * COLS + c
        if codes[i] != _DARK and i != _CENTRE:
            shown[i] = code
    return bytes(shown)


def cell_codes(state: State) -> np.ndarray:
    """The window as cell codes (uint8, ROWS x COLS): what each visible cell shows, before the
    glyph lookup (``_TABLE``)."""
    codes, _, marks = _window(state)
    return np.frombuffer(_drawn(codes, marks), np.uint8).reshape(ROWS, COLS).copy()


def rows(state: State) -> tuple[str, ...]:
    """The 9 rows of 11 glyphs around the player, as a tuple: the window's rows as cut (kept
    with the band), the glyphs of the mobs in view put in."""
    codes, shown, marks = _window(state)
    if shown is None:      # (a code with no glyph: decoding the drawn window raises, or not)
        text = _charmap_decode(_drawn(codes, marks), "strict", _DECODING)[0]
        return tuple([text[i:i + COLS] for i in _ROW_STARTS])
    if marks:
        last = _last_drawn
        if shown is last[0] and marks == last[1]:    # (the same window and mobs as last time)
            return last[2]
        lines = list(shown)
        for r, c, code in marks:
            i = r * COLS + c
            if codes[i] != _DARK and i != _CENTRE:
                glyph = _DECODING[code]
                if glyph == "\ufffe":       # (no glyph: decoding raises, as it always did)
                    _charmap_decode(_drawn(codes, marks), "strict", _DECODING)
                line = lines[r]
                lines[r] = line[:c] + glyph + line[c + 1:]
        last[:] = shown, marks, tuple(lines)
        shown = last[2]
    return shown


_last_drawn: list = [None, None, None]     # the window's rows, the mobs drawn, the rows drawn


def grid(state: State) -> list[str]:
    """The 9 rows of 11 glyphs around the player."""
    return list(rows(state))


# ---- the rules text ----------------------------------------------------------------------

# (action name, cost, needs a crafting table nearby, needs a furnace nearby), from tables.py's
# RECIPES (made at a table, some also at a furnace) and PLACING (anywhere)
RECIPES: tuple[tuple[str, dict[str, int], bool, bool], ...] = (
    *((action.name, dict(recipe.cost), True, recipe.furnace)
      for action, recipe in CRAFTING.items()),
    *((action.name, {item: cost}, False, False) for action, (item, cost, _, _) in PLACING.items()),
)
# the pickaxe tier each mined block needs (0: none), from tables.py's MINING, lowest tier first
# (the stations, which DO only removes, left out)
MINING_TIERS = tuple(sorted(((block, tier) for block, (tier, item, _) in MINING.items()
                             if item is not None), key=lambda pair: pair[1]))


# inventory fields named in the plural, for a count of one
_SINGULAR = {"torches": "torch", "arrows": "arrow", "books": "book"}


def _count(n: int, item: str) -> str:
    """``n`` of an inventory field: ``2 wood``, ``1 torch``."""
    return f"{n} {_SINGULAR.get(item, item) if n == 1 else item}"


def _recipe_lines(recipes) -> list[str]:
    """Recipes grouped by where they are made, those with equal costs merged:
    ``table: wood pickaxe/wood sword 1 wood; ...``."""
    places: dict[str, dict[tuple, list[str]]] = {}
    for name, cost, table, furnace in recipes:
        place = "table+furnace" if table and furnace else "table" if table else \
            "furnace" if furnace else "anywhere"
        what = name.lower().removeprefix("make_").replace("_", " ")
        places.setdefault(place, {}).setdefault(tuple(cost.items()), []).append(what)
    lines = []
    for place, groups in places.items():
        items = [f"{'/'.join(names)} {'+'.join(_count(n, item) for item, n in cost)}"
                 for cost, names in groups.items()]
        lines.append(f"{place}: " + "; ".join(items))
    return lines


def rules_text(recipes=RECIPES, mining=MINING_TIERS, topics=("craft", "floors"),
               drains: bool = True) -> str:
    """The rules section of the Craftax system prompt, generated from the tables: the view and
    DO always; the mining tiers and the recipes with ``"craft"`` in ``topics``; the vitals when
    ``drains`` (the intrinsics are on); the ladders with ``"floors"``."""
    lines = ["The view is 9x11 around you; your arrow shows your facing; positions are row,col. "
             "DO acts on the faced cell: mine, attack, eat (cow, ripe plant), drink water, open a chest."]
    if "craft" in topics:
        by_tier: dict[int, list[str]] = {}
        for block, tier in mining:
            by_tier.setdefault(tier, []).append(BLOCK_GLYPHS[block][1])
        tiers = "; ".join(f"{TIERS[t] + ' pickaxe' if t else 'no tool'}: {', '.join(names)}"
                          for t, names in sorted(by_tier.items()))
        lines += [f"Mining needs {tiers}.",
                  "Crafting and placing (table, furnace: one must be among your 8 neighbours):",
                  *_recipe_lines(recipes)]
    if drains:
        lines.append("Food, drink and energy drop over time; at 0 they cost HP, when all are up "
                     "HP regrows. SLEEP restores energy.")
    if "floors" in topics:
        lines.append(f"A ladder down (>) opens after {KILLS_TO_OPEN_LADDER} kills on its floor (] "
                     "until then). On dark floors only lit cells show.")
    return "\n".join(lines)
