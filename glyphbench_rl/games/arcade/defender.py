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
from .scroller import FLY_ACTIONS, FLY_SHOT, FLY_UP, GROUND, LEFT_ME, RIGHT_ME, Flyer

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
        return any(lander.r == r and lander.c == c for lander in self.landers)

    def _play(self, action: int) -> None:
        p = self.params
        if action == FLY_UP and self.r == 0 and self._rescue():
            return
        self.fly(action, self.stand)
        for _, cell in self.gun.advance(self._hit):
            if cell is not None:
                self._shoot(cell[0], cell[1] % p.world)
        for man in self.people:
            if man.data == FALL:
                man.r += 1
                if man.r >= self.stand:
                    man.r, man.data = self.stand, STAND
            if man.data != RIDE and man.data != GRABBED and (man.r, man.c) == (self.r, self.x):
                man.data = RIDE
                self.say("Human picked up!")
        if self.tick % p.descend == 0 and self._landers_move():
            return
        if len(self.landers) < p.landers:
            x = (self.x + 3 + self.draws.below(p.world - 5)) % p.world   # not on top of you
            self.landers.append(Body(0, x, glyph=LANDER))
        if any((lander.r, lander.c) == (self.r, self.x) for lander in self.landers):
            self._shoot(self.r, self.x)
            self.lose_life("A lander hit you!")

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
            free = [m for m in self.people if m.data == STAND]
            if not free:
                continue
            target = min(free, key=lambda m: min((m.c - lander.c) % p.world, (lander.c - m.c) % p.world))
            dx = (target.c - lander.c) % p.world
            dr, dc = chase(lander.r, 0, target.r - 1, dx - p.world if dx > p.world // 2 else dx)
            lander.r, lander.c = lander.r + dr, (lander.c + dc) % p.world
            if (lander.r + 1, lander.c) == (target.r, target.c):
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

    def _sprites(self):
        cam = self.camera
        cam.follow(self.x)
        out = [(m.r, cam.screen(m.c), HUMAN) for m in self.people if m.data != RIDE]
        out += [(lander.r, cam.screen(lander.c), LANDER) for lander in self.landers]
        return self.fly_sprites(out)

    def _extra_hud(self) -> str:
        return "Carrying a human" if any(m.data == RIDE for m in self.people) else ""


register_arcade(Defender, "defender",
                mini=dict(max_turns=300),
                atari=dict(width=30, height=16, world=60, lives=3, goal=10, unit=1.0, death=-1.0,
                           humans=5, landers=3, descend=3, reach=10, renew=1, max_turns=10000))
