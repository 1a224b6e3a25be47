"""Scripted win and loss paths for the Craftax floor, fight-magic and descent tasks.

Each win path plays the task through ``task.step`` only (``planner.Planner``: it reads the state
to plan, as an agent reads the observation) and must win; each loss path plays a losing policy
(walk up to the monsters and stand still: ``Planner.surrender``) and must die, paying the
scenario's death penalty. Seeds are listed per task: the scripted player is competent, not
perfect, on these hard floors (the report lists the seeds it loses).
"""

from __future__ import annotations

import pytest

from glyphbench_rl.core import registry
from glyphbench_rl.games.craftax.planner import Planner
from glyphbench_rl.games.craftax.scenarios import SCENARIOS, parse_test
from glyphbench_rl.games.craftax.tables import Action as A, BlockType as B


def _floor(p):
    p.descend_floor(limit=480)


def _floors(n):
    def play(p):
        for _ in range(n):
            if p.done:
                break
            p.descend_floor(limit=480)
    return play


def _learn_spell(p):
    p.open_chest()
    p.act(A.READ_BOOK)
    p.act(A.CAST_FIREBALL if p.state.learned_spells[0] else A.CAST_ICEBALL)


def _enchant_weapon(p):
    p.enchant(A.ENCHANT_SWORD, B.ENCHANTMENT_TABLE_FIRE)
    p.hunt("kobold", 2, limit=140)


def _enchant_choice(p):
    p.enchant(A.ENCHANT_SWORD, B.ENCHANTMENT_TABLE_ICE)
    p.hunt("fire elemental", 2, limit=180, ranged=False)


def _spell_only(p):
    p.cast("fire elemental", 2, spell=A.CAST_ICEBALL, limit=200)


def _torchdescend(p):
    p.craft(A.MAKE_TORCH)
    p.torch()
    p.descend_floor(limit=300)


def _dark_ambush(p):
    p.torch()
    p.hunt("kobold", 4, limit=200)


# task -> (win policy, seeds it wins on)
WINS = {
    "dungeonexplore": (_floor, (0, 3)),
    "dungeonclear": (lambda p: p.hunt(count=5, limit=220), (0, 1)),
    "dungeon": (_floor, (1, 2)),
    "gnomish-mines": (_floor, (0, 1)),
    "sewers": (_floor, (0, 1)),
    "vaults": (_floor, (0, 1)),
    "troll-mines": (_floor, (1, 2)),
    "fire-realm": (_floor, (0, 1)),
    "ice-realm": (_floor, (0, 1)),
    "bossfight": (lambda p: p.hunt("troll", 1, limit=480), (0, 1)),
    "learn-spell": (_learn_spell, (0, 1)),
    "enchant-weapon": (_enchant_weapon, (0, 1)),
    "enchant-choice": (_enchant_choice, (0, 1)),
    "spell-only-kill": (_spell_only, (0, 1)),
    "speedrun": (_floors(5), (0, 1)),
    "torchdescend": (_torchdescend, (0, 1)),
    "dark-ambush": (_dark_ambush, (0, 1)),
    "floor-clear-9hp": (_floor, (1, 3)),
    "descent-gauntlet": (_floors(2), (0, 1)),
    "clear-floor-8gate": (_floor, (0, 1)),
}
LOSS_SEEDS = (0, 1)


def play(name: str, seed: int, policy):
    task = registry.make(f"glyphbench/craftax-{name}-v0")
    task.reset(seed=seed)
    planner = Planner(task)
    policy(planner)
    return task, planner


@pytest.mark.parametrize("name,seed", [(n, s) for n, (_, seeds) in WINS.items() for s in seeds])
def test_win_path(name, seed):
    task, planner = play(name, seed, WINS[name][0])
    assert task.won, (name, seed, planner.total, task.tally.kills, float(task.state.player_health))
    assert task.state.player_health > 0
    assert 0.99 <= planner.total <= 1.0 + 1e-9


LOSERS = list(WINS)      # (the necromancer's paths: test_craftax_plans_necromancer.py)


@pytest.mark.parametrize("name,seed", [(n, s) for n in LOSERS for s in LOSS_SEEDS])
def test_loss_path(name, seed):
    scenario = SCENARIOS[name]
    task, planner = play(name, seed, lambda p: p.surrender(limit=scenario.horizon))
    assert task.done and task.won is False
    assert task.state.player_health <= 0
    assert scenario.death == -1.0
    # the return is what the terms paid before the end (each test here only grows) plus the
    # death penalty, paid on the dying step
    paid = sum(t.unit * t.units(task.tally, parse_test(t.test, task.tally)) for t in scenario.terms)
    assert planner.total == pytest.approx(paid + scenario.death)
    assert planner.total < 0.5
