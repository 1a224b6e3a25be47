"""Classics: puzzles and familiar games. Importing a module registers its tasks.

Each game is one module built on ``core.GlyphTask`` and the shared mechanics in ``games.common``
(grid motion and search, lanes, physics, waves, board cells, the palette). The one engine-level
module of the family is ``versus`` (the turn loop and outcomes of games against a built-in
opponent); game modules import it, never each other.
"""

from . import snake  # noqa: F401
from . import maze  # noqa: F401
from . import twenty48  # noqa: F401
from . import lightsout  # noqa: F401
from . import sokoban  # noqa: F401
from . import floodfill  # noqa: F401
from . import nonogram  # noqa: F401
from . import pipeconnect  # noqa: F401
from . import mirrorlaser  # noqa: F401
from . import minesweeper  # noqa: F401
from . import memorymatch  # noqa: F401
from . import icesliding  # noqa: F401
from . import rushhour  # noqa: F401
from . import gravitymaze  # noqa: F401
from . import guardevasion  # noqa: F401
from . import warehouse  # noqa: F401
from . import farm  # noqa: F401
from . import bomberman  # noqa: F401
from . import towerdefense  # noqa: F401
from . import wavedefense  # noqa: F401
from . import connectfour  # noqa: F401
from . import nim  # noqa: F401
from . import battleship  # noqa: F401
from . import tron  # noqa: F401
from . import artillery  # noqa: F401
from . import match3  # noqa: F401
from . import tetris  # noqa: F401
from . import flappy  # noqa: F401
from . import frogger  # noqa: F401
from . import ski  # noqa: F401
from . import lunarlander  # noqa: F401
from . import platformer  # noqa: F401
