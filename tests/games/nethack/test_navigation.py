"""Win and loss paths of the 31 MiniHack navigation tasks, played by the scripted player of
``players.py`` (which reads only the grid, legend, HUD and message the agent reads).

Every task is won on a pinned seed (+1, the episode ends). Every task can be lost: where the
level holds something deadly (monsters, CorridorBattle's rats, HideNSeek's hunter) the test dies
to it; elsewhere the level itself cannot kill (no monsters, and MiniHack spawns none; Room-Trap's
traps only teleport), so the test dies the one way NetHack always offers, praying again and again
until the angered god strikes, and checks that standing still until the horizon gives 0.
"""

from __future__ import annotations

import pytest

import glyphbench_rl
from glyphbench_rl.games.nethack.levels import LEVELS
from players import KIN, Player, hold_corridor, hunt, is_trap, keyroom, stairs


def make(level: str):
    return glyphbench_rl.make(f"glyphbench/minihack-{level}-v0")


# level -> (seed, policy, fights, what the log must show, in order: "ACTION: message" substrings)
WINS = {
    "room-5x5": (0, stairs, True, ()),
    "room-15x15": (0, stairs, True, ()),
    "room-random-5x5": (0, stairs, True, ()),
    "room-random-15x15": (2, stairs, True, ()),
    "room-dark-5x5": (0, stairs, True, ()),
    "room-dark-15x15": (3, stairs, True, ()),
    "room-monster-5x5": (3, stairs, True, ("You kill the jackal!",)),
    "room-monster-15x15": (0, stairs, True, ()),
    "room-trap-5x5": (3, stairs, True, ()),
    "room-trap-15x15": (2, stairs, True, ()),
    "room-ultimate-5x5": (3, stairs, True, ()),
    "room-ultimate-15x15": (3, stairs, True, ()),
    "corridor-r2": (14, stairs, True, ("SEARCH: You find a hidden door.",)),
    # a locked door: DROP the blindfold and the sack so that APPLY takes the lock pick
    "corridor-r3": (10, stairs, True, ("This door is locked.", "DROP: You drop an uncursed blindfold.",
                                       "DROP: You drop an empty uncursed sack.",
                                       "APPLY: You succeed in picking the lock.", "The door opens.")),
    "corridor-r5": (3, stairs, True, ()),
    "corridorbattle": (2, hold_corridor, True, ("You kill the giant rat!",)),
    "corridorbattle-dark": (1, hold_corridor, True, ("You kill the giant rat!",)),
    # upstream's KeyRoom step: APPLY with the key beside the locked door unlocks and opens it
    "keyroom-s5": (0, keyroom, True, ("PICKUP: h - a key named", "This door is locked.", "APPLY: ")),
    "keyroom-s15": (4, keyroom, True, ("This door is locked.", "APPLY: ")),
    "keyroom-dark-s5": (3, keyroom, True, ("This door is locked.", "APPLY: ")),
    "keyroom-dark-s15": (1, keyroom, True, ("This door is locked.", "APPLY: ")),
    "mazewalk-9x9": (3, stairs, True, ()),
    "mazewalk-15x15": (0, stairs, True, ()),
    "mazewalk-45x19": (0, stairs, True, ()),
    "mazewalk-mapped-9x9": (1, stairs, True, ()),
    "mazewalk-mapped-15x15": (0, stairs, True, ()),
    "mazewalk-mapped-45x19": (0, stairs, True, ()),
    "hidenseek": (5, stairs, False, ()),
    "hidenseek-mapped": (1, stairs, False, ()),
    "hidenseek-lava": (6, stairs, False, ()),
    "hidenseek-big": (0, stairs, False, ()),
}

# level -> (seed, policy) of a death by what the level holds
DEADLY = {
    "room-monster-5x5": (3, lambda p: "WAIT"),
    "room-monster-15x15": (3, lambda p: "WAIT"),
    "room-ultimate-5x5": (3, lambda p: "WAIT"),
    "room-ultimate-15x15": (3, lambda p: "WAIT"),
    "corridorbattle": (0, stairs),               # straight into the hall: the rats surround you
    "corridorbattle-dark": (0, stairs),
    "hidenseek": (0, hunt),
    "hidenseek-mapped": (0, hunt),
    "hidenseek-lava": (0, hunt),
    "hidenseek-big": (0, hunt),
}
HARMLESS = sorted(set(WINS) - set(DEADLY))      # levels that cannot kill you by themselves


