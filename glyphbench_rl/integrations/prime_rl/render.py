"""A training config rendered as the equivalent Prime-RL ``rl`` TOML.

Target schema: PrimeIntellect-ai/prime-rl at ``schema.PRIME_RL_COMMIT`` (the one place naming the
commit; the newest stored one), whose pinned verifiers (``schema.VERIFIERS_PIN``) loads the
glyphbench-rl plugin, as verifiers 0.4.0 from PyPI does. ``schema.py`` transcribes the keys;
``scripts/validate_prime_rl.py`` parses rendered files with a checkout's own RLConfig.
Files read, all under packages/prime-rl-configs/src/prime_rl/configs/:

  ours -> Prime-RL key                                            [file: class]
  model (hub ID or folder) -> [model] name                        [rl.py: SharedModelConfig]
  steps -> max_steps; seq_len -> seq_len (fills trainer.model.seq_len and orchestrator.seq_len)
                                                                  [rl.py: RLConfig; utils/validation.py]
  (run directory) -> output_dir = RUN_DIR, [run] name = the run directory's name, dir = "outputs":
      Prime-RL writes to RUN_DIR/outputs, the same directory on every render, so a resumed run
      finds it (without a name Prime-RL makes a fresh output_dir/<env>--<model>--<random>); the
      name is also the W&B run name unless wandb_name is set  [shared.py: RunConfig]
  checkpoint_every, keep_checkpoints -> [ckpt] interval, keep_last  [rl.py: SharedCheckpointConfig]
  --resume -> [resume] (empty: the latest checkpoint)             [shared.py: ResumeConfig]
  loss ipo -> [trainer.loss] type="ipo", ipo_threshold, adv_tau, kl_tau
                                                                  [trainer.py: IPOLossConfig]
  loss default -> [trainer.loss] type="default", dppo_mask_low, dppo_mask_high, adv_tau, kl_tau
                                                                  [trainer.py: DefaultLossConfig]
  kl_coef -> kl_tau (the coefficient of the squared log-ratio penalty, default 1e-3)
  lr, betas, weight_decay, grad_clip -> [trainer.optim] type="adamw", lr, betas1, betas2,
      weight_decay, max_norm (Prime-RL's own defaults differ: betas2 0.999, weight decay 0.01)
                                                                  [trainer.py: AdamWConfig]
  (constant lr) -> [trainer.scheduler] type="constant"            [trainer.py: ConstantSchedulerConfig]
  gradient_checkpointing -> stated either way, since Prime-RL checkpoints by default:
      true -> [trainer.model.ac] mode="full", freq=1 (every layer);
      false -> trainer.model ac = "None" and ac_offloading = "None" (offloading, on by default,
      would switch checkpointing back on)                         [trainer.py: ModelConfig.ac]
  logprob_chunk -> trainer.model.fused_lm_head_token_chunk_size  [trainer.py: ModelConfig]
  group_size -> orchestrator.group_size; group_size x groups_per_update -> orchestrator.batch_size
      (rollouts per step)                                         [orchestrator.py: OrchestratorConfig]
  (mean-centred advantages) -> [orchestrator.algo] type="grpo"   [algorithm.py: GRPOAlgoConfig]
  (zero-advantage groups kept) -> [orchestrator.train] filter_zero_advantages=false (its default
      drops their tokens)                                          [orchestrator.py: TrainConfig]
  temperature, max_new_tokens -> [orchestrator.train.sampling] temperature, max_completion_tokens
                                                                  [orchestrator.py: TrainSamplingConfig]
  tasks, harness.* -> [[orchestrator.train.source]] name, [....env.taskset] id = glyphbench-rl,
      split "train"                                               [orchestrator.py: TrainSourceConfig]
  eval_every, eval_episodes -> [orchestrator.eval] interval + a held-out source
                                                                  [orchestrator.py: EvalConfig]
  wandb_project, wandb_entity, wandb_name -> [monitors.wandb] project, entity, name
                                                                  [rl.py: SharedWandbConfig]
  (chat template) -> [orchestrator.renderer] name="default" for local folders and SmolLM2, which
      renderers.base.MODEL_RENDERER_MAP lacks (renderers 0.1.12: DefaultRendererConfig)

Values with no Prime-RL equivalent are refused with a one-line error (``ONLY_AT_DEFAULT``, and
harness keys the taskset does not take); local knobs that Prime-RL sizes itself are not carried
(``NOT_CARRIED``). A test checks that every TrainConfig field is classified.

Differences that remain: Prime-RL draws its examples (one task and one training seed per row)
from the taskset instead of cycling through the tasks, and all ``group_size`` rollouts of a group
play that one row's seed, where the built-in trainer gives each member its own seed.
"""

