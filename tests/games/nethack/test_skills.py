"""The 14 MiniHack skill tasks (eat, pray, read, sink, wield, each plain and with distractions,
and the four wand-of-death levels) on the real NetHack engine: a scripted win and a loss on
pinned seeds, and the answer rules each task leans on.

The players (``skill_players``) see only what an agent sees. Upstream's rewards: the eat, read
and wield tasks pay +1 once for a message event (the apple eaten, "This scroll seems to be
blank.", "dagger (weapon in hand)"), pray and sink +1 for PRAY or QUAFF on the altar or sink
confirmed with yes, wod-easy +1 for "You kill the minotaur", wod-medium/hard/pro +1 on the
staircase down; MiniHackTask adds -1 on death. Every one of these tasks can be lost: where no
monster is around, praying off the altar twice angers the god into killing the caveman.
"""

from __future__ import annotations

import re

import pytest

import glyphbench_rl
import skill_players as play   # noqa: E402  (this folder's helper)

SKILL_TASKS = ("eat", "eat-distract", "pray", "pray-distract", "read", "read-distract", "sink",
               "sink-distract", "wield", "wield-distract", "wod-easy", "wod-medium", "wod-hard",
               "wod-pro")
PLAYERS = {
    "eat": lambda t: play.use_in_place(t, "apple", "EAT"),
    "pray": lambda t: play.use_in_place(t, "altar", "PRAY"),
    "sink": lambda t: play.use_in_place(t, "sink", "QUAFF"),
    "read": lambda t: play.carry_and_use(t, "scroll", "READ"),
    "wield": lambda t: play.carry_and_use(t, "dagger", "WIELD"),
    "wod": play.wand_of_death,
}


def make(level: str, seed: int):
    task = glyphbench_rl.make(f"glyphbench/minihack-{level}-v0")
    task.reset(seed=seed)
    return task


def run_to_end(task, action: str) -> None:
    while not task.done:
        task.step(action)


# -- win paths ------------------------------------------------------------------------------------
WINS = [
    ("eat", 0),
    ("eat-distract", 3),          # the apple lies under you at the start ("You see here an apple.")
    ("eat-distract", 9),          # a lichen, and the random object is a second apple
    ("pray", 0),
    ("pray-distract", 6),         # a fox attacks on the way
    ("read", 0),
    ("read-distract", 2),         # the random object is another scroll
    ("read-distract", 3),         # the scroll lies under you at the start
    ("sink", 0),
    ("sink-distract", 2),         # a sewer rat
    ("wield", 0),
    ("wield-distract", 0),        # the random object is a banded mail (left on the floor)
    ("wod-easy", 0),
    ("wod-medium", 0),
    ("wod-hard", 0),
    ("wod-pro", 0),
]


@pytest.mark.parametrize("level,seed", WINS, ids=[f"{lv}-{s}" for lv, s in WINS])
def test_win_path(level, seed):
    task = make(level, seed)
    PLAYERS[level.split("-")[0]](task)
    assert task.done and task.won is True, task.frame.render()
    assert task.episode_return == 1.0          # one upstream event, no other reward on the way
    assert task.turn < task.max_turns
    assert "Reward +1" in task.frame.message


def test_all_skill_tasks_have_a_win_and_a_loss():
    assert {lv for lv, _ in WINS} == set(SKILL_TASKS)
    assert {lv for lv, *_ in LOSSES} == set(SKILL_TASKS)


# -- loss paths -----------------------------------------------------------------------------------
def pray_until_smitten(task):
    """No monster here: praying off the altar (too soon) angers the god, who kills you."""
    run_to_end(task, "PRAY")


def wait_for_the_monster(task):
    """Stand still; the room's hostile monster (or the awake minotaur) bites until you die."""
    run_to_end(task, "WAIT")


def attack_the_minotaur(task):
    """Ignore the wand: walk into the minotaur (exploring until it is seen) and fight it."""
    while not task.done:
        f = task.frame
        foes = play.monsters(f)
        step = play.path_step(f, foes) if foes else play.path_step(f, play.frontier(f))
        task.step(step or "WAIT")


LOSSES = [
    ("eat", 0, pray_until_smitten, "Ishtar"),        # (the caveman's god)
    ("pray", 0, pray_until_smitten, "Ishtar"),       # (the hero starts off the altar)
    ("read", 0, pray_until_smitten, "Ishtar"),
    ("sink", 0, pray_until_smitten, "Ishtar"),
    ("wield", 0, pray_until_smitten, "Ishtar"),
    ("eat-distract", 0, wait_for_the_monster, "a newt"),
    ("pray-distract", 2, wait_for_the_monster, "a sewer rat"),
    ("read-distract", 9, wait_for_the_monster, "a kobold"),
    ("sink-distract", 6, wait_for_the_monster, "a fox"),
    ("wield-distract", 7, wait_for_the_monster, "a jackal"),
    ("wod-easy", 0, attack_the_minotaur, "a minotaur"),      # it sleeps until attacked
    ("wod-medium", 0, attack_the_minotaur, "a minotaur"),
    ("wod-hard", 0, wait_for_the_monster, "a minotaur"),     # it is awake and comes for you
    ("wod-pro", 0, attack_the_minotaur, "a minotaur"),       # it never finds you if you wait
]


