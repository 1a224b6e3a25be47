"""Starting Prime-RL's ``rl`` launcher on a rendered config, or saying how to."""

from __future__ import annotations

import shlex
import shutil
import subprocess
from pathlib import Path
from typing import Callable


def launch(path: str | Path, *, log: Callable[[str], None] = print) -> int:
    """Run ``rl @ PATH`` in the foreground (inherited stdio) and return its exit status; when no
    ``rl`` is on PATH, print the command to run where Prime-RL is installed and return 0."""
    path = Path(path).resolve()
    exe = shutil.which("rl")
    if exe is None:
        log(f"wrote {path}\n`rl` (Prime-RL's launcher) is not on PATH; where prime-rl and glyphbench_rl "
            f"are installed, run:\n  {shlex.join(['rl', '@', str(path)])}")
        return 0
    cmd = [exe, "@", str(path)]
    log(f"launching: {shlex.join(cmd)}")
    proc = subprocess.Popen(cmd)
    try:
        code = proc.wait()
    except KeyboardInterrupt:
        # Ctrl-C reached rl too (same process group): let it stop its trainer, orchestrator and
        # inference server; a second Ctrl-C asks it to terminate.
        try:
            code = proc.wait()
        except KeyboardInterrupt:
            proc.terminate()
            code = proc.wait()
    return code if code >= 0 else 128 - code        # killed by signal N: the shell's 128 + N
