"""The 63 MiniHack tasks and full NetHack, registered as data (no engine import).

Horizons are upstream MiniHack's ``max_episode_steps`` capped at the standard tier's 512.

Full NetHack (``full.NetHackFull``, extended tier: NetHack's score as reward, no clamp) gets
10,000 turns. A turn is one command, and one command (FAR_E, TRAVEL, a count) can take many game
turns, so this is room to clear several dungeon levels and to meet hunger (a new character starts
with 900 nutrition and burns one a turn) while one episode still fits a rollout budget. NLE's
own cap, a million keystrokes, is for agents that press one key per step.
"""

from __future__ import annotations

from ...core import register_variants
from ...core.task import STANDARD_TURN_CAP

# level -> upstream horizon
_HORIZONS = {
    "room-5x5": 100, "room-15x15": 300, "room-random-5x5": 100, "room-random-15x15": 300,
    "room-dark-5x5": 100, "room-dark-15x15": 300, "room-monster-5x5": 100, "room-monster-15x15": 300,
    "room-trap-5x5": 100, "room-trap-15x15": 300, "room-ultimate-5x5": 100, "room-ultimate-15x15": 300,
    "corridor-r2": 1000, "corridor-r3": 1000, "corridor-r5": 1000,
    "corridorbattle": 350, "corridorbattle-dark": 350,
    "keyroom-s5": 200, "keyroom-s15": 400, "keyroom-dark-s5": 200, "keyroom-dark-s15": 400,
    "mazewalk-9x9": 200, "mazewalk-15x15": 1000, "mazewalk-45x19": 1000,
    "mazewalk-mapped-9x9": 200, "mazewalk-mapped-15x15": 1000, "mazewalk-mapped-45x19": 1000,
    "river": 350, "river-narrow": 350, "river-lava": 350, "river-monster": 350, "river-monsterlava": 350,
    "hidenseek": 200, "hidenseek-mapped": 200, "hidenseek-lava": 200, "hidenseek-big": 400,
    "boxoban-unfiltered": 400, "boxoban-medium": 400, "boxoban-hard": 400,
    "memento-short": 5000, "memento-f2": 5000, "memento-f4": 5000,
    "memento-hard": 512, "quaff": 250, "quaff-distract": 250,   # ours (custom.py): no upstream horizon
    "eat": 250, "eat-distract": 250, "pray": 250, "pray-distract": 250, "read": 250, "read-distract": 250,
    "sink": 250, "sink-distract": 250, "wield": 250, "wield-distract": 250,
    "wod-easy": 50, "wod-medium": 150, "wod-hard": 400, "wod-pro": 1000,
    "lavacross-full": 250, "lavacross-levitate": 400, "lavacross-levitate-potion-inv": 400,
    "lavacross-levitate-ring-inv": 400,
}

register_variants("glyphbench_rl.games.nethack.engine:MiniHackTask", "MiniHack", {
    f"glyphbench/minihack-{level}-v0": dict(level=level, max_turns=min(steps, STANDARD_TURN_CAP))
    for level, steps in _HORIZONS.items()
})

register_variants("glyphbench_rl.games.nethack.full:NetHackFull", "NetHack", {
    "glyphbench/nethack-full-v0": dict(max_turns=10_000),
}, tier="extended")
