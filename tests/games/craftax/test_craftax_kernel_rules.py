"""The compiled player rules and upkeep (``kernel_rules.act`` then ``kernel_rules.upkeep``) play
as the reference step (``rules.step``) with the mobs switched off (``mobs.update`` and
``mobs.spawn`` do nothing), so the reference step is exactly: the action's rules, the upkeep,
the reward, the timestep and its light level. Each case is a randomised state (a generated world
or a scenario's start, then a level, a cell, the block and mob in front, vitals, inventory,
attributes, sleep, settings ...) and an action; both sides start from copies of it with the same
draws, and every field of the two states after the step must be the same (arrays by bytes,
floats by repr), and so must the reward and the number of draws taken. The cases are themed
(crafting, chests, the necromancer, ladders, fights, placing, enchanting, potions and spells,
the upkeep, the map's edge, mining, anything) and the test counts what they did, to show every
branch was taken."""

from __future__ import annotations

import copy
from collections import Counter

import numpy as np
import pytest

from glyphbench_rl.games.common.lanes import Draws
from glyphbench_rl.games.craftax import kernel_rules, rules, upkeep, worldgen
from glyphbench_rl.games.craftax.bestiary import MOB_NAMES, MOB_TYPE_HEALTH_MAPPING
from glyphbench_rl.games.craftax.packed import ACH, DRAW_AT, HEALTH, LIGHT, TIMESTEP, pack, unpack
from glyphbench_rl.games.craftax.scenarios import SCENARIOS
from glyphbench_rl.games.craftax.state import (MAX_GROWING_PLANTS, MAX_PLAYER_PROJECTILES,
                                               NUM_LEVELS, Inventory, Mobs, Settings, State,
                                               float32)
from glyphbench_rl.games.craftax.tables import (
    ACHIEVEMENT_REWARD, BOSS_LEVEL, DRINK_BLOCKS, ENCHANT_TABLES, IS_SOLID, LEVEL_ACHIEVEMENT,
    MINING_BY_BLOCK, MOVES, PLACING, POTION_ACTIONS, RECIPE_BY_ACTION, SPELLS, Achievement,
    Action, BlockType, ItemType, max_food, max_health, max_mana,
)

B = BlockType
ROWS, COLS = 48, 48
GROUPS = ("passive_mobs", "melee_mobs", "ranged_mobs")
_WEIGHTS = np.array(ACHIEVEMENT_REWARD, np.float64)
_INVENTORY_FIELDS = ("wood", "stone", "coal", "iron", "diamond", "sapling", "pickaxe", "sword",
                     "bow", "arrows", "torches", "ruby", "sapphire", "books")
_FLOAT_FIELDS = {"player_health", "player_recover", "player_hunger", "player_thirst",
                 "player_fatigue", "player_recover_mana", "light_level"}

RECIPES = sorted(RECIPE_BY_ACTION)
PLACES = sorted(int(a) for a in PLACING)
POTIONS = [int(a) for a in POTION_ACTIONS]
CASTS = sorted(int(a) for a in SPELLS)
ENCHANTS = [int(a) for a in (Action.ENCHANT_SWORD, Action.ENCHANT_ARMOUR, Action.ENCHANT_BOW)]
LEVEL_UPS = [int(a) for a in (Action.LEVEL_UP_DEXTERITY, Action.LEVEL_UP_STRENGTH,
                              Action.LEVEL_UP_INTELLIGENCE)]
MOVE_ACTIONS = sorted(MOVES)
LADDERS = [int(Action.DESCEND), int(Action.ASCEND)]
DO, NOOP, SLEEP, REST = int(Action.DO), int(Action.NOOP), int(Action.SLEEP), int(Action.REST)
ALL_ACTIONS = [int(a) for a in Action]
CASES = 10_000


# ---------------------------------------------------------------------------------------------
# comparing states


def _scalar(name: str, value):
    return repr(float(value)) if name in _FLOAT_FIELDS else int(value)


def snapshot(state: State) -> dict:
    """Every field of ``state`` as comparable values: arrays as (dtype, shape, bytes), floats
    by repr (a -0.0 counts), the mob slots' lists with their health by repr."""
    out = {}
    for name, value in vars(state).items():
        if isinstance(value, np.ndarray):
            out[name] = (value.dtype.str, value.shape, value.tobytes())
        elif isinstance(value, Mobs):       # (the lists' repr: a float's sign, an int's type)
            out[name] = repr((value.position, value.health, value.mask, value.attack_cooldown,
                              value.type_id))
        elif isinstance(value, Inventory):
            out[name] = {k: ((v.dtype.str, v.tobytes()) if isinstance(v, np.ndarray) else int(v))
                         for k, v in vars(value).items()}
        else:
            out[name] = _scalar(name, value)
    return out


