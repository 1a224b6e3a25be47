"""Training run configuration: documented defaults, YAML files that list only what they change.

``load_config(path, overrides)`` reads a YAML mapping, applies ``key=value`` overrides (dotted
keys reach into ``harness``), and validates everything before any model loads: an unknown key or
a value of the wrong type or range is a one-line ``ConfigError`` naming the key. The resolved
config is what a run saves beside its outputs.
"""

from __future__ import annotations

import dataclasses
import difflib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Mapping

from ..agent.harness import HarnessConfig


class ConfigError(ValueError):
    pass


LOSSES = ("ipo", "default")


@dataclass
class TrainConfig:
    # policy
    model: str = "smollm2"             # `smollm2` (embedded), a local folder / .gguf, or a hub ID
    device: str | None = None          # default: cuda when available, else cpu
    dtype: str | None = None           # default: bfloat16 on GPU, float32 on CPU
    gradient_checkpointing: bool = False
    # tasks and rollouts
    tasks: str | list = "tasks/standard.txt"   # task-list file, glob, comma list or list of IDs
    steps: int = 100                   # optimizer steps
    group_size: int = 32               # rollouts per group: one task, different training seeds
    groups_per_update: int = 1         # groups per optimizer step (tasks cycle through the list)
    max_episodes_at_once: int = 64     # rollout batch (episodes played concurrently)
    temperature: float = 1.0
    top_p: float = 1.0
    max_new_tokens: int = 4096         # per action-generation call
    max_turns: int | None = None       # cap every episode's horizon (default: each task's own)
    harness: dict = field(default_factory=dict)   # HarnessConfig fields (history, legend, ...)
    include_truncated: bool = True     # truncated episodes count in the group baseline
    std_normalize: bool = False        # divide advantages by the group's standard deviation
    # format shaping, off by default (the paper's objective): the advantage uses the return plus
    # format_reward x the episode's format score, the mean over its turns of 1 for a valid action,
    # 0.5 for a complete <action> tag naming no valid action, 0 otherwise. For policies that do
    # not follow the action format yet (every episode forfeits, so every group is flat).
    format_reward: float = 0.0
    # objective and optimizer
    loss: str = "ipo"
    threshold: float = 0.1             # ipo: probability-difference mask
    mask_low: float = 0.2              # default loss: DPPO masks
    mask_high: float = 0.2
    adv_tau: float = 1.0
    kl_coef: float = 1e-3
    lr: float = 1e-6
    betas: list = field(default_factory=lambda: [0.9, 0.95])
    weight_decay: float = 0.0
    grad_clip: float = 1.0
    seq_len: int = 32768               # longest training sequence; longer turns are skipped
    micro_batch_tokens: int = 16384    # padded tokens per forward/backward micro-batch
    logprob_chunk: int = 1024          # positions per chunk of the output head
    # run
    seed: int = 0
    checkpoint_every: int = 10         # steps between checkpoints (the last step always saves)
    keep_checkpoints: int = 2
    eval_every: int = 0                # steps between held-out evaluations (0: never)
    eval_episodes: int = 4             # held-out episodes per task at each evaluation
    save_rollouts: bool = True         # trajectories of every step, for replay
    tensorboard: bool = True           # mirror metrics to <run>/tensorboard (needs tensorboard)
    wandb_project: str | None = None   # mirror metrics to this W&B project (needs wandb)
    wandb_entity: str | None = None
    wandb_name: str | None = None      # default: the run directory's name

    def __post_init__(self) -> None:
        ints = {"steps": 1, "group_size": 1, "groups_per_update": 1, "max_episodes_at_once": 1,
                "max_new_tokens": 1, "seq_len": 16, "micro_batch_tokens": 16, "logprob_chunk": 1,
                "seed": 0, "checkpoint_every": 1, "keep_checkpoints": 1, "eval_every": 0,
                "eval_episodes": 1}
        for name, lo in ints.items():
            v = getattr(self, name)
            if isinstance(v, bool) or not isinstance(v, int) or v < lo:
                raise ConfigError(f"{name} must be an int >= {lo}, got {v!r}")
        floats = {"temperature": (1e-6, 10), "top_p": (1e-6, 1), "threshold": (0, 1),
                  "mask_low": (0, 1), "mask_high": (0, 1), "adv_tau": (0, 100), "kl_coef": (0, 10),
                  "lr": (0, 1), "weight_decay": (0, 10), "grad_clip": (0, 1e6),
                  "format_reward": (0, 100)}
        for name, (lo, hi) in floats.items():
            v = getattr(self, name)
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not lo <= v <= hi:
                raise ConfigError(f"{name} must be a number in [{lo:g}, {hi:g}], got {v!r}")
            setattr(self, name, float(v))
        for name in ("wandb_project", "wandb_entity", "wandb_name"):
            v = getattr(self, name)
            if v is not None and (not isinstance(v, str) or not v.strip()):
                raise ConfigError(f"{name} must be a non-empty string or null, got {v!r}")
        for name in ("gradient_checkpointing", "include_truncated", "std_normalize", "save_rollouts",
                     "tensorboard"):
            if not isinstance(getattr(self, name), bool):
                raise ConfigError(f"{name} must be true or false, got {getattr(self, name)!r}")
        if self.max_turns is not None and (isinstance(self.max_turns, bool)
                                           or not isinstance(self.max_turns, int) or self.max_turns < 1):
            raise ConfigError(f"max_turns must be an int >= 1 or null, got {self.max_turns!r}")
        if self.loss not in LOSSES:
            raise ConfigError(f"loss must be one of {LOSSES}, got {self.loss!r}")
        if not isinstance(self.model, str) or not self.model:
            raise ConfigError(f"model must be a name or path, got {self.model!r}")
        if (not isinstance(self.betas, (list, tuple)) or len(self.betas) != 2
                or not all(isinstance(b, (int, float)) and 0 <= b < 1 for b in self.betas)):
            raise ConfigError(f"betas must be two numbers in [0, 1), got {self.betas!r}")
        if not isinstance(self.tasks, (str, list)) or not self.tasks:
            raise ConfigError(f"tasks must be a task-list path, glob, comma list or list, got {self.tasks!r}")
        if not isinstance(self.harness, dict):
            raise ConfigError(f"harness must be a mapping, got {self.harness!r}")
        try:
            self.harness_config()
        except TypeError as e:
            raise ConfigError(f"harness: {e}") from None
        except ValueError as e:
            raise ConfigError(str(e)) from None

    def harness_config(self) -> HarnessConfig:
        unknown = set(self.harness) - {f.name for f in dataclasses.fields(HarnessConfig)}
        if unknown:
            raise ConfigError(f"unknown key harness.{sorted(unknown)[0]}; harness keys: "
                              f"{', '.join(f.name for f in dataclasses.fields(HarnessConfig))}")
        return HarnessConfig(**self.harness)

    def to_dict(self) -> dict[str, Any]:
        return dataclasses.asdict(self)


