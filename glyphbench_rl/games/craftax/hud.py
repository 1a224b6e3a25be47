"""The Craftax HUD: one line of vitals, inventory, equipment, potions, spells, attributes, floor,
position, facing, light and rest state (``hud``; ``_hud`` is the same line written out with
nothing remembered; ``packed_hud`` the same line read from the packed state, ``packed``). The
grid is ``view``'s.
"""

from __future__ import annotations

import numpy as np

from .packed import (ARMOUR, ARMOUR_ENCH, BOW_ENCH, COL, DEX, DIRECTION, DRINK, ENERGY, FOOD,
                     HEALTH, HUD_RANGES, INT, INV, INVENTORY, KILLED, LEVEL, LIGHT, MANA,
                     POTIONS, RESTING, ROW, SLEEPING, STR, SWORD_ENCH, XP, Packed)
from .packed import SPELLS as _SPELLS      # (``SPELLS`` here: the spells' names)
from .state import NUM_LEVELS, Settings, State
from .tables import (DARK_LEVELS, LEVEL_NAMES, NIGHT_LIGHT, POTION_COLOURS, Action, max_drink,
                     max_energy, max_food, max_health, max_mana)
from .tables import MONSTERS_KILLED_TO_CLEAR_LEVEL as KILLS_TO_OPEN_LADDER

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
    return _maxima(state.player_strength, state.player_dexterity, state.player_intelligence)


def _maxima(strength: int, dex: int, intelligence: int) -> tuple[int, int, int, int, int]:
    return (max_health(strength), max_food(dex), max_drink(dex), max_energy(dex),
            max_mana(intelligence))


def _number(x: float) -> str:
    r = round(x, 1)
    return str(int(r)) if r == int(r) else str(r)


# The HUD is made every step. It is ``head | place[ | rest]``: the head is the vitals (which
# change on many turns, in a fight to values not seen before) and the kit (inventory, gear,
# potions, spells, attributes: few turns); the place (floor, position, facing, light, kills)
# changes on most turns, but only in its position. ``hud`` reads everything each time (an
# edited state shows at once) into one key of the parts' keys: the same key as last turn's
# gives last turn's line; otherwise each part is remade only when what it reads was not seen
# before, and the place's text around the position likewise.
_VITALS: dict[tuple, str] = {}     # what the vitals read -> their text
_KITS: dict[tuple, str] = {}       # what the kit reads -> its text ("" for none)
_PLACES: dict[tuple, tuple[str, str]] = {}   # floor, facing, daylight, kills -> text around the position
# last turn's vitals key, vitals, kit key, kit, place key, place, the whole key, the line
_last: list = [None, "", None, "", None, ("", ""), None, ""]


def hud(state: State, settings: Settings | None = None) -> str:
    """One line: vitals, inventory, equipment, potions, spells, attributes, floor, position,
    facing, light and rest state; empty parts left out, parts joined by `` | ``. (Its parts
    are remembered by the values they read, see above.)"""
    del settings   # (the HUD reads only the state; kept for the engine's call shape)
    inv, last, level = state.inventory, _last, state.player_level
    strength, dex, intelligence = (state.player_strength, state.player_dexterity,
                                   state.player_intelligence)
    vitals_key = (state.player_health, state.player_food, state.player_drink,
                  state.player_energy, state.player_mana, strength, dex, intelligence)
    kit_key = (state.player_xp, strength, dex, intelligence, inv.wood, inv.stone, inv.coal,
               inv.iron, inv.diamond, inv.sapphire, inv.ruby, inv.sapling, inv.torches,
               inv.arrows, inv.books, inv.pickaxe, inv.sword, inv.bow, state.sword_enchantment,
               state.bow_enchantment, inv.armour.tobytes(), state.armour_enchantments.tobytes(),
               inv.potions.tobytes(), state.learned_spells.tobytes())
    place_key = (level, state.player_direction, state.light_level >= NIGHT_LIGHT,
                 state.monsters_killed.item(level))
    key = (vitals_key, kit_key, place_key, state.player_position.tolist(), state.is_sleeping,
           state.is_resting)
    if key == last[6]:      # (most turns: nothing the line shows changed)
        return last[7]
    if vitals_key == last[0]:
        vitals = last[1]
    else:
        vitals = _remembered(_VITALS, vitals_key, _vitals, *vitals_key)
        last[0], last[1] = vitals_key, vitals
    if kit_key == last[2]:
        kit = last[3]
    else:
        kit = _KITS.get(kit_key)
        if kit is None:
            kit = _keep(_KITS, kit_key, _kit(*_kit_values(state)))
        last[2], last[3] = kit_key, kit
    if place_key == last[4]:
        before, after = last[5]
    else:
        place = _remembered(_PLACES, place_key, _place, *place_key)
        last[4], last[5] = place_key, place
        before, after = place
    row, col = key[3]
    rest = " | Sleeping" if key[4] else " | Resting" if key[5] else ""
    last[6], last[7] = key, f"{vitals}{kit} | {before}{row},{col}{after}{rest}"
    return last[7]