from __future__ import annotations

import hashlib
import math
import os
import re
from pathlib import Path
from typing import Any

from ...agent.harness import HarnessConfig
from ...core import resolve_tasks
from ...train.config import TrainConfig
from .schema import PRIME_RL_COMMIT

TASKSET_ID = "glyphbench-rl"
TOML_NAME = "prime_rl.toml"
RUN_SUBDIR = "outputs"           # Prime-RL writes to RUN_DIR/outputs
SMOLLM2_HUB_ID = "HuggingFaceTB/SmolLM2-135M-Instruct"
_CHECKSUM = "# glyphbench-train checksum: "

# How each TrainConfig field reaches Prime-RL.
CARRIED = ("model", "gradient_checkpointing", "tasks", "steps", "group_size", "groups_per_update",
           "temperature", "max_new_tokens", "harness", "loss", "threshold", "mask_low", "mask_high",
           "adv_tau", "kl_coef", "lr", "betas", "weight_decay", "grad_clip", "seq_len", "logprob_chunk",
           "checkpoint_every", "keep_checkpoints", "eval_every", "eval_episodes", "wandb_project",
           "wandb_entity", "wandb_name")
ONLY_AT_DEFAULT = {       # expressible only at their default value
    "top_p": "Prime-RL samples training rollouts at top_p 1",
    "max_turns": "the glyphbench-rl taskset plays each task's own horizon",
    "include_truncated": "Prime-RL's group baseline keeps truncated episodes",
    "std_normalize": "Prime-RL's grpo advantages are only mean-centred",
    "format_reward": "the glyphbench-rl env rewards the episode return only",
}
NOT_CARRIED = ("device", "dtype", "micro_batch_tokens", "max_episodes_at_once", "save_rollouts", "seed",
               "tensorboard", "save_optimizer")
TASKSET_PROMPT_KEYS = ("history", "legend", "max_context_tokens")   # harness keys the taskset takes


class PrimeRLConfigError(ValueError):
    """A training config value that Prime-RL cannot express."""


def render_toml(cfg: TrainConfig, *, run_dir: str | Path, resume: bool = False) -> str:
    """The Prime-RL ``rl`` config equivalent to ``cfg``; its outputs go to ``run_dir/outputs``."""
    _refuse_inexpressible(cfg)
    tasks = resolve_tasks(cfg.tasks)
    model, renderer = _policy_model(cfg.model)
    run_dir = Path(run_dir).resolve()
    harness = cfg.harness_config()
    prompt = {k: getattr(harness, k) for k in TASKSET_PROMPT_KEYS if getattr(harness, k) is not None}
    # one training row per group the built-in trainer would play of each task
    rows_per_task = math.ceil(cfg.steps * cfg.groups_per_update / len(tasks))
    train_taskset = {"id": TASKSET_ID, "tasks": tasks, "split": "train", "episodes": rows_per_task,
                     "seed_start": 0, **({"harness": prompt} if prompt else {})}
    sampling = {"temperature": cfg.temperature, "max_completion_tokens": cfg.max_new_tokens}
    orchestrator: dict[str, Any] = {
        "batch_size": cfg.group_size * cfg.groups_per_update,
        "group_size": cfg.group_size,
        "algo": {"type": "grpo"},
    }
    if renderer:
        orchestrator["renderer"] = {"name": renderer}
    # Zero-advantage groups still add KL-penalty tokens and count in the loss's token total
    # (paper eq. 3), so they are kept.
    orchestrator["train"] = {
        "filter_zero_advantages": False,
        "sampling": sampling,
        "source": [{"name": TASKSET_ID, "env": {"taskset": train_taskset}}],
    }
    if cfg.eval_every:
        heldout = {**train_taskset, "split": "heldout", "episodes": cfg.eval_episodes}
        orchestrator["eval"] = {
            "interval": cfg.eval_every, "skip_first_step": True, "group_size": 1, "num_examples": -1,
            "sampling": dict(sampling),
            "source": [{"name": f"{TASKSET_ID}-heldout", "env": {"taskset": heldout}}],
        }
    doc: dict[str, Any] = {
        "output_dir": str(run_dir),
        "max_steps": cfg.steps,
        "seq_len": cfg.seq_len,
        # a fixed name: Prime-RL writes to output_dir/outputs on every launch (an unnamed run
        # gets a fresh random directory, which --resume would not find)
        "run": {"name": run_dir.name or "run", "dir": RUN_SUBDIR},
        "model": {"name": model},
        "ckpt": {"interval": cfg.checkpoint_every, "keep_last": cfg.keep_checkpoints},
    }
    if resume:
        doc["resume"] = {}                # Prime-RL: an empty [resume] takes the latest checkpoint
    if cfg.wandb_project:
        doc["monitors"] = {"wandb": {k: v for k, v in (
            ("project", cfg.wandb_project), ("entity", cfg.wandb_entity), ("name", cfg.wandb_name)) if v}}
    doc["inference"] = {}                 # present: the rl launcher starts the vLLM server
    doc["trainer"] = {
        "model": {"fused_lm_head_token_chunk_size": cfg.logprob_chunk, **_activation_checkpointing(cfg)},
        "loss": _loss(cfg),
        "optim": {"type": "adamw", "lr": cfg.lr, "betas1": float(cfg.betas[0]),
                  "betas2": float(cfg.betas[1]), "weight_decay": cfg.weight_decay,
                  "max_norm": cfg.grad_clip},
        "scheduler": {"type": "constant"},
    }
    doc["orchestrator"] = orchestrator
    body = dumps(doc)
    header = (f"# Prime-RL config rendered by glyphbench-train --backend prime-rl from the resolved\n"
              f"# config.yaml beside it (keys: PrimeIntellect-ai/prime-rl@{PRIME_RL_COMMIT[:12]}).\n"
              f"# Launch with `rl @ {TOML_NAME}` where prime-rl and glyphbench_rl are installed.\n"
              f"# Edit the YAML and render again: a hand-edited file is never overwritten.\n")
    return f"{header}{_CHECKSUM}{_digest(header + body)}\n{body}"


