"""Procgen CoinRun: run right over a side-scrolling level to the coin at its end.

Ground of varying height with pits, floating platforms and crates, saws that kill on touch and
enemies patrolling stretches of ground. Every level is checked by a search over the game's own
physics, enemies' timing included, and redrawn (seeded) until the coin is reachable."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from .engine import OPEN, PLAYER_GLYPHS
from .platforms import ENEMY, GROUND, PLATFORM, PlatformTask, flats, ground_level, ground_patrols

COIN, SAW = "$", "S"
HEIGHT = 12


@dataclass(frozen=True)
class CoinRunParams:
    min_width: int = param(40, 24, 80)
    max_width: int = param(59, lambda p: p.min_width, 80)
    pits: int = param(3, 0, 5)           # at most (pits may merge or be left out)
    saws: int = param(2, 0, 4)
    enemies: int = param(2, 0, 3)
    platforms: int = param(4, 0, 8)


class ProcgenCoinRun(PlatformTask):
    title = "Procgen CoinRun"
    rules = ("A side view {height} rows high and {min_width} to {max_width} columns long; the view "
             "follows you. {physics} Falling into a pit (off the bottom), touching a saw (S) or a "
             "patrolling enemy (E) kills you. Touch the coin ($) at the right end.")
    rewards = "+1 for the coin; dying ends the episode with nothing."
    ends = "when you touch the coin or die"
    Params = CoinRunParams
    hazards = SAW
    shows_motion = True
    glyphs = {GROUND: "ground", PLATFORM: "platform or crate", OPEN: "air", SAW: "saw",
              ENEMY: "enemy", COIN: "coin", **PLAYER_GLYPHS}

    def prompt_fields(self) -> dict:
        return {**super().prompt_fields(), "height": HEIGHT}

    def _build(self, rng: np.random.Generator, easy: bool) -> None:
        p = self.params
        width = int(rng.integers(p.min_width, p.max_width + 1))
        rows, tops = ground_level(rng, width, HEIGHT, lo=6, hi=9, pits=0 if easy else p.pits,
                                  pit_width=(2, 3), step=0 if easy else 2)
        body = range(6, width - 7)
        n_platforms = 0 if easy or not p.platforms else int(rng.integers(1, p.platforms + 1))
        for _ in range(n_platforms):
            c0, length = int(rng.choice(body)), int(rng.integers(3, 6))
            r = min(t for t in tops[c0:c0 + length] + [9] if t is not None) - int(rng.integers(3, 5))
            span = range(c0, min(c0 + length, width - 7))
            if all(rows[r][c] == OPEN and rows[r + 1][c] == OPEN for c in span):
                for c in span:
                    rows[r][c] = PLATFORM
        for c, t in flats(tops, 1, 6, width - 7)[::7] if not easy else ():
            if rng.random() < 0.5:                      # a crate or two on the ground
                for r in range(t - int(rng.integers(1, 3)), t):
                    rows[r][c] = PLATFORM
        surface = [(t - 1, c) for c, t in flats(tops, 3, 6, width - 7) if rows[t - 1][c + 1] == OPEN]
        for i in rng.choice(len(surface), min(p.saws, len(surface)), replace=False) if not easy else ():
            r, c = surface[int(i)]
            rows[r][c + 1] = SAW
        self.patrols = ground_patrols(rng, rows, tops, None if easy else p.enemies, 8, width - 7)
        self.start = (tops[2] - 1, 2)
        coin = (tops[width - 3] - 1, width - 3)
        rows[coin[0]][coin[1]] = COIN
        self.goals = frozenset([coin])
        self.rows = rows

    def _touch(self, cell, ch) -> None:
        if ch == COIN:
            self.reward(1.0)
            self.say("You got the coin.")
            self.finish(won=True)

    def _extras(self) -> str:
        d = self.width - 3 - self.pos[1]
        return f"Coin {abs(d)}{'←' if d < 0 else '→'}"


register_variants(ProcgenCoinRun, "Procgen", {"glyphbench/procgen-coinrun-v0": dict(max_turns=500)})