def differences(a: dict, b: dict) -> list[str]:
    return [k for k in a if a[k] != b[k]]


def clone(state: State) -> State:
    """A deep copy of ``state`` (``copy.deepcopy``'s, quicker)."""
    fields = {}
    for name, value in vars(state).items():
        if isinstance(value, np.ndarray):
            value = value.copy()
        elif isinstance(value, Mobs):
            value = copy.deepcopy(value)
        elif isinstance(value, Inventory):
            value = Inventory(**{k: v.copy() if isinstance(v, np.ndarray) else v
                                 for k, v in vars(value).items()})
        fields[name] = value
    return State(**fields)


# ---------------------------------------------------------------------------------------------
# building varied states


@pytest.fixture(scope="module")
def bases():
    """Start states: generated worlds (one in god mode: its full inventory) and every
    scenario's start, each with the settings it was made for."""
    out = [(worldgen.generate(np.random.default_rng(seed), Settings()), Settings())
           for seed in range(3)]
    god = Settings(god_mode=True)
    out.append((worldgen.generate(np.random.default_rng(9), god), god))
    for name in sorted(SCENARIOS):
        scenario = SCENARIOS[name]
        out.append((scenario.build(np.random.default_rng(7))[0], scenario.settings))
    return out


def _settings(rng, base: Settings) -> Settings:
    if rng.random() < 0.25:
        return base
    return Settings(day_length=int(rng.choice([300, 300, 120])),
                    max_attribute=int(rng.choice([3, 5, 5, 8])),
                    god_mode=bool(rng.random() < 0.15), intrinsics=bool(rng.random() < 0.75),
                    daylight=bool(rng.random() < 0.8), spawning=bool(rng.random() < 0.5))


def _facing(state: State) -> tuple[int, int]:
    d_row, d_col = MOVES.get(state.player_direction, (0, 0))
    row, col = state.player_position.tolist()
    return row + d_row, col + d_col


def _inside(r: int, c: int) -> bool:
    return 0 <= r < ROWS and 0 <= c < COLS


def put_mob(state: State, rng, kind: int, cell, tough: bool | None = None) -> None:
    """A mob of class ``kind`` (a random type) at ``cell`` of the player's level, in a free slot
    (else slot 0, whose old mob leaves the mob map)."""
    level = state.player_level
    group = getattr(state, GROUPS[kind])
    mask = group.mask[level]
    slot = mask.index(False) if False in mask else 0
    if mask[slot]:
        old = group.position[level][slot]
        state.mob_map[level, old[0], old[1]] = False
    type_id = int(rng.integers(len(MOB_NAMES[kind])))
    full = MOB_TYPE_HEALTH_MAPPING[type_id][kind]
    if tough is None:
        tough = rng.random() < 0.5
    health = full * rng.uniform(0.6, 1.0) if tough else rng.uniform(0.1, 1.5)
    group.position[level][slot] = (int(cell[0]), int(cell[1]))
    mask[slot] = True
    group.type_id[level][slot] = type_id
    group.health[level][slot] = float32(health)
    group.attack_cooldown[level][slot] = int(rng.integers(0, 5))
    state.mob_map[level, cell[0], cell[1]] = True


def _random_cell(state: State, rng, level: int, walkable: bool = True) -> tuple[int, int]:
    blocks = state.map[level].ravel()
    if walkable:
        cells = np.flatnonzero(~np.array(IS_SOLID)[blocks])
        if cells.size:
            i = int(cells[rng.integers(cells.size)])
            return divmod(i, COLS)
    return int(rng.integers(ROWS)), int(rng.integers(COLS))


def _edge_cell(rng) -> tuple[int, int]:
    side, at = int(rng.integers(4)), int(rng.integers(ROWS))
    return ((0, at), (ROWS - 1, at), (at, 0), (at, COLS - 1))[side]


def _inventory(state: State, rng, kind: str) -> None:
    inv = state.inventory
    if kind == "keep":
        return
    if kind == "empty":
        state.inventory = Inventory()
        return
    most = 12 if kind == "rich" else 3
    for name in ("wood", "stone", "coal", "iron", "diamond", "sapling", "arrows", "torches",
                 "ruby", "sapphire"):
        n = int(rng.integers(0, most + 1))
        if kind == "rich" and rng.random() < 0.08:
            n = int(rng.integers(97, 106))       # (over the stack limit: the upkeep clips it)
        setattr(inv, name, n)
    inv.pickaxe, inv.sword = int(rng.integers(0, 5)), int(rng.integers(0, 5))
    inv.bow, inv.books = int(rng.integers(0, 2)), int(rng.integers(0, 3))
    inv.armour[:] = rng.integers(0, 3, 4)
    inv.potions[:] = rng.integers(0, 3, 6)
    if rng.random() < 0.05:
        inv.potions[int(rng.integers(6))] = 99


