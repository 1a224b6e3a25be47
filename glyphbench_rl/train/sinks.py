"""Where a run's per-step metrics go besides ``metrics.jsonl``: TensorBoard and Weights & Biases.

``metrics.jsonl`` is the record of a run (resume, plots and sweeps read it); the sinks mirror it
for the dashboards people already use. Nested values such as ``train/return_by_task`` are
flattened to ``train/return_by_task/<task id>`` scalars. TensorBoard event files go to
``<run>/tensorboard``; W&B logs when ``wandb_project`` is set (``WANDB_MODE=offline`` works
without a network), resuming the same W&B run when the training run resumes.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any, Protocol


class MetricSink(Protocol):
    def log(self, metrics: dict[str, Any], step: int) -> None: ...

    def close(self) -> None: ...


class SinkError(RuntimeError):
    """A configured sink that cannot start (its package is missing); one line with the fix."""


def flatten(metrics: dict[str, Any], prefix: str = "") -> dict[str, float]:
    """Numeric leaves of ``metrics`` under slash-joined keys; ``step`` and non-numbers left out."""
    out: dict[str, float] = {}
    for key, value in metrics.items():
        name = f"{prefix}{key}"
        if isinstance(value, dict):
            out.update(flatten(value, f"{name}/"))
        elif isinstance(value, (int, float)) and not isinstance(value, bool) and name != "step":
            if math.isfinite(value):
                out[name] = float(value)
    return out


class TensorBoardSink:
    def __init__(self, logdir: Path) -> None:
        try:
            from torch.utils.tensorboard import SummaryWriter
        except ImportError:
            raise SinkError("tensorboard: true needs the tensorboard package "
                            "(pip install tensorboard), or set tensorboard: false") from None
        self.writer = SummaryWriter(str(logdir))

    def log(self, metrics: dict[str, Any], step: int) -> None:
        for key, value in flatten(metrics).items():
            self.writer.add_scalar(key, value, step)
        self.writer.flush()

    def close(self) -> None:
        self.writer.close()


class WandbSink:
    """One W&B run per training run; its id is kept in ``<run>/wandb_id`` so --resume continues it."""

    def __init__(self, run_dir: Path, *, project: str, entity: str | None, name: str | None,
                 config: dict[str, Any]) -> None:
        try:
            import wandb
        except ImportError:
            raise SinkError("wandb_project is set but the wandb package is missing "
                            "(pip install wandb), or remove wandb_project") from None
        id_file = run_dir / "wandb_id"
        run_id = id_file.read_text().strip() if id_file.exists() else wandb.util.generate_id()
        id_file.write_text(run_id + "\n")
        self.run = wandb.init(project=project, entity=entity, name=name or run_dir.name, id=run_id,
                              resume="allow", dir=str(run_dir), config=config)

    def log(self, metrics: dict[str, Any], step: int) -> None:
        self.run.log(flatten(metrics), step=step)

    def close(self) -> None:
        self.run.finish()


def open_sinks(run_dir: Path, cfg) -> list[MetricSink]:
    """The sinks ``cfg`` asks for; a missing package fails here, before any model loads."""
    sinks: list[MetricSink] = []
    if cfg.tensorboard:
        sinks.append(TensorBoardSink(run_dir / "tensorboard"))
    if cfg.wandb_project:
        sinks.append(WandbSink(run_dir, project=cfg.wandb_project, entity=cfg.wandb_entity,
                               name=cfg.wandb_name, config=json.loads(json.dumps(cfg.to_dict()))))
    return sinks
