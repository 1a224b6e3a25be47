"""glyphbench_rl: glyph-rendered game tasks and tools for RL post-training of language models."""

from .core import (ActionSet, EpisodeEnded, Frame, GlyphTask, TaskSpec, UnknownTaskError,
                   get_spec, list_tasks, make, resolve_tasks)
from . import games as _games  # noqa: F401  (registers every task)

__version__ = "0.1.0"

__all__ = ["ActionSet", "EpisodeEnded", "Frame", "GlyphTask", "TaskSpec", "UnknownTaskError",
           "get_spec", "list_tasks", "make", "resolve_tasks", "__version__"]
