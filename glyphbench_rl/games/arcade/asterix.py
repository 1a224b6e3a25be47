"""Asterix: the field is a stack of horizontal lanes; along each lane one thing at a time drifts
in from an edge and across: a magic potion to collect (*) or a harmful lyre (E). You move between
lanes and along them. Every so many potions the things drift faster (pattern D)."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.params import param
from .bodies import Body
from .chase import ACTIONS, STEPS
from .engine import EMPTY, ArcadeParams, ArcadeTask, register_arcade

YOU, FOOD, LYRE = "A", "*", "E"


@dataclass(frozen=True)
class AsterixParams(ArcadeParams):
    width: int = param(12, 6, 60)
    height: int = param(6, 2, 30)        # lanes
    goal: int = param(5, 1, 1000)
    unit: float = param(0.2, 0, 10)
    slowest: int = param(3, 1, 8)        # a thing moves a cell every 1..slowest turns
    spawn: float = param(0.25, 0, 1)     # chance a turn that an empty lane gets a new thing
    harm: float = param(0.5, 0, 1)       # share of new things that are lyres
    faster: int = param(0, 0, 100)       # every this many potions things move a cell a turn more (0: never)


class Asterix(ArcadeTask):
    title = "Asterix"
    rules = ("{height} lanes, one per row, {width} cells long. Along each lane one thing at a time "
             "drifts in from the left or right edge and across to the other, one cell every 1 to "
             "{slowest} turns: a potion (*) or, about {harm} of the time, a lyre (E). You (A) move "
             "one cell a turn along your lane or to the next lane. Touch a potion to collect it; "
             "touching a lyre costs a life; you have {lives_text}.{fast}")
    rewards = "+{unit} for each potion collected; -1 when your last life is lost."
    ends = "when you have collected {goal} potions, or a lyre hits you with no lives left"
    ACTIONS = ACTIONS
    Params = AsterixParams
    pattern = "D"
    glyphs = {EMPTY: "lane", YOU: "you", FOOD: "potion", LYRE: "lyre (harmful)"}

    def prompt_fields(self) -> dict:
        f = self.params.faster
        fast = f" Every {f} potions everything drifts one cell a turn faster." if f else ""
        return {**super().prompt_fields(), "fast": fast}

    def _setup(self, rng) -> None:
        self.start(rng)
        p = self.params
        self.r, self.c = p.height // 2, p.width // 2
        self.things: list[Body | None] = [None] * p.height
        self.periods = [int(rng.integers(1, p.slowest + 1)) for _ in range(p.height)]
        self.periods[self.r] = p.slowest

    def _respawn(self) -> None:
        self.r, self.c = self.params.height // 2, self.params.width // 2
        self.things = [None] * self.params.height

    def _meet(self) -> bool:
        """The thing in your cell, if any, acts: True when it cost the last life."""
        t = self.things[self.r]
        if t is None or t.c != self.c:
            return False
        self.things[self.r] = None
        if t.glyph == FOOD:
            self.say("A potion!")
            self.score.gain()
            return False
        return self.lose_life("Hit by a lyre!")

    def _play(self, action: int) -> None:
        p = self.params
        dr, dc = STEPS[action]
        r, c, w = self.r + dr, self.c + dc, p.width
        self.r = me_r = 0 if r < 0 else r if r < p.height else p.height - 1
        self.c = me_c = 0 if c < 0 else c if c < w else w - 1
        t = self.things[me_r]
        if t is not None and t.c == me_c and (self._meet() or self.done):   # (a call only to meet)
            return
        things = self.things   # (after meeting: a life lost clears the lanes)
        step = 1 + (self.score.done // p.faster if p.faster else 0)
        periods, tick, draw, spawn = self.periods, self.tick, self.draws.random, p.spawn
        for lane, t in enumerate(things):
            if t is None:
                if draw() < spawn:
                    right = draw() < 0.5
                    kind = LYRE if draw() < p.harm else FOOD
                    things[lane] = Body(lane, 0 if right else w - 1, 0, 1 if right else -1, kind)
            elif tick % periods[lane] == 0:
                old = t.c
                t.c = new = old + t.dc * step
                if lane == me_r and (old <= me_c <= new or new <= me_c <= old):
                    t.c = me_c                         # a fast thing cannot skip over you
                elif not 0 <= new < w:
                    things[lane] = None
        t = things[me_r]
        if t is not None and t.c == me_c:
            self._meet()

    def _sprites(self):
        out = [(t.r, t.c, t.glyph) for t in self.things if t is not None]
        out.append((self.r, self.c, YOU))
        return out

    def _grid(self) -> list[str]:
        """``_sprites()`` drawn straight from the things (all inside the field), each row
        remembered (``_draw``)."""
        rows = self.still[:]
        self._grids += 1
        drawn = self._drawn
        for t in self.things:
            if t is not None:
                r = t.r
                key = (rows[r], t.c, t.glyph)
                rows[r] = drawn.get(key) or self._draw(key)
        r = self.r
        key = (rows[r], self.c, YOU)
        rows[r] = drawn.get(key) or self._draw(key)
        return rows


register_arcade(Asterix, "asterix",
                mini=dict(max_turns=300),
                atari=dict(width=20, height=8, goal=50, unit=1.0, lives=3, slowest=3, spawn=0.2,
                           harm=0.6, faster=10, max_turns=10000))
