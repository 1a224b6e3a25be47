"""The mob movers' shortcuts give what the plain rules give: the table of blocks a mob may enter
(``bestiary.MOB_TYPE_ENTERABLE``, which the movers read in place of upstream's collision test)
and the damage a blow does to the player when it has no fire or ice in it (the enchantments are
then not read)."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from glyphbench_rl import make
from glyphbench_rl.games.craftax import mobs
from glyphbench_rl.games.craftax.bestiary import (MOB_TYPE_COLLISION_MAPPING,
                                                   MOB_TYPE_DAMAGE_MAPPING, MOB_TYPE_ENTERABLE,
                                                   PROJECTILE_DAMAGE)
from glyphbench_rl.games.craftax.tables import (ARMOUR_DEFENCE_PER_TIER, BOSS_FIGHT_EXTRA_DAMAGE,
                                                BOSS_LEVEL, ENCHANTED_ARMOUR_DEFENCE,
                                                SLEEPING_MELEE_FACTOR, SOLID_BLOCKS, BlockType)


def _upstream_may_enter(block: BlockType, collision: tuple) -> bool:
    """The block part of upstream's is_position_in_bounds_not_in_mob_not_colliding, as it is
    written there: not solid, and each of ground (neither solid, water nor lava), water and
    lava allowed unless the collision triple forbids it."""
    solid, water, lava = block in SOLID_BLOCKS, block == BlockType.WATER, block == BlockType.LAVA
    on_ground = not solid and not water and not lava
    return (not solid and (not collision[0] or not on_ground) and (not collision[1] or not water)
            and (not collision[2] or not lava))


def test_enterable_table_is_upstreams_collision_rule():
    for type_id, row in enumerate(MOB_TYPE_COLLISION_MAPPING):
        for kind, collision in enumerate(row):
            assert [MOB_TYPE_ENTERABLE[type_id][kind][b] for b in BlockType] == \
                [_upstream_may_enter(b, collision) for b in BlockType], (type_id, kind)


def _plain_damage(state, damage: tuple) -> float:
    """Upstream's get_damage_done_to_player as one sum over the three elements."""
    enchant = state.armour_enchantments.tolist()
    defence = (ARMOUR_DEFENCE_PER_TIER * sum(state.inventory.armour.tolist()),
               ENCHANTED_ARMOUR_DEFENCE * enchant.count(1),
               ENCHANTED_ARMOUR_DEFENCE * enchant.count(2))
    scale = 1.0 + BOSS_FIGHT_EXTRA_DAMAGE if state.player_level == BOSS_LEVEL else 1.0
    return sum((1.0 - d) * x * scale for d, x in zip(defence, damage))


# every blow a mob deals (melee and projectile columns), and each asleep (melee x3.5)
BLOWS = sorted({d for row in MOB_TYPE_DAMAGE_MAPPING for d in (row[1], row[3])}
               | set(PROJECTILE_DAMAGE))
BLOWS += [tuple(SLEEPING_MELEE_FACTOR * x for x in d) for d in BLOWS]


@pytest.mark.parametrize("level", [0, BOSS_LEVEL])
def test_damage_to_player_is_the_plain_sum_to_the_last_bit(level):
    rng = np.random.default_rng(level)
    task = make("glyphbench/craftax-firstday-v0")
    task.reset(seed=0)
    state = task.state
    state.player_level = level
    kits = [rng.integers(0, 3, 4) for _ in range(20)] + [np.full(4, 2), np.zeros(4, int)]
    for armour, damage in itertools.product(kits, BLOWS):
        state.inventory.armour[:] = armour
        state.armour_enchantments[:] = rng.integers(0, 3, 4)
        assert mobs.damage_to_player(state, damage) == _plain_damage(state, damage), \
            (armour, state.armour_enchantments, damage)
    assert any(d[1] == d[2] == 0.0 for d in BLOWS) and any(d[1] or d[2] for d in BLOWS)
