"""The part of Prime-RL's ``rl`` config schema that glyphbench renders into, transcribed as data.

Prime-RL is not on PyPI, so the tests check rendered files against this transcription, and
``scripts/validate_prime_rl.py`` checks the transcription (and the files) against a checkout.
``PRIME_RL_COMMIT`` is the one place that names the commit; the renderer writes it into every
file's header.

Source: PrimeIntellect-ai/prime-rl at ``PRIME_RL_COMMIT`` (2026-08-21), files under
packages/prime-rl-configs/src/prime_rl/configs/: rl.py (RLConfig, SharedModelConfig,
SharedCheckpointConfig, SharedMonitorsConfig, SharedWandbConfig), shared.py (RunConfig,
ResumeConfig), trainer.py (TrainerConfig, ModelConfig, ActivationCheckpointConfig, the loss,
optimizer and scheduler unions), orchestrator.py (OrchestratorConfig, TrainConfig,
TrainSourceConfig, EvalConfig, EvalSourceConfig, TrainSamplingConfig, EvalSamplingConfig),
algorithm.py (the ``algo`` union); verifiers' v1 EnvConfig at the commit Prime-RL pins
(a60a606, deps/verifiers: configs/env.py) plus the ``agent`` seat of glyphbench's own env
config; renderers 0.1.12 (AutoRendererConfig, DefaultRendererConfig). Only the fields of these
classes are listed, so a key outside them (a typo, or a key of another Prime-RL version) fails.

``TABLES`` maps a dotted table path ("[]" marks the items of an array of tables) to its keys and
their value types: a Python type, a tuple of types, ``[T]`` for an array of T, ``TABLE`` for a
sub-table, ``TABLE_OR_NONE`` for an optional sub-table that may be switched off with the string
``"None"`` (pydantic-config's null), ``TABLE_ARRAY`` for an array of tables, ``TASKSET`` for a
verifiers taskset config (whose keys are the taskset plugin's own and are checked against that
plugin), or ``ANY`` for a key whose value is not transcribed. ``UNIONS`` holds the discriminated
unions: path -> (discriminator key, {value: keys of that variant}).
"""

from __future__ import annotations

PRIME_RL_COMMIT = "559b44772e471d1538537b8805cc77f3824a5e64"
PRIME_RL_COMMIT_DATE = "2026-08-21"
VERIFIERS_PIN = "a60a606ecc4d309247edf9ff92c3eabca362781f"   # prime-rl's deps/verifiers at that commit

TABLE = "table"
TABLE_OR_NONE = "table, or \"None\" to switch it off"
TABLE_ARRAY = "array of tables"
TASKSET = "taskset plugin config"
ANY = "any value (not transcribed)"
FLOAT = (int, float)     # pydantic takes an int for a float field
OPT_INT = int            # `int | None` fields: TOML has no null, so a present value is an int

_SAMPLING_TRAIN = {"temperature": FLOAT, "max_completion_tokens": OPT_INT, "extra_body": TABLE}
_SAMPLING_EVAL = {"temperature": FLOAT, "top_p": FLOAT, "top_k": int, "min_p": FLOAT,
                  "max_completion_tokens": OPT_INT, "reasoning_effort": str, "extra_body": TABLE}
# orchestrator.py EnvConfig: the verifiers env block (`env`, narrowed to the env named by its
# taskset id), how it is served, and the orchestrator's own per-env knobs
_SOURCE = {"env": TABLE, "serve": TABLE, "name": str, "ratio": FLOAT}
# verifiers.v1 EnvConfig (configs/env.py) + GlyphbenchEnvConfig's one seat
_ENV = {"id": str, "taskset": TASKSET, "timeout": TABLE, "retries": TABLE,
        "max_concurrent_agents": int, "interception": TABLE, "agent": TABLE}
_ALGO_SAMPLING = {"source": (str, dict)}

