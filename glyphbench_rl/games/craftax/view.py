"""The Craftax observation: the 9 x 11 glyph grid around the player, the HUD line, and the rules
text of the system prompt.

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

from .mobs import is_boss_vulnerable
from .state import Settings, State
from .tables import (BOSS_LEVEL, DARK_LEVELS, LEVEL_NAMES, LIGHT_VISIBLE, MINING, NIGHT_LIGHT, PLACING,
                     POTION_COLOURS, RECIPES as CRAFTING, Action, BlockType, ItemType,
                     ProjectileType, max_drink, max_energy, max_food, max_health, max_mana)
from .tables import MONSTERS_KILLED_TO_CLEAR_LEVEL as KILLS_TO_OPEN_LADDER

ROWS, COLS = 9, 11                       # upstream's OBS_DIM
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

_NECROMANCER = int(BlockType.NECROMANCER)
_NECROMANCER_VULNERABLE = int(BlockType.NECROMANCER_VULNERABLE)
_VISIBLE_LIGHT32 = np.float32(LIGHT_VISIBLE)      # (light_map is float32: compare as upstream)


def _item_codes(ladder_open: bool) -> bytes:
    """``codes[item]``: the code an item shows as (a closed floor's down ladder: blocked)."""
    codes = [_ITEM0 + i for i in range(len(ItemType))]
    if not ladder_open:
        codes[ItemType.LADDER_DOWN] = _ITEM0 + ItemType.LADDER_DOWN_BLOCKED
    return bytes(codes)


_ITEM_CODES = (_item_codes(False), _item_codes(True))    # by whether the floor's ladder is open
_ROW_STARTS = tuple(range(0, ROWS * COLS, COLS))
_OFF_MAP = bytes((int(BlockType.OUT_OF_BOUNDS),))
_FULL_LIGHT = np.ones(ROWS * COLS, np.float32).tobytes()     # a fully lit window's light map
_INT32 = np.dtype(np.int32)
_LOW = 0 if sys.byteorder == "little" else 3      # (where an int32's low byte is)
_MEMO_SIZE = 4096
# a window's light map (float32 bytes) -> its unlit cells (a byte each, 1: unlit); the light map
# changes only where a torch is placed, and windows recur as the player walks back and forth
_DARKNESS: dict[bytes, bytes] = {}
# cell codes -> the rows of glyphs (``rows``)
_ROWS: dict[bytes, tuple[str, ...]] = {}
_NECROMANCER_BYTES = bytes((_NECROMANCER,)), bytes((_NECROMANCER_VULNERABLE,))


def _low_bytes(array: np.ndarray) -> bytes:
    """The values of a small non-negative integer array (each below 256), one byte each in row
    order (the slow path of ``_codes``, for arrays not kept as the state keeps them)."""
    return array.astype(np.uint8).tobytes()


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


def _codes(state: State) -> bytearray:
    """The window as cell codes, ROWS * COLS bytes row by row. Few numpy calls (on arrays this
    small each costs about as much as the work in it): the window's blocks, items and light are
    each read as bytes once; items and darkness go over the blocks where the window has any,
    then mobs and projectiles (not on unlit cells), then the player."""
    level = state.player_level
    pr, pc = state.player_position.tolist()
    r0, c0 = pr - HALF_R, pc - HALF_C
    rows, cols = state.map.shape[1:]
    ra, rb, ca, cb = max(r0, 0), min(r0 + ROWS, rows), max(c0, 0), min(c0 + COLS, cols)
    if ra < rb and ca < cb:
        # the part of the window on the map: blocks, items over them, darkness over all (a
        # cell is unlit at light <= LIGHT_VISIBLE); most windows have no item and no dark cell
        window = (level, slice(ra, rb), slice(ca, cb))
        blocks, items = state.map[window], state.item_map[window]
        if blocks.dtype == _INT32 and items.dtype == _INT32:     # (as the state keeps them)
            codes, items = blocks.tobytes()[_LOW::4], items.tobytes()[_LOW::4]
        else:
            codes, items = _low_bytes(blocks), _low_bytes(items)
        if items.count(0) != len(items):
            open_ = state.monsters_killed.item(level) >= KILLS_TO_OPEN_LADDER
            if not items.translate(None, _BELOW[4]) and not codes.translate(None, _BELOW[64]):
                codes = _merge(codes, items, 6).translate(_OVERLAYS[open_])
            else:
                codes = bytearray(codes)
                _mark(codes, items, _ITEM_CODES[open_])
        light = state.light_map[window]
        lit = light.tobytes()
        if light.dtype != np.float32 or lit != _FULL_LIGHT[:len(lit)]:
            # (else the window is in full light: nothing dark)
            dark = _DARKNESS.get(lit) if light.dtype == np.float32 else None
            if dark is None:
                dark = np.less_equal(light, _VISIBLE_LIGHT32).tobytes()
                if light.dtype == np.float32:
                    if len(_DARKNESS) >= _MEMO_SIZE:
                        _DARKNESS.clear()
                    _DARKNESS[lit] = dark
            if 1 in dark:
                if not codes.translate(None, _BELOW[128]):
                    codes = _merge(codes, dark, 7).translate(_DARKEN)
                else:
                    codes = bytearray(codes)
                    _mark(codes, dark, _DARK_CODE)
        inside = codes
    else:
        inside = b""
    if len(inside) == ROWS * COLS:
        codes = bytearray(inside)
    else:       # cells off the map: their own glyph, lit
        codes = bytearray(_OFF_MAP * (ROWS * COLS))
        width, at = cb - ca, ca - c0
        for j, r in enumerate(range(ra - r0, rb - r0)):
            codes[r * COLS + at:r * COLS + at + width] = inside[j * width:(j + 1) * width]
    if level == BOSS_LEVEL and _NECROMANCER in codes and is_boss_vulnerable(state):
        codes = codes.replace(*_NECROMANCER_BYTES)
    for k, mobs in enumerate((state.melee_mobs, state.passive_mobs, state.ranged_mobs,
                              state.mob_projectiles, state.player_projectiles)):
        live = mobs.mask[level].tolist()
        if True not in live:
            continue
        base = _MOB0 + 8 * k
        positions, types = mobs.position[level].tolist(), mobs.type_id[level].tolist()
        for slot, on in enumerate(live):
            if on:
                r, c = positions[slot]
                r -= r0
                c -= c0
                if 0 <= r < ROWS and 0 <= c < COLS and codes[r * COLS + c] != _DARK:
                    codes[r * COLS + c] = base + types[slot]
    codes[HALF_R * COLS + HALF_C] = _PLAYER0 + (0 if state.is_sleeping else state.player_direction)
    return codes


def cell_codes(state: State) -> np.ndarray:
    """The window as cell codes (uint8, ROWS x COLS): what each visible cell shows, before the
    glyph lookup (``_TABLE``)."""
    return np.frombuffer(bytes(_codes(state)), np.uint8).reshape(ROWS, COLS).copy()


def rows(state: State) -> tuple[str, ...]:
    """The 9 rows of 11 glyphs around the player, as a tuple (remembered by the cell codes)."""
    codes = bytes(_codes(state))
    shown = _ROWS.get(codes)
    if shown is None:
        text = _charmap_decode(codes, "strict", _DECODING)[0]
        if len(_ROWS) >= _MEMO_SIZE:
            _ROWS.clear()
        shown = _ROWS[codes] = tuple([text[i:i + COLS] for i in _ROW_STARTS])
    return shown


def grid(state: State) -> list[str]:
    """The 9 rows of 11 glyphs around the player."""
    return list(rows(state))


# ---- the HUD -----------------------------------------------------------------------------

TIERS = ("", "wood", "stone", "iron", "diamond")
ARMOUR_TIERS = ("", "iron", "diamond")
ARMOUR_SLOTS = ("helmet", "chest", "legs", "boots")
ENCHANTS = ("", "fire", "ice")
SPELLS = ("fireball", "iceball")
VITALS = ("HP", "Food", "Drink", "Energy", "Mana")
FACING = {Action.LEFT: "left", Action.RIGHT: "right", Action.UP: "up", Action.DOWN: "down"}
# the inventory's countable items, in upstream's symbolic observation order
COUNTED = ("wood", "stone", "coal", "iron", "diamond", "sapphire", "ruby", "sapling", "torches",
           "arrows", "books")
_COUNTED_LABELS = tuple((name, name.capitalize()) for name in COUNTED)


def max_vitals(state: State) -> tuple[int, int, int, int, int]:
    """Upstream's maxima (``tables.max_*``): health 8+str, food/drink/energy 7+2*dex, mana
    6+3*int (dexterity, strength and intelligence start at 1)."""
    dex = state.player_dexterity
    return (max_health(state.player_strength), max_food(dex), max_drink(dex), max_energy(dex),
            max_mana(state.player_intelligence))


def _number(x: float) -> str:
    r = round(x, 1)
    return str(int(r)) if r == int(r) else str(r)


_HUDS: dict[tuple, str] = {}      # everything the HUD reads -> the HUD (``hud``)


def hud(state: State, settings: Settings | None = None) -> str:
    """One line: vitals, inventory, equipment, potions, spells, attributes, floor, position,
    facing, light and rest state; empty parts left out, parts joined by `` | ``. (Remembered by
    the values it reads: most turns change few of them, and a state seen before is common.)"""
    del settings   # (the HUD reads only the state; kept for the engine's call shape)
    inv, level = state.inventory, state.player_level
    key = (state.player_health, state.player_food, state.player_drink, state.player_energy,
           state.player_mana, state.player_strength, state.player_dexterity,
           state.player_intelligence, state.player_xp, inv.wood, inv.stone, inv.coal, inv.iron,
           inv.diamond, inv.sapphire, inv.ruby, inv.sapling, inv.torches, inv.arrows, inv.books,
           inv.pickaxe, inv.sword, inv.bow, state.sword_enchantment, state.bow_enchantment,
           inv.armour.tobytes(), state.armour_enchantments.tobytes(), inv.potions.tobytes(),
           state.learned_spells.tobytes(), level, state.player_position.tobytes(),
           state.player_direction, state.light_level >= NIGHT_LIGHT, state.monsters_killed.tobytes(),
           state.is_sleeping, state.is_resting)
    line = _HUDS.get(key)
    if line is None:
        if len(_HUDS) >= 10_000:
            _HUDS.clear()
        line = _HUDS[key] = _hud(state)
    return line


def _hud(state: State) -> str:
    maxima = max_vitals(state)
    values = (_number(state.player_health), state.player_food, state.player_drink,
              state.player_energy, state.player_mana)
    if len(set(maxima)) == 1:      # (the usual case: every maximum 9) said once
        parts = [" ".join(f"{name} {v}" for name, v in zip(VITALS, values)) + f" (max {maxima[0]})"]
    else:
        parts = [" ".join(f"{name} {v}/{m}" for name, v, m in zip(VITALS, values, maxima))]
    inv = state.inventory
    counted = [f"{label} {n}" for name, label in _COUNTED_LABELS if (n := getattr(inv, name))]
    if counted:
        parts.append(" ".join(counted))
    gear = []
    if inv.pickaxe:
        gear.append(f"{TIERS[inv.pickaxe]} pickaxe")
    if inv.sword:
        gear.append(f"{_enchanted(state.sword_enchantment)}{TIERS[inv.sword]} sword")
    if inv.bow:
        gear.append(f"{_enchanted(state.bow_enchantment)}bow")
    armour = []
    if np.count_nonzero(inv.armour):
        armour = [f"{_enchanted(e)}{ARMOUR_TIERS[t]} {slot}" for slot, t, e in
                  zip(ARMOUR_SLOTS, inv.armour.tolist(), state.armour_enchantments.tolist()) if t]
    if gear or armour:
        parts.append(", ".join(gear + armour))
    if np.count_nonzero(inv.potions):
        parts.append("Potions " + " ".join(
            f"{colour} {n}" for colour, n in zip(POTION_COLOURS, inv.potions.tolist()) if n))
    if np.count_nonzero(state.learned_spells):
        parts.append("Spells " + " ".join(
            name for name, known in zip(SPELLS, state.learned_spells.tolist()) if known))
    levels = [f"{name} {v}" for name, v in (("Dex", state.player_dexterity),
                                              ("Str", state.player_strength),
                                              ("Int", state.player_intelligence)) if v > 1]
    if state.player_xp or levels:
        parts.append(" ".join([f"XP {state.player_xp}", *levels]))
    level = state.player_level
    row, col = state.player_position.tolist()
    where = f"Floor {level} {LEVEL_NAMES[level]} at {row},{col} facing {FACING.get(state.player_direction, '?')}"
    if level == 0:
        where += " Day" if state.light_level >= NIGHT_LIGHT else " Night"
    elif level in DARK_LEVELS:
        where += " dark"
    killed = state.monsters_killed.tolist()[level]
    if level < len(LEVEL_NAMES) - 1 and killed < KILLS_TO_OPEN_LADDER:
        where += f" Kills {killed}/{KILLS_TO_OPEN_LADDER}"
    parts.append(where)
    if state.is_sleeping:
        parts.append("Sleeping")
    elif state.is_resting:
        parts.append("Resting")
    return " | ".join(parts)


def _enchanted(kind: int) -> str:
    return f"{ENCHANTS[kind]} " if kind else ""


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
        items = [f"{'/'.join(names)} {'+'.join(f'{n} {item}' for item, n in cost)}"
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
