"""MiniGrid: Farama MiniGrid's tasks on one shared engine. Importing a module registers its tasks.

Engine-level modules: ``engine`` (``MiniGridTask``: MiniGrid's rules, its level-building helpers
and random draws, ``beside``), ``world`` (the objects, their glyphs on top of the shared
palette in ``games.common.palette``), ``grid`` (the grid and the agent's view), ``rooms``
(MiniGrid's RoomGrid, the two-room layout and the pick-up-the-target mission) and ``solver``
(a search used by win scripts and tests). Each game module only generates its level and
imports engine-level modules, never another game.
"""

from . import empty  # noqa: F401
from . import doorkey  # noqa: F401
from . import fourrooms  # noqa: F401
from . import lavagap  # noqa: F401
from . import crossing  # noqa: F401
from . import dynamicobstacles  # noqa: F401
from . import distshift  # noqa: F401
from . import multiroom  # noqa: F401
from . import keycorridor  # noqa: F401
from . import lockedroom  # noqa: F401
from . import unlock  # noqa: F401
from . import unlockpickup  # noqa: F401
from . import blockedunlockpickup  # noqa: F401
from . import memory  # noqa: F401
from . import fetch  # noqa: F401
from . import gotodoor  # noqa: F401
from . import gotoobject  # noqa: F401
from . import putnear  # noqa: F401
from . import redbluedoors  # noqa: F401
from . import obstructedmaze  # noqa: F401
from . import playground  # noqa: F401
