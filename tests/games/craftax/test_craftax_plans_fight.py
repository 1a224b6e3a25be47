"""Scripted win and loss paths for the Craftax fight and survival tasks.

Each WIN path plays the task through ``task.step`` only (``planner.Planner``: it reads the
state to plan: mob cells, cooldowns, health) and wins with every reward term paid (or, for the
tasks that run to the horizon, ends alive with a return of at least 0.5). The potion tasks are
won blind (potions tried once health can take the harmful one); a second test drinks the
healing potion by its (hidden) effect. Each LOSS path dies and is paid the scenario's death
penalty on the step it dies. No jax here.
"""

from __future__ import annotations

import pytest

from glyphbench_rl.core import registry
from glyphbench_rl.games.craftax.planner import Planner, live_mobs
from glyphbench_rl.games.craftax.scenarios import SCENARIOS
from glyphbench_rl.games.craftax.tables import Action as A
from glyphbench_rl.games.craftax.tables import BlockType as B


def start(name: str, seed: int) -> Planner:
    task = registry.make(f"glyphbench/craftax-{name}-v0")
    task.reset(seed=seed)
    return Planner(task)


def kills(p, name: str) -> int:
    return p.task.tally.kills.get(name, 0)


# -- win paths ------------------------------------------------------------------------------------

def win_fightzombie(p):
    p.skirmish("zombie", 2)


def win_survivehorde(p):
    p.skirmish(None, 8, rest_below=3, rest_to=3)


def win_fight_cow(p):
    # the zombie comes at turn 30: meet it first (0.3), then the cow (0.7, ends the episode)
    p.skirmish("zombie", 1, rest_below=3, rest_to=3)
    p.skirmish("cow", 1)


def win_fight_zombies(p):
    p.skirmish("zombie", 5, rest_below=3, rest_to=3)


def win_fight_skeletons(p):
    p.skirmish("skeleton", 4, rest_below=3, rest_to=3)


def win_wave_defense(p):
    # 5 of the 10 zombies (half the return), then keep out of reach to the horizon
    p.skirmish("zombie", 5, rest_below=3, rest_to=3)
    p.survive(200, keep_away=True)


def win_bow(p):
    # shoot; out of arrows, make more at the table (1 wood + 1 stone: 2 arrows), placing a new
    # table (2 wood) when the skeletons' arrows broke it; then the sword
    need = 4 if p.task.scenario.name == "bow-kite" else 5
    p.shoot("skeleton", need)
    inv = p.state.inventory
    while not p.done and inv.wood >= 1 and inv.stone >= 1 and kills(p, "skeleton") < need:
        arrows = inv.arrows
        if not p.cells(B.CRAFTING_TABLE) and (inv.wood < 3 or not p.table()):
            break
        if not p.craft(A.MAKE_ARROW) or inv.arrows != arrows + 2:
            break
    p.shoot("skeleton", need - kills(p, "skeleton"))
    p.skirmish("skeleton", need - kills(p, "skeleton"), rest_below=3, rest_to=3)


def win_fight_archers(p):
    p.shoot("skeleton", 5)
    p.skirmish("skeleton", 5, rest_below=3, rest_to=3)


def win_fight_spiders(p):
    p.skirmish("kobold", 3, rest_below=3, rest_to=3)


def win_fight_bats(p):
    p.skirmish("bat", 6)


def win_kiteskeletons(p):
    p.skirmish("skeleton", 4, rest_below=3, rest_to=3)


def win_survive(p):
    p.survive(200, keep_away=True)


def win_night_horde(p):
    p.skirmish(None, 4, rest_below=4, rest_to=4, until=lambda: p.task.tally.value("turn") >= 150)
    p.survive(200, keep_away=True)


def win_potion(p):
    # blind: keep away from the zombies until health can take a harmful potion (3), drink the
    # colours until health jumps (the healing one), then the zombies
    health = [p.state.player_health]

    def healed():
        jumped = p.state.player_health >= health[0] + 4
        health[0] = p.state.player_health
        return jumped

    assert p.try_potions(healed)
    p.skirmish("zombie", 2, rest_below=3, rest_to=3)


def win_potion_known(p):
    # the healing potion by its effect, read off the episode's (hidden) potion mapping
    assert p.drink_potion("heal")
    p.skirmish("zombie", 2, rest_below=3, rest_to=3)


