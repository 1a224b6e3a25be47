"""``glyphbench-sweep SWEEP.yaml``: expand a grid of training runs, run them, tabulate them.

The sweep itself is ``train.sweep``; this command adds the choices of where conditions run:
locally N at a time, as a Slurm array job, or rendered as Prime-RL configs (``--prime-rl``), and
draws the learning-curve figure (``replay.plots``) when the runs are done.
"""

from __future__ import annotations

import argparse
import shlex
import sys
from pathlib import Path
from typing import Sequence

from ..integrations.prime_rl import PrimeRLConfigError, started, write_toml
from ..train.config import ConfigError, config_from_dict, read_yaml
from ..train.sweep import expand, run_local, slurm_script, table, write_conditions


def write_prime_rl(out: Path, rows) -> list[Path]:
    """Each condition as a Prime-RL config, ``runs/<name>/prime_rl.toml``; a condition Prime-RL
    already started is rendered with ``[resume]``, so a rerun continues it (from its latest
    checkpoint, or from scratch when it saved none) instead of refusing its directory."""
    return [write_toml(config_from_dict(cfg), out / "runs" / name, resume=started(out / "runs" / name))
            for name, cfg, _ in rows]


def main(argv: Sequence[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="glyphbench-sweep", description=__doc__.splitlines()[0])
    ap.add_argument("sweep", help="sweep YAML (base, grid, rollout_budget, variants)")
    ap.add_argument("--out", help="sweep directory (default: runs/<sweep name>)")
    ap.add_argument("--parallel", type=int, default=1, help="conditions run at once (local)")
    ap.add_argument("--slurm", action="store_true", help="write sweep.sbatch (an array job) instead of running")
    ap.add_argument("--sbatch-extra", default="", help="extra #SBATCH lines for --slurm")
    ap.add_argument("--prime-rl", action="store_true",
                    help="render each condition as runs/<name>/prime_rl.toml and write prime_rl.sh "
                         "(with --slurm: an array job running Prime-RL's rl) instead of running")
    ap.add_argument("--dry-run", action="store_true", help="list the conditions and stop")
    ap.add_argument("--table", action="store_true", help="only tabulate what has run")
    args = ap.parse_args(argv)
    out = Path(args.out or Path("runs") / Path(args.sweep).stem)
    try:
        conditions = expand(read_yaml(args.sweep, "sweep"))
    except ConfigError as e:
        print(f"glyphbench-sweep: error: {str(e).splitlines()[0]}", file=sys.stderr)
        return 2
    if args.dry_run:
        for name, cfg in conditions:
            print(f"{name}: steps {config_from_dict(cfg).steps}")
        print(f"{len(conditions)} conditions")
        return 0
    rows = write_conditions(out, conditions)
    (out / "sweep.yaml").write_text(Path(args.sweep).read_text(encoding="utf-8"), encoding="utf-8")
    if args.prime_rl:
        try:
            tomls = write_prime_rl(out, rows)
        except (PrimeRLConfigError, FileExistsError, ValueError) as e:
            print(f"glyphbench-sweep: error: {str(e).splitlines()[0]}", file=sys.stderr)
            return 2
        (out / "logs").mkdir(parents=True, exist_ok=True)
        if args.slurm:
            path = out / "prime_rl.sbatch"
            path.write_text(slurm_script(out, rows, args.sbatch_extra, prime_rl=tomls))
            print(f"wrote {len(tomls)} Prime-RL configs and {path}; submit with: sbatch {path}")
        else:
            path = out / "prime_rl.sh"
            path.write_text("#!/bin/bash\nset -e\n" + "".join(f"rl @ {shlex.quote(str(t))}\n" for t in tomls))
            path.chmod(0o755)
            print(f"wrote {len(tomls)} Prime-RL configs and {path} (runs them one after another)")
        return 0
    if args.slurm:
        (out / "logs").mkdir(parents=True, exist_ok=True)
        path = out / "sweep.sbatch"
        path.write_text(slurm_script(out, rows, args.sbatch_extra))
        print(f"wrote {path} ({len(rows)} array tasks); submit with: sbatch {path}")
        return 0
    failed = 0 if args.table else run_local(out, rows, max(1, args.parallel))
    print(table(out, rows))
    from ..replay.plots import PlotError, plot_sweep
    try:
        print(f"learning curves: {plot_sweep(out, out / 'curves.png')}")
    except PlotError as e:          # nothing has metrics yet, or no matplotlib
        print(f"(no figure: {e})")
    return 1 if failed else 0


if __name__ == "__main__":
    raise SystemExit(main())
