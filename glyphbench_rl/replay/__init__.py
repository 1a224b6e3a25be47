"""Trajectory schema and the replay viewers."""

from .schema import SCHEMA_VERSION, Step, Trajectory, TrajectoryFormatError, read_jsonl

__all__ = ["SCHEMA_VERSION", "Step", "Trajectory", "TrajectoryFormatError", "read_jsonl"]