def _remembered(memo: dict, key: tuple, make, *values):
    """``memo[key]``, made by ``make(*values)`` the first time (``_keep``)."""
    value = memo.get(key)
    if value is None:
        value = _keep(memo, key, make(*values))
    return value


def _keep(memo: dict, key: tuple, value):
    """``value``, kept as ``memo[key]`` (a memo holds 10,000 at most)."""
    if len(memo) >= 10_000:
        memo.clear()
    memo[key] = value
    return value


# ---- the same line from the packed state (``packed``) ------------------------------------
#
# ``Line.update`` reads ``p.ints`` as one byte string (one numpy call) and keys the line on the
# slices of it the line reads (``packed.HUD_RANGES``: the scalars up to the enchantments, the
# inventory's counts up to the spells, which hold the potion mapping too, never changed in an
# episode, the floors' kills), with the health and the daylight. A key not seen before makes the
# text from the same part builders as ``hud``, each part remembered by its own values; the
# position is written between the text before and after it. ``Line.moved`` writes only the
# position again, for a step that changed none of the key's values (the compiled step says so:
# ``kernel.CHANGED_HUD``).
_WORD = np.dtype(np.int64).itemsize
_KEY_SLICES = tuple(slice(a * _WORD, b * _WORD) for a, b in HUD_RANGES)
_HEAD, _KIT, _KILLS = _KEY_SLICES
_COUNTED_AT = tuple(INV + INVENTORY.index(name) for name in COUNTED)      # COUNTED in p.ints
_PICKAXE, _SWORD, _BOW = (INV + INVENTORY.index(name) for name in ("pickaxe", "sword", "bow"))
# (the key's slices hold every int the line reads)
assert HUD_RANGES[0] == (0, BOW_ENCH + 1) and HUD_RANGES[1] == (INV, _SPELLS + 2) \
    and HUD_RANGES[2] == (KILLED, KILLED + NUM_LEVELS)
assert max(LEVEL, DIRECTION, FOOD, DRINK, ENERGY, MANA, SLEEPING, RESTING, XP, DEX, STR, INT,
           SWORD_ENCH) < BOW_ENCH + 1 <= INV
assert INV <= min(_COUNTED_AT) and ARMOUR + 4 <= _SPELLS and POTIONS + 6 <= _SPELLS \
    and ARMOUR_ENCH + 4 <= _SPELLS
_PACKED_TEXT: dict[tuple, tuple[str, str]] = {}   # the key -> text before and after the position
_PACKED_VITALS: dict[tuple, str] = {}
_PACKED_KITS: dict[tuple, str] = {}
_PACKED_PLACES: dict[tuple, tuple[str, str]] = {}


class Line:
    """One task's HUD line from its packed state: ``update`` makes it from the state, ``moved``
    writes the position again into the text ``update`` made last (the rest unchanged);
    ``line`` is the line made last."""

    __slots__ = ("key", "text", "line")

    def __init__(self) -> None:
        self.key, self.text, self.line = None, ("", ""), ""

    def update(self, p: Packed) -> str:
        ints = p.ints
        b = ints.tobytes()
        key = (b[_HEAD], b[_KIT], b[_KILLS], p.floats.item(HEALTH),
               p.floats.item(LIGHT) >= NIGHT_LIGHT)
        if key != self.key:
            text = _PACKED_TEXT.get(key)
            if text is None:
                text = _packed_text(ints, key)
            self.key, self.text = key, text
        return self.moved(p)

    def moved(self, p: Packed) -> str:
        ints = p.ints
        before, after = self.text
        self.line = line = f"{before}{ints.item(ROW)},{ints.item(COL)}{after}"
        return line


def packed_hud(p: Packed) -> str:
    """``hud`` of the state ``p`` packs, read from ``p.ints`` and ``p.floats``."""
    return Line().update(p)


def _packed_text(ints: np.ndarray, key: tuple) -> tuple[str, str]:
    """The line's text before and after the position for ``packed_hud``'s key (remembered)."""
    v = ints[:_SPELLS + 2].tolist()
    level, strength, dex, intelligence = v[LEVEL], v[STR], v[DEX], v[INT]
    vitals = (key[3], v[FOOD], v[DRINK], v[ENERGY], v[MANA], strength, dex, intelligence)
    kit = (v[XP], strength, dex, intelligence, tuple([v[i] for i in _COUNTED_AT]), v[_PICKAXE],
           v[_SWORD], v[_BOW], v[SWORD_ENCH], v[BOW_ENCH], v[ARMOUR:ARMOUR + 4],
           v[ARMOUR_ENCH:ARMOUR_ENCH + 4], v[POTIONS:POTIONS + 6], v[_SPELLS:_SPELLS + 2])
    place = (level, v[DIRECTION], key[4], ints.item(KILLED + level))
    before, after = _remembered(_PACKED_PLACES, place, _place, *place)
    rest = " | Sleeping" if v[SLEEPING] else " | Resting" if v[RESTING] else ""
    head = (_remembered(_PACKED_VITALS, vitals, _vitals, *vitals)
            + _remembered(_PACKED_KITS, (key[1], *kit[:4], *kit[8:10]), _kit, *kit))
    return _keep(_PACKED_TEXT, key, (f"{head} | {before}", f"{after}{rest}"))


