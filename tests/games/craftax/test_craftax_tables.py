"""Every table of ``games.craftax.tables`` equals the ``craftax`` package's constant (the mob
tables are ``bestiary``'s: test_craftax_bestiary.py). Numbers upstream writes inline in
``game_logic.py`` (recipes, mining tiers, intrinsic limits, chest loot, potion effects, spell and
enchant costs) are named in ``tables`` and checked where they act: in the lockstep test
(test_craftax_lockstep.py) against the package's step, and below where a table is plain data
(the maxima formulas, the damage vector). No jit is needed here."""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("craftax")

from craftax.craftax import constants as C  # noqa: E402
from craftax.craftax.craftax_state import StaticEnvParams  # noqa: E402
from craftax.craftax.util import game_logic_utils as U  # noqa: E402

from glyphbench_rl.games.craftax import mobs, rules, tables as T  # noqa: E402


def test_enumerations_match():
    for ours, theirs in ((T.BlockType, C.BlockType), (T.ItemType, C.ItemType),
                         (T.Action, C.Action), (T.Achievement, C.Achievement)):
        assert {m.name: m.value for m in ours} == {m.name: m.value for m in theirs}


def test_block_tables():
    assert list(T.IS_SOLID) == [bool(x) for x in np.asarray(C.SOLID_BLOCK_MAPPING)]
    assert list(T.CAN_PLACE_ITEM) == [bool(x) for x in np.asarray(C.CAN_PLACE_ITEM_MAPPING)]
    assert T.SOLID_BLOCKS == frozenset(C.SOLID_BLOCKS)
    assert T.CAN_PLACE_ITEM_BLOCKS == frozenset(C.CAN_PLACE_ITEM_BLOCKS)


def test_directions_and_close_blocks():
    dirs = np.asarray(C.DIRECTIONS)
    for action in T.Action:
        expected = tuple(int(x) for x in dirs[action]) if action < len(dirs) else (0, 0)
        assert T.DIRECTIONS.get(action, (0, 0)) == expected
    assert [tuple(x) for x in np.asarray(C.CLOSE_BLOCKS).tolist()] == list(T.CLOSE_BLOCKS)


def test_achievement_weights_and_level_maps():
    assert list(T.ACHIEVEMENT_REWARD) == np.asarray(C.ACHIEVEMENT_REWARD_MAP).tolist()
    assert T.INTERMEDIATE_ACHIEVEMENTS == frozenset(C.INTERMEDIATE_ACHIEVEMENTS)
    assert T.VERY_ADVANCED_ACHIEVEMENTS == frozenset(C.VERY_ADVANCED_ACHIEVEMENTS)
    level_map = np.asarray(C.LEVEL_ACHIEVEMENT_MAP).tolist()
    assert T.LEVEL_ACHIEVEMENT[0] is None and len(T.LEVEL_ACHIEVEMENT) == len(level_map)
    assert [int(a) for a in T.LEVEL_ACHIEVEMENT[1:]] == level_map[1:]
    # the level names follow the entry achievements' names
    for name, achievement in zip(T.LEVEL_NAMES[1:], T.LEVEL_ACHIEVEMENT[1:]):
        words = name.upper().split()
        assert all(w.rstrip("S") in achievement.name for w in words), (name, achievement)


def test_game_mechanics_constants():
    assert T.MONSTERS_KILLED_TO_CLEAR_LEVEL == C.MONSTERS_KILLED_TO_CLEAR_LEVEL
    assert T.BOSS_FIGHT_EXTRA_DAMAGE == C.BOSS_FIGHT_EXTRA_DAMAGE
    assert T.BOSS_FIGHT_SPAWN_TURNS == C.BOSS_FIGHT_SPAWN_TURNS
    assert T.BOSS_LEVEL == T.NUM_LEVELS - 1 == StaticEnvParams().num_levels - 1
    np.testing.assert_array_equal(T.TORCH_LIGHT_MAP, np.asarray(C.TORCH_LIGHT_MAP))


