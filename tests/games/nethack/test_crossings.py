"""River, LavaCross and Memento on the real NetHack: scripted wins and losses on pinned seeds.

The players (``crossing_players``) read only the frame the agent reads and answer with action
names. Seeds are pinned where a level's random draw matters (LavaCross's item, Memento's cue,
River's monsters, which a scripted fighter does not always survive).
"""

from __future__ import annotations

import pytest

import glyphbench_rl
from crossing_players import (LavaCrossPlayer, MementoPlayer, RiverPlayer, Sight, kind_of, play,
                              walk_into_lava)


def make(level: str):
    return glyphbench_rl.make(f"glyphbench/minihack-{level}-v0")


def assert_won(task, ep) -> None:
    assert ep.terminated and not ep.truncated
    assert ep.won is True and ep.reward == 1.0 and task.episode_return == 1.0
    assert "Reward +1" in ep.messages[-1]


def assert_lost(task, ep) -> None:
    assert ep.terminated and ep.won is False
    assert ep.reward == -1.0 and task.episode_return == -1.0


# -- River: a ford of boulders --------------------------------------------------------------------
# (river 7 and river-narrow 10: the shown box grows westward; river-lava 3: the fords start hidden
# behind boulders; river-monster 0: a boulder already lies under the first water cell tried)
RIVER_WINS = [("river", 0), ("river", 7), ("river-narrow", 10), ("river-lava", 1), ("river-lava", 3),
              ("river-monster", 0), ("river-monster", 1), ("river-monsterlava", 6),
              ("river-monsterlava", 8)]
FORD = {"river-narrow": 2}                                 # water cells across; else 3


@pytest.mark.parametrize("level,seed", RIVER_WINS)
def test_river_won_by_pushing_boulders_into_the_water(level, seed):
    task = make(level)
    ep = play(task, RiverPlayer(), seed)
    assert_won(task, ep)
    fills = sum("Now you can cross it!" in m for m in ep.messages)
    assert fills >= FORD.get(level, 3)                     # a boulder that sinks fills nothing


def test_river_water_throws_you_back_and_waiting_pays_nothing():
    """Water is not deadly (you crawl back out, items rust): a River episode whose ford is never
    built ends unpaid at the horizon."""
    task = make("river")
    task.reset(seed=0)
    s = Sight(task.frame)
    row = s.hero[1]
    water_x = min(x for (x, y), m in s.cells.items() if m == "water" and y == row)
    for _ in range(water_x - s.hero[0]):
        _, reward, term, trunc, _ = task.step("MOVE_E")
        assert not term and reward == 0.0
    assert "crawl out of the water" in task.frame.message
    assert Sight(task.frame).hero[0] == water_x - 1
    while not (term or trunc):
        _, reward, term, trunc, info = task.step("SEARCH")
    assert trunc and not term and info["won"] is None and task.episode_return == 0.0
    assert task.turn == task.max_turns == 350


@pytest.mark.parametrize("level,seed", [("river-lava", 0), ("river-monsterlava", 0)])
def test_river_lost_in_the_lava(level, seed):
    task = make(level)
    ep = play(task, walk_into_lava, seed)
    assert_lost(task, ep)
    assert "lava" in ep.messages[-1] and task.frame.hud.endswith("Dead")


def test_river_monsters_kill_a_hero_who_stands_still():
    task = make("river-monster")
    ep = play(task, lambda frame: "SEARCH", 1)
    assert_lost(task, ep)
    assert "You die" in ep.messages[-1]


# -- LavaCross: float or freeze -------------------------------------------------------------------
LAVA_WINS = [("lavacross-full", 0, "horn"), ("lavacross-full", 2, "potion"),
             ("lavacross-full", 3, "wand"), ("lavacross-full", 6, "ring"),
             ("lavacross-full", 11, "boots"), ("lavacross-levitate", 0, "boots"),
             ("lavacross-levitate", 2, "ring"), ("lavacross-levitate", 6, "potion"),
             ("lavacross-levitate-potion-inv", 0, "potion"), ("lavacross-levitate-potion-inv", 1, "potion"),
             ("lavacross-levitate-ring-inv", 0, "ring"), ("lavacross-levitate-ring-inv", 1, "ring")]