def _activation_checkpointing(cfg: TrainConfig) -> dict[str, Any]:
    """Stated either way: Prime-RL checkpoints every layer unless told not to."""
    if cfg.gradient_checkpointing:
        return {"ac": {"mode": "full", "freq": 1}}
    # "None" is pydantic-config's null; activation offloading (on by default) needs checkpointing
    # and would switch it back on
    return {"ac": "None", "ac_offloading": "None"}


def write_toml(cfg: TrainConfig, run_dir: str | Path, *, resume: bool = False) -> Path:
    """Render ``cfg`` into ``run_dir/prime_rl.toml`` (and its resolved ``config.yaml``)."""
    import yaml

    run_dir = Path(run_dir)
    text = render_toml(cfg, run_dir=run_dir, resume=resume)
    path = run_dir / TOML_NAME
    if (run_dir / "metrics.jsonl").exists():
        raise FileExistsError(f"{run_dir} holds a built-in training run; choose another --out")
    if path.exists() and not _unedited(path.read_text(encoding="utf-8", errors="replace")):
        raise FileExistsError(f"{path} was edited after glyphbench-train wrote it; move it away or "
                              f"choose another --out")
    run_dir.mkdir(parents=True, exist_ok=True)
    _write_atomic(run_dir / "config.yaml", yaml.safe_dump(cfg.to_dict(), sort_keys=False))
    _write_atomic(path, text)
    return path


def started(run_dir: str | Path) -> bool:
    """Whether Prime-RL has written to ``run_dir``'s output directory (a launch that ran at all):
    rendering it again without ``resume`` would make Prime-RL refuse the directory."""
    out = Path(run_dir) / RUN_SUBDIR
    return out.is_dir() and any(out.iterdir())


def _refuse_inexpressible(cfg: TrainConfig) -> None:
    defaults = {name: f.default for name, f in TrainConfig.model_fields.items()}
    problems = [f"{name}={_show(getattr(cfg, name))} ({why})" for name, why in ONLY_AT_DEFAULT.items()
                if getattr(cfg, name) != defaults[name]]
    harness, plain = cfg.harness_config(), HarnessConfig()
    problems += [f"harness.{name}={_show(getattr(harness, name))} (the glyphbench-rl taskset "
                 f"takes only {', '.join(TASKSET_PROMPT_KEYS)})" for name in HarnessConfig.model_fields
                 if name not in TASKSET_PROMPT_KEYS and getattr(harness, name) != getattr(plain, name)]
    if problems:
        raise PrimeRLConfigError("no Prime-RL equivalent for " + "; ".join(problems))