TABLES: dict[str, dict] = {
    "": {"trainer": TABLE, "orchestrator": TABLE, "inference": TABLE, "env_vars": TABLE, "run": TABLE,
         "output_dir": str, "clean": bool, "log": TABLE, "ckpt": TABLE, "resume": TABLE,
         "monitors": TABLE, "model": TABLE, "tokenizer": TABLE, "max_steps": int, "seq_len": int,
         "weight_broadcast": TABLE, "rollout_transport": TABLE, "deployment": TABLE, "slurm": TABLE,
         "dry_run": bool},
    "run": {"name": str, "dir": str},
    "resume": {"step": int, "dir": str},
    "model": {"name": str, "vlm": TABLE},
    "ckpt": {"output_dir": str, "interval": int, "keep_last": int, "keep_interval": int},
    "monitors": {"wandb": TABLE_OR_NONE, "file": TABLE_OR_NONE, "prime": TABLE_OR_NONE},
    "monitors.wandb": {"project": str, "entity": str, "name": str, "group": str, "tags": [str],
                       "offline": bool},
    # InferenceConfig's keys are not transcribed: glyphbench renders the table empty (its
    # presence makes the rl launcher start the vLLM server), so any key here fails.
    "inference": {},
    "trainer": {"model": TABLE, "tokenizer": TABLE, "data": TABLE, "loss": TABLE, "optim": TABLE,
                "scheduler": TABLE, "ckpt": TABLE, "resume": TABLE, "weight_broadcast": TABLE,
                "rollout_transport": TABLE, "log": TABLE, "monitors": TABLE, "output_dir": str,
                "matmul_precision": str, "max_steps": int, "enable_router_replay": bool,
                "memory_profiler_path": str, "gc": TABLE_OR_NONE, "trace_path": str,
                "dist_timeout_seconds": int, "heartbeat": TABLE, "metrics_server": TABLE,
                "enable_token_export": bool, "env_vars": TABLE},
    "trainer.model": {"name": str, "trust_remote_code": bool, "vlm": TABLE, "conversion_dir": str,
                      "seq_len": int, "attn": str, "compile": TABLE_OR_NONE, "ac": TABLE_OR_NONE,
                      "ac_offloading": TABLE_OR_NONE, "fsdp_cpu_offload": bool,
                      "optim_cpu_offload": bool, "full_offload": (bool, dict),
                      "reshard_after_forward": bool, "dp_replicate": int, "ep": (int, str),
                      "ep_comm_backend": str, "deepep_num_sms": int, "deepep_token_chunk_size": int,
                      "cp": int, "cp_style": str, "impl": str, "optimization_dtype": str,
                      "reduce_dtype": str, "moe_router_dtype": str, "moe_use_grouped_mm": bool,
                      "moe_fused_kernel": bool, "quantization": TABLE, "index_cache": TABLE,
                      "freeze_moe_router": bool, "lora": TABLE, "debug": TABLE,
                      "fused_lm_head_token_chunk_size": (int, str)},
    "trainer.model.ac": {"mode": str, "freq": int, "targets": [str]},
    "orchestrator": {"algo": TABLE, "model": TABLE, "train": TABLE, "tokenizer": TABLE,
                     "renderer": TABLE, "eval": TABLE, "log": TABLE, "env_vars": TABLE,
                     "monitors": TABLE, "collect_inference_metrics": bool,
                     "inference_metrics_roles": [str], "ckpt": TABLE, "resume": TABLE,
                     "weight_broadcast": TABLE, "rollout_transport": TABLE, "output_dir": str,
                     "tasks_per_minute": int, "env_server_base_port": int, "batch_size": int,
                     "token_batch_size": int, "concurrency": TABLE, "group_size": int,
                     "seq_len": int, "num_train_workers": int, "pad_to_multiple_of": int,
                     "max_steps": int, "max_off_policy_steps": int, "heartbeat": TABLE},
    "orchestrator.train": {"source": TABLE_ARRAY, "sampling": TABLE, "filter_zero_advantages": bool},
    "orchestrator.train.sampling": _SAMPLING_TRAIN,
    "orchestrator.train.source[]": {**_SOURCE, "sampling": TABLE, "group_size": int, "algo": TABLE,
                                    "curriculum": TABLE},
    "orchestrator.train.source[].env": _ENV,
    "orchestrator.train.source[].sampling": _SAMPLING_TRAIN,
    "orchestrator.eval": {"source": TABLE_ARRAY, "sampling": TABLE, "num_examples": int,
                          "group_size": int, "interval": int, "skip_first_step": bool,
                          "retrigger_on_resume": bool},
    "orchestrator.eval.sampling": _SAMPLING_EVAL,
    "orchestrator.eval.source[]": {**_SOURCE, "sampling": TABLE, "num_examples": int,
                                   "group_size": int, "interval": int},
    "orchestrator.eval.source[].env": _ENV,
    "orchestrator.eval.source[].sampling": _SAMPLING_EVAL,
}
for _path in ("orchestrator.train.source[].env.agent", "orchestrator.eval.source[].env.agent",
              "orchestrator.train.source[].env.timeout", "orchestrator.eval.source[].env.timeout"):
    TABLES[_path] = {"*": ANY}      # verifiers' own sub-configs: not transcribed

