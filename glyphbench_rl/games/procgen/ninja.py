"""Procgen Ninja: climb ledges of varied heights to the goal at the right end, throwing shuriken.

Ledges, pits, breakable walls (B) and patrolling enemies; THROW sends a shuriken flying the way
you last moved sideways: it breaks a wall it hits and kills an enemy. The search that checks
every level does not throw, so each level is winnable without a kill (walls can be jumped);
kills pay a little and walls block shots and paths alike."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from ..common.palette import GOAL
from .engine import OPEN, PLAYER_GLYPHS
from .platforms import (BREAKABLE, ENEMY, GROUND, PLATFORM, SHURIKEN, SHURIKEN_SPEED, THROW_ACTIONS,
                        PlatformTask, flats, ground_level, ground_patrols)

HEIGHT = 12
KILLS_PAID = 3


@dataclass(frozen=True)
class NinjaParams:
    width: int = param(40, 24, 80)
    pits: int = param(2, 0, 4)
    walls: int = param(2, 0, 4)
    enemies: int = param(3, 0, 5)
    platforms: int = param(4, 0, 8)
    goal_reward: float = param(0.7, 0, 1)
    kill_reward: float = param(0.1, 0, lambda p: round((1 - p.goal_reward) / KILLS_PAID, 9))
    death_penalty: float = param(0.3, 0, 1)


class ProcgenNinja(PlatformTask):
    title = "Procgen Ninja"
    rules = ("A side view {height} rows high and {width} columns long; the view follows you. "
             "{physics} Falling into a pit (off the bottom) or touching an enemy (E) kills you. "
             "THROW sends a shuriken (-) the way you last moved sideways, {speed} columns a turn: "
             "it breaks a breakable wall (B, the whole column) or kills an enemy it hits. Reach "
             "the goal ({goal}) at the right end.")
    rewards = ("+{goal_reward:g} for the goal, +{kill_reward:g} for each of the first {kills_paid} "
               "kills, -{death_penalty:g} for dying.")
    ends = "when you reach the goal or die"
    Params = NinjaParams
    ACTIONS = THROW_ACTIONS
    shows_motion = True
    glyphs = {GROUND: "ground", PLATFORM: "platform", OPEN: "air", BREAKABLE: "breakable wall",
              ENEMY: "enemy", SHURIKEN: "shuriken", GOAL: "goal", **PLAYER_GLYPHS}
    extra_chars = PlatformTask.extra_chars + GOAL

    def prompt_fields(self) -> dict:
        return {**super().prompt_fields(), "height": HEIGHT, "speed": SHURIKEN_SPEED,
                "goal": GOAL, "kills_paid": KILLS_PAID}

    @property
    def death_penalty(self) -> float:
        return self.params.death_penalty

    def _build(self, rng: np.random.Generator, easy: bool) -> None:
        p, w = self.params, self.params.width
        rows, tops = ground_level(rng, w, HEIGHT, lo=4, hi=9, pits=0 if easy else p.pits,
                                  pit_width=(2, 3), step=0 if easy else 3)
        for _ in range(0 if easy else p.platforms):
            c0, length = int(rng.integers(6, w - 10)), int(rng.integers(3, 6))
            r = min([t for t in tops[c0:c0 + length] if t is not None] + [9]) - int(rng.integers(3, 5))
            span = range(c0, c0 + length)
            if r > 0 and all(rows[r][c] == OPEN and rows[r + 1][c] == OPEN for c in span):
                for c in span:
                    rows[r][c] = PLATFORM
        spots = [(c, t) for c, t in flats(tops, 3, 7, w - 7) if t >= 3]
        walls = [] if easy else rng.choice(len(spots), min(p.walls, len(spots)), replace=False).tolist()
        for i in walls:
            c, t = spots[i]
            if rows[t - 1][c + 1] == OPEN and rows[t - 2][c + 1] == OPEN:
                rows[t - 1][c + 1] = rows[t - 2][c + 1] = BREAKABLE
        self.patrols = ground_patrols(rng, rows, tops, None if easy else p.enemies, 8, w - 6)
        self.start = (tops[2] - 1, 2)
        goal = (tops[w - 2] - 1, w - 2)
        rows[goal[0]][goal[1]] = GOAL
        self.goals = frozenset([goal])
        self.rows = rows

    def _touch(self, cell, ch) -> None:
        if ch == GOAL:
            self.reward(self.params.goal_reward)
            self.say("You reached the goal.")
            self.finish(won=True)

    def _kill(self) -> None:
        self.say("Your shuriken killed an enemy.")
        if self.kills <= KILLS_PAID:
            self.reward(self.params.kill_reward)

    def _extras(self) -> str:
        d = self.width - 2 - self.pos[1]
        return f"Goal {abs(d)}{'←' if d < 0 else '→'} | Kills {self.kills}"


register_variants(ProcgenNinja, "Procgen", {"glyphbench/procgen-ninja-v0": dict(max_turns=500)})
