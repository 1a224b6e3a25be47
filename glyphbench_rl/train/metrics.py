"""The trainer's ``metrics.jsonl``: one JSON object per step, read back strictly.

A bad line in the middle is an error naming file:line; only a cut-short last line (a run still
writing) is left out, with a note through ``log``.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any, Callable


class MetricsError(ValueError):
    """A metrics file that cannot be read; the message is one line naming file:line."""


def read_metrics(path: str | os.PathLike, log: Callable[[str], None] | None = None) -> list[dict[str, Any]]:
    """The records of a ``metrics.jsonl``: each a JSON object with an int ``step`` and a number
    ``train/return_mean``."""
    path = Path(path)
    if not path.is_file():
        raise MetricsError(f"{path} does not exist (not a training run directory?)")
    with open(path, "rb") as fh:
        lines = fh.read().split(b"\n")
    out = []
    for n, raw in enumerate(lines, 1):
        if not raw.strip():
            continue
        last = n == len(lines)              # no newline after it: possibly a write cut short
        try:
            rec = json.loads(raw)
        except ValueError as e:
            if last:
                if log:
                    log(f"{path}:{n}: cut-short last line left out (a run still writing?)")
                continue
            raise MetricsError(f"{path}:{n}: not valid JSON ({str(e).splitlines()[0]})") from None
        if not isinstance(rec, dict):
            raise MetricsError(f"{path}:{n}: expected a JSON object, got {type(rec).__name__}")
        step, ret = rec.get("step"), rec.get("train/return_mean")
        if isinstance(step, bool) or not isinstance(step, int):
            raise MetricsError(f"{path}:{n}: 'step' is missing or not an integer")
        if isinstance(ret, bool) or not isinstance(ret, (int, float)):
            raise MetricsError(f"{path}:{n}: 'train/return_mean' is missing or not a number")
        out.append(rec)
    if not out:
        raise MetricsError(f"{path} holds no metrics yet")
    return out
