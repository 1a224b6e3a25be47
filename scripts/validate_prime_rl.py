"""Parse rendered Prime-RL configs with a Prime-RL checkout's own RLConfig, as ``rl @ FILE`` does.

    python scripts/validate_prime_rl.py PRIME_RL_CHECKOUT FILE.toml [FILE.toml ...] [--schema]

Run it in an environment that has Prime-RL's config package and glyphbench_rl importable (Prime-RL
is not on PyPI, so never in the project's own environment; the tests use the transcription in
glyphbench_rl/integrations/prime_rl/schema.py). For example, with Python 3.11+:

    python -m venv /tmp/prime-venv
    /tmp/prime-venv/bin/pip install prime-pydantic-config renderers verifiers==0.4.0 -e .
    /tmp/prime-venv/bin/pip install --no-deps --ignore-requires-python \\
        -e PRIME_RL_CHECKOUT/packages/prime-rl-configs

(``--ignore-requires-python``: the package declares Python 3.12; its config code runs on 3.11.)
Each file goes through ``pydantic_config.cli(RLConfig, args=["@", FILE])``, the call behind
Prime-RL's ``rl`` entry point (src/prime_rl/entrypoints/rl.py: ``rl(cli(RLConfig))``), and
prints one line: ``ok`` with what the config resolved to, or the validation error. ``--schema``
also compares the transcribed keys with the checkout's model fields. Exit status: 0 when every
file validates (and the schema matches), 1 otherwise.
"""

from __future__ import annotations

import argparse
import contextlib
import importlib
import io
import sys
from pathlib import Path


def check_schema() -> list[str]:
    """Transcribed tables whose keys differ from the checkout's classes."""
    from glyphbench_rl.integrations.prime_rl import schema

    problems = []
    for path, (module, cls_name) in schema.SOURCES.items():
        cls = getattr(importlib.import_module(f"prime_rl.configs.{module}"), cls_name)
        fields = set(cls.model_fields)
        if "=" in path:
            table, variant = path.split("=")
            disc, variants = schema.UNIONS[table]
            keys = {disc, *variants[variant]}
        else:
            keys = set(schema.TABLES[path])
        if keys != fields:
            problems.append(f"[{path}] {module}.{cls_name}: missing {sorted(fields - keys)}, "
                            f"extra {sorted(keys - fields)}")
    return problems


def validate(path: Path) -> str:
    """One line: ok and the resolved essentials, or the error."""
    from prime_rl.configs.rl import RLConfig
    from pydantic_config import cli

    err = io.StringIO()
    try:
        with contextlib.redirect_stderr(err):
            cfg = cli(RLConfig, args=["@", str(path)])
    except SystemExit:
        return "FAILED\n" + err.getvalue().rstrip()
    except Exception as e:          # noqa: BLE001 - report whatever the config raised
        return f"FAILED {type(e).__name__}: {e}"
    orch, trainer = cfg.orchestrator, cfg.trainer
    src = orch.train.source[0]
    # the rows Prime-RL's orchestrator would sample: the taskset plugin, built from the parsed config
    from verifiers.v1.utils.loaders import taskset_class
    rows = sum(1 for _ in taskset_class(src.env.taskset.id)(src.env.taskset))
    ac = trainer.model.ac
    return (f"ok  run_dir={cfg.run_dir} steps={cfg.max_steps} model={trainer.model.name} "
            f"loss={trainer.loss.type} lr={trainer.optim.lr} batch={orch.batch_size}x{orch.group_size} "
            f"algo={src.algo.type} filter_zero_advantages={orch.train.filter_zero_advantages} "
            f"ac={'off' if ac is None else f'{ac.mode}/{ac.freq}'} resume={cfg.resume is not None} "
            f"env={type(src.env).__name__}({type(src.env.taskset).__name__}: "
            f"{len(src.env.taskset.tasks or [])} tasks, split {src.env.taskset.split}, {rows} rows) "
            f"eval={'off' if orch.eval is None else orch.eval.interval} "
            f"wandb={None if cfg.monitors.wandb is None else cfg.monitors.wandb.project}")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("checkout", type=Path, help="a Prime-RL checkout (its config package installed)")
    ap.add_argument("files", nargs="*", type=Path, help="rendered prime_rl.toml files")
    ap.add_argument("--schema", action="store_true", help="compare the transcription with the checkout")
    args = ap.parse_intermixed_args(argv)
    import prime_rl.configs

    pkg = Path(prime_rl.configs.__file__).resolve()
    want = (args.checkout / "packages/prime-rl-configs/src/prime_rl/configs").resolve()
    if pkg.parent != want:
        print(f"prime_rl.configs is imported from {pkg.parent}, not {want}", file=sys.stderr)
        return 1
    failed = 0
    if args.schema:
        problems = check_schema()
        print("schema: " + ("transcription matches the checkout" if not problems else "\n  ".join(["", *problems])))
        failed += bool(problems)
    for path in args.files:
        line = validate(path)
        failed += not line.startswith("ok")
        print(f"{path}: {line}")
    return 1 if failed else 0


if __name__ == "__main__":
    raise SystemExit(main())
