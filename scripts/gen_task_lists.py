#!/usr/bin/env python
"""Regenerate tasks/standard.txt and tasks/extended.txt from the registry.

    python scripts/gen_task_lists.py          # write the files
    python scripts/gen_task_lists.py --check  # exit 1 if they differ from the registry
"""

import argparse
import sys
from pathlib import Path

from glyphbench_rl.core.tasklist import task_list_text

TASKS = Path(__file__).resolve().parents[1] / "tasks"


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--check", action="store_true")
    args = p.parse_args()
    stale = []
    for tier in ("standard", "extended"):
        path = TASKS / f"{tier}.txt"
        text = task_list_text(tier)
        if args.check:
            if not path.exists() or path.read_text(encoding="utf-8") != text:
                stale.append(path.name)
        else:
            path.write_text(text, encoding="utf-8")
            print(f"wrote {path} ({sum(1 for l in text.splitlines() if l and not l.startswith('#'))} tasks)")
    if stale:
        print(f"stale: {', '.join(stale)}; run python scripts/gen_task_lists.py", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
