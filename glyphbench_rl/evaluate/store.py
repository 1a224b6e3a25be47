"""``episodes.jsonl``: one JSON line per finished episode, durable as soon as it is written.

Each record is written in one ``write`` and fsync'd before the next episode can finish, so a
crash can cut short only the last line. ``scan`` reads a log without changing it: a bad line in
the middle is a hard error (someone edited or concatenated files; guessing would hide it), a bad
last line is reported as ``partial`` and ``move_aside_partial`` later keeps its bytes in
``episodes.jsonl.partial-<n>`` before the job appends again — never silently deleted.
"""

from __future__ import annotations

import contextlib
import json
import os
import signal
import threading
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..rollout.trajectory import Trajectory

# the scalar fields a summary needs; the turn-by-turn data is left on disk
_SCALARS = {"task_id": str, "seed": int, "return": (int, float), "length": int}
_OPTIONAL = {"forfeits": 0, "prompt_tokens": 0, "completion_tokens": 0, "won": None,
             "terminated": False, "truncated": False, "context_drops": 0}


class EpisodeLogError(ValueError):
    """An episode log that cannot be used as it is; one line naming file:line, nothing modified."""


@dataclass
class Partial:
    line: int          # 1-based line number of the cut-short record
    offset: int        # byte offset where it starts (the log is truncated back to here)
    data: bytes


@dataclass
class Scan:
    records: list[dict[str, Any]] = field(default_factory=list)   # scalar fields, first per pair
    duplicates: int = 0
    partial: Partial | None = None
    needs_newline: bool = False   # the last record is complete but its newline is missing

    def pairs(self) -> set[tuple[str, int]]:
        return {(r["task_id"], r["seed"]) for r in self.records}


def _record(raw: bytes, where: str) -> dict[str, Any]:
    """The scalar fields of one line, or EpisodeLogError (ValueError covers JSON and UTF-8)."""
    try:
        obj = json.loads(raw)
    except ValueError as e:
        raise EpisodeLogError(f"{where}: not valid JSON ({e})") from None
    if not isinstance(obj, dict):
        raise EpisodeLogError(f"{where}: expected a JSON object, got {type(obj).__name__}")
    out = {}
    for key, kind in _SCALARS.items():
        value = obj.get(key)
        if isinstance(value, bool) or not isinstance(value, kind):
            raise EpisodeLogError(f"{where}: field {key!r} is missing or has the wrong type")
        out[key] = value
    for key, default in _OPTIONAL.items():
        out[key] = obj.get(key, default)
    return out


def scan(path: str | os.PathLike) -> Scan:
    """Read a log without modifying it; a missing file is an empty log. Streams the file (a
    long job's log with full replies can be gigabytes); only scalar fields stay in memory."""
    path = Path(path)
    result = Scan()
    seen: set[tuple[str, int]] = set()

    def take(n: int, start: int, raw: bytes, last: bool) -> None:
        if not raw.strip():
            return
        try:
            rec = _record(raw, f"{path}:{n}")
        except EpisodeLogError as e:
            if last and (not raw.endswith(b"\n") or _json_error(raw) is not None):
                result.partial = Partial(n, start, raw)
                return
            raise EpisodeLogError(f"{e}; {path.name} was not modified (fix or delete that line, "
                                  f"or write to a new --out)") from None
        if last and not raw.endswith(b"\n"):
            result.needs_newline = True
        key = (rec["task_id"], rec["seed"])
        if key in seen:     # two runs appended the same pair: the first one counts
            result.duplicates += 1
            return
        seen.add(key)
        result.records.append(rec)

    if not path.exists():
        return result
    with open(path, "rb") as fh:   # lines keep their b"\n"; an unterminated last line has none
        held, offset = None, 0     # one line of look-ahead: only the last line may be partial
        for n, raw in enumerate(fh, 1):
            if held is not None:
                take(*held, last=False)
            held, offset = (n, offset, raw), offset + len(raw)
        if held is not None:
            take(*held, last=True)
    return result


def _json_error(raw: bytes) -> ValueError | None:
    try:
        json.loads(raw)
    except ValueError as e:
        return e
    return None


def move_aside_partial(path: str | os.PathLike, partial: Partial) -> Path:
    """Keep the cut-short line in ``<path>.partial-<n>``, then truncate the log before it."""
    path = Path(path)
    n = 1
    while (aside := path.with_name(f"{path.name}.partial-{n}")).exists():
        n += 1
    with open(aside, "xb") as fh:    # write the copy durably before the log loses the bytes
        fh.write(partial.data)
        fh.flush()
        os.fsync(fh.fileno())
    with open(path, "r+b") as fh:
        fh.truncate(partial.offset)
        fh.flush()
        os.fsync(fh.fileno())
    return aside


def encode_record(traj: Trajectory, *, tokens: bool = False) -> bytes:
    record = traj.to_dict(tokens=tokens)
    text = json.dumps(record, ensure_ascii=False)
    try:
        return text.encode("utf-8") + b"\n"
    except UnicodeEncodeError:   # a lone surrogate in a model reply: escape rather than crash
        return json.dumps(record, ensure_ascii=True).encode("ascii") + b"\n"


class EpisodeWriter:
    """Appends records durably (write + flush + fsync per episode)."""

    def __init__(self, path: str | os.PathLike, *, tokens: bool = False, needs_newline: bool = False):
        self.path = Path(path)
        self.tokens = tokens
        created = not self.path.exists()
        self._fh = open(self.path, "ab")
        if needs_newline:
            self._fh.write(b"\n")
        if created:
            _fsync_dir(self.path.parent)

    def append(self, traj: Trajectory) -> None:
        self._fh.write(encode_record(traj, tokens=self.tokens))
        self._fh.flush()
        os.fsync(self._fh.fileno())

    def close(self) -> None:
        self._fh.close()

    def __enter__(self) -> "EpisodeWriter":
        return self

    def __exit__(self, *exc) -> None:
        self.close()


@contextlib.contextmanager
def deferred_interrupt():
    """Hold Ctrl-C back while a record is written and counted, so an interrupt can neither cut
    the line short nor land between "on disk" and "counted"; it is raised right after.

    A Python-level handler, not a signal mask: a mask covers one thread, and the kernel hands
    a process-wide SIGINT to any thread that does not block it (numpy's BLAS threads). A kill or
    a crash can still cut the last line short; ``scan`` handles that case.
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    pending: list[int] = []
    old = signal.signal(signal.SIGINT, lambda signum, frame: pending.append(signum))
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, old)
        if pending:
            if callable(old):
                old(signal.SIGINT, None)       # the default handler raises KeyboardInterrupt
            elif old == signal.SIG_DFL:
                signal.raise_signal(signal.SIGINT)


def _fsync_dir(path: Path) -> None:
    """Make a new file's directory entry durable too (POSIX; a no-op where unsupported)."""
    try:
        fd = os.open(path, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)


def write_atomic(path: str | os.PathLike, text: str) -> None:
    """Replace a small file (config, summary) in one step, so an interrupt never leaves half."""
    path = Path(path)
    tmp = path.with_name(path.name + ".tmp")
    with open(tmp, "w", encoding="utf-8") as fh:
        fh.write(text)
        fh.flush()
        os.fsync(fh.fileno())
    os.replace(tmp, path)