@pytest.mark.parametrize("level,seed,player,killer", LOSSES, ids=[f"{lv}-{s}" for lv, s, _, _ in LOSSES])
def test_loss_path(level, seed, player, killer):
    task = make(level, seed)
    if level == "pray":
        assert play.cells(task.frame, lambda m: "altar" in m)     # seen, so not under the hero
    player(task)
    assert task.done and task.won is False, task.frame.render()
    assert task.episode_return == -1.0 and task.turn < task.max_turns
    assert task.frame.hud.endswith("Dead")
    killed_by = re.search(r"killed by ([^.,]*)", task.frame.message).group(1)
    assert killed_by == killer if killer.startswith("a ") else killer in killed_by


def test_waiting_out_the_horizon_pays_nothing():
    task = make("eat", 0)
    run_to_end(task, "WAIT")
    assert task.turn == task.max_turns == 250
    assert task.won is None and task.episode_return == 0.0


# -- the answer rules each task needs -------------------------------------------------------------
def test_eat_a_carried_apple_takes_the_newest_item():
    task = make("eat", 0)
    assert play.walk_onto(task, "apple")
    task.step("PICKUP")
    assert [n for _, n in play.inventory(task.frame)][-1] == "apple"
    assert not task.done
    task.step("EAT")                               # "What do you want to eat? [f or ?*]": f
    assert task.won is True and task.episode_return == 1.0


def test_wield_takes_the_newest_equipment_and_drop_clears_a_misfit():
    """WIELD equips the newest equipment: body armour picked up after the dagger cannot be worn
    over the caveman's leather armour, so WIELD keeps trying it; DROP (the newest item) clears it."""
    task = make("wield-distract", 0)
    for word in ("dagger", "banded mail"):
        assert play.walk_onto(task, word)
        task.step("PICKUP")
    assert [n for _, n in play.inventory(task.frame)][-2:] == ["dagger", "banded mail"]
    task.step("WIELD")
    assert "already wearing" in task.frame.message and not task.done
    task.step("WIELD")
    assert "already wearing" in task.frame.message and not task.done
    task.step("DROP")
    assert "You drop a banded mail" in task.frame.message
    task.step("WIELD")
    assert task.won is True and "dagger (weapon in hand)" in task.frame.message


def test_read_the_other_scroll_after_a_wrong_one():
    """read-distract seed 2: the random object is a second scroll; reading it pays nothing, the
    blank one then wins (READ takes the newest scroll)."""
    task = make("read-distract", 2)
    scrolls = play.cells(task.frame, lambda m: "scroll" in m and play.is_item(m))
    assert len(scrolls) == 2
    play.carry_and_use(task, "scroll", "READ")
    assert task.won is True and task.episode_return == 1.0


def test_a_kill_before_a_more_prompt_still_pays():
    """wod-easy seed 0: the death ray kills the minotaur, then "The death ray bounces!" needs a
    --More--; upstream's message event reads only the last message, so the engine checks the
    messages before each --More-- too (else the task could never be won after this zap)."""
    task = make("wod-easy", 0)
    assert "wand" in play.inventory(task.frame)[-1][1]      # autopickup: it is yours already
    task.step("MOVE_E")
    task.step("ZAP")                                        # the only monster is due east
    msg = task.frame.message
    assert "You kill the minotaur!" in msg and "bounces" in msg.split("You kill the minotaur!")[1]
    assert task.won is True and task.episode_return == 1.0


def test_pray_needs_the_altar():
    task = make("pray", 0)
    task.step("PRAY")                               # off the altar: the god is displeased, no reward
    assert not task.done and task.episode_return == 0.0
    play.use_in_place(task, "altar", "PRAY")
    assert task.won is True and task.episode_return == 1.0


def test_goal_texts_name_real_actions():
    from glyphbench_rl.games.nethack.engine import ACTIONS
    from glyphbench_rl.games.nethack.levels import LEVELS
    names = {a.name for a in ACTIONS}
    for level in SKILL_TASKS:
        goal = LEVELS[level].goal
        for word in re.findall(r"\b[A-Z]{3,}\b", goal):
            assert word in names, (level, word)


def test_a_pile_is_listed_without_the_map_beside_it():
    """NetHack lists a pile in a window drawn over the map; the message keeps only the window."""
    task = make("wield-distract", 0)
    assert play.walk_onto(task, "banded mail")
    task.step("PICKUP")
    assert play.walk_onto(task, "dagger")
    task.step("DROP")                              # the mail now lies on the dagger
    task.step("MOVE_S")
    task.step("MOVE_N")
    assert task.frame.message == "Things that are here: a banded mail, a dagger."
