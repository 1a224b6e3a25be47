"""Training run configuration: documented defaults, YAML files that list only what they change.

``load_config(path, overrides)`` reads a YAML mapping, applies ``key=value`` overrides (dotted
keys reach into ``harness``), and validates everything before any model loads: an unknown key or
a value of the wrong type or range is a one-line ``ConfigError`` naming the key. The resolved
config is what a run saves beside its outputs.
"""

from __future__ import annotations

import functools
import re
from pathlib import Path
from typing import Annotated, Any, ClassVar, Literal, Mapping, get_args

from pydantic import Field

from ..agent.harness import HarnessConfig
from ..settings import Settings, unknown_key


class ConfigError(ValueError):
    pass


Loss = Literal["ipo", "default"]
LOSSES = get_args(Loss)

# value shapes, each named by the one-line error a bad value gets
Count = Annotated[int, Field(ge=1)]                       # an int >= 1
Fraction = Annotated[float, Field(ge=0, le=1)]            # a number in [0, 1]
Name = Annotated[str, Field(pattern=r"\S", description="a non-empty string")]
TaskItem = Annotated[str, Field(pattern=r"\S")]
Tasks = Annotated[TaskItem | Annotated[list[TaskItem], Field(min_length=1)],
                  Field(description="a task-list file, glob or comma list, or a non-empty list of "
                                    "task IDs")]
Betas = Annotated[list[Annotated[float, Field(ge=0, lt=1)]],
                  Field(min_length=2, max_length=2, description="two numbers in [0, 1)")]


class TrainConfig(Settings):
    error: ClassVar[type[Exception]] = ConfigError

    # policy
    model: Name = "smollm2"            # `smollm2` (embedded), a local folder / .gguf, or a hub ID
    device: Name | None = None         # default: cuda when available, else cpu
    dtype: Literal["float32", "bfloat16", "float16"] | None = None   # default: bf16 GPU, fp32 CPU
    gradient_checkpointing: bool = False
    # tasks and rollouts (a relative task-list path missing here is read from the shipped tasks/)
    tasks: Tasks = Field("tasks/standard.txt", validate_default=True)
    steps: Count = 100                 # optimizer steps
    # rollouts per group: one task, different training seeds (a group of one has no advantage)
    group_size: Annotated[int, Field(ge=2)] = 32
    groups_per_update: Count = 1       # groups per optimizer step (tasks cycle through the list)
    max_episodes_at_once: Count = 64   # rollout batch (episodes played concurrently)
    temperature: Annotated[float, Field(gt=0, le=10)] = 1.0
    top_p: Annotated[float, Field(gt=0, le=1)] = 1.0
    max_new_tokens: Count = 4096       # per action-generation call
    max_turns: Count | None = None     # cap every episode's horizon (default: each task's own)
    harness: dict[str, Any] = Field(default_factory=dict)   # HarnessConfig fields (history, ...)
    include_truncated: bool = True     # truncated episodes count in the group baseline
    std_normalize: bool = False        # divide advantages by the group's standard deviation
    # format shaping, off by default (the paper's objective): the advantage uses the return plus
    # format_reward x the episode's format score, the mean over its turns of 1 for a valid action,
    # 0.5 for a complete <action> tag naming no valid action, 0 otherwise. For policies that do
    # not follow the action format yet (every episode forfeits, so every group is flat).
    format_reward: Annotated[float, Field(ge=0, le=100)] = 0.0
    # objective and optimizer
    loss: Loss = "ipo"
    threshold: Fraction = 0.1          # ipo: probability-difference mask
    mask_low: Fraction = 0.2           # default loss: DPPO masks
    mask_high: Fraction = 0.2
    adv_tau: Annotated[float, Field(ge=0, le=100)] = 1.0
    kl_coef: Annotated[float, Field(ge=0, le=10)] = 1e-3
    lr: Annotated[float, Field(gt=0, le=1)] = 1e-6
    betas: Betas = Field(default_factory=lambda: [0.9, 0.95])
    weight_decay: Annotated[float, Field(ge=0, le=10)] = 0.0
    grad_clip: Annotated[float, Field(ge=0, le=1e6)] = 1.0
    # longest training sequence (longer turns are skipped); padded tokens per micro-batch
    seq_len: Annotated[int, Field(ge=16)] = 32768
    micro_batch_tokens: Annotated[int, Field(ge=16)] = 16384
    logprob_chunk: Count = 1024        # positions per chunk of the output head
    # run
    seed: Annotated[int, Field(ge=0)] = 0
    checkpoint_every: Count = 10       # steps between checkpoints (the last step always saves)
    keep_checkpoints: Count = 2
    #: AdamW state in the latest checkpoint (twice the weights' size), for an exact --resume;
    #: false saves weights only, and a resume starts the optimizer afresh
    save_optimizer: bool = True
    eval_every: Annotated[int, Field(ge=0)] = 0   # steps between held-out evaluations (0: never)
    eval_episodes: Count = 4           # held-out episodes per task at each evaluation
    save_rollouts: bool = True         # trajectories of every step, for replay
    tensorboard: bool = True           # mirror metrics to <run>/tensorboard (needs tensorboard)
    wandb_project: Name | None = None  # mirror metrics to this W&B project (needs wandb)
    wandb_entity: Name | None = None
    wandb_name: Name | None = None     # default: the run directory's name

    def check(self) -> None:
        self.harness_config()

    def harness_config(self) -> HarnessConfig:
        try:
            return HarnessConfig(**self.harness)
        except ValueError as e:        # already one line naming harness.<key>
            raise ConfigError(str(e)) from None

    def to_dict(self) -> dict[str, Any]:
        return self.model_dump()


