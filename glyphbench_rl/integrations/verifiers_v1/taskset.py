"""The rows: one (task ID, seed) pair per episode, nothing else.

Seeds come from the held-out range by default (evaluation); ``split="train"`` draws them from the
training range instead, for trainers such as Prime-RL that pull their examples from this taskset.
The game is rebuilt from its row when the episode runs (``GlyphbenchEnv.run``), so a row is a
few bytes on the wire and a trace names exactly the instance that was played.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Literal

import verifiers.v1 as vf
from pydantic import Field, TypeAdapter, field_validator, model_validator

from ...agent.harness import HarnessConfig, check_prompt_kind
from ...core import list_tasks, resolve_tasks
from ...core.seeding import TRAIN_SEEDS, heldout_seeds


class GlyphbenchTasksetConfig(vf.TasksetConfig):
    """--env.taskset.*: which tasks, how many episodes each, and how prompts are composed."""

    tasks: list[str] | None = None
    """Task IDs, globs, comma lists or task-list files, as glyphbench_rl.resolve_tasks reads
    them; None: every standard-tier task."""
    split: Literal["heldout", "train"] = "heldout"
    """Which seed range the rows use: heldout [1,000,000, 2,000,000) for evaluation (rows task by
    task), or train [0, 1,000,000) for training (rows round-robin over the tasks)."""
    episodes: int = Field(1, ge=1)
    """Episodes per task, each on its own seed of the split (the same seeds for every model)."""
    seed_start: int = Field(0, ge=0)
    """Offset into the split's seed range."""
    harness: HarnessConfig = HarnessConfig()
    """How prompts are composed (--env.taskset.harness.history, .legend, .max_context_tokens): the
    engine's own HarnessConfig, so glyphbench-eval and vf-eval prompts are identical. The
    context budget counts estimated tokens (chars/4): prompts go out as chat messages."""

    @field_validator("harness", mode="before")
    @classmethod
    def _harness_from_flags(cls, value):
        # command-line flags arrive as strings ("--env.taskset.harness.history 2"): read them as
        # the values they spell; the checks themselves are HarnessConfig's own
        if isinstance(value, dict):
            return HarnessConfig(**{k: _from_flag(k, v) for k, v in value.items()})
        return value

    @model_validator(mode="after")
    def _check(self):
        # Fail while the config is parsed, before any model call: unknown IDs name the closest
        # ones, and harness values get the engine's own one-line errors.
        self.task_ids()
        check_prompt_kind(self.harness, tokens=False)
        self.seeds()
        return self

    def seeds(self) -> list[int]:
        """The seeds every task plays: ``episodes`` consecutive seeds of the split from ``seed_start``."""
        if self.split == "heldout":
            return heldout_seeds(self.episodes, self.seed_start)
        if self.seed_start + self.episodes > len(TRAIN_SEEDS):
            raise ValueError(f"training seeds {self.seed_start}..{self.seed_start + self.episodes} "
                             f"exceed the training range (at most {len(TRAIN_SEEDS):,})")
        return list(TRAIN_SEEDS[self.seed_start:self.seed_start + self.episodes])

    def task_ids(self) -> list[str]:
        if self.tasks is None:
            return list_tasks(tier="standard")
        try:
            return resolve_tasks(list(self.tasks))
        except LookupError as e:   # UnknownTaskError: pydantic reports only ValueErrors cleanly
            raise ValueError(str(e)) from None


def _from_flag(key: str, value):
    """A flag's string as the harness field's type reads it ("2" -> 2), else unchanged."""
    field = HarnessConfig.model_fields.get(key)
    if field is None or not isinstance(value, str):
        return value
    try:
        return TypeAdapter(field.annotation).validate_python(value, strict=False)
    except ValueError:
        return value            # HarnessConfig names the key and what it must be


class GlyphbenchData(vf.TaskData):
    task_id: str
    seed: int


class GlyphbenchTask(vf.Task[GlyphbenchData, vf.State, vf.TaskConfig]):
    @property
    def key(self) -> str:
        # durable across task lists and orderings (the default hash includes the row index)
        return f"{self.data.task_id}@{self.data.seed}"


class GlyphbenchTaskset(vf.Taskset[GlyphbenchTask, GlyphbenchTasksetConfig]):
    def load(self) -> Iterator[GlyphbenchTask]:
        seeds, task_ids = self.config.seeds(), self.config.task_ids()
        if self.config.split == "train":
            # round-robin over the tasks (row r plays task r mod n), the order the built-in
            # trainer cycles through them; Prime-RL's default sampler takes rows in source order
            rows = ((task_id, seed) for seed in seeds for task_id in task_ids)
        else:
            rows = ((task_id, seed) for task_id in task_ids for seed in seeds)
        for task_id, seed in rows:
            # prompt=None: the env opens each conversation with the first observation
            yield GlyphbenchTask(GlyphbenchData(id=f"{task_id}@{seed}", name=task_id,
                                                task_id=task_id, seed=seed), self.config.task)