def _recipe_inventory(inv: Inventory, rng, recipe) -> None:
    """Mostly the recipe's cost (or more), and its result below its limit (else at it)."""
    if rng.random() < 0.75:
        for item, n in recipe.cost.items():
            setattr(inv, item, max(getattr(inv, item), n + int(rng.integers(0, 3))))
    full = rng.random() < 0.25
    if recipe.result == "armour":
        inv.armour[:] = rng.integers(recipe.tier if full else 0, 3, 4)
        if not full:
            inv.armour[int(rng.integers(4))] = int(rng.integers(0, recipe.tier))
    elif recipe.result in ("pickaxe", "sword"):
        setattr(inv, recipe.result, int(rng.integers(recipe.tier, 5) if full
                                         else rng.integers(0, recipe.tier)))
    else:
        setattr(inv, recipe.result, int(rng.integers(99, 102) if full else rng.integers(0, 99)))


def _vitals(state: State, rng, extreme: bool) -> None:
    strength, dex, intel = (int(x) for x in rng.integers(1, 6, 3))
    state.player_strength, state.player_dexterity, state.player_intelligence = strength, dex, intel
    state.player_xp = int(rng.integers(0, 4))
    top = max_food(dex)
    if extreme:
        state.player_health = float(rng.choice([-0.5, 0.0, 0.7, 9.0, max_health(strength),
                                                max_health(strength) + 2.5, 15.0]))
        state.player_food, state.player_drink, state.player_energy = (
            int(rng.choice([-1, 0, 1, top - 1, top, top + 3])) for _ in range(3))
        state.player_mana = int(rng.choice([-2, 0, 1, 8, 9, max_mana(intel), max_mana(intel) + 4]))
    else:
        state.player_health = float(rng.choice([float(rng.integers(1, 10)),
                                                round(rng.uniform(0.2, 12), 2)]))
        state.player_food, state.player_drink, state.player_energy = (
            int(rng.integers(0, top + 1)) for _ in range(3))
        state.player_mana = int(rng.integers(0, max_mana(intel) + 1))
    near = rng.random() < 0.4       # (at the intrinsics' limits)
    # (-0.0 too: a sum with it keeps its sign only where the reference's does)
    state.player_hunger = float(rng.choice([24.5, 25.0, 24.9, -0.0])) if near else rng.uniform(0, 25)
    state.player_thirst = float(rng.choice([19.5, 20.0, 19.9, -0.0])) if near else rng.uniform(0, 20)
    state.player_fatigue = (float(rng.choice([29.5, 30.0, -9.5, -10.0, 0.0, -0.0, 0.5, 1.0]))
                            if near else rng.uniform(-11, 30))
    state.player_recover = (float(rng.choice([24.5, 25.0, -14.5, -14.0, 0.0, -0.0])) if near
                            else rng.uniform(-15, 25))
    state.player_recover_mana = (float(rng.choice([29.5, 12.0, 20.0, 0.0, -0.0])) if near
                                 else rng.uniform(0, 30))
    state.is_sleeping = bool(rng.random() < 0.12)
    state.is_resting = bool(rng.random() < 0.08)


def _plants(state: State, rng, front) -> None:
    n = MAX_GROWING_PLANTS
    state.growing_plants_mask[:] = rng.random(n) < 0.5
    state.growing_plants_age[:] = rng.choice([0, 0, 3, 598, 599, 600, 650], n)
    state.growing_plants_positions[:] = rng.integers(0, ROWS, (n, 2))
    if front is not None and rng.random() < 0.7:
        state.growing_plants_positions[int(rng.integers(n))] = front


def _projectiles(state: State, rng) -> None:
    level = state.player_level
    shots = state.player_projectiles
    for slot in range(MAX_PLAYER_PROJECTILES):
        live = bool(rng.random() < 0.4)
        shots.mask[level][slot] = live
        if live:
            shots.position[level][slot] = (int(rng.integers(ROWS)), int(rng.integers(COLS)))
            shots.type_id[level][slot] = int(rng.integers(0, 8))


THEMES = ("random", "craft", "chest", "necromancer", "ladder", "fight", "place", "enchant",
          "magic", "upkeep", "edge", "mine")
_MINED = [int(b) for b in MINING_BY_BLOCK] + [int(b) for b in (
    B.SAPPHIRE, B.RUBY, B.DIAMOND, B.WATER, B.FOUNTAIN, B.RIPE_PLANT, B.LAVA, B.SAND)]
_PLACE_ONTO = [int(b) for b in (B.GRASS, B.GRASS, B.WATER, B.LAVA, B.SAND, B.PATH, B.STONE,
                                B.TREE, B.FIRE_GRASS, B.ICE_GRASS, B.RIPE_PLANT)]


