"""``glyphbench plot``: training curves, a paired comparison of two evaluation jobs, a sweep grid.

    glyphbench plot training RUN_DIR [RUN_DIR ...] --out FILE [--window N]
    glyphbench plot compare JOB_A JOB_B --out FILE
    glyphbench plot sweep SWEEP_DIR --out FILE [--window-rollouts N] [--select GLOB]

FILE ends in .png, .pdf or .svg. The figures are drawn by ``glyphbench_rl.plots``, imported only
when a plot is asked for (the rest of ``glyphbench`` runs without matplotlib).
"""

from __future__ import annotations

import sys


def _warn(message: str) -> None:
    print(f"glyphbench: warning: {message}", file=sys.stderr)


def cmd_training(args) -> int:
    from ..replay.plots import plot_training
    print(f"wrote {plot_training(args.run_dirs, args.out, window=args.window, log=_warn)}")
    return 0


def cmd_compare(args) -> int:
    from ..replay.plots import plot_comparison
    print(f"wrote {plot_comparison(args.job_a, args.job_b, args.out, log=_warn)}")
    return 0


def cmd_sweep(args) -> int:
    from ..replay.plots import plot_sweep
    path = plot_sweep(args.sweep_dir, args.out, window_rollouts=args.window_rollouts,
                      select=args.select, log=_warn)
    print(f"wrote {path}")
    return 0


def register(subparsers) -> None:
    """Add ``plot`` and its three kinds to the ``glyphbench`` subcommands."""
    p = subparsers.add_parser("plot", help="figures: training curves, paired comparison, sweep grid",
                              description=__doc__.split("\n\n")[0].replace("``", ""))
    kinds = p.add_subparsers(dest="plot_kind", required=True, metavar="{training,compare,sweep}")

    s = kinds.add_parser("training", help="return and forfeit rate per step of one or more runs")
    s.add_argument("run_dirs", nargs="+", metavar="RUN_DIR", help="glyphbench-train --out directory")
    s.add_argument("--out", required=True, help="figure file (.png, .pdf or .svg)")
    s.add_argument("--window", type=int, default=10, help="trailing-mean window in steps (default 10)")
    s.set_defaults(func=cmd_training)

    s = kinds.add_parser("compare", help="two evaluation jobs paired per (task, seed), by suite")
    s.add_argument("job_a", metavar="JOB_A", help="evaluation job directory (or its episodes.jsonl)")
    s.add_argument("job_b", metavar="JOB_B")
    s.add_argument("--out", required=True, help="figure file (.png, .pdf or .svg)")
    s.set_defaults(func=cmd_compare)

    s = kinds.add_parser("sweep", help="a glyphbench-sweep directory: rows lr, colours group size")
    s.add_argument("sweep_dir", metavar="SWEEP_DIR")
    s.add_argument("--out", required=True, help="figure file (.png, .pdf or .svg)")
    s.add_argument("--window-rollouts", type=int, default=512,
                   help="trailing-mean window in rollouts (default 512, as in the paper)")
    s.add_argument("--select", metavar="GLOB", help="only conditions whose name matches, e.g. 'long_*'")
    s.set_defaults(func=cmd_sweep)

