"""The part of Prime-RL's ``rl`` config schema that glyphbench renders into, transcribed as data.

Source: PrimeIntellect-ai/prime-rl at commit 004274ec964f016ec9b17b5ae990a4b535314ff1, files under
packages/prime-rl-configs/src/prime_rl/: configs/rl.py (RLConfig, SharedModelConfig,
SharedCheckpointConfig), configs/trainer.py (TrainerConfig, ModelConfig,
ActivationCheckpointConfig, AdamWConfig, ConstantSchedulerConfig, DefaultLossConfig,
IPOLossConfig), configs/orchestrator.py (OrchestratorConfig, TrainConfig, TrainEnvConfig,
EvalConfig, EvalEnvConfig, TrainSamplingConfig, EvalSamplingConfig, the three filter configs);
and renderers 0.1.12 (DefaultRendererConfig). Only the fields of the classes above are listed, so a
key outside them (a typo, or a key from another Prime-RL version) fails the check.

``TABLES`` maps a dotted table path ("[]" marks the items of an array of tables) to its keys and
their value types: a Python type, a tuple of types, ``[T]`` for an array of T, ``TABLE`` for a
sub-table, ``TABLE_ARRAY`` for an array of tables, or ``TASKSET`` for a verifiers taskset config
(whose keys are the taskset plugin's own and are checked against that plugin). ``UNIONS`` holds
the discriminated unions: path -> (discriminator key, {value: keys of that variant}).
"""

TABLE = "table"
TABLE_ARRAY = "array of tables"
TASKSET = "taskset plugin config"
FLOAT = (int, float)     # pydantic takes an int for a float field
OPT_INT = int            # `int | None` fields: TOML has no null, so a present value is an int

PRIME_RL_COMMIT = "004274ec964f016ec9b17b5ae990a4b535314ff1"

_SAMPLING_TRAIN = {"temperature": FLOAT, "max_completion_tokens": OPT_INT, "extra_body": TABLE}
_SAMPLING_EVAL = {"temperature": FLOAT, "top_p": FLOAT, "top_k": int, "min_p": FLOAT,
                  "max_completion_tokens": OPT_INT, "reasoning_effort": str, "extra_body": TABLE}
# orchestrator.py EnvConfig's own fields (it extends vf.EnvServerConfig, whose `taskset` is a
# verifiers TasksetConfig narrowed to the plugin named by its id)
_ENV = {"name": str, "address": str, "ratio": FLOAT, "max_retries": int, "taskset": TASKSET}

