#!/usr/bin/env python
"""Benchmark every registered task (or a selection): step+render time, observation and prompt size.

    python scripts/bench_envs.py [--tasks IDS|GLOB|FILE] [--runs 3] [--steps 400] [--rounds 3] [--tokenizer smollm2]

Same as ``glyphbench bench``; prints a table (our median step time including rendering, the
reference implementation's from tasks/baselines/reference-figures.tsv, their ratio), then per
suite and overall the geometric-mean and median ratios and the tasks slower than the reference,
against the targets (no task above ratio 1, median ratio <= 0.5; median over tasks <= 25 us per
step, no task above 250 us). With --tokenizer, our tokens per observation and prompt beside theirs.
"""

import sys

from glyphbench_rl.cli.main import main

if __name__ == "__main__":
    sys.exit(main(["bench", *sys.argv[1:]]))
