"""scripts/bench_trainer.py measures each size against its own process's baseline."""

import importlib.util
import subprocess
import sys
from pathlib import Path

import pytest

pytest.importorskip("torch")
ROOT = Path(__file__).resolve().parents[2]


def test_child_memory_is_not_the_parents_high_water_mark():
    """A parent that once held 1.5 GB: the child's baseline and peak are its own, so a log-prob
    call that allocates shows as growth (it read +0 when the child inherited the parent's peak)."""
    script = f"""
import importlib.util, json, numpy as np
spec = importlib.util.spec_from_file_location("bench", {str(ROOT / 'scripts' / 'bench_trainer.py')!r})
bench = importlib.util.module_from_spec(spec); spec.loader.exec_module(bench)
big = np.ones(1536 * 2**20 // 8); big += 1; del big
print(json.dumps(bench.child_memory(4096, 20000)))
"""
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr[-2000:]
    import json
    r = json.loads(out.stdout.strip().splitlines()[-1])
    assert r["base_mb"] < 1200 and r["peak_mb"] < 1400, r   # the child alone: ~400 / ~610 MB
    assert r["peak_mb"] - r["base_mb"] > 20, r          # 4096 x 20000 x 4 B logits per chunk pass