def build_case(bases, rng) -> tuple[State, Settings, int, str]:
    """A randomised state, its settings, an action and the theme."""
    base, base_settings = bases[int(rng.integers(len(bases)))]
    state = clone(base)
    settings = _settings(rng, base_settings)
    theme = THEMES[int(rng.integers(len(THEMES)))]
    on_theme = rng.random() < 0.85
    # the action
    choices = {"craft": RECIPES, "chest": [DO], "necromancer": [DO], "ladder": LADDERS,
               "fight": [DO] * 4 + [int(Action.SHOOT_ARROW)] + CASTS + MOVE_ACTIONS + PLACES,
               "place": PLACES, "enchant": ENCHANTS,
               "magic": POTIONS + CASTS + [int(Action.READ_BOOK), int(Action.SHOOT_ARROW)],
               "upkeep": [NOOP, SLEEP, REST] + LEVEL_UPS,
               "edge": MOVE_ACTIONS + [DO] + PLACES + ENCHANTS + [int(Action.SHOOT_ARROW)],
               "mine": [DO]}.get(theme, ALL_ACTIONS)
    action = int(rng.choice(choices if on_theme else ALL_ACTIONS))

    # the level and the cell
    level = state.player_level if rng.random() < 0.4 else int(rng.integers(NUM_LEVELS))
    if theme == "chest":
        level = int(rng.choice([0, 1, 1, 3, 4, int(rng.integers(NUM_LEVELS))]))
    elif theme == "necromancer" and rng.random() < 0.8:
        level = BOSS_LEVEL
    state.player_level = level
    if theme == "ladder":
        ladders = state.down_ladders if rng.random() < 0.5 else state.up_ladders
        cell = tuple(int(x) for x in ladders[level])
        state.monsters_killed[level] = int(rng.choice([0, 7, 8, 12]))
    elif theme == "edge" or rng.random() < 0.05:
        cell = _edge_cell(rng)
    else:
        cell = _random_cell(state, rng, level, walkable=rng.random() < 0.9)
    state.player_position[:] = cell
    state.player_direction = int(rng.integers(1, 5))
    front = _facing(state)
    inside = _inside(*front)

    # the block, item and mob in front, the crafting stations around
    if inside:
        blocks = state.map[level]
        if theme == "craft" or rng.random() < 0.15:
            around = [(cell[0] + dr, cell[1] + dc) for dr in (-1, 0, 1) for dc in (-1, 0, 1)
                      if (dr or dc) and _inside(cell[0] + dr, cell[1] + dc)]
            picks = rng.permutation(len(around))
            if rng.random() < 0.85:
                blocks[around[picks[0]]] = B.CRAFTING_TABLE
            if rng.random() < 0.6 and len(picks) > 1:
                blocks[around[picks[1]]] = B.FURNACE
        if theme == "chest":
            blocks[front] = B.CHEST
        elif theme == "necromancer":
            blocks[front] = B.NECROMANCER if rng.random() < 0.8 else B.NECROMANCER_VULNERABLE
        elif theme == "enchant" and rng.random() < 0.85:
            blocks[front] = int(rng.choice([int(b) for b in ENCHANT_TABLES]))
        elif theme == "mine":
            blocks[front] = int(B.GRASS) if rng.random() < 0.25 else int(rng.choice(_MINED))
        elif theme == "place":
            blocks[front] = int(rng.choice(_PLACE_ONTO))
        elif rng.random() < 0.5:
            blocks[front] = int(rng.integers(len(BlockType)))
        if rng.random() < 0.12:
            state.item_map[level][front] = int(rng.integers(1, len(ItemType)))
        if theme == "fight" or rng.random() < 0.08:
            put_mob(state, rng, int(rng.integers(3)), front)
        elif rng.random() < 0.03:
            state.mob_map[level][front] = True    # (a mob map with no mob: the rule goes on)
        if rng.random() < 0.5:      # the light around: the torch's is added and clipped
            r0, r1 = max(front[0] - 4, 0), min(front[0] + 5, ROWS)
            c0, c1 = max(front[1] - 4, 0), min(front[1] + 5, COLS)
            light = rng.random((r1 - r0, c1 - c0)).astype(np.float32)
            light[rng.random(light.shape) < 0.2] = 1.0
            state.light_map[level, r0:r1, c0:c1] = light
    if theme == "necromancer" or level == BOSS_LEVEL:
        state.boss_progress = int(rng.choice([0, 3, 7, 7, 8, 9]))
        state.boss_timesteps_to_spawn_this_round = int(rng.choice([-1, 0, 0, 1, 5]))
        if rng.random() < 0.3:
            other = _random_cell(state, rng, level)
            if other != cell and other != front and not state.mob_map[level][other]:
                put_mob(state, rng, int(rng.integers(1, 3)), other)
    elif rng.random() < 0.1:
        state.boss_progress = int(rng.choice([8, 9]))

    # the player
    inventory = ("rich" if theme in ("craft", "enchant", "place") and rng.random() < 0.7
                 else str(rng.choice(["rich", "sparse", "empty", "keep"])))
    _inventory(state, rng, inventory)
    _vitals(state, rng, extreme=theme == "upkeep" or rng.random() < 0.2)
    if theme == "mine":
        state.inventory.pickaxe = int(rng.choice([0, 1, 2, 3, 4, 4]))
    if theme == "craft" and action in RECIPE_BY_ACTION:
        _recipe_inventory(state.inventory, rng, RECIPE_BY_ACTION[action])
    if theme in ("enchant", "magic") and rng.random() < 0.6:
        state.player_mana = int(rng.choice([1, 2, 8, 9, 12]))
    if theme not in ("upkeep", "random") and rng.random() < 0.7:
        state.is_sleeping = state.is_resting = False
    state.learned_spells[:] = rng.random(2) < 0.5
    state.sword_enchantment, state.bow_enchantment = (int(x) for x in rng.integers(0, 3, 2))
    state.armour_enchantments[:] = (rng.integers(0, 3, 4) if rng.random() < 0.6
                                    else int(rng.integers(0, 3)))
    state.potion_mapping[:] = rng.permutation(6)
    if rng.random() < 0.35 or theme == "upkeep":
        _plants(state, rng, front if inside else None)
    if rng.random() < 0.5 or theme == "magic":
        _projectiles(state, rng)
    if rng.random() < 0.5:
        state.achievements[:] = rng.random(len(state.achievements)) < 0.3
    if theme == "ladder":
        for a in LEVEL_ACHIEVEMENT[1:]:
            state.achievements[a] = rng.random() < 0.5
    state.chests_opened[:] = rng.random(NUM_LEVELS) < 0.3
    state.timestep = int(rng.integers(0, 3000))
    state.light_level = upkeep.daylight(state.timestep, settings)

    return state, settings, action, theme