_GRPO = {"sampling": TABLE, "length_penalty": TABLE}
UNIONS: dict[str, tuple[str, dict]] = {
    "trainer.loss": ("type", {
        "default": {"dppo_mask_low": FLOAT, "dppo_mask_high": FLOAT, "adv_tau": FLOAT, "kl_tau": FLOAT},
        "ipo": {"ipo_threshold": FLOAT, "adv_tau": FLOAT, "kl_tau": FLOAT},
        "custom": {"import_path": str, "kwargs": TABLE},
    }),
    "trainer.optim": ("type", {
        "adamw": {"lr": FLOAT, "weight_decay": FLOAT, "max_norm": FLOAT, "betas1": FLOAT, "betas2": FLOAT},
    }),
    "trainer.scheduler": ("type", {
        "constant": {},
        "linear": {"warmup_steps": int, "decay_steps": int, "min_lr": FLOAT},
        "cosine": {"warmup_steps": int, "min_lr": FLOAT},
    }),
    "orchestrator.algo": ("type", {"grpo": _GRPO, "max_rl": {"sampling": TABLE}}),
    "orchestrator.renderer": ("name", {
        "auto": {"thinking_retention": ANY},
        "default": {"thinking_retention": ANY, "tool_parser": str, "reasoning_parser": str},
    }),
}
UNIONS["orchestrator.train.source[].algo"] = UNIONS["orchestrator.algo"]
TABLES["orchestrator.algo.sampling"] = TABLES["orchestrator.train.source[].algo.sampling"] = _ALGO_SAMPLING

