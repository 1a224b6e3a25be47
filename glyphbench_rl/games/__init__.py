"""Game families. Importing this package registers every task (heavy engines load lazily).

One subpackage per family (``classics``, ``minigrid`` ...), one module per game, plus each
family's own engine-level modules; ``common`` holds the mechanics more than one family uses
(grid motion and search, lines of sight, lanes and spawners, falling and ballistics, waves,
board-cell helpers, the shared glyph palette). A family imports only ``core`` and ``common``,
never another family; a game module imports only its family's engine-level modules, never
another game (``tests/test_import_graph.py`` checks all of this).
"""

from . import arcade  # noqa: F401
from . import classics  # noqa: F401
from . import craftax  # noqa: F401
from . import minigrid  # noqa: F401
from . import nethack  # noqa: F401
from . import procgen  # noqa: F401
