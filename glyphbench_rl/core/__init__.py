"""The task contract: no torch, no verifiers."""

from .actions import Action, ActionSet, cell_names
from .frame import Frame, build_frame, check_frame, render
from .registry import (MissingExtraError, TaskSpec, UnknownTaskError, get_spec, list_tasks, make,
                       register, register_variants)
from .seeding import HELDOUT_SEEDS, TRAIN_SEEDS, heldout_seeds, training_seeds
from .task import STANDARD_TURN_CAP, EpisodeEnded, GlyphTask
from .tasklist import read_task_file, resolve_tasks

__all__ = [
    "Action", "ActionSet", "cell_names", "Frame", "build_frame", "check_frame", "render",
    "MissingExtraError", "TaskSpec", "UnknownTaskError", "get_spec", "list_tasks", "make",
    "register", "register_variants", "HELDOUT_SEEDS", "TRAIN_SEEDS", "heldout_seeds", "training_seeds",
    "STANDARD_TURN_CAP", "EpisodeEnded", "GlyphTask", "read_task_file", "resolve_tasks",
]