FIELDS = {f.name for f in dataclasses.fields(TrainConfig)}


def _unknown(key: str) -> ConfigError:
    close = difflib.get_close_matches(key, sorted(FIELDS), n=1)
    hint = f"; did you mean {close[0]!r}?" if close else ""
    return ConfigError(f"unknown config key {key!r}{hint}")


def parse_override(text: str) -> tuple[str, Any]:
    """``key=value`` with the value read as YAML (``lr=5e-6``, ``harness.history=2``)."""
    import yaml

    key, sep, raw = text.partition("=")
    if not sep or not key.strip():
        raise ConfigError(f"override {text!r} is not key=value")
    try:
        value = yaml.safe_load(raw) if raw.strip() else ""
    except yaml.YAMLError:
        value = raw
    return key.strip(), value


def merge(base: Mapping[str, Any], overrides: list[str]) -> dict[str, Any]:
    data = {k: (dict(v) if isinstance(v, dict) else v) for k, v in base.items()}
    for text in overrides:
        key, value = parse_override(text)
        head, _, rest = key.partition(".")
        if head not in FIELDS:
            raise _unknown(head)
        if rest:
            if head != "harness":
                raise ConfigError(f"{head} has no sub-keys (override {text!r})")
            data.setdefault("harness", {})[rest] = value
        else:
            data[head] = value
    return data


def config_from_dict(data: Mapping[str, Any]) -> TrainConfig:
    if not isinstance(data, Mapping):
        raise ConfigError(f"a config is a mapping of keys to values, got {type(data).__name__}")
    for key in data:
        if key not in FIELDS:
            raise _unknown(str(key))
    try:
        return TrainConfig(**dict(data))
    except TypeError as e:
        raise ConfigError(str(e)) from None


def load_config(path: str | Path | None, overrides: list[str] = ()) -> TrainConfig:
    import yaml

    data: Any = {}
    if path is not None:
        p = Path(path)
        if not p.is_file():
            raise ConfigError(f"config file {p} does not exist")
        try:
            data = yaml.safe_load(p.read_text(encoding="utf-8")) or {}
        except yaml.YAMLError as e:
            mark = getattr(e, "problem_mark", None)
            where = f" at line {mark.line + 1}" if mark is not None else ""
            raise ConfigError(f"{p}: not valid YAML{where}") from None
        if not isinstance(data, dict):
            raise ConfigError(f"{p}: a config is a mapping of keys to values")
    return config_from_dict(merge(data, list(overrides)))
