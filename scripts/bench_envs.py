#!/usr/bin/env python
"""Benchmark every registered task (or a selection): step+render time, observation and prompt size.

    python scripts/bench_envs.py [--tasks IDS|GLOB|FILE] [--runs 3] [--steps 400] [--rounds 3] [--tokenizer smollm2]

Same as ``glyphbench bench``; prints a table (our median step time including rendering, the
reference implementation's from tasks/baselines/reference-figures.tsv, their ratio), then per
suite and overall the geometric-mean and median ratios and the tasks slower than the reference,
against the targets (no task above ratio 1, median ratio <= 0.5; median over tasks <= 25 us per
step, no task above 250 us). With --tokenizer, our tokens per observation and prompt beside theirs.

For tasks over an external engine (MiniHack and NetHack on NLE) it also prints the engine alone on
the same turns (upstream's environment stepping the keys our turns sent, no wrapper, no
rendering), the ratio of ours to it per task and its median (target <= 1.3), the median tokens
per observation (target <= 110 SmolLM2 tokens), and the memory each episode adds with 64 open at
once in a fresh process (--live N to change, 0 to skip):

    python scripts/bench_envs.py --tasks 'glyphbench/minihack-*' --tokenizer smollm2
"""

import sys

from glyphbench_rl.cli.main import main

if __name__ == "__main__":
    sys.exit(main(["bench", *sys.argv[1:]]))