# ---------------------------------------------------------------------------------------------
# one case on both sides


def reference(state: State, settings: Settings, action: int, seed: int):
    draws = Draws(np.random.default_rng(seed))
    reward = rules.step(state, action, settings, draws)
    return reward, draws.random()


def kernel(state: State, settings: Settings, action: int, seed: int):
    p = pack(state, settings)
    p.draws = np.random.default_rng(seed).random(256)
    p.ints[DRAW_AT] = 0
    before = p.ints[ACH:ACH + len(_WEIGHTS)].astype(bool)
    health = p.floats.item(HEALTH)
    played = kernel_rules.act(p.map, p.item_map, p.mob_map, p.light_map, p.ints, p.floats, p.mobs,
                              p.health, p.kills, p.draws, p.settings, action)
    kernel_rules.upkeep(p.map, p.ints, p.floats, p.settings, played)
    after = p.ints[ACH:ACH + len(_WEIGHTS)].astype(bool)
    reward = 0.0                                  # (as rules.step adds it up)
    if (after != before).any():
        reward = float(_WEIGHTS[after & ~before].sum())
    reward += (p.floats.item(HEALTH) - health) * 0.1
    p.ints[TIMESTEP] += 1
    p.floats[LIGHT] = upkeep.daylight(int(p.ints[TIMESTEP]), settings)
    unpack(p, state)
    return reward, played, p.draws[p.ints[DRAW_AT]], int(p.ints[DRAW_AT]), p.kills


@pytest.fixture
def no_mobs(monkeypatch):
    monkeypatch.setattr(rules.mobs, "update", lambda *args, **kwargs: None)
    monkeypatch.setattr(rules.mobs, "spawn", lambda *args, **kwargs: None)


def _held(state: State) -> dict:
    inv = state.inventory
    out = {name: int(getattr(inv, name)) for name in _INVENTORY_FIELDS}
    out["armour"], out["potions"] = inv.armour.tolist(), inv.potions.tolist()
    return out


