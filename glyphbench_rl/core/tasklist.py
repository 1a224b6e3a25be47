"""Task lists as data: files of IDs (one per line, ``#`` comments), globs, or comma lists."""

from __future__ import annotations

import os
from pathlib import Path

from .registry import get_spec, list_tasks


def read_task_file(path: str | os.PathLike) -> list[str]:
    ids = []
    for n, line in enumerate(Path(path).read_text(encoding="utf-8").splitlines(), 1):
        line = line.split("#", 1)[0].strip()
        if line:
            ids.append(line)
    return ids


def resolve_tasks(selection: str | list[str]) -> list[str]:
    """IDs named by ``selection``: a task-list file, a glob, comma-separated IDs, or a list.

    Every ID is checked against the registry (unknown ones raise naming the closest IDs);
    duplicates keep their first position.
    """
    items = selection if isinstance(selection, list) else [selection]
    out: list[str] = []
    for item in items:
        item = item.strip()
        if not item:
            continue
        if os.path.isfile(item):
            ids = read_task_file(item)
        elif any(ch in item for ch in "*?["):
            ids = list_tasks(pattern=item)
            if not ids:
                raise ValueError(f"no registered task matches {item!r}")
        elif "," in item:
            ids = [p for p in (s.strip() for s in item.split(",")) if p]
        else:
            ids = [item]
        for task_id in ids:
            get_spec(task_id)
            if task_id not in out:
                out.append(task_id)
    if not out:
        raise ValueError(f"no tasks selected by {selection!r}")
    return out
