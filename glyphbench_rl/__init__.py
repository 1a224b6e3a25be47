"""glyphbench_rl: glyph-rendered game tasks and tools for RL post-training of language models."""

from importlib.util import find_spec as _find_spec

from .core import (ActionSet, EpisodeEnded, Frame, GlyphTask, TaskSpec, UnknownTaskError,
                   get_spec, list_tasks, make, resolve_tasks)
from . import games as _games  # noqa: F401  (registers every task)
from ._version import __version__


__all__ = ["ActionSet", "EpisodeEnded", "Frame", "GlyphTask", "TaskSpec", "UnknownTaskError",
           "get_spec", "list_tasks", "make", "resolve_tasks", "__version__"]

# `vf-eval glyphbench-rl` makes verifiers v1 import this module and take the Taskset, Env and
# Harness classes it exports. They load on first access, so `import glyphbench_rl` never imports
# verifiers, and `from glyphbench_rl import *` names them only where verifiers is installed.
_VERIFIERS_V1 = ("GlyphbenchTaskset", "GlyphbenchEnv", "GlyphbenchHarness")
if _find_spec("verifiers") is not None:
    __all__ += _VERIFIERS_V1


def __getattr__(name: str):
    if name in _VERIFIERS_V1:
        try:
            from .integrations import verifiers_v1
        except AttributeError as e:
            # verifiers' loader reads an AttributeError here as "no such export" and reports
            # that the module exports no Taskset; say what is really wrong instead
            from importlib.metadata import version
            raise ImportError(f"glyphbench_rl's verifiers adapter needs the verifiers v1 API of "
                              f"verifiers 0.4.0; this verifiers ({version('verifiers')}) lacks "
                              f"it: {e}") from e
        return getattr(verifiers_v1, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
