#!/usr/bin/env python
"""Benchmark every registered task (or a selection): step+render time, observation and prompt size.

    python scripts/bench_envs.py [--tasks IDS|GLOB|FILE] [--runs 5] [--steps 400] [--tokenizer smollm2]

Same as ``glyphbench bench``; prints a table and the summary against the targets
(median over tasks <= 25 us per step including rendering, no task above 250 us).
"""

import sys

from glyphbench_rl.cli.main import main

if __name__ == "__main__":
    sys.exit(main(["bench", *sys.argv[1:]]))
