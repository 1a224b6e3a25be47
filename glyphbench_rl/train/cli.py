"""``glyphbench-train CONFIG.yaml [--out DIR] [--resume] [key=value ...]``: the built-in trainer."""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path
from typing import Sequence

from ..core.registry import UnknownTaskError
from .config import ConfigError, load_config


def main(argv: Sequence[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="glyphbench-train", description=__doc__.splitlines()[0])
    ap.add_argument("config", help="YAML run config (keys not given keep their documented defaults)")
    ap.add_argument("overrides", nargs="*", metavar="key=value",
                    help="config overrides, e.g. lr=5e-6 harness.history=2")
    ap.add_argument("--out", help="run directory (default: runs/<config name>)")
    ap.add_argument("--resume", action="store_true", help="continue from the last checkpoint in --out")
    args = ap.parse_intermixed_args(argv)   # overrides may come after --out
    try:
        cfg = load_config(args.config, args.overrides)
        out = Path(args.out or Path("runs") / Path(args.config).stem)
        from .trainer import Trainer
        trainer = Trainer(cfg, out, resume=args.resume)
    except (ConfigError, UnknownTaskError, FileExistsError, FileNotFoundError, ValueError) as e:
        print(f"glyphbench-train: error: {str(e).splitlines()[0]}", file=sys.stderr)
        return 2
    t0 = time.perf_counter()
    try:
        trainer.run()
    except KeyboardInterrupt:
        print(f"glyphbench-train: interrupted at step {trainer.step}; rerun with --resume to "
              f"continue from the last checkpoint in {out}", file=sys.stderr)
        return 130
    print(f"done: {trainer.step} steps in {time.perf_counter() - t0:.0f}s; metrics in "
          f"{out / 'metrics.jsonl'}, checkpoints in {out / 'checkpoints'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
