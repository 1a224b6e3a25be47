"""Craftax: upstream Craftax 1.6.1's rules as numpy tables and small sub-rules, and the suite's
Craftax tasks as scenarios on that one engine.

Modules: ``state`` (upstream's EnvState in numpy), ``tables`` (enumerations and constant tables),
``bestiary`` (mobs), ``rules`` (the step), ``mobs`` (mob movement, attacks, projectiles,
spawning), ``worldgen`` (the nine levels), ``view`` (the grid and the rules text), ``hud`` (the HUD
line), ``task`` (the task class), ``scenarios`` (the tasks as data). The ``craftax`` package itself is only a test oracle.
"""

from ...core import register_variants
from . import suite  # noqa: F401  (defines the scenarios)
from .scenarios import SCENARIOS
from .task import CraftaxTask

for _name, _scenario in SCENARIOS.items():
    register_variants(CraftaxTask, "Craftax",
                      {f"glyphbench/craftax-{_name}-v0": dict(scenario=_name, max_turns=_scenario.horizon)})

from . import full  # noqa: F401,E402  (glyphbench/craftaxfull-v0, the extended full game)
