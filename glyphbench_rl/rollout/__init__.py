"""Batched multi-turn rollouts and the policy backends they call."""

from .backend import (BackendError, GenRequest, Generation, PolicyBackend, RandomBackend,
                      ScriptedBackend)
from .engine import EngineStats, EpisodeSpec, RolloutEngine

__all__ = ["BackendError", "EngineStats", "EpisodeSpec", "GenRequest", "Generation",
           "PolicyBackend", "RandomBackend", "RolloutEngine", "ScriptedBackend"]
