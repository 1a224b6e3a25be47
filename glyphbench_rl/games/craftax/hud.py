"""The Craftax HUD: one line of vitals, inventory, equipment, potions, spells, attributes, floor,
position, facing, light and rest state (``hud``; ``_hud`` is the same line written out with
nothing remembered). The grid is ``view``'s.
"""

from __future__ import annotations

import numpy as np

from .state import Settings, State
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
    dex = state.player_dexterity
    return (max_health(state.player_strength), max_food(dex), max_drink(dex), max_energy(dex),
            max_mana(state.player_intelligence))


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
        vitals = _remembered(_VITALS, vitals_key, _vitals, state)
        last[0], last[1] = vitals_key, vitals
    if kit_key == last[2]:
        kit = last[3]
    else:
        kit = _remembered(_KITS, kit_key, _kit, state)
        last[2], last[3] = kit_key, kit
    if place_key == last[4]:
        before, after = last[5]
    else:
        place = _remembered(_PLACES, place_key, _place, state)
        last[4], last[5] = place_key, place
        before, after = place
    row, col = key[3]
    rest = " | Sleeping" if key[4] else " | Resting" if key[5] else ""
    last[6], last[7] = key, f"{vitals}{kit} | {before}{row},{col}{after}{rest}"
    return last[7]


def _remembered(memo: dict, key: tuple, make, state: State):
    """``memo[key]``, made by ``make(state)`` the first time (a memo holds 10,000 at most)."""
    value = memo.get(key)
    if value is None:
        if len(memo) >= 10_000:
            memo.clear()
        value = memo[key] = make(state)
    return value


def _hud(state: State) -> str:
    """The HUD made from the state (nothing remembered)."""
    parts = [_vitals(state) + _kit(state), _where(state)]
    if state.is_sleeping:
        parts.append("Sleeping")
    elif state.is_resting:
        parts.append("Resting")
    return " | ".join(parts)


def _vitals(state: State) -> str:
    """The HUD's vitals with their maxima."""
    maxima = max_vitals(state)
    values = (_number(state.player_health), state.player_food, state.player_drink,
              state.player_energy, state.player_mana)
    if len(set(maxima)) == 1:      # (the usual case: every maximum 9) said once
        return " ".join(f"{name} {v}" for name, v in zip(VITALS, values)) + f" (max {maxima[0]})"
    return " ".join(f"{name} {v}/{m}" for name, v, m in zip(VITALS, values, maxima))


def _kit(state: State) -> str:
    """The HUD's inventory, gear, potions, spells and attributes, each part after `` | ``
    ("" when there are none)."""
    parts = [""]
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
    return " | ".join(parts)


def _where(state: State) -> str:
    """The HUD's floor, position, facing, daylight or darkness, and kills toward the ladder."""
    row, col = state.player_position.tolist()
    before, after = _place(state)
    return f"{before}{row},{col}{after}"


def _place(state: State) -> tuple[str, str]:
    """``_where``'s text before the position and after it."""
    level = state.player_level
    after = f" facing {FACING.get(state.player_direction, '?')}"
    if level == 0:
        after += " Day" if state.light_level >= NIGHT_LIGHT else " Night"
    elif level in DARK_LEVELS:
        after += " dark"
    killed = state.monsters_killed.tolist()[level]
    if level < len(LEVEL_NAMES) - 1 and killed < KILLS_TO_OPEN_LADDER:
        after += f" Kills {killed}/{KILLS_TO_OPEN_LADDER}"
    return f"Floor {level} {LEVEL_NAMES[level]} at ", after


def _enchanted(kind: int) -> str:
    return f"{ENCHANTS[kind]} " if kind else ""
