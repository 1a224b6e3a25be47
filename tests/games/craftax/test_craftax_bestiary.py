"""Every mob table of ``bestiary`` equals upstream Craftax 1.6.1's constant (the ``craftax``
package is the oracle; no jit needed)."""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("craftax")

from craftax.craftax import constants as C  # noqa: E402
from craftax.craftax.craftax_state import EnvParams, StaticEnvParams  # noqa: E402

from glyphbench_rl.games.craftax import bestiary as B  # noqa: E402
from glyphbench_rl.games.craftax import state as S  # noqa: E402
from glyphbench_rl.games.craftax.tables import MobType  # noqa: E402


@pytest.mark.parametrize("name, ours", [
    ("FLOOR_MOB_MAPPING", B.FLOOR_MOB_MAPPING),
    ("FLOOR_MOB_SPAWN_CHANCE", B.FLOOR_MOB_SPAWN_CHANCE),
    ("MOB_TYPE_COLLISION_MAPPING", B.MOB_TYPE_COLLISION_MAPPING),
    ("MOB_TYPE_DAMAGE_MAPPING", B.MOB_TYPE_DAMAGE_MAPPING),
    ("MOB_TYPE_HEALTH_MAPPING", B.MOB_TYPE_HEALTH_MAPPING),
    ("MOB_TYPE_DEFENSE_MAPPING", B.MOB_TYPE_DEFENCE_MAPPING),
    ("RANGED_MOB_TYPE_TO_PROJECTILE_TYPE_MAPPING", B.RANGED_MOB_TYPE_TO_PROJECTILE_TYPE_MAPPING),
    ("MOB_ACHIEVEMENT_MAP", B.MOB_ACHIEVEMENT_MAP),
])
def test_table_equals_upstream(name, ours):
    theirs = np.asarray(getattr(C, name))
    mine = np.asarray(ours, dtype=theirs.dtype)
    assert mine.shape == theirs.shape
    np.testing.assert_allclose(mine, theirs, rtol=0, atol=1e-6)


def test_collision_kinds_equal_upstream():
    for name in ("COLLISION_LAND_CREATURE", "COLLISION_FLYING", "COLLISION_AQUATIC",
                 "COLLISION_AMPHIBIAN"):
        assert list(getattr(B, name)) == list(getattr(C, name))


def test_projectile_damage_is_the_projectile_column():
    theirs = np.asarray(C.MOB_TYPE_DAMAGE_MAPPING)[:, C.MobType.PROJECTILE.value]
    np.testing.assert_array_equal(np.asarray(B.PROJECTILE_DAMAGE, np.float32), theirs)
    assert len(B.PROJECTILE_DAMAGE) == len(C.ProjectileType)


def test_mechanics_constants():
    # (the level and boss-fight constants the mobs read are tables.py's: test_craftax_tables)
    static, params = StaticEnvParams(), EnvParams()
    assert params.mob_despawn_distance == S.Settings().mob_despawn_distance
    assert (S.MAX_MELEE, S.MAX_PASSIVE, S.MAX_RANGED) == (
        static.max_melee_mobs, static.max_passive_mobs, static.max_ranged_mobs)
    assert (B.MAX_MOB_PROJECTILE_SLOTS, B.MAX_PLAYER_PROJECTILE_SLOTS) == (
        static.max_mob_projectiles, static.max_player_projectiles)
    assert B.MAX_MOBS[MobType.MELEE] == static.max_melee_mobs


def test_enumerations_match_upstream():
    assert {m.name: m.value for m in MobType} == {m.name: m.value for m in C.MobType}


def test_names():
    assert B.mob_name(MobType.MELEE, 0, 0) == "zombie"
    assert B.mob_name(MobType.MELEE, 2, 1) == "gnome warrior"
    assert B.mob_name(MobType.RANGED, 5, 5) == "deep thing"
    assert B.mob_name(MobType.PASSIVE, 0, 0) == "cow"
    assert B.mob_name(MobType.PROJECTILE, 0, 5) == "slimeball"
    # every (class, type) a level spawns has a name, and they differ within a class
    for kind in (MobType.PASSIVE, MobType.MELEE, MobType.RANGED):
        names = {B.mob_name(kind, lvl, B.FLOOR_MOB_MAPPING[lvl][kind]) for lvl in range(9)}
        assert all(names)
    assert len(set(B.MOB_NAMES[MobType.MELEE])) == 8 == len(set(B.MOB_NAMES[MobType.RANGED]))
    # the achievement names agree with our names (DEFEAT_<NAME>, EAT_<NAME>)
    for kind in (MobType.MELEE, MobType.RANGED):
        for type_id, name in enumerate(B.MOB_NAMES[kind]):
            achievement = C.Achievement(B.MOB_ACHIEVEMENT_MAP[kind][type_id]).name
            words = name.upper().split(" ")
            assert words[-1] in achievement or name == "orc soldier", (name, achievement)