FIELDS = set(TrainConfig.model_fields)


def _unknown(key: str) -> ConfigError:
    return ConfigError(unknown_key(key, sorted(FIELDS)))


def parse_override(text: str) -> tuple[str, Any]:
    """``key=value`` with the value read as YAML (``lr=5e-6``, ``harness.history=2``)."""
    import yaml

    key, sep, raw = text.partition("=")
    if not sep or not key.strip():
        raise ConfigError(f"override {text!r} is not key=value")
    try:
        value = yaml.load(raw, Loader=config_loader()) if raw.strip() else ""
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
            harness = data.setdefault("harness", {})
            if not isinstance(harness, dict):
                raise ConfigError(f"harness must be a mapping, got {harness!r}")
            harness[rest] = value
        else:
            data[head] = value
    return data


def config_from_dict(data: Mapping[str, Any]) -> TrainConfig:
    if not isinstance(data, Mapping):
        raise ConfigError(f"a config is a mapping of keys to values, got {type(data).__name__}")
    for key in data:                   # a misspelt key first: it explains a "missing" value
        if key not in FIELDS:
            raise _unknown(str(key))
    return TrainConfig(**data)


def load_config(path: str | Path | None, overrides: list[str] = ()) -> TrainConfig:
    data: Any = {}
    if path is not None:
        data = read_yaml(path) or {}
        if not isinstance(data, dict):
            raise ConfigError(f"{path}: a config is a mapping of keys to values")
    return config_from_dict(merge(data, list(overrides)))


def read_yaml(path: str | Path, what: str = "config") -> Any:
    """A YAML file's content; anything wrong with the file is a one-line ``ConfigError`` naming
    it: missing, a directory, not UTF-8 text, not YAML, or a key given twice in one mapping."""
    import yaml

    p = Path(path)
    if p.is_dir():
        raise ConfigError(f"{what} file {p} is a directory, not a YAML file")
    if not p.exists():
        raise ConfigError(f"{what} file {p} does not exist")
    try:
        text = p.read_text(encoding="utf-8")
    except UnicodeDecodeError as e:
        raise ConfigError(f"{p}: not a text file (byte {e.start} is not UTF-8)") from None
    except OSError as e:
        raise ConfigError(f"{what} file {p} cannot be read ({e.strerror or e})") from None
    try:
        return yaml.load(text, Loader=config_loader())
    except yaml.YAMLError as e:
        mark = getattr(e, "problem_mark", None)
        line = f" at line {mark.line + 1}" if mark is not None else ""
        if getattr(e, "problem", "").startswith("duplicate key"):
            raise ConfigError(f"{p}: {e.problem}{line}") from None
        raise ConfigError(f"{p}: not valid YAML{line}") from None


@functools.cache
def config_loader() -> type:
    """``yaml.SafeLoader`` for configs: a key given twice in one mapping is an error (PyYAML
    keeps the last silently), and ``5e-6`` is a number as in YAML 1.2 (1.1 wants ``5.0e-6``)."""
    import yaml

    class ConfigLoader(yaml.SafeLoader):
        def construct_mapping(self, node, deep=False):
            seen = set()
            for key_node, _ in node.value:
                if key_node.tag == "tag:yaml.org,2002:merge":     # `<<: *base` may override
                    continue
                key = self.construct_object(key_node, deep=True)
                try:
                    again = key in seen
                    seen.add(key)
                except TypeError:              # an unhashable key: PyYAML's own error follows
                    continue
                if again:
                    raise yaml.constructor.ConstructorError(
                        "while reading a mapping", node.start_mark, f"duplicate key {key!r}",
                        key_node.start_mark)
            return super().construct_mapping(node, deep)

    ConfigLoader.add_implicit_resolver(
        "tag:yaml.org,2002:float", re.compile(r"^[-+]?[0-9][0-9_]*(?:\.[0-9_]*)?[eE][-+]?[0-9]+$"),
        list("-+0123456789"))
    return ConfigLoader
