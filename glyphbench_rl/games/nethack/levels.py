"""The MiniHack levels as data (light: imports nothing heavy).

Each level names where it comes from, the goal the system prompt states, and whether the
episode can be lost. ``source`` is upstream MiniHack's registered ID (its des file, reward events
and end condition are used unchanged) or ``"module:function"`` of a level of our own, for the IDs
upstream lacks: the function returns the env keyword arguments (a des file and, if any, a reward
manager) and is imported only when such a task is made.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Level:
    source: str
    goal: str
    lose: str = "you die"          # how the episode is lost ("" = it cannot be)
    rewards: str = ""              # the prompt's reward text, when not the plain win/lose one
    actions: tuple[str, ...] = ()  # the only actions offered (upstream's own restriction), or all


STAIRS = "reach the staircase down (>)"
_SQUEAK = "a board squeaks under you or you die"
_ROOM = "The level is one room. Goal: " + STAIRS + "."
_OURS = "glyphbench_rl.games.nethack.custom:"   # our levels for the IDs upstream lacks
_CORRIDOR = ("Rooms joined by corridors; a door or corridor may be hidden (SEARCH finds it) and a door "
             "locked (APPLY your lock pick beside it; KICK is not offered). Goal: ")
_KEYROOM = ("The staircase is in a small room behind a locked door. PICKUP the key, then APPLY beside "
            "the door: that unlocks and opens it. Goal: " + STAIRS + ".")


def _level(source: str, goal: str, lose: str = "you die") -> Level:
    return Level(source, goal, lose)


def _boxoban(difficulty: str, about: str) -> Level:
    return Level(f"glyphbench_rl.games.nethack.boxoban_env:{difficulty}",
                 f"A 10x10 Sokoban level ({about}): push every boulder onto a fountain. You "
                 "push a boulder by walking into it; it moves one cell unless a wall or another "
                 "boulder is behind it, and it cannot be pulled. Only the four straight moves are offered.",
                 lose="", actions=("MOVE_N", "MOVE_S", "MOVE_E", "MOVE_W"),
                 rewards="+0.1 each time a boulder is pushed onto a fountain (-0.1 when one is pushed "
                         "off), +0.7 when every boulder stands on a fountain (+1 in all); no other reward.")


LEVELS: dict[str, Level] = {
    # -- navigation (a rogue with autopickup on) ----------------------------------------------
    "room-5x5": _level("MiniHack-Room-5x5-v0", _ROOM),
    "room-15x15": _level("MiniHack-Room-15x15-v0", _ROOM),
    "room-random-5x5": _level("MiniHack-Room-Random-5x5-v0", _ROOM),
    "room-random-15x15": _level("MiniHack-Room-Random-15x15-v0", _ROOM),
    "room-dark-5x5": _level("MiniHack-Room-Dark-5x5-v0", "The level is one unlit room: you see only next to you. Goal: " + STAIRS + "."),
    "room-dark-15x15": _level("MiniHack-Room-Dark-15x15-v0", "The level is one unlit room: you see only next to you. Goal: " + STAIRS + "."),
    "room-monster-5x5": _level("MiniHack-Room-Monster-5x5-v0", "A random monster is in the room. Goal: " + STAIRS + "."),
    "room-monster-15x15": _level("MiniHack-Room-Monster-15x15-v0", "Random monsters are in the room. Goal: " + STAIRS + "."),
    "room-trap-5x5": _level("MiniHack-Room-Trap-5x5-v0", "The room holds a hidden teleportation trap. Goal: " + STAIRS + "."),
    "room-trap-15x15": _level("MiniHack-Room-Trap-15x15-v0", "The room holds many hidden teleportation traps. Goal: " + STAIRS + "."),
    "room-ultimate-5x5": _level("MiniHack-Room-Ultimate-5x5-v0", "The room is unlit and holds a random monster and a hidden teleportation trap. Goal: " + STAIRS + "."),
    "room-ultimate-15x15": _level("MiniHack-Room-Ultimate-15x15-v0", "The room is unlit and holds random monsters and many hidden teleportation traps. Goal: " + STAIRS + "."),
    "corridor-r2": _level("MiniHack-Corridor-R2-v0", _CORRIDOR + STAIRS + "."),
    "corridor-r3": _level("MiniHack-Corridor-R3-v0", _CORRIDOR + STAIRS + "."),
    "corridor-r5": _level("MiniHack-Corridor-R5-v0", _CORRIDOR + STAIRS + "."),
    "corridorbattle": _level("MiniHack-CorridorBattle-v0", "A corridor leads from your room to a hall where giant rats wait by the stairs; in the corridor they come one at a time. Goal: " + STAIRS + "."),
    "corridorbattle-dark": _level("MiniHack-CorridorBattle-Dark-v0", "The level is unlit. A corridor leads from your room to a hall where giant rats wait by the stairs; in the corridor they come one at a time. Goal: " + STAIRS + "."),
    "keyroom-s5": _level("MiniHack-KeyRoom-S5-v0", _KEYROOM),
    "keyroom-s15": _level("MiniHack-KeyRoom-S15-v0", _KEYROOM),
    "keyroom-dark-s5": _level("MiniHack-KeyRoom-Dark-S5-v0", "The rooms are unlit. " + _KEYROOM),
    "keyroom-dark-s15": _level("MiniHack-KeyRoom-Dark-S15-v0", "The rooms are unlit. " + _KEYROOM),
    "mazewalk-9x9": _level("MiniHack-MazeWalk-9x9-v0", "An unlit maze. Goal: " + STAIRS + "."),
    "mazewalk-15x15": _level("MiniHack-MazeWalk-15x15-v0", "An unlit maze. Goal: " + STAIRS + "."),
    "mazewalk-45x19": _level("MiniHack-MazeWalk-45x19-v0", "An unlit maze. Goal: " + STAIRS + "."),
    "mazewalk-mapped-9x9": _level("MiniHack-MazeWalk-Mapped-9x9-v0", "A maze shown in full from the start. Goal: " + STAIRS + "."),
    "mazewalk-mapped-15x15": _level("MiniHack-MazeWalk-Mapped-15x15-v0", "A maze shown in full from the start. Goal: " + STAIRS + "."),
    "mazewalk-mapped-45x19": _level("MiniHack-MazeWalk-Mapped-45x19-v0", "A maze shown in full from the start. Goal: " + STAIRS + "."),
    "river": _level("MiniHack-River-v0", "A river of water lies between you and the stairs; you cannot swim, but a boulder pushed into the water (walk into it) usually fills that cell. Goal: " + STAIRS + "."),
    "river-narrow": _level("MiniHack-River-Narrow-v0", "A narrow river of water lies between you and the stairs; you cannot swim, but a boulder pushed into the water (walk into it) usually fills that cell. Goal: " + STAIRS + "."),
    "river-lava": _level("MiniHack-River-Lava-v0", "A river of water and lava lies between you and the stairs; walking into lava is deadly; a boulder pushed into water (walk into it) usually fills that cell. Goal: " + STAIRS + "."),
    "river-monster": _level("MiniHack-River-Monster-v0", "A river of water lies between you and the stairs, and monsters roam; a boulder pushed into the water (walk into it) usually fills that cell. Goal: " + STAIRS + "."),
    "river-monsterlava": _level("MiniHack-River-MonsterLava-v0", "A river of water and lava lies between you and the stairs, and monsters roam; walking into lava is deadly; a boulder pushed into water (walk into it) usually fills that cell. Goal: " + STAIRS + "."),
    "hidenseek": _level("MiniHack-HideNSeek-v0", "Trees and clouds block the view; a powerful monster is somewhere. Goal: " + STAIRS + " without being caught."),
    "hidenseek-mapped": _level("MiniHack-HideNSeek-Mapped-v0", "Trees and clouds block the view, the layout is shown; a powerful monster is somewhere. Goal: " + STAIRS + " without being caught."),
    "hidenseek-lava": _level("MiniHack-HideNSeek-Lava-v0", "Trees, clouds and lava; a powerful monster is somewhere. Goal: " + STAIRS + " without being caught."),
    "hidenseek-big": _level("MiniHack-HideNSeek-Big-v0", "A large field of trees and clouds; a powerful monster is somewhere. Goal: " + STAIRS + " without being caught."),
    "memento-short": _level("MiniHack-Memento-Short-F2-v0", "The monster shown behind bars at the start tells which branch of the fork ahead is the right one; remember it. Goal: kill the grid bug (x) at the end of the right branch; the other branch holds a squeaky board.", _SQUEAK),
    "memento-f2": _level("MiniHack-Memento-F2-v0", "The monster shown behind bars at the start tells which of the two branches at the end of the long dark corridor is the right one; remember it. Goal: kill the grid bug (x) at the end of the right branch; the other branch holds a squeaky board.", _SQUEAK),
    "memento-f4": _level("MiniHack-Memento-F4-v0", "The two monsters shown behind bars at the start tell which of the four branches at the end of the long dark corridor is the right one; remember them. Goal: kill the grid bug (x) at the end of the right branch; the others hold squeaky boards.", _SQUEAK),
    "memento-hard": _level(_OURS + "memento_hard", "Three monsters are shown behind bars at the start; remember them. Of the eight branches at the end of the dark corridor, one is right for that trio of monsters: kill the grid bug at its end (+1); the others end on squeaky boards (-1).", _SQUEAK),
    "boxoban-unfiltered": _boxoban("unfiltered", "any solvable level, four boulders"),
    "boxoban-medium": _boxoban("medium", "four boulders, 14 to 17 pushes at best"),
    "boxoban-hard": _boxoban("hard", "four boulders, 18 or more pushes at best"),
    # -- skills (a caveman, autopickup off) ----------------------------------------------------------
    "eat": _level("MiniHack-Eat-v0", "Goal: eat the apple (%) (walk onto it and EAT, or PICKUP and EAT)."),
    "eat-distract": _level("MiniHack-Eat-Distr-v0", "A monster and a random object are in the room too. Goal: eat an apple (walk onto it and EAT, or PICKUP and EAT)."),
    "pray": _level("MiniHack-Pray-v0", "Goal: PRAY while standing on the altar (_)."),
    "pray-distract": _level("MiniHack-Pray-Distr-v0", "A monster and a random object are in the room too. Goal: PRAY while standing on the altar (_)."),
    "read": _level("MiniHack-Read-v0", "Goal: READ the scroll (?) (PICKUP it first)."),
    "read-distract": _level("MiniHack-Read-Distr-v0", "A monster and a random object (maybe another scroll) are in the room too. Goal: READ the blank (unlabeled) scroll (PICKUP it first)."),
    "sink": _level("MiniHack-Sink-v0", "Goal: QUAFF from the sink (#): stand on it and QUAFF."),
    "sink-distract": _level("MiniHack-Sink-Distr-v0", "A monster and a random object are in the room too. Goal: QUAFF from the sink (#): stand on it and QUAFF."),
    "quaff": _level(_OURS + "quaff", "Goal: QUAFF the potion of healing (!) (PICKUP it first)."),
    "quaff-distract": _level(_OURS + "quaff_distract", "A monster and another object (maybe another potion) are in the room too. Goal: QUAFF the potion of healing (!) (PICKUP it first)."),
    "wield": _level("MiniHack-Wield-v0", "Goal: WIELD the dagger ()) (PICKUP it first)."),
    "wield-distract": _level("MiniHack-Wield-Distr-v0", "A monster and a random object are in the room too. Goal: WIELD the dagger (PICKUP it first)."),
    "wod-easy": _level("MiniHack-WoD-Easy-Full-v0", "You carry a wand of death (an unidentified wand); a minotaur sleeps down the corridor. Goal: kill it: ZAP the wand at it (the ray flies 7-13 cells straight and bounces off walls)."),
    "wod-medium": _level("MiniHack-WoD-Medium-Full-v0", "A wand of death (an unidentified wand) lies next to you; a sleeping minotaur blocks the far end of the corridor. Goal: " + STAIRS + " behind it (PICKUP the wand and ZAP it at the minotaur; the ray flies 7-13 cells straight and bounces off walls)."),
    "wod-hard": _level("MiniHack-WoD-Hard-Full-v0", "A wand of death (an unidentified wand) lies in your room; an awake minotaur comes down the corridor. Goal: " + STAIRS + " at its end (PICKUP the wand and ZAP it at the minotaur; the ray flies 7-13 cells straight and bounces off walls)."),
    "wod-pro": _level("MiniHack-WoD-Pro-Full-v0", "A maze; a wand of death (an unidentified wand) lies somewhere in it and an awake minotaur roams it. Goal: " + STAIRS + " (PICKUP the wand and ZAP it at the minotaur; the ray flies 7-13 cells straight and bounces off walls)."),
    "lavacross-full": _level("MiniHack-LavaCross-Full-v0", "A river of lava lies between you and the stairs. An item on your side (PICKUP it) gets you across: a potion or ring of levitation or levitation boots let you float (QUAFF, WIELD), a wand of cold or a frost horn freezes the lava in a ray (ZAP, APPLY). Goal: " + STAIRS + "."),
    "lavacross-levitate": _level("MiniHack-LavaCross-Levitate-Full-v0", "A river of lava lies between you and the stairs. A levitation item on your side (a potion, ring or boots: PICKUP it, then QUAFF or WIELD it) lets you float across. Goal: " + STAIRS + "."),
    "lavacross-levitate-potion-inv": _level("MiniHack-LavaCross-Levitate-Potion-Inv-Full-v0", "A river of lava lies between you and the stairs. You carry a potion of levitation: QUAFF it and float across. Goal: " + STAIRS + "."),
    "lavacross-levitate-ring-inv": _level("MiniHack-LavaCross-Levitate-Ring-Inv-Full-v0", "A river of lava lies between you and the stairs. You carry a ring of levitation: put it on (WIELD) and float across. Goal: " + STAIRS + "."),
}
