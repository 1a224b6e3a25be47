"""``glyphbench-train CONFIG.yaml [--out DIR] [--resume] [--backend B] [key=value ...]``: train a policy.

``--backend builtin`` (default) runs the built-in trainer here; ``--backend prime-rl`` renders the
equivalent Prime-RL config into the run directory and launches Prime-RL's ``rl`` on it (or prints
the command when ``rl`` is absent).
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path
from typing import Sequence

from ..core.registry import MissingExtraError, UnknownTaskError
from ..train.config import ConfigError, load_config
from ..train.sinks import SinkError


def main(argv: Sequence[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="glyphbench-train", description=__doc__.splitlines()[0])
    ap.add_argument("config", help="YAML run config (keys not given keep their documented defaults)")
    ap.add_argument("overrides", nargs="*", metavar="key=value",
                    help="config overrides, e.g. lr=5e-6 harness.history=2")
    ap.add_argument("--out", help="run directory (default: runs/<config name>)")
    ap.add_argument("--resume", action="store_true", help="continue from the last checkpoint in --out")
    ap.add_argument("--backend", choices=("builtin", "prime-rl"), default="builtin",
                    help="builtin: train on this machine (default); prime-rl: write DIR/prime_rl.toml "
                         "and run Prime-RL's `rl` on it")
    args = ap.parse_intermixed_args(argv)   # overrides may come after --out
    try:
        cfg = load_config(args.config, args.overrides)
        out = Path(args.out or Path("runs") / Path(args.config).stem)
        if args.backend == "prime-rl":
            from ..integrations.prime_rl import write_toml
            toml_path = write_toml(cfg, out, resume=args.resume)
        else:
            from ..train.trainer import Trainer
            trainer = Trainer(cfg, out, resume=args.resume)
    except (ConfigError, UnknownTaskError, MissingExtraError, FileExistsError, FileNotFoundError, ValueError, SinkError) as e:
        print(f"glyphbench-train: error: {str(e).splitlines()[0]}", file=sys.stderr)
        return 2
    if args.backend == "prime-rl":
        from ..integrations.prime_rl import launch
        return launch(toml_path)
    from ..train.display import make_display
    t0 = time.perf_counter()
    try:
        with make_display(cfg.steps, start=trainer.step, title=f"glyphbench-train {out}") as display:
            trainer.run(display)
    except KeyboardInterrupt:
        print(f"glyphbench-train: interrupted at step {trainer.step}; rerun with --resume to "
              f"continue from the last checkpoint in {out}", file=sys.stderr)
        return 130
    print(f"done: {trainer.step} steps in {time.perf_counter() - t0:.0f}s; metrics in "
          f"{out / 'metrics.jsonl'}, checkpoints in {out / 'checkpoints'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
