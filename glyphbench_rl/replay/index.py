"""An index over trajectory files: one pass records where each episode is, episodes load on demand.

``EpisodeIndex(path)`` reads a JSONL trajectory file (or an evaluation job directory, a training
run directory or its ``rollouts/`` folder) once, line by line, and keeps per episode only its byte
offset and length plus a few summary fields; ``load(i)`` seeks to one line and parses it. So a file
of ten thousand episodes opens in memory proportional to the number of episodes, not their size.

Unlike ``read_jsonl``, the index is lenient: a line that is not valid JSON, not UTF-8, or not a
trajectory record is skipped with a warning naming ``file:line`` (kept in ``index.warnings`` and
passed to ``on_warning``, by default ``warnings.warn``). A source with no readable episode at all
is an error.
"""

from __future__ import annotations

import fnmatch
import sys
import warnings
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Callable

from ..core.registry import UnknownTaskError, get_spec
from ..rollout.trajectory import Trajectory, TrajectoryFormatError, parse_record
from .view import EpisodeView, model_name


class CorruptLineWarning(UserWarning):
    """A trajectory line that the index skipped."""


@dataclass(frozen=True, slots=True)
class IndexEntry:
    file: Path
    line: int                 # 1-based line number in ``file``
    offset: int               # byte offset of the line
    size: int                 # byte length of the line, newline excluded
    task_id: str
    suite: str
    seed: int
    episode_return: float
    length: int
    forfeits: int
    won: bool | None
    model: str

    @property
    def where(self) -> str:
        return f"{self.file}:{self.line}"


@lru_cache(maxsize=None)
def suite_of(task_id: str) -> str:
    """The registered suite of a task, or 'unknown' for an ID this installation does not know."""
    try:
        return get_spec(task_id).suite
    except UnknownTaskError:
        return "unknown"


def trajectory_files(path: str | Path) -> list[Path]:
    """The JSONL files behind ``path``: the file itself, a job's ``episodes.jsonl``, or the
    ``step_*.jsonl`` files of a run's ``rollouts/`` folder (in step order)."""
    path = Path(path)
    if path.is_file():
        return [path]
    if not path.exists():
        raise FileNotFoundError(f"{path}: no such file or directory")
    if (path / "episodes.jsonl").is_file():
        return [path / "episodes.jsonl"]
    for folder in (path / "rollouts", path):
        files = sorted(folder.glob("step_*.jsonl"))
        if files:
            return files
    raise FileNotFoundError(f"{path}: a directory without episodes.jsonl or rollouts/step_*.jsonl")


class EpisodeIndex:
    """Where each readable episode of a trajectory source lies, with its summary; see the module."""

    def __init__(self, path: str | Path, on_warning: Callable[[str], None] | None = None) -> None:
        self.path = Path(path)
        self.files = trajectory_files(self.path)
        self.warnings: list[str] = []
        self._on_warning = on_warning
        self.entries: list[IndexEntry] = []
        lines = 0
        for file in self.files:
            lines += self._scan(file)
        if not self.entries:
            if not lines:
                raise TrajectoryFormatError(f"{self.path}: no episodes (the file is empty)")
            raise TrajectoryFormatError(f"{self.path}: no readable episode; {len(self.warnings)} line(s) "
                                        f"skipped, the first: {self.warnings[0]}")

    def _warn(self, message: str) -> None:
        self.warnings.append(message)
        if self._on_warning is not None:
            self._on_warning(message)
        else:
            warnings.warn(message, CorruptLineWarning, stacklevel=3)

    def _scan(self, file: Path) -> int:
        """Index one file's episodes; returns how many non-blank lines it has."""
        lines = 0
        offset = 0
        with open(file, "rb") as fh:
            for number, raw in enumerate(fh, 1):
                start, offset = offset, offset + len(raw)
                line = raw.rstrip(b"\r\n")
                if not line.strip():
                    continue
                lines += 1
                where = f"{file}:{number}"
                try:
                    traj = parse_record(line, where)
                except TrajectoryFormatError as e:
                    cut = "" if raw.endswith(b"\n") else ", the last line, cut short"
                    self._warn(f"{e} (line skipped{cut})")
                    continue
                self.entries.append(IndexEntry(
                    file, number, start, len(line), sys.intern(traj.task_id), suite_of(traj.task_id),
                    traj.seed, traj.episode_return, traj.length, traj.forfeits, traj.won,
                    sys.intern(model_name(traj.meta))))
        return lines

    def __len__(self) -> int:
        return len(self.entries)

    def load(self, i: int) -> Trajectory:
        """Episode ``i`` (0-based), read from disk now."""
        if not 0 <= i < len(self.entries):
            raise IndexError(f"episode {i} is out of range: {self.path} has {len(self.entries)} "
                             f"episode(s), 0-{len(self.entries) - 1}")
        e = self.entries[i]
        with open(e.file, "rb") as fh:
            fh.seek(e.offset)
            line = fh.read(e.size)
        try:
            traj = parse_record(line, e.where)
        except TrajectoryFormatError:
            traj = None
        if traj is None or (traj.task_id, traj.seed) != (e.task_id, e.seed):
            raise TrajectoryFormatError(f"{e.where}: the file changed since it was indexed; open it again")
        return traj

    def view(self, i: int) -> EpisodeView:
        """Episode ``i`` parsed for a viewer."""
        e = self.entries[i]
        return EpisodeView.from_trajectory(self.load(i), index=i, source=e.where, suite=e.suite)

    def select(self, task: str | None = None) -> list[int]:
        """Indices of the episodes whose task ID equals ``task`` or matches it as a glob
        (``*snake*``); all episodes when ``task`` is None."""
        if task is None:
            return list(range(len(self.entries)))
        return [i for i, e in enumerate(self.entries)
                if e.task_id == task or fnmatch.fnmatchcase(e.task_id, task)]
