"""Procgen: grid re-imaginings of OpenAI Procgen's games, every seed a different level.

Engine-level modules: ``engine`` (``ProcgenTask``: the five actions, the agent-centred view
window, the player's arrow, the HUD, the horizon) and ``mazes`` (maze levels over
``games.common.grid``, braiding, cached distance maps for chasers). Each game module generates
its level, moves its entities and pays its rewards, importing only those.
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