TABLES = {
    "": {"trainer": TABLE, "orchestrator": TABLE, "inference": TABLE, "output_dir": str,
         "clean_output_dir": bool, "env_server_base_port": int, "log": TABLE, "ckpt": TABLE,
         "wandb": TABLE, "model": TABLE, "tokenizer": TABLE, "max_steps": int, "seq_len": int,
         "weight_broadcast": TABLE, "bench": bool, "deployment": TABLE, "slurm": TABLE,
         "dry_run": bool, "experimental": TABLE},
    "model": {"name": str, "vlm": TABLE},
    "wandb": {"project": str, "entity": str, "name": str, "group": str, "tags": [str], "offline": bool},
    "ckpt": {"output_dir": str, "interval": int, "resume_step": int, "keep_last": int,
             "keep_interval": int},
    # InferenceConfig's keys are not transcribed: glyphbench renders the table empty (its
    # presence makes the rl launcher start the vLLM server), so any key here fails.
    "inference": {},
    "trainer": {"model": TABLE, "tokenizer": TABLE, "data": TABLE, "loss": TABLE, "optim": TABLE,
                "scheduler": TABLE, "ckpt": TABLE, "weight_broadcast": TABLE,
                "rollout_transport": TABLE, "log": TABLE, "wandb": TABLE, "output_dir": str,
                "matmul_precision": str, "max_steps": int, "enable_router_replay": bool,
                "memory_profiler_path": str, "bench": TABLE, "gc": TABLE, "trace_path": str,
                "dist_timeout_seconds": int, "heartbeat": TABLE, "metrics_server": TABLE,
                "max_concurrent_runs": int, "enable_token_export": bool},
    "trainer.model": {"name": str, "seq_len": int, "attn": str, "compile": TABLE, "ac": TABLE,
                      "ac_offloading": TABLE, "fsdp_cpu_offload": bool, "optim_cpu_offload": bool,
                      "reshard_after_forward": bool, "dp_replicate": int, "ep": int,
                      "ep_comm_backend": str, "deepep_num_sms": int, "deepep_token_chunk_size": int,
                      "cp": int, "cp_style": str, "impl": str, "optimization_dtype": str,
                      "reduce_dtype": str, "moe_use_grouped_mm": bool, "fp8": bool,
                      "index_cache": TABLE, "freeze_moe_router": bool, "lora": TABLE, "debug": TABLE,
                      "fused_lm_head_token_chunk_size": (int, str), "trust_remote_code": bool,
                      "vlm": TABLE},
    "trainer.model.ac": {"mode": str, "freq": int, "targets": [str]},
    "orchestrator": {"model": TABLE, "actor": str, "algorithms": [str], "models": TABLE,
                     "train": TABLE, "tokenizer": TABLE, "renderer": TABLE, "pool_size": int,
                     "optim": TABLE, "eval": TABLE, "pre_batch_filters": TABLE_ARRAY,
                     "post_batch_filters": TABLE_ARRAY, "log": TABLE, "wandb": TABLE,
                     "prime_monitor": TABLE, "collect_inference_metrics": bool,
                     "inference_metrics_roles": [str], "ckpt": TABLE, "weight_broadcast": TABLE,
                     "rollout_transport": TABLE, "output_dir": str, "tasks_per_minute": int,
                     "batch_size": int, "token_batch_size": int, "oversampling_factor": FLOAT,
                     "max_inflight_rollouts": int, "group_size": int, "seq_len": int,
                     "num_train_workers": int, "max_steps": int, "max_off_policy_steps": int,
                     "bench": bool, "heartbeat": TABLE, "env_install_prerelease": bool,
                     "experimental": TABLE},
    "orchestrator.train": {"env": TABLE_ARRAY, "sampling": TABLE, "max_retries": int},
    "orchestrator.train.sampling": _SAMPLING_TRAIN,
    "orchestrator.train.env[]": {**_ENV, "sampling": TABLE, "group_size": int, "algorithms": [str]},
    "orchestrator.train.env[].sampling": _SAMPLING_TRAIN,
    "orchestrator.eval": {"env": TABLE_ARRAY, "sampling": TABLE, "num_examples": int,
                          "group_size": int, "max_retries": int, "interval": int,
                          "skip_first_step": bool},
    "orchestrator.eval.sampling": _SAMPLING_EVAL,
    "orchestrator.eval.env[]": {**_ENV, "sampling": TABLE, "num_examples": int, "group_size": int,
                                "interval": int},
    "orchestrator.eval.env[].sampling": _SAMPLING_EVAL,
}

UNIONS = {
    "trainer.loss": ("type", {
        "default": {"dppo_mask_low": FLOAT, "dppo_mask_high": FLOAT, "adv_tau": FLOAT, "kl_tau": FLOAT},
        "ipo": {"ipo_threshold": FLOAT, "adv_tau": FLOAT, "kl_tau": FLOAT},
    }),
    "trainer.optim": ("type", {
        "adamw": {"lr": FLOAT, "weight_decay": FLOAT, "max_norm": FLOAT, "betas1": FLOAT, "betas2": FLOAT},
    }),
    "trainer.scheduler": ("type", {"constant": {}}),
    "orchestrator.renderer": ("name", {"auto": {}, "default": {"tool_parser": str}}),
    "orchestrator.post_batch_filters[]": ("type", {
        "gibberish": {"enforce": bool, "token_id_threshold": int, "logprob_offset": FLOAT},
        "repetition": {"enforce": bool, "window": int, "prob_threshold": FLOAT},
        "zero_advantage": {"enforce": bool},
    }),
}
UNIONS["orchestrator.pre_batch_filters[]"] = UNIONS["orchestrator.post_batch_filters[]"]


def check(doc: dict, path: str = "") -> list[str]:
    """Problems with ``doc`` against the schema, one line each (none when it conforms). Taskset
    tables are only checked for an id here: ``tasksets`` hands them to the plugin's validator."""
    problems: list[str] = []
    _check_table(doc, path, problems)
    return problems


def tasksets(doc: dict) -> list[dict]:
    """Every taskset table of the train and eval environments."""
    orch = doc.get("orchestrator", {})
    envs = orch.get("train", {}).get("env", []) + orch.get("eval", {}).get("env", [])
    return [env["taskset"] for env in envs if "taskset" in env]


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
    if keys is None:
        return
    for key, value in table.items():
        where = f"{path}.{key}" if path else key
        if key not in keys:
            problems.append(f"unknown key {where}")
            continue
        want = keys[key]
        if want == TABLE:
            if isinstance(value, dict):
                _check_table(value, where, problems)
            else:
                problems.append(f"{where} should be a table")
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