def in_order(log: list[tuple[str, str]], expected: tuple[str, ...]) -> bool:
    lines = iter(f"{action}: {message}" for action, message in log)
    return all(any(want in line for line in lines) for want in expected)


def test_the_tables_cover_the_navigation_tasks():
    navigation = {level for level in LEVELS
                  if level.startswith(("room-", "corridor", "keyroom", "mazewalk", "hidenseek"))}
    assert set(WINS) == navigation and len(WINS) == 31


@pytest.mark.parametrize("level", sorted(WINS))
def test_win(level):
    seed, policy, fights, expected = WINS[level]
    p = Player(make(level), seed, fight=fights).play(policy)
    assert p.info["won"] is True and p.terminated and not p.truncated
    assert p.reward == 1.0 and p.ret == 1.0 and p.info["return"] == 1.0   # +1, and nothing else
    assert p.message.endswith("Reward +1")
    assert in_order(p.log, expected), p.log


def _die(p: Player) -> None:
    assert p.info["won"] is False and p.terminated and not p.truncated
    assert p.reward == -1.0 and p.ret == -1.0
    assert p.hud.endswith("| Dead") and "killed by" in p.message and p.message.endswith("Reward -1")
    assert "-1 if you die" in p.task.system_prompt()


@pytest.mark.parametrize("level", sorted(DEADLY))
def test_death_by_the_level(level):
    seed, policy = DEADLY[level]
    p = Player(make(level), seed).play(policy)
    _die(p)
    assert "killed by the wrath" not in p.message


@pytest.mark.parametrize("level", HARMLESS)
def test_death_by_prayer(level):
    """Praying at once, and again, angers the god, who strikes within a few prayers."""
    p = Player(make(level), 0).play(lambda p: "PRAY", max_steps=12)
    _die(p)
    assert "Thou hast angered me." in p.message and "killed by the wrath of" in p.message


@pytest.mark.parametrize("level", HARMLESS)
def test_standing_still_until_the_horizon_gives_nothing(level):
    task = make(level)
    task.reset(seed=1)
    total, done = 0.0, False
    while not done:
        _, r, terminated, truncated, info = task.step("WAIT")
        total, done = total + r, terminated or truncated
    assert truncated and not terminated and task.turn == task.max_turns
    assert total == 0.0 and info["return"] == 0.0 and info["won"] is not True


@pytest.mark.parametrize("level", ["room-trap-5x5", "room-trap-15x15"])
def test_teleportation_traps_do_not_kill(level):
    """Walk over every floor cell but the stairs, then to and fro over the traps found, until
    the horizon: the traps teleport you around the room, nothing hurts you, and the player keeps
    its bearings through each teleport."""
    task = make(level)
    p = Player(task, 0)
    offsets, places, traps = set(), [], set()

    def wander(p: Player) -> str:
        offsets.add((p.hero[0] - task.hero[0], p.hero[1] - task.hero[1]))
        places.append(task.hero)
        p.blocked |= set(p.find(lambda m: m == "stairs down"))
        traps.update(p.find(is_trap))
        floor = [c for c in p.find(lambda m: KIN.get(m, m) == "floor") if c != p.hero]
        return p.toward([c for c in floor if c not in p.visited] or list(traps - {p.hero}) or floor) or "WAIT"

    p.play(wander)
    assert p.truncated and p.ret == 0.0 and not p.hud.endswith("Dead")
    assert traps and all(p.map[c] in ("teleportation trap", "you") for c in traps)
    assert len(offsets) == 1                                          # our map never slipped
    jumps = sum(max(abs(a[0] - b[0]), abs(a[1] - b[1])) > 1 for a, b in zip(places, places[1:]))
    assert jumps >= 2                                                 # teleported, more than once
