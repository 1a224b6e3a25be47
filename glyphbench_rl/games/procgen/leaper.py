"""Procgen Leaper: Frogger. Cross roads of cars and rivers of floating logs to the goal row.

Every lane scrolls on its own, left or right, one cell every turn or every second turn (drawn
at its right-hand end: ``«``/``»`` fast, ``<``/``>`` slow); lanes wrap around. A log carries you;
water, a car, or a log carrying you off the edge ends the game. A level is kept only if a search
over (row, column, tick) with the game's own step reaches the goal row."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from ..common.lanes import Lane, runs
from .engine import PLAYER_GLYPHS, ProcgenTask
from .scrolling import OPEN, LaneLevel, Strip

CAR, LOG, WATER, GOAL, EDGE = "C", "=", "~", "G", "|"
MARKERS = {(-1, 1): "«", (1, 1): "»", (-1, 2): "<", (1, 2): ">"}   # (direction, period)
GOAL_REWARD = 1.0
DEATHS = {"car": "A car hit you.", "water": "You fell into the water.",
          "edge": "A log carried you off the edge."}


@dataclass(frozen=True)
class LeaperParams:
    width: int = param(13, 7, 19)          # lane cells (the marker column comes on top)
    height: int = param(14, 6, 24)         # rows: the start row at the bottom, the goal at the top
    slow_share: float = param(0.5, 0, 1)   # share of lanes moving every second turn


class ProcgenLeaper(ProcgenTask):
    title = "Procgen Leaper"
    rules = ("Cross from the bottom row to the goal row (G) at the top of a {width}-wide, "
             "{height}-row field. Road lanes carry cars (C), river lanes carry logs (=) on water "
             "(~); every lane slides sideways and wraps around. The character at a lane's right "
             "end tells its motion: « or » one cell left or right every turn, < or > one cell "
             "every second turn; | is a still, safe row. Standing on a log carries you along with "
             "it. Moves happen first, then the lanes slide. Walking into a car or a car driving "
             "into you, stepping onto water, or being carried off the edge ends the game.")
    rewards = "+{goal_reward} for reaching the goal row; dying costs nothing but ends the game."
    ends = "when you reach the goal row or die"
    Params = LeaperParams
    glyphs = {OPEN: "road or safe ground", CAR: "car", LOG: "log", WATER: "water",
              GOAL: "goal row", EDGE: "safe row (edge marker)", "«": "lane moving left every turn",
              "»": "lane moving right every turn", "<": "lane moving left every second turn",
              ">": "lane moving right every second turn", **PLAYER_GLYPHS}
    extra_chars = "".join(PLAYER_GLYPHS) + "«»"
    view_h, view_w = 12, 14

    def prompt_fields(self) -> dict:
        return {**super().prompt_fields(), "goal_reward": GOAL_REWARD}

    def _setup(self, rng: np.random.Generator) -> None:
        p = self.params
        while True:
            self.level = LaneLevel(self._lanes(rng), p.width)
            start = (p.height - 1, p.width // 2)
            if self.level.solve(start) is not None:
                break
        self.place_player(start)
        self.tick = 0
        still = [(GOAL if r == 0 else OPEN) * p.width + EDGE for r in range(p.height)]
        self._frames = [[s.lane.row(t) + s.marker if s else still[r]      # the level repeats
                         for r, s in enumerate(self.level.strips)]         # every cycle ticks
                        for t in range(self.level.cycle)]

    def _lanes(self, rng: np.random.Generator) -> list[Strip | None]:
        """Groups of one to three road or river lanes (alternating, first kind from the seed),
        each followed by a safe row; the goal row on top, the start row at the bottom."""
        p, strips = self.params, [None]
        river = bool(rng.integers(2))
        while len(strips) < p.height - 1:
            for _ in range(int(rng.integers(1, 4))):
                if len(strips) >= p.height - 1:
                    break
                direction = int(rng.choice((-1, 1)))
                period = 2 if rng.random() < p.slow_share else 1
                if river:
                    pattern = runs(rng, p.width, LOG, WATER, (2, 4), (1, 4))
                    strip = Strip(Lane(pattern, direction, period, int(rng.integers(period))),
                                  WATER, True, MARKERS[direction, period])
                else:
                    pattern = runs(rng, p.width, CAR, OPEN, (1, 2), (2, 5))
                    strip = Strip(Lane(pattern, direction, period, int(rng.integers(period))),
                                  CAR, False, MARKERS[direction, period])
                strips.append(strip)
            if len(strips) < p.height - 1:
                strips.append(None)
            river = not river
        return strips + [None]

    def _rows(self) -> list[str]:
        return self._frames[self.tick % self.level.cycle]

    def solution(self) -> list[int] | None:
        """The shortest winning action list from here (the generator's own check)."""
        return self.level.solve(self.pos, 0, self.tick)

    def _act(self, action: int) -> None:
        self.target(action)
        r, c, death = self.level.move(*self.pos, self.tick, action)
        self.tick += 1
        self.pos = (r, min(max(c, 0), self.params.width - 1))
        if death:
            self.say(DEATHS[death])
            self.finish(won=False)
        elif r == 0:
            self.reward(GOAL_REWARD)
            self.say("You reached the goal.")
            self.finish(won=True)


register_variants(ProcgenLeaper, "Procgen", {"glyphbench/procgen-leaper-v0": dict(max_turns=500)})