# ---- the parts ---------------------------------------------------------------------------

def _hud(state: State) -> str:
    """The HUD made from the state (nothing remembered)."""
    parts = [_vitals(*_vitals_values(state)) + _kit(*_kit_values(state)), _where(state)]
    if state.is_sleeping:
        parts.append("Sleeping")
    elif state.is_resting:
        parts.append("Resting")
    return " | ".join(parts)


def _vitals_values(state: State) -> tuple:
    """What ``_vitals`` reads, from the state."""
    return (state.player_health, state.player_food, state.player_drink, state.player_energy,
            state.player_mana, state.player_strength, state.player_dexterity,
            state.player_intelligence)


def _vitals(health: float, food: int, drink: int, energy: int, mana: int, strength: int,
            dex: int, intelligence: int) -> str:
    """The HUD's vitals with their maxima (``max_vitals``)."""
    maxima = _maxima(strength, dex, intelligence)
    values = (_number(health), food, drink, energy, mana)
    if len(set(maxima)) == 1:      # (the usual case: every maximum 9) said once
        return " ".join(f"{name} {v}" for name, v in zip(VITALS, values)) + f" (max {maxima[0]})"
    return " ".join(f"{name} {v}/{m}" for name, v, m in zip(VITALS, values, maxima))


def _kit_values(state: State) -> tuple:
    """What ``_kit`` reads, from the state."""
    inv = state.inventory
    return (state.player_xp, state.player_strength, state.player_dexterity,
            state.player_intelligence, tuple([getattr(inv, name) for name in COUNTED]),
            inv.pickaxe, inv.sword, inv.bow, state.sword_enchantment, state.bow_enchantment,
            inv.armour.tolist(), state.armour_enchantments.tolist(), inv.potions.tolist(),
            state.learned_spells.tolist())


def _kit(xp: int, strength: int, dex: int, intelligence: int, counts: tuple, pickaxe: int,
         sword: int, bow: int, sword_enchantment: int, bow_enchantment: int, armour: list,
         armour_enchantments: list, potions: list, spells: list) -> str:
    """The HUD's inventory (``counts``: ``COUNTED``'s), gear, potions, spells and attributes,
    each part after `` | `` ("" when there are none)."""
    parts = [""]
    counted = [f"{label} {n}" for (_, label), n in zip(_COUNTED_LABELS, counts) if n]
    if counted:
        parts.append(" ".join(counted))
    gear = []
    if pickaxe:
        gear.append(f"{TIERS[pickaxe]} pickaxe")
    if sword:
        gear.append(f"{_enchanted(sword_enchantment)}{TIERS[sword]} sword")
    if bow:
        gear.append(f"{_enchanted(bow_enchantment)}bow")
    pieces = [f"{_enchanted(e)}{ARMOUR_TIERS[t]} {slot}" for slot, t, e in
              zip(ARMOUR_SLOTS, armour, armour_enchantments) if t]
    if gear or pieces:
        parts.append(", ".join(gear + pieces))
    if any(potions):
        parts.append("Potions " + " ".join(
            f"{colour} {n}" for colour, n in zip(POTION_COLOURS, potions) if n))
    if any(spells):
        parts.append("Spells " + " ".join(name for name, known in zip(SPELLS, spells) if known))
    levels = [f"{name} {v}" for name, v in (("Dex", dex), ("Str", strength),
                                              ("Int", intelligence)) if v > 1]
    if xp or levels:
        parts.append(" ".join([f"XP {xp}", *levels]))
    return " | ".join(parts)


def _where(state: State) -> str:
    """The HUD's floor, position, facing, daylight or darkness, and kills toward the ladder."""
    row, col = state.player_position.tolist()
    level = state.player_level
    before, after = _place(level, state.player_direction, state.light_level >= NIGHT_LIGHT,
                           state.monsters_killed.tolist()[level])
    return f"{before}{row},{col}{after}"


def _place(level: int, direction: int, day: bool, killed: int) -> tuple[str, str]:
    """``_where``'s text before the position and after it (``day``: the light level is at
    least ``NIGHT_LIGHT``; ``killed``: the floor's kills)."""
    after = f" facing {FACING.get(direction, '?')}"
    if level == 0:
        after += " Day" if day else " Night"
    elif level in DARK_LEVELS:
        after += " dark"
    if level < len(LEVEL_NAMES) - 1 and killed < KILLS_TO_OPEN_LADDER:
        after += f" Kills {killed}/{KILLS_TO_OPEN_LADDER}"
    return f"Floor {level} {LEVEL_NAMES[level]} at ", after


def _enchanted(kind: int) -> str:
    return f"{ENCHANTS[kind]} " if kind else ""