# The classes each transcribed table was read from (module under prime_rl.configs, class), for
# scripts/validate_prime_rl.py --schema, which compares the keys with a checkout's model_fields.
SOURCES = {
    "": ("rl", "RLConfig"), "run": ("shared", "RunConfig"), "resume": ("shared", "ResumeConfig"),
    "model": ("rl", "SharedModelConfig"), "ckpt": ("rl", "SharedCheckpointConfig"),
    "monitors": ("rl", "SharedMonitorsConfig"), "monitors.wandb": ("rl", "SharedWandbConfig"),
    "trainer": ("trainer", "TrainerConfig"), "trainer.model": ("trainer", "ModelConfig"),
    "trainer.model.ac": ("trainer", "ActivationCheckpointConfig"),
    "trainer.loss=default": ("trainer", "DefaultLossConfig"), "trainer.loss=ipo": ("trainer", "IPOLossConfig"),
    "trainer.loss=custom": ("trainer", "CustomLossConfig"), "trainer.optim=adamw": ("trainer", "AdamWConfig"),
    "trainer.scheduler=constant": ("trainer", "ConstantSchedulerConfig"),
    "trainer.scheduler=linear": ("trainer", "LinearSchedulerConfig"),
    "trainer.scheduler=cosine": ("trainer", "CosineSchedulerConfig"),
    "orchestrator": ("orchestrator", "OrchestratorConfig"), "orchestrator.train": ("orchestrator", "TrainConfig"),
    "orchestrator.train.sampling": ("orchestrator", "TrainSamplingConfig"),
    "orchestrator.train.source[]": ("orchestrator", "TrainSourceConfig"),
    "orchestrator.eval": ("orchestrator", "EvalConfig"),
    "orchestrator.eval.sampling": ("orchestrator", "EvalSamplingConfig"),
    "orchestrator.eval.source[]": ("orchestrator", "EvalSourceConfig"),
    "orchestrator.algo=grpo": ("algorithm", "GRPOAlgoConfig"),
    "orchestrator.algo=max_rl": ("algorithm", "MaxRLAlgoConfig"),
    "orchestrator.algo.sampling": ("algorithm", "SamplingConfig"),
}


def check(doc: dict, path: str = "") -> list[str]:
    """Problems with ``doc`` against the schema, one line each (none when it conforms). Taskset
    tables are only checked for an id here: ``tasksets`` hands them to the plugin's validator."""
    problems: list[str] = []
    _check_table(doc, path, problems)
    return problems


def tasksets(doc: dict) -> list[dict]:
    """Every taskset table of the train and eval sources."""
    orch = doc.get("orchestrator", {})
    sources = orch.get("train", {}).get("source", []) + orch.get("eval", {}).get("source", [])
    return [src["env"]["taskset"] for src in sources if "taskset" in src.get("env", {})]


def _keys(path: str, table: dict, problems: list[str]) -> dict | None:
    if path in UNIONS:
        disc, variants = UNIONS[path]
        kind = table.get(disc)
        if kind not in variants:
            problems.append(f"{path}.{disc} = {kind!r}: not one of {sorted(variants)}")
            return None
        return {disc: str, **variants[kind]}
    if path not in TABLES:
        problems.append(f"[{path}] is not a table of the transcribed schema")
        return None
    return TABLES[path]


def _check_table(table: dict, path: str, problems: list[str]) -> None:
    keys = _keys(path, table, problems)
    if keys is None or keys.get("*") == ANY:
        return
    for key, value in table.items():
        where = f"{path}.{key}" if path else key
        if key not in keys:
            problems.append(f"unknown key {where}")
            continue
        want = keys[key]
        if want == ANY:
            continue
        if want in (TABLE, TABLE_OR_NONE):
            if isinstance(value, dict):
                _check_table(value, where, problems)
            elif not (want == TABLE_OR_NONE and value == "None"):
                problems.append(f"{where} should be a table" + (' or "None"' if want == TABLE_OR_NONE else ""))
        elif want == TABLE_ARRAY:
            if isinstance(value, list) and all(isinstance(v, dict) for v in value):
                for item in value:
                    _check_table(item, f"{where}[]", problems)
            else:
                problems.append(f"{where} should be an array of tables")
        elif want == TASKSET:
            if not isinstance(value, dict) or not isinstance(value.get("id"), str):
                problems.append(f"{where} should be a taskset table with an id")
        elif isinstance(want, list):
            if not isinstance(value, list) or not all(_is(v, want[0]) for v in value):
                problems.append(f"{where} should be an array of {want[0]}")
        elif not _is(value, want):
            problems.append(f"{where} = {value!r} has the wrong type (want {want})")


def _is(value, types) -> bool:
    types = types if isinstance(types, tuple) else (types,)
    if isinstance(value, bool) and bool not in types:
        return False
    return isinstance(value, types)
