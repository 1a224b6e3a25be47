"""Classics: puzzles and familiar games. Importing a module registers its tasks."""

from . import snake  # noqa: F401
from . import maze  # noqa: F401
from . import twenty48  # noqa: F401
from . import lightsout  # noqa: F401
from . import sokoban  # noqa: F401
