"""Arcade: grid re-imaginings of Atari 2600 games, each registered twice from one parameter set:
``glyphbench/miniatari-<game>-v0`` (MiniAtari, standard tier: a compact field, a return in
[-1, 1]) and ``glyphbench/atari-<game>-v0`` (Atari, extended tier: a larger field, lives, a long
horizon, native-style points).

Engine-level modules, which the games import (and nothing else of the family):
- ``engine``: ``ArcadeTask``, ``ArcadeParams``, the score rules of patterns A/B/C/D (``Tally``,
  ``Milestones``, ``Duel``), lives, the still-rows-plus-movers field, the HUD, and
  ``register_arcade`` (both presets from one call);
- ``bodies``: bodies with a velocity and swept motion, wrapping, guns (range, cooldown,
  limit), formations that sweep and descend, scripted opponents (``track``, ``chase``),
  countdowns (fuel, oxygen, clocks).
"""

from . import freeway, pong, spaceinvaders
from . import alien, asteroids, battlezone, berzerk, robotank, seaquest, timepilot, wizardofwor, yarsrevenge

__all__ = ["freeway", "pong", "spaceinvaders", "alien", "berzerk", "wizardofwor", "battlezone", "robotank", "timepilot", "asteroids", "yarsrevenge", "seaquest"]
