"""The full game, ``glyphbench/craftaxfull-v0`` (extended tier): Craftax as upstream plays it.

Upstream's world (nine floors from the seed), every rule on (hunger, thirst, fatigue, day and
night, spawning), and upstream's own reward, which ``rules.step`` returns: each achievement pays
its weight the first time it is earned (basic 1, intermediate 3, advanced 5, very advanced 8) and
every point of health gained or lost pays +0.1 or -0.1. No objective ends it: the episode runs
until the player dies or the turn cap (10,000 by default; upstream's own is 100,000), and the
return is not clamped. The observation is the standard tasks' (``view``), with the count of
achievements earned in the HUD; the prompt lists every achievement by weight.
"""

from __future__ import annotations

import numpy as np

from ...core import register_variants
from ...core.task import NoParams
from .packed import ACH, HEALTH
from .scenarios import Scenario
from .state import Settings
from .tables import (ACHIEVEMENT_REWARD, ADVANCED_WEIGHT, BASIC_WEIGHT, INTERMEDIATE_WEIGHT,
                     VERY_ADVANCED_WEIGHT, Achievement)
from .task import CraftaxTask

HORIZON = 10_000
FULL = Scenario(name="full", objective="Play the whole game: survive, gather, craft, fight and go "
                "down through the nine floors, earning as many achievements as you can.",
                success="", terms=(), horizon=HORIZON, settings=Settings(), death=0.0,
                topics=("craft", "floors"))
GRADES = ((BASIC_WEIGHT, "basic"), (INTERMEDIATE_WEIGHT, "intermediate"),
          (ADVANCED_WEIGHT, "advanced"), (VERY_ADVANCED_WEIGHT, "very advanced"))


def achievements_text() -> str:
    """Every achievement by its weight, from the tables."""
    parts = []
    for weight, grade in GRADES:
        names = [a.name.lower().replace("_", " ").replace("solider", "soldier")   # (upstream spells it so)
                 for a in Achievement if ACHIEVEMENT_REWARD[a] == weight]
        parts.append(f"+{weight} each {grade} one ({len(names)}): {', '.join(names)}")
    return "; ".join(parts)


class CraftaxFull(CraftaxTask):
    """Craftax from upstream's reset, paying upstream's reward."""
    Params = NoParams
    default_max_turns = HORIZON
    rules = "{objective} {game_rules}"
    rewards = ("each achievement pays its weight the first time you earn it: {achievements}. Each "
               "point of health gained pays +0.1 and each point lost -0.1.")
    ends = "when you die"

    def _init(self) -> None:
        self.scenario, self.settings = FULL, FULL.settings

    def prompt_fields(self) -> dict:
        return {**super().prompt_fields(), "achievements": achievements_text()}

    def _score(self, tally, native: float) -> None:
        self.reward(native)
        if self.packed.floats.item(HEALTH) <= 0:
            self.say("You died.")
            self.finish(won=False)

    def _hud(self) -> str:
        line = self._line()
        earned = int(np.count_nonzero(self.packed.ints[ACH:ACH + len(Achievement)]))
        return f"{line} | Achievements {earned}/{len(Achievement)}"


register_variants(CraftaxFull, "FullCraftax", {"glyphbench/craftaxfull-v0": {"max_turns": HORIZON}}, tier="extended")