def test_dark_levels_follow_the_world_generation_configs():
    from craftax.craftax.world_gen import world_gen_configs as W
    smooth = np.asarray(W.ALL_SMOOTHGEN_CONFIGS.default_light).tolist()
    # generate_world splices levels as (smooth 0, dungeon 0, smooth 1, dungeon 1, dungeon 2,
    # smooth 2, smooth 3, smooth 4, smooth 5); dungeon levels are fully lit (light_map = 1)
    spliced = [smooth[0], 1.0, smooth[1], 1.0, 1.0, smooth[2], smooth[3], smooth[4], smooth[5]]
    assert list(T.LEVEL_DEFAULT_LIGHT) == spliced
    assert T.DARK_LEVELS == {2, 5, 7, 8}


class _Player:
    """Enough of a state for the package's stat helpers."""

    def __init__(self, **kw):
        self.__dict__.update(kw)


@pytest.mark.parametrize("attr", [1, 2, 3, 5])
def test_maxima_formulas(attr):
    p = _Player(player_strength=attr, player_dexterity=attr, player_intelligence=attr)
    assert T.max_health(attr) == int(U.get_max_health(p))
    assert T.max_food(attr) == int(U.get_max_food(p))
    assert T.max_drink(attr) == int(U.get_max_drink(p))
    assert T.max_energy(attr) == int(U.get_max_energy(p))
    assert T.max_mana(attr) == int(U.get_max_mana(p))


@pytest.mark.parametrize("sword,strength,intelligence,enchant",
                         [(0, 1, 1, 0), (1, 3, 1, 0), (2, 2, 4, 1), (4, 5, 5, 2), (3, 1, 2, 1)])
def test_player_damage_vector(sword, strength, intelligence, enchant):
    inv = _Player(sword=sword)
    p = _Player(inventory=inv, player_strength=strength, player_intelligence=intelligence,
                sword_enchantment=enchant)
    assert np.allclose(rules.player_damage_vector(p), np.asarray(U.get_player_damage_vector(p)))


@pytest.mark.parametrize("armour,enchantments,level,sleeping",
                         [((0, 0, 0, 0), (0, 0, 0, 0), 0, False), ((1, 2, 1, 0), (1, 0, 2, 0), 3, False),
                          ((2, 2, 2, 2), (1, 1, 2, 2), 8, True)])
def test_player_damage_taken(armour, enchantments, level, sleeping):
    import jax.numpy as jnp
    inv = _Player(armour=np.array(armour))
    p = _Player(inventory=inv, armour_enchantments=np.array(enchantments), player_level=level,
                is_sleeping=sleeping)
    ju = _Player(inventory=_Player(armour=jnp.array(armour)), player_level=level,
                 armour_enchantments=jnp.array(enchantments))
    static = _Player(num_levels=9)
    for vec in ((2.0, 0.0, 0.0), (1.0, 3.0, 0.5), (0.0, 0.0, 4.0)):
        theirs = float(U.get_damage_done_to_player(ju, static, jnp.array(vec)))
        assert np.isclose(mobs.damage_to_player(p, vec), theirs, atol=1e-5)
        # upstream scales a melee hit on a sleeper by 1 + 2.5 before the defence; the blow wakes
        melee = float(U.get_damage_done_to_player(
            ju, static, jnp.array(vec) * (1 + 2.5 * sleeping)))
        p.player_health, p.is_sleeping, p.is_resting = 20.0, sleeping, False
        p.achievements = np.zeros(T.NUM_ACHIEVEMENTS, bool)
        assert np.isclose(mobs.hurt_player(p, vec, melee=True), melee, atol=1e-5)
        assert np.isclose(p.player_health, 20.0 - melee, atol=1e-5) and not p.is_sleeping
        assert p.achievements[T.Achievement.WAKE_UP] == sleeping


def test_light_level_formula():
    for t in (0, 1, 75, 150, 299, 300, 451, 1000):
        theirs = float(U.calculate_light_level(t, _Player(day_length=300)))
        assert abs(T.light_level(t, 300) - theirs) < 1e-5


def test_recipes_are_complete():
    crafting = {a for a in T.Action if a.name.startswith("MAKE_")}
    assert set(T.RECIPES) == crafting
    assert set(T.PLACING) == {a for a in T.Action if a.name.startswith("PLACE_")}
