"""glyphbench_rl as a verifiers v1 plugin (``pip install glyphbench_rl[verifiers]``).

    vf-eval glyphbench-rl -m MODEL --client.base-url URL --client.api-key-var OPENAI_API_KEY \
        --env.taskset.tasks '["glyphbench/classics-*-easy-v0"]' --env.taskset.episodes 5 --no-push

Rows are (task ID, held-out seed) pairs (``GlyphbenchTaskset``); ``GlyphbenchEnv`` rebuilds the
game per episode and drives it turn by turn with the rollout engine's prompt and parse code;
``GlyphbenchHarness`` sends each turn's prompt, as composed, through the rollout's interception.

v1 resolves the taskset id ``glyphbench-rl`` to the top-level module ``glyphbench_rl``, which
re-exports the three plugin classes lazily (its ``__getattr__``), so ``import glyphbench_rl``
stays free of verifiers. Exporting the harness makes it the seat's default program.
"""

from .env import GlyphbenchEnv, GlyphbenchEnvConfig
from .harness import GlyphbenchHarness, GlyphbenchHarnessConfig
from .taskset import GlyphbenchData, GlyphbenchTask, GlyphbenchTaskset, GlyphbenchTasksetConfig

__all__ = ["GlyphbenchData", "GlyphbenchEnv", "GlyphbenchEnvConfig", "GlyphbenchHarness",
           "GlyphbenchHarnessConfig", "GlyphbenchTask", "GlyphbenchTaskset",
           "GlyphbenchTasksetConfig"]
