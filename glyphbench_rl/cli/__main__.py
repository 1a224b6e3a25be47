"""``python -m glyphbench_rl.cli``: the ``glyphbench`` command."""

from .main import main

raise SystemExit(main())