USED = {"potion": "QUAFF", "ring": "WIELD", "boots": "WIELD", "wand": "ZAP", "horn": "APPLY"}


@pytest.mark.parametrize("level,seed,kind", LAVA_WINS)
def test_lavacross_won_with_each_item(level, seed, kind):
    task = make(level)
    task.reset(seed=seed)
    s = Sight(task.frame)
    shown = [kind_of(m) for m in s.cells.values()] + [kind_of(i) for i in s.inventory()]
    assert kind in shown                                    # the pinned seed's item
    ep = play(task, LavaCrossPlayer(), seed)
    assert_won(task, ep)
    used = ep.actions.index(USED[kind])
    if kind in ("wand", "horn"):
        assert "The lava cools and solidifies." in ep.messages[used]
    else:
        assert "You start to float in the air!" in ep.messages[used]
        assert "Lev" in task.frame.hud.split(" | ")[1]     # won on the stairs while floating
    if level.endswith("-inv"):
        assert "PICKUP" not in ep.actions


@pytest.mark.parametrize("level", ["lavacross-full", "lavacross-levitate", "lavacross-levitate-potion-inv",
                                   "lavacross-levitate-ring-inv"])
def test_lavacross_lost_in_the_lava(level):
    task = make(level)
    ep = play(task, walk_into_lava, 0)
    assert_lost(task, ep)
    assert "You fall into the lava!" in ep.messages[-1]


# -- Memento: remember the cue --------------------------------------------------------------------
MEMENTO = [("memento-short", 0, {"lichen"}), ("memento-short", 1, {"blue jelly"}),
           ("memento-f2", 0, {"lichen"}), ("memento-f2", 1, {"blue jelly"}),
           ("memento-f4", 0, {"blue jelly", "green mold"}), ("memento-f4", 1, {"spotted jelly", "red mold"}),
           ("memento-f4", 2, {"spotted jelly", "green mold"}), ("memento-f4", 5, {"blue jelly", "red mold"})]
CUES = ("jelly", "lichen", "mold")


def cues(task) -> set[str]:
    return {m for _, m in task.frame.legend if m.endswith(CUES)}


@pytest.mark.parametrize("level,seed,cue", MEMENTO)
def test_memento_won_by_the_cued_branch(level, seed, cue):
    task = make(level)
    task.reset(seed=seed)
    assert cues(task) == cue
    ep = play(task, MementoPlayer(), seed)
    assert_won(task, ep)
    assert "You kill the grid bug!" in ep.messages[-1]
    assert not cues(task)                                  # the cue was remembered, not seen


@pytest.mark.parametrize("level,seed,cue", MEMENTO)
def test_memento_lost_by_another_branch(level, seed, cue):
    """Upstream pays -1 and ends the episode when a squeaky board squeaks; that is a loss."""
    task = make(level)
    ep = play(task, MementoPlayer(wrong=True), seed)
    assert_lost(task, ep)
    assert "squeaks" in ep.messages[-1]


@pytest.mark.parametrize("level", ["river", "river-narrow"])
def test_river_lost_to_an_angry_god(level):
    """Their water is not deadly, but praying again and again is, in every MiniHack task: the
    prompt's "-1 if you die" holds here too."""
    task = make(level)
    task.reset(seed=0)
    for _ in range(12):
        _, reward, term, trunc, info = task.step("PRAY")
        if term:
            break
    assert term and info["won"] is False and reward == -1.0 and task.episode_return == -1.0
    assert "killed by the wrath of" in task.frame.message
    assert "-1 if you die" in task.system_prompt()