def win_xp_attribute_spend(p):
    # the zombies first (at strength 1), health back to full, then the 2 XP on strength: the
    # knight (6 a blow, half of a sword's blow blocked) comes, and meets the sword in front
    p.skirmish("zombie", 2, rest_below=3, rest_to=3)
    while not p.done and p.state.player_health < 9:
        p.survive(1, keep_away=True)
    p.act(A.LEVEL_UP_STRENGTH)
    p.act(A.LEVEL_UP_STRENGTH)
    p.skirmish("knight", 1)


def win_reach_dungeon(p):
    assert p.take_ladder()


WINS = {
    "fightzombie": win_fightzombie, "survivehorde": win_survivehorde, "fight-cow": win_fight_cow,
    "fight-zombies": win_fight_zombies, "fight-skeletons": win_fight_skeletons,
    "wave-defense": win_wave_defense, "bow-kite": win_bow, "bow-kite-hard": win_bow,
    "fight-archers": win_fight_archers, "fight-spiders": win_fight_spiders,
    "fight-bats": win_fight_bats, "kiteskeletons": win_kiteskeletons, "survive-night": win_survive,
    "survivenight": win_survive, "night-horde-no-shelter": win_night_horde,
    "reach-dungeon": win_reach_dungeon, "potion-triage": win_potion, "potion-id-stakes": win_potion,
    "xp-attribute-spend": win_xp_attribute_spend,
}
SEEDS = {name: (0, 1) for name in WINS}
# the scripted player loses some seeds of these (seeds 0-5 measured: see the report); the
# seeds below are two it wins
SEEDS.update({"survivehorde": (0, 2), "wave-defense": (0, 2),
              "fight-zombies": (1, 2), "potion-triage": (1, 2)})


@pytest.mark.parametrize("name,seed", [(n, s) for n in WINS for s in SEEDS[n]])
def test_win_path(name, seed):
    p = start(name, seed)
    WINS[name](p)
    scenario = SCENARIOS[name]
    if scenario.success:
        assert p.task.won is True, (name, seed, p.total, p.task.tally.kills)
        assert p.total == pytest.approx(sum(t.unit * t.cap for t in scenario.terms))   # all terms
    else:
        p.wait(scenario.horizon)          # to the horizon
        assert p.done and p.task.won is not False
        assert p.state.player_health > 0
        assert p.total >= 0.5, (name, seed, p.total)


@pytest.mark.parametrize("name", ["potion-triage", "potion-id-stakes"])
@pytest.mark.parametrize("seed", [0, 1])
def test_win_path_knowing_the_potions(name, seed):
    p = start(name, seed)
    win_potion_known(p)
    assert p.task.won is True and p.total == pytest.approx(1.0)
    assert p.task.tally.potions["heal"] == 1 and p.task.tally.potions["harm"] == 0


# -- loss paths -----------------------------------------------------------------------------------

def die(p, limit: int = 600) -> float:
    """Stand in harm's way: walk beside the nearest monster (an archer: stay in its line) and
    wait there; returns the reward of the last step."""
    last = 0.0
    for _ in range(limit):
        if p.done:
            break
        before, turn = p.total, p.task.tally.value("turn")
        monsters = [m for m in live_mobs(p.state) if m.kind > 0]
        if monsters:
            m = min(monsters, key=lambda m: abs(m.cell[0] - p.pos[0]) + abs(m.cell[1] - p.pos[1]))
            near = abs(m.cell[0] - p.pos[0]) + abs(m.cell[1] - p.pos[1])
            in_line = m.cell[0] == p.pos[0] or m.cell[1] == p.pos[1]
            if not (m.kind == 2 and in_line and near <= 5):
                p.go([m.cell], limit=1)
        if p.task.tally.value("turn") == turn:
            p.act(A.NOOP)
        last = p.total - before
    return last


LOSSES = [n for n in WINS if n != "reach-dungeon"] + ["reach-dungeon"]


@pytest.mark.parametrize("name", LOSSES)
def test_loss_path(name):
    p = start(name, 0)
    last = die(p)
    assert p.done and p.task.won is False, (name, p.total)
    assert p.state.player_health <= 0
    assert last == pytest.approx(SCENARIOS[name].death)
    assert p.total <= 1.0 + SCENARIOS[name].death + 1e-9



@pytest.mark.parametrize("name", ["potion-triage", "potion-id-stakes"])
def test_loss_by_the_harmful_potion(name):
    # at 2 health the harmful potion (-3) kills on the step it is drunk
    p = start(name, 0)
    assert p.drink_potion("harm")
    assert p.done and p.task.won is False and p.state.player_health <= 0
    assert p.total == pytest.approx(SCENARIOS[name].death)
