"""Prime-RL for multi-GPU and multi-node training: a training YAML rendered as Prime-RL's ``rl``
TOML (``render_toml``, ``write_toml``) whose environment is the verifiers v1 taskset
``glyphbench-rl`` on training seeds, and ``launch`` to start it. Imports neither prime-rl nor
verifiers: the rendered file is all that crosses over. ``schema`` transcribes the part of
Prime-RL's config schema the file uses and names the commit it follows (``PRIME_RL_COMMIT``).
"""

from .launch import launch
from .render import TOML_NAME, PrimeRLConfigError, render_toml, started, write_toml
from .schema import PRIME_RL_COMMIT

__all__ = ["PRIME_RL_COMMIT", "TOML_NAME", "PrimeRLConfigError", "launch", "render_toml", "started",
           "write_toml"]