def _facts(state: State) -> dict:
    """What the coverage counts compare before and after."""
    level = state.player_level
    r, c = _facing(state)
    inside = _inside(r, c)
    return dict(
        level=level, position=tuple(state.player_position.tolist()), inside=inside,
        front=int(state.map[level, r, c]) if inside else None,
        mob_front=bool(state.mob_map[level, r, c]) if inside else False,
        item_here=(int(state.item_map[level][tuple(state.player_position.tolist())])
                   if _inside(*state.player_position.tolist()) else None),
        held=_held(state), spells=state.learned_spells.tolist(),
        ench=(state.sword_enchantment, state.bow_enchantment,
              state.armour_enchantments.tolist()),
        vitals=(state.player_health, state.player_food, state.player_drink, state.player_energy,
                state.player_mana),
        attributes=(state.player_dexterity, state.player_strength, state.player_intelligence),
        xp=state.player_xp, sleeping=state.is_sleeping, resting=state.is_resting,
        boss=(state.boss_progress, state.boss_timesteps_to_spawn_this_round),
        mobs=[(list(getattr(state, g).mask[level]), list(getattr(state, g).health[level]),
               list(getattr(state, g).type_id[level])) for g in GROUPS],
        shots=state.player_projectiles.mask[level].count(True),
        near=(rules.is_near_block(state, int(B.CRAFTING_TABLE))
              if _inside(*state.player_position.tolist()) else False,
              rules.is_near_block(state, int(B.FURNACE))
              if _inside(*state.player_position.tolist()) else False),
        achievements=state.achievements.copy(), killed=int(state.monsters_killed[level]),
        chest_opened=bool(state.chests_opened[level]),
        ripe=int((state.map[0] == B.RIPE_PLANT).sum()),
        plants=(state.growing_plants_mask.copy(), state.growing_plants_age.copy()),
    )


def count(counts: Counter, a: dict, b: dict, action: int, played: int, settings: Settings):
    """Tally what the step did (the reference's before ``a`` and after ``b``)."""
    name = Action(played).name
    new = b["achievements"] & ~a["achievements"]
    if played != action:
        counts["asleep or resting: NOOP"] += 1
    held_a, held_b = a["held"], b["held"]
    # (the action changed the inventory: the counts after the upkeep's clip of those before)
    changed = held_b != {k: min(v, 99) if isinstance(v, int) else v for k, v in held_a.items()}
    if played in RECIPE_BY_ACTION:
        counts[f"craft {name}" if changed else "craft refused"] += 1
        recipe = RECIPE_BY_ACTION[played]
        if not changed and all(held_a[k] >= n for k, n in recipe.cost.items()):
            if not a["near"][0] or (recipe.furnace and not a["near"][1]):
                counts["craft refused: no table or furnace near"] += 1
            else:
                counts[f"craft refused: {recipe.result} at its limit"] += 1
    elif played == DO:
        front = a["front"]
        hit = a["mobs"] != b["mobs"]
        if not a["inside"]:
            counts["do: off the map"] += 1
        elif hit:
            killed = [k for k in range(3) if a["mobs"][k][0] != b["mobs"][k][0]]
            counts[f"do: killed {GROUPS[killed[0]]}" if killed else "do: hit a mob"] += 1
        elif a["mob_front"]:
            counts["do: mob map with no mob"] += 1
        if not a["inside"] or hit:
            pass
        elif front in MINING_BY_BLOCK:
            counts[f"mine {B(front).name}" if b["front"] != front
                   else "mine: pickaxe too weak"] += 1
        elif front == B.GRASS:
            counts["sapling found" if held_b["sapling"] > held_a["sapling"] else "grass"] += 1
        elif front in DRINK_BLOCKS:
            counts[f"drink {B(front).name}"] += 1
        elif front == B.RIPE_PLANT:
            counts["eat plant"] += 1
        elif front == B.CHEST:
            counts[f"chest opened on level {a['level']}"] += 1
            if held_b["bow"] > held_a["bow"]:
                counts["chest: the bow"] += 1
            if held_b["books"] > held_a["books"]:
                counts["chest: a book"] += 1
            if held_b["pickaxe"] > held_a["pickaxe"] or held_b["sword"] > held_a["sword"]:
                counts["chest: a tool"] += 1
            if held_b["potions"] != held_a["potions"]:
                counts["chest: potions"] += 1
        elif front == B.NECROMANCER:
            counts["necromancer damaged" if b["boss"][0] > a["boss"][0]
                   else "necromancer not vulnerable"] += 1
    elif played in PLACING:
        counts[f"place {name}" if changed else "place refused"] += 1
        if changed and played == Action.PLACE_TORCH and not (
                4 <= b["position"][0] < ROWS - 4 and 4 <= b["position"][1] < COLS - 4):
            counts["torch light cut at the map's edge"] += 1
    elif played == Action.SHOOT_ARROW:
        counts["arrow shot" if changed else "arrow refused"] += 1
    elif played in SPELLS:
        counts[f"cast {name}" if b["shots"] > a["shots"] else "cast refused"] += 1
    elif played in POTIONS:
        counts["potion drunk" if changed else "potion refused"] += 1
        if changed:
            colour = POTIONS.index(played)
            counts[f"potion effect {b['effect_of'][colour]}"] += 1
    elif played == Action.READ_BOOK:
        if changed:
            counts["book: learned" if a["spells"] != b["spells"] else "book: both known"] += 1
            if b["draws"]:
                counts["book: drawn between two"] += 1
    elif played in ENCHANTS:
        if changed:
            counts[f"enchant {name} {B(a['front']).name}"] += 1
            if played == Action.ENCHANT_ARMOUR and b["ench"] == a["ench"]:
                counts["enchant armour: all of that element already"] += 1
            if played == Action.ENCHANT_ARMOUR and b["draws"]:
                counts["enchant armour: drawn among pieces"] += 1
        else:
            counts["enchant refused"] += 1
    elif played in LEVEL_UPS:
        counts[f"{name}" if b["attributes"] != a["attributes"] else "level up refused"] += 1
    elif played in LADDERS:
        if b["level"] != a["level"]:
            counts[f"{name} (god mode)" if settings.god_mode else name] += 1
        elif played == Action.DESCEND and a["item_here"] == ItemType.LADDER_DOWN:
            counts["descend: too few kills" if a["killed"] < 8 else "descend: the last level"] += 1
        else:
            counts["ladder: not on one"] += 1
    elif played in MOVES:
        if b["position"] != a["position"]:
            counts["move (god mode)" if settings.god_mode else "move"] += 1
        else:
            counts["move blocked"] += 1
    if b["xp"] > a["xp"] and played not in LEVEL_UPS:
        counts["first entry: achievement and XP"] += 1
    if b["level"] == BOSS_LEVEL:
        counts["boss rule on the boss level"] += 1
    if new[Achievement.DEFEAT_NECROMANCER]:
        counts["necromancer defeated"] += 1
    # the upkeep
    if a["sleeping"] and not b["sleeping"]:
        counts["woke up"] += 1
    if played == SLEEP and b["sleeping"] and not a["sleeping"]:
        counts["fell asleep"] += 1
    if played == REST:
        counts["rest started" if b["resting"] else "rest refused"] += 1
    if a["resting"] and not b["resting"]:
        counts["rest ended"] += 1
    va, vb = a["vitals"], b["vitals"]
    if not settings.intrinsics:
        counts["intrinsics off"] += 1
    if a["plants"][0].any() and b["ripe"] > a["ripe"]:
        counts["plant ripened"] += 1
    if max(v for v in held_a.values() if isinstance(v, int)) > 99:
        counts["inventory clipped"] += 1
    if va[0] > max_health(b["attributes"][1]) or va[0] < 0 or max(va[1:4]) > max_food(
            b["attributes"][0]) or min(va[1:]) < 0:
        counts["vitals clipped"] += 1
    if vb[0] != va[0] and played not in POTIONS:
        counts["health changed by the upkeep"] += 1
    if vb[4] > va[4]:
        counts["mana recovered"] += 1
    in_range = 0 <= min(va[1:4]) and max(va[1:4]) <= max_food(a["attributes"][0])
    for i, vital in ((1, "food"), (2, "drink"), (3, "energy")):
        if vb[i] < va[i] and in_range and played not in POTIONS:
            counts[f"{vital} fell"] += 1
    if vb[3] > va[3] and in_range and played not in POTIONS:
        counts["energy rose"] += 1
    if b["draws"]:
        counts["drew"] += 1


