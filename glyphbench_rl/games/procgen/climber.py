"""Procgen Climber: jump from platform to platform up a tall shaft to the goal at the top,
collecting stars; enemies patrol some platforms.

Platforms are solid from every side, so you climb by jumping up beside one and stepping onto it
at the top of the jump. Levels are redrawn (seeded) until the search over the game's own
physics, enemies' timing included, reaches the goal."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from ..common.palette import GOAL
from .engine import OPEN, PLAYER_GLYPHS
from .platforms import ENEMY, GROUND, PLATFORM, PlatformTask

STAR = "*"
WIDTH = 14
STARS_PAID = 8


@dataclass(frozen=True)
class ClimberParams:
    height: int = param(40, 16, 80)
    enemy_every: int = param(2, 1, 10)        # an enemy on every n-th platform row (if long enough)
    star_reward: float = param(0.1, 0, 1 / STARS_PAID)
    goal_reward: float = param(0.2, 0, lambda p: round(1 - STARS_PAID * p.star_reward, 9))


class ProcgenClimber(PlatformTask):
    title = "Procgen Climber"
    rules = ("A shaft {width} columns wide and {height} rows high, seen through a window that "
             "follows you. {physics} Climb the platforms to the goal ({goal}) at the top, picking "
             "up stars (*) on the way; touching a patrolling enemy (E) kills you.")
    rewards = ("+{star_reward:g} for each of the first {stars_paid} stars, +{goal_reward:g} for "
               "the goal; dying ends the episode with what you have.")
    ends = "when you reach the goal or die"
    Params = ClimberParams
    shows_motion = True
    view_h, view_w = 20, 14
    glyphs = {GROUND: "wall", PLATFORM: "platform", OPEN: "air", STAR: "star", ENEMY: "enemy",
              GOAL: "goal", **PLAYER_GLYPHS}
    extra_chars = PlatformTask.extra_chars + GOAL

    def prompt_fields(self) -> dict:
        return {**super().prompt_fields(), "width": WIDTH, "goal": GOAL, "stars_paid": STARS_PAID}

    def _build(self, rng: np.random.Generator, easy: bool) -> None:
        p, h = self.params, self.params.height
        rows = [[GROUND] + [OPEN] * (WIDTH - 2) + [GROUND] for _ in range(h)]
        rows[h - 1] = rows[h - 2] = [GROUND] * WIDTH
        self.patrols = []
        span = int(rng.integers(2, 4))
        r, band = h - 2, 0
        while r - 3 > 3:
            r -= int(rng.integers(2, 4)) if not easy else 2
            band += 1
            if easy:   # a staircase, two rows a step, zigzagging across the shaft
                c0 = 1 + (band * 4) % (WIDTH - 5)
                rows[r][c0:c0 + 3] = [PLATFORM] * 3
                continue
            placed = []
            for _ in range(int(rng.integers(1, 3))):
                length = int(rng.integers(3, 6))
                c0 = int(rng.integers(1, WIDTH - 1 - length + 1))
                if any(c0 <= b + 1 and a <= c0 + length for a, b in placed):
                    continue
                rows[r][c0:c0 + length] = [PLATFORM] * length
                placed.append((c0, c0 + length - 1))
                rows[r - 1][c0 + int(rng.integers(length))] = STAR
            a, b = placed[0]
            if b - a >= span and band % p.enemy_every == 0:
                self.patrols.append((r - 1, a, a + span, int(rng.integers(2 * span))))
        top = r - 3
        rows[top][5:9] = [PLATFORM] * 4
        goal = (top - 1, 6)
        rows[goal[0]][goal[1]] = GOAL
        self.start = (h - 3, int(rng.integers(1, WIDTH - 1)))
        self.goals, self.goal_row = frozenset([goal]), goal[0]
        self.rows = rows
        self.taken = 0

    def _touch(self, cell, ch) -> None:
        if ch == STAR:
            self.set_tile(*cell, OPEN)
            self.taken += 1
            self.say("You took a star.")
            if self.taken <= STARS_PAID:
                self.reward(self.params.star_reward)
        elif ch == GOAL:
            self.reward(self.params.goal_reward)
            self.say("You reached the goal.")
            self.finish(won=True)

    def _extras(self) -> str:
        d = self.pos[0] - self.goal_row
        return f"Stars {self.taken} | Goal {abs(d)}{'↓' if d < 0 else '↑'}"


register_variants(ProcgenClimber, "Procgen", {"glyphbench/procgen-climber-v0": dict(max_turns=500)})
