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


STAIRS = "reach the staircase down (>)"
_SQUEAK = "a board squeaks under you or you die"
_ROOM = "The level is one room. Goal: " + STAIRS + "."


def _level(source: str, goal: str, lose: str = "you die") -> Level:
    return Level(source, goal, lose)


LEVELS: dict[str, Level] = {
    # -- navigation (a rogue with autopickup on) ----------------------------------------------
    "room-5x5": _level("MiniHack-Room-5x5-v0", _ROOM),
    "room-15x15": _level("MiniHack-Room-15x15-v0", _ROOM),
    "room-random-5x5": _level("MiniHack-Room-Random-5x5-v0", _ROOM),
    "room-random-15x15": _level("MiniHack-Room-Random-15x15-v0", _ROOM),
    "room-dark-5x5": _level("MiniHack-Room-Dark-5x5-v0", "The level is one unlit room: you see only next to you. Goal: " + STAIRS + "."),
    "room-dark-15x15": _level("MiniHack-Room-Dark-15x15-v0", "The level is one unlit room: you see only next to you. Goal: " + STAIRS + "."),
    "room-monster-5x5": _level("MiniHack-Room-Monster-5x5-v0", "The room holds a hostile monster. Goal: " + STAIRS + "."),
    "room-monster-15x15": _level("MiniHack-Room-Monster-15x15-v0", "The room holds hostile monsters. Goal: " + STAIRS + "."),
    "room-trap-5x5": _level("MiniHack-Room-Trap-5x5-v0", "The room holds a hidden or visible trap. Goal: " + STAIRS + "."),
    "room-trap-15x15": _level("MiniHack-Room-Trap-15x15-v0", "The room holds many traps. Goal: " + STAIRS + "."),
    "room-ultimate-5x5": _level("MiniHack-Room-Ultimate-5x5-v0", "The room is unlit and holds a monster and a trap. Goal: " + STAIRS + "."),
    "room-ultimate-15x15": _level("MiniHack-Room-Ultimate-15x15-v0", "The room is unlit and holds monsters and traps. Goal: " + STAIRS + "."),
    "corridor-r2": _level("MiniHack-Corridor-R2-v0", "Rooms joined by corridors; doors may be closed or locked (walk into a door to open it, KICK is not offered). Goal: " + STAIRS + "."),
    "corridor-r3": _level("MiniHack-Corridor-R3-v0", "Rooms joined by corridors; doors may be closed or locked. Goal: " + STAIRS + "."),
    "corridor-r5": _level("MiniHack-Corridor-R5-v0", "Rooms joined by corridors; doors may be closed or locked. Goal: " + STAIRS + "."),
    "corridorbattle": _level("MiniHack-CorridorBattle-v0", "A corridor leads from your room to a hall full of rats; fight them in the corridor one at a time. Goal: " + STAIRS + "."),
    "corridorbattle-dark": _level("MiniHack-CorridorBattle-Dark-v0", "An unlit corridor leads from your room to a hall full of rats; fight them in the corridor one at a time. Goal: " + STAIRS + "."),
    "keyroom-s5": _level("MiniHack-KeyRoom-S5-v0", "The staircase is in a small room behind a locked door. Pick up the key, APPLY it toward the door to unlock it, open the door by walking into it, and " + STAIRS + "."),
    "keyroom-s15": _level("MiniHack-KeyRoom-S15-v0", "The staircase is in a small room behind a locked door. Pick up the key, APPLY it toward the door to unlock it, open the door by walking into it, and " + STAIRS + "."),
    "keyroom-dark-s5": _level("MiniHack-KeyRoom-Dark-S5-v0", "The rooms are unlit. The staircase is in a small room behind a locked door. Pick up the key, APPLY it toward the door to unlock it, open the door by walking into it, and " + STAIRS + "."),
    "keyroom-dark-s15": _level("MiniHack-KeyRoom-Dark-S15-v0", "The rooms are unlit. The staircase is in a small room behind a locked door. Pick up the key, APPLY it toward the door to unlock it, open the door by walking into it, and " + STAIRS + "."),
    "mazewalk-9x9": _level("MiniHack-MazeWalk-9x9-v0", "An unlit maze. Goal: " + STAIRS + ".", ""),
    "mazewalk-15x15": _level("MiniHack-MazeWalk-15x15-v0", "An unlit maze. Goal: " + STAIRS + ".", ""),
    "mazewalk-45x19": _level("MiniHack-MazeWalk-45x19-v0", "An unlit maze. Goal: " + STAIRS + ".", ""),
    "mazewalk-mapped-9x9": _level("MiniHack-MazeWalk-Mapped-9x9-v0", "A maze whose walls are all shown. Goal: " + STAIRS + ".", ""),
    "mazewalk-mapped-15x15": _level("MiniHack-MazeWalk-Mapped-15x15-v0", "A maze whose walls are all shown. Goal: " + STAIRS + ".", ""),
    "mazewalk-mapped-45x19": _level("MiniHack-MazeWalk-Mapped-45x19-v0", "A maze whose walls are all shown. Goal: " + STAIRS + ".", ""),
    "river": _level("MiniHack-River-v0", "A river of water lies between you and the stairs; you cannot swim, but a boulder pushed into the water (walk into it) usually fills that cell. Goal: " + STAIRS + ".", ""),
    "river-narrow": _level("MiniHack-River-Narrow-v0", "A narrow river of water lies between you and the stairs; you cannot swim, but a boulder pushed into the water (walk into it) usually fills that cell. Goal: " + STAIRS + ".", ""),
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
    # -- skills (a caveman, autopickup off) ----------------------------------------------------------
    "eat": _level("MiniHack-Eat-v0", "Goal: eat the apple (%) (walk onto it and EAT, or PICKUP and EAT)."),
    "eat-distract": _level("MiniHack-Eat-Distr-v0", "A monster and another object are in the room too. Goal: eat the apple (%)."),
    "pray": _level("MiniHack-Pray-v0", "Goal: PRAY while standing on the altar (_)."),
    "pray-distract": _level("MiniHack-Pray-Distr-v0", "A monster and another object are in the room too. Goal: PRAY while standing on the altar (_)."),
    "read": _level("MiniHack-Read-v0", "Goal: READ the scroll (?) (PICKUP it first)."),
    "read-distract": _level("MiniHack-Read-Distr-v0", "A monster and another object are in the room too. Goal: READ the scroll (?) (PICKUP it first)."),
    "sink": _level("MiniHack-Sink-v0", "Goal: QUAFF from the sink (#): stand on it and QUAFF."),
    "sink-distract": _level("MiniHack-Sink-Distr-v0", "A monster and another object are in the room too. Goal: QUAFF from the sink (#)."),
    "wield": _level("MiniHack-Wield-v0", "Goal: WIELD the dagger ()) (PICKUP it first)."),
    "wield-distract": _level("MiniHack-Wield-Distr-v0", "A monster and another object are in the room too. Goal: WIELD the dagger ()) (PICKUP it first)."),
    "wod-easy": _level("MiniHack-WoD-Easy-Full-v0", "You stand on a wand of death; a minotaur sleeps down the corridor. Goal: kill the minotaur (PICKUP the wand and ZAP it toward the minotaur)."),
    "wod-medium": _level("MiniHack-WoD-Medium-Full-v0", "A wand of death lies near you; a minotaur waits in the long corridor. Goal: " + STAIRS + " at the far end (kill the minotaur with the wand on the way)."),
    "wod-hard": _level("MiniHack-WoD-Hard-Full-v0", "A wand of death lies in the safe room; an awake minotaur guards the corridor. Goal: " + STAIRS + " (kill the minotaur with the wand)."),
    "wod-pro": _level("MiniHack-WoD-Pro-Full-v0", "A wand of death lies somewhere in the spiral maze with a minotaur. Goal: " + STAIRS + "."),
    "lavacross-full": _level("MiniHack-LavaCross-Full-v0", "A river of lava lies between you and the stairs. An item on your side (PICKUP it) gets you across: a potion or ring of levitation or levitation boots let you float (QUAFF, WIELD), a wand of cold or a frost horn freezes the lava in a ray (ZAP, APPLY). Goal: " + STAIRS + "."),
    "lavacross-levitate": _level("MiniHack-LavaCross-Levitate-Full-v0", "A river of lava lies between you and the stairs. A levitation item on your side (a potion, ring or boots: PICKUP it, then QUAFF or WIELD it) lets you float across. Goal: " + STAIRS + "."),
    "lavacross-levitate-potion-inv": _level("MiniHack-LavaCross-Levitate-Potion-Inv-Full-v0", "A river of lava lies between you and the stairs. You carry a potion of levitation: QUAFF it and float across. Goal: " + STAIRS + "."),
    "lavacross-levitate-ring-inv": _level("MiniHack-LavaCross-Levitate-Ring-Inv-Full-v0", "A river of lava lies between you and the stairs. You carry a ring of levitation: put it on (WIELD) and float across. Goal: " + STAIRS + "."),
}
