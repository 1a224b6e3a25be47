"""MiniGrid: Farama MiniGrid's tasks on one shared engine. Importing a module registers its tasks.

``engine.MiniGridTask`` holds MiniGrid's rules, ``world`` its objects, ``grid`` the grid and the
agent's view, ``solver`` a search used by tests; each family module only generates its level
(see README_FAMILIES.md).
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