def test_act_and_upkeep_play_as_the_reference_step(bases, no_mobs):
    counts = Counter()
    for case in range(CASES):
        rng = np.random.default_rng(case)
        state, settings, action, theme = build_case(bases, rng)
        ours = clone(state)
        a = _facts(state)
        want, next_draw = reference(state, settings, action, case)
        got, played, kernel_next, drawn, kills = kernel(ours, settings, action, case)
        diff = differences(snapshot(state), snapshot(ours))
        assert not diff, (case, theme, Action(action).name, diff)
        assert repr(got) == repr(want), (case, theme, Action(action).name, got, want)
        assert next_draw == kernel_next, (case, theme, Action(action).name, drawn)
        asleep = a["sleeping"] or a["resting"]
        assert played == (NOOP if asleep else action)
        b = _facts(state)
        b["draws"], b["effect_of"] = drawn, state.potion_mapping.tolist()
        killed = np.zeros_like(kills)       # (the kernel's kill tally: the mobs gone)
        for k, (alive, _, types) in enumerate(a["mobs"]):
            now = getattr(state, GROUPS[k]).mask[a["level"]]
            for slot, was in enumerate(alive):
                killed[k, types[slot]] += was and not now[slot]
        assert (kills == killed).all(), (case, kills, killed)
        counts[f"theme {theme}"] += 1
        counts[f"action {Action(action).name}"] += 1
        count(counts, a, b, action, played, settings)
    print("\n".join(f"{k}: {v}" for k, v in sorted(counts.items())))
    least = {f"craft {Action(a).name}": 10 for a in RECIPES}
    least |= {f"place {Action(a).name}": 10 for a in PLACES}
    least |= {f"cast {Action(a).name}": 15 for a in CASTS}
    least |= {f"potion effect {e}": 10 for e in range(6)}
    least |= {f"action {a.name}": 80 for a in Action}
    least |= {f"theme {t}": 500 for t in THEMES}
    least |= {Action(a).name: 10 for a in LEVEL_UPS}
    least |= {f"mine {B(b).name}": 5 for b in MINING_BY_BLOCK}
    least |= {f"enchant {act} {table}": 5
              for act in ("ENCHANT_SWORD", "ENCHANT_ARMOUR", "ENCHANT_BOW")
              for table in ("ENCHANTMENT_TABLE_FIRE", "ENCHANTMENT_TABLE_ICE")}
    least |= {f"chest opened on level {level}": 20 for level in (0, 1, 3, 4)}
    least |= dict.fromkeys((
        "asleep or resting: NOOP", "craft refused", "do: off the map", "do: hit a mob",
        "do: killed passive_mobs", "do: killed melee_mobs", "do: killed ranged_mobs",
        "do: mob map with no mob", "mine: pickaxe too weak", "sapling found", "grass",
        "drink WATER", "drink FOUNTAIN", "eat plant", "chest: the bow", "chest: a book",
        "chest: a tool", "chest: potions", "necromancer damaged", "necromancer not vulnerable",
        "place refused", "arrow shot", "arrow refused", "cast refused", "potion drunk",
        "potion refused", "book: learned", "book: both known", "enchant refused",
        "enchant armour: all of that element already", "level up refused", "DESCEND",
        "DESCEND (god mode)", "ASCEND", "ASCEND (god mode)", "descend: too few kills",
        "ladder: not on one", "move", "move (god mode)", "move blocked",
        "first entry: achievement and XP", "boss rule on the boss level", "necromancer defeated",
        "woke up", "fell asleep", "rest started", "rest refused", "rest ended", "intrinsics off",
        "plant ripened", "inventory clipped", "vitals clipped", "health changed by the upkeep",
        "mana recovered", "food fell", "drink fell", "energy fell", "energy rose", "drew",
        "craft refused: no table or furnace near", "craft refused: armour at its limit",
        "craft refused: pickaxe at its limit", "craft refused: sword at its limit",
        "craft refused: arrows at its limit", "craft refused: torches at its limit",
        "torch light cut at the map's edge", "book: drawn between two",
        "enchant armour: drawn among pieces"), 5)
    short = {k: (counts[k], n) for k, n in least.items() if counts[k] < n}
    assert not short, short