def _show(value: Any) -> str:
    """A config value as it is written in YAML."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return f"{value:g}"
    return repr(value) if isinstance(value, str) else str(value)


def _policy_model(name: str) -> tuple[str, str | None]:
    """(Prime-RL model name, renderer to pin or None for Prime-RL's automatic choice)."""
    from ...models import is_default_model

    if is_default_model(name):
        # the embedded GGUF cannot be trained by Prime-RL; its hub original can
        return SMOLLM2_HUB_ID, "default"
    path = Path(name).expanduser()
    if path.suffix == ".gguf" or (path.is_dir() and not (path / "config.json").exists()):
        raise PrimeRLConfigError(f"model {name!r}: Prime-RL trains Hugging Face checkpoints (a folder "
                                 f"with config.json or a hub ID), not GGUF files")
    if path.is_dir():
        # a local fine-tune: render prompts with its own chat template
        return str(path.resolve()), "default"
    if path.is_absolute() or name.startswith((".", "~")):
        raise PrimeRLConfigError(f"model path {name} does not exist")
    return name, None


def _loss(cfg: TrainConfig) -> dict[str, Any]:
    if cfg.loss == "ipo":
        return {"type": "ipo", "ipo_threshold": cfg.threshold, "adv_tau": cfg.adv_tau, "kl_tau": cfg.kl_coef}
    return {"type": "default", "dppo_mask_low": cfg.mask_low, "dppo_mask_high": cfg.mask_high,
            "adv_tau": cfg.adv_tau, "kl_tau": cfg.kl_coef}


def _digest(text: str) -> str:
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


def _unedited(text: str) -> bool:
    """Whether ``text`` is a file render_toml wrote, unchanged since."""
    lines = text.splitlines(keepends=True)
    marks = [i for i, line in enumerate(lines) if line.startswith(_CHECKSUM)]
    if len(marks) != 1:
        return False
    rest = "".join(lines[:marks[0]] + lines[marks[0] + 1:])
    return lines[marks[0]][len(_CHECKSUM):].strip() == _digest(rest)


def _write_atomic(path: Path, text: str) -> None:
    tmp = path.with_name(f".{path.name}.tmp")
    tmp.write_text(text, encoding="utf-8")
    os.replace(tmp, path)


# -- a small TOML writer: tables, arrays of tables, strings, numbers, booleans, arrays ------------

_BARE_KEY = re.compile(r"[A-Za-z0-9_-]+\Z")
_ESCAPES = {'"': '\\"', "\\": "\\\\", "\b": "\\b", "\t": "\\t", "\n": "\\n", "\f": "\\f", "\r": "\\r"}
_LINE = 100


def dumps(doc: dict[str, Any]) -> str:
    """``doc`` as TOML: a table's plain keys first, then its sub-tables, then its arrays of tables."""
    lines: list[str] = []
    _table(lines, [], doc, array_item=False)
    return "\n".join(lines).lstrip("\n") + "\n"


def _table(lines: list[str], path: list[str], table: dict[str, Any], *, array_item: bool) -> None:
    plain = {k: v for k, v in table.items() if not isinstance(v, dict) and not _is_table_array(v)}
    tables = {k: v for k, v in table.items() if isinstance(v, dict)}
    arrays = {k: v for k, v in table.items() if _is_table_array(v)}
    if path and (array_item or plain or not (tables or arrays)):
        name = ".".join(_key(p) for p in path)
        lines += ["", f"[[{name}]]" if array_item else f"[{name}]"]
    lines += [f"{_key(k)} = {_value(v)}" for k, v in plain.items()]
    for k, v in tables.items():
        _table(lines, [*path, k], v, array_item=False)
    for k, items in arrays.items():
        for item in items:
            _table(lines, [*path, k], item, array_item=True)


def _is_table_array(value: Any) -> bool:
    return isinstance(value, list) and bool(value) and all(isinstance(v, dict) for v in value)


def _key(key: str) -> str:
    return key if _BARE_KEY.match(key) else _string(key)


def _string(text: str) -> str:
    out = (_ESCAPES.get(ch) or (f"\\u{ord(ch):04x}" if ord(ch) < 0x20 or ord(ch) == 0x7F else ch)
           for ch in text)
    return '"' + "".join(out) + '"'


def _value(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if not math.isfinite(value):
            raise ValueError(f"TOML value {value!r}: only finite numbers are written")
        return repr(value)
    if isinstance(value, str):
        return _string(value)
    if isinstance(value, list):
        if any(isinstance(v, dict) for v in value):
            raise TypeError("an array mixing tables and values has no TOML form")
        items = [_value(v) for v in value]
        one_line = "[" + ", ".join(items) + "]"
        return one_line if len(one_line) <= _LINE else "[\n" + "".join(f"    {i},\n" for i in items) + "]"
    raise TypeError(f"no TOML form for {type(value).__name__} value {value!r}")
