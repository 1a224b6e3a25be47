"""Procgen: grid re-imaginings of OpenAI Procgen's games, every seed a different level.

Engine-level modules, which the games import (and nothing else of the family):
- ``engine``: ``ProcgenTask``, the five actions, the agent-centred view window, the player's
  arrow, the HUD (score, motion), the horizon;
- ``mazes``: maze levels over ``games.common.grid``, braiding, cached distance maps (maze,
  heist, chaser, miner);
- ``platforms``: side-view integer physics, patrols, shuriken and the level search over the
  game's own physics (coinrun, jumper, ninja, climber);
- ``shooting``: bodies with swept movement and collisions, guns, spawners (starpilot,
  bossfight, plunder, caveflyer, bigfish, dodgeball);
- ``scrolling``: lanes and auto-scroll (leaper, fruitbot).
Each game module generates its level, moves its entities and pays its rewards.
"""

from . import maze  # noqa: F401
from . import heist  # noqa: F401
from . import chaser  # noqa: F401
from . import miner  # noqa: F401
from . import coinrun  # noqa: F401
from . import jumper  # noqa: F401
from . import ninja  # noqa: F401
from . import climber  # noqa: F401
from . import leaper  # noqa: F401
from . import fruitbot  # noqa: F401
from . import bigfish  # noqa: F401
from . import dodgeball  # noqa: F401
from . import starpilot  # noqa: F401
from . import bossfight  # noqa: F401
from . import plunder  # noqa: F401
from . import caveflyer  # noqa: F401
