"""Defender: a ship guards humans on a planet's surface from landers that descend, grab a human
and carry it up. Pick a human up (touch it: standing, falling or freed by shooting its lander)
and fly it off the top edge to rescue it. A human carried off the top by a lander is lost. On
the Atari preset the planet is wider than the view (it wraps and follows you) and rescued humans
are replaced (pattern D; the MiniAtari preset pays no death penalty)."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.params import param, require
from .bodies import Body, chase
from .engine import EMPTY, ArcadeParams, ArcadeTask, register_arcade
from .scroller import FLY_ACTIONS, FLY_SHOT, FLY_UP, GROUND, LEFT_ME, RIGHT_ME, Flyer, fly_shots

LANDER, HUMAN = "L", "h"
STAND, GRABBED, FALL, RIDE = range(4)


@dataclass(frozen=True)
class DefenderParams(ArcadeParams):
    width: int = param(14, 8, 60)
    height: int = param(8, 5, 30)
    goal: int = param(3, 1, 500)           # humans to rescue
    unit: float = param(1 / 3, 0, 100)
    death: float = param(0.0, -1, 0)
    world: int = param(14, 8, 200)         # the planet's width (wider than the view: it scrolls)
    humans: int = param(3, 1, 20)
    landers: int = param(2, 1, 10)         # landers in the air at once
    descend: int = param(3, 1, 10)         # turns per step a lander takes
    reach: int = param(4, 2, 30)           # your shot's range
    renew: int = param(0, 0, 1)            # 1: a rescued human is replaced on the ground

    def check(self) -> None:
        require(self.world >= self.width, "world", "be at least the view's width", self.world)
        require(self.humans >= 1 and 2 * self.humans <= self.world, "humans", "fit the ground", self.humans)


class Defender(Flyer, ArcadeTask):
    title = "Defender"
    rules = ("You fly the ship (> or <, the way you face) over a planet {world} columns wide"
             "{scroll_text}, with {lives_text}. {humans} humans (h) stand on the ground. {landers} "
             "landers (L) at a time descend on them, a step every {descend} turns; one that reaches "
             "a human carries it up, and a human carried off the top edge is lost. FIRE shoots the "
             "way you face for {reach} cells; a human freed from its lander falls. Touch a human to "
             "pick it up, then fly UP off the top edge to rescue it{renew_text}. Touching a lander "
             "costs a life.")
    rewards = "+{unit} for each human rescued{death_text}."
    ends = "when you have rescued {goal} humans, or too few are left to do it, or the game is lost"
    ACTIONS = FLY_ACTIONS
    Params = DefenderParams
    pattern = "D"
    glyphs = {EMPTY: "sky", GROUND: "ground", HUMAN: "human", LANDER: "lander", FLY_SHOT: "your shot",
              RIGHT_ME: "you (facing right)", LEFT_ME: "you (facing left)"}

    def prompt_fields(self) -> dict:
        p = self.params
        return {**super().prompt_fields(), **self.fly_fields(),
                "renew_text": " (a new human then lands)" if p.renew else "",
                "death_text": f"; {p.death} when the game is lost" if p.death else ""}

    def _setup(self, rng) -> None:
        self.start(rng)
        p = self.params
        self.fly_start(1)
        self.stand = p.height - 2
        gap = p.world // p.humans
        self.people = [Body(self.stand, gap // 2 + k * gap, data=STAND) for k in range(p.humans)]
        self.landers: list[Body] = []

    def _hit(self, r: int, c: int) -> bool:
        c %= self.params.world
        for lander in self.landers:
            if lander.c == c and lander.r == r:
                return True
        return False

    def _shot_down(self, r: int, c: int) -> None:
        self._shoot(r, c % self.params.world)

    def _play(self, action: int) -> None:
        p = self.params
        if action == FLY_UP and self.r == 0 and self._rescue():
            return
        self.fly(action, self.stand)
        if self.gun.shots:
            fly_shots(self.gun, self._hit, self._shot_down)
        r, x = self.r, self.x
        for man in self.people:
            if man.data == FALL:
                man.r += 1
                if man.r >= self.stand:
                    man.r, man.data = self.stand, STAND
            if man.c == x and man.r == r and man.data != RIDE and man.data != GRABBED:
                man.data = RIDE
                self.say("Human picked up!")
        if self.tick % p.descend == 0 and self._landers_move():
            return
        if len(self.landers) < p.landers:
            c = (x + 3 + self.draws.below(p.world - 5)) % p.world   # not on top of you
            self.landers.append(Body(0, c, glyph=LANDER))
        for lander in self.landers:
            if lander.c == x and lander.r == r:
                self._shoot(r, x)
                self.lose_life("A lander hit you!")
                return

    def _rescue(self) -> bool:
        for man in self.people:
            if man.data == RIDE:
                self.people.remove(man)
                self.say("Human rescued!")
                self.score.gain()
                if self.params.renew and not self.done:
                    self.people.append(Body(self.stand, self.draws.below(self.params.world), data=STAND))
                return self.done or self._doomed()
        return False

    def _shoot(self, r: int, c: int) -> None:
        for lander in self.landers:
            if (lander.r, lander.c) == (r, c):
                self.landers.remove(lander)
                if lander.data is not None:
                    lander.data.data = FALL
                return

    def _landers_move(self) -> bool:
        p = self.params
        w = p.world
        for lander in self.landers:
            man = lander.data
            if man is not None:
                lander.r -= 1
                man.r = lander.r + 1
                if lander.r < 0:
                    self.people.remove(man)
                    lander.data = None
                    self.say("A human was abducted!")
                continue
            target, near, c = None, w, lander.c      # the nearest standing human, first of equals
            for m in self.people:
                if m.data == STAND:
                    d = (m.c - c) % w
                    d = w - d if d + d > w else d
                    if d < near:
                        target, near = m, d
            if target is None:
                continue
            dx = (target.c - c) % w
            dr, dc = chase(lander.r, 0, target.r - 1, dx - p.world if dx > p.world // 2 else dx)
            lander.r, lander.c = lander.r + dr, (lander.c + dc) % p.world
            if lander.c == target.c and lander.r + 1 == target.r:
                lander.data, target.data = target, GRABBED
        self.landers = [lander for lander in self.landers if lander.r >= 0]
        return self._doomed()

    def _doomed(self) -> bool:
        if self.score.done + len(self.people) * (not self.params.renew) < self.params.goal and \
                (not self.params.renew or not self.people):
            self.reward(self.params.death)
            self.say("Too few humans are left.")
            self.finish(won=False)
            return True
        return False

    def _grid(self) -> list[str]:
        rows, left, w, view = self.fly_view()
        drawn = self._drawn   # (each row remembered: see ``_draw``)
        for m in self.people:                  # (humans and landers keep to the rows)
            if m.data != RIDE:
                c = (m.c - left) % w
                if c < view:
                    key = (rows[m.r], c, HUMAN)
                    rows[m.r] = drawn.get(key) or self._draw(key)
        for lander in self.landers:
            c = (lander.c - left) % w
            if c < view:
                key = (rows[lander.r], c, LANDER)
                rows[lander.r] = drawn.get(key) or self._draw(key)
        return self.fly_draw(rows)

    def _extra_hud(self) -> str:
        for m in self.people:
            if m.data == RIDE:
                return "Carrying a human"
        return ""


register_arcade(Defender, "defender",
                mini=dict(max_turns=300),
                atari=dict(width=30, height=16, world=60, lives=3, goal=10, unit=1.0, death=-1.0,
                           humans=5, landers=3, descend=3, reach=10, renew=1, max_turns=10000))