# ---------------------------------------------------------------------------------------------
# the helpers, one by one


def test_helpers_match_the_reference(bases):
    """``in_bounds``, ``is_in_mob``, ``is_free``, ``player_can_enter``, ``is_near_block``,
    ``facing`` and ``player_damage_vector`` give the reference's answers, at and off the map's
    edges too; ``add_torch_light`` lights the same float32 values."""
    rng = np.random.default_rng(5)
    checked = Counter()
    for case in range(400):
        state, settings, _, _ = build_case(bases, rng)
        p = pack(state, settings)
        level = state.player_level
        for _ in range(10):
            r, c = (int(x) for x in rng.integers(-2, ROWS + 2, 2))
            assert kernel_rules.in_bounds(p.map, r, c) == rules.in_bounds(state, r, c)
            if not rules.in_bounds(state, r, c):
                checked["off the map"] += 1
                continue
            assert kernel_rules.is_in_mob(p.mob_map, p.ints, level, r, c) == rules.is_in_mob(
                state, level, r, c)
            assert kernel_rules.is_free(p.map, p.mob_map, p.ints, level, r, c) == rules.is_free(
                state, level, (r, c))
            want = rules.player_can_enter(state, r, c)
            assert kernel_rules.player_can_enter(p.map, p.mob_map, p.ints, r, c) == want
            checked[f"can enter {want}"] += 1
        for block in (B.CRAFTING_TABLE, B.FURNACE, B.WATER, int(rng.integers(len(B)))):
            want = rules.is_near_block(state, int(block))
            assert kernel_rules.is_near_block(p.map, p.ints, int(block)) == want
            checked[f"near {want}"] += 1
        assert tuple(kernel_rules.facing(p.ints)) == rules.facing(state)
        want = rules.player_damage_vector(state)
        got = kernel_rules.player_damage_vector(p.ints)
        assert [repr(float(x)) for x in got] == [repr(float(x)) for x in want]
        # a torch anywhere (the map's corners and edges too)
        r, c = (int(x) for x in rng.integers(0, ROWS, 2))
        if rng.random() < 0.3:
            r, c = _edge_cell(rng)
        ours = state.light_map.copy()
        rules.add_torch_light(state, level, r, c)
        kernel_rules.add_torch_light(ours, level, r, c)
        assert ours.tobytes() == state.light_map.tobytes()
    assert checked["near True"] > 100 and checked["near False"] > 100
    assert checked["can enter True"] > 100 and checked["can enter False"] > 100
