"""Game families. Importing this package registers every task (heavy engines load lazily)."""

from . import classics  # noqa: F401
from . import minigrid  # noqa: F401
