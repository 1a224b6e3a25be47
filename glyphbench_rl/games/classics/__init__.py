"""Classics: puzzles and familiar games. Importing a module registers its tasks."""

from . import snake  # noqa: F401
