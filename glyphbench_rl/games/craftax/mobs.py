"""TEMPORARY placeholder: mob movement, attacks, projectiles and spawning do nothing here.

Another helper writes the real ``mobs`` module (upstream ``update_mobs`` / ``spawn_mobs``); it
replaces this file at the merge with the same two signatures, which ``rules.step`` calls.
"""

from __future__ import annotations


def update(state, settings, draws) -> None:
    """Placeholder: upstream moves mobs and projectiles here; this does nothing."""


def spawn(state, settings, draws) -> None:
    """Placeholder: upstream spawns and despawns mobs here; this does nothing."""
