"""Chopper Command: a helicopter guards a convoy of trucks driving along the desert floor while
enemy helicopters dive at them. Shoot the enemies (your gun fires the way you face); a truck an
enemy reaches is lost, and when the whole convoy is lost the game is. On the Atari preset the
desert is wider than the view (it wraps and follows you) and each cleared wave brings a bigger
one (pattern D)."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.params import param, require
from .bodies import Body, chase
from .engine import EMPTY, ArcadeParams, ArcadeTask, register_arcade
from .scroller import FLY_ACTIONS, FLY_SHOT, GROUND, LEFT_ME, RIGHT_ME, Flyer, fly_shots

ENEMY, TRUCK = "X", "T"


@dataclass(frozen=True)
class ChopperParams(ArcadeParams):
    width: int = param(14, 8, 60)
    height: int = param(8, 5, 30)
    goal: int = param(5, 1, 500)
    unit: float = param(0.2, 0, 100)
    world: int = param(14, 8, 200)        # the desert's width (wider than the view: it scrolls)
    trucks: int = param(3, 1, 12)
    wave: int = param(5, 1, 30)           # enemies in the first wave (each wave one more)
    active: int = param(2, 1, 10)         # enemies in the air at once
    dive: int = param(3, 1, 10)           # turns per step an enemy takes
    convoy: int = param(0, 0, 10)         # turns per cell the trucks drive (0: parked)
    reach: int = param(6, 2, 40)          # your shot's range

    def check(self) -> None:
        require(self.world >= self.width, "world", "be at least the view's width", self.world)
        require(2 * self.trucks <= self.world, "trucks", "fit the ground", self.trucks)


class ChopperCommand(Flyer, ArcadeTask):
    title = "Chopper Command"
    rules = ("You fly the helicopter (> or <, the way you face) over a desert {world} columns "
             "wide{scroll_text}, with {lives_text}. {trucks} trucks (T) drive on the ground row{convoy_text}. "
             "Enemy helicopters (X) come in waves ({wave} first, one more each wave), {active} in "
             "the air at once, each stepping toward a truck every {dive} turns; a truck it reaches "
             "is lost. FIRE shoots the way you face, two cells a turn for {reach} cells. Touching an "
             "enemy costs a life; losing every truck ends the game.")
    rewards = "+{unit} for each enemy shot down; {death} when the game is lost."
    ends = "when you have shot down {goal} enemies or the game is lost"
    ACTIONS = FLY_ACTIONS
    Params = ChopperParams
    pattern = "D"
    glyphs = {EMPTY: "sky", GROUND: "ground", TRUCK: "truck", ENEMY: "enemy helicopter",
              FLY_SHOT: "your shot", RIGHT_ME: "you (facing right)", LEFT_ME: "you (facing left)"}

    def prompt_fields(self) -> dict:
        p = self.params
        return {**super().prompt_fields(), **self.fly_fields(),
                "convoy_text": f", a cell right every {p.convoy} turns" if p.convoy else ""}

    def _setup(self, rng) -> None:
        self.start(rng)
        p = self.params
        self.fly_start(p.height // 2)
        gap = p.world // p.trucks
        self.trucks = [gap // 2 + k * gap for k in range(p.trucks)]
        self.enemies: list[Body] = []
        self.level, self.left_in_wave, self.to_launch = 0, p.wave, p.wave
        self._ground_key = self._ground = None

    def _shot_hits(self, r: int, c: int) -> bool:
        c %= self.params.world
        for e in self.enemies:
            if e.c == c and e.r == r:
                return True
        return False

    def _play(self, action: int) -> None:
        p = self.params
        self.fly(action, p.height - 2)
        if (self.gun.shots and self._shots()) or self._touch():   # (no call without shots)
            return
        if p.convoy and self.tick % p.convoy == 0:
            self.trucks = [(t + 1) % p.world for t in self.trucks]
        if self.tick % p.dive == 0:
            for e in self.enemies:
                self._dive(e)
            if not self.trucks:
                self.reward(p.death)
                self.say("The convoy is lost!")
                self.finish(won=False)
                return
        if len(self.enemies) < p.active and self.to_launch:
            self.to_launch -= 1
            x = (self.x + p.width // 2 + self.draws.below(p.world - p.width + 1)) % p.world
            self.enemies.append(Body(0, x, glyph=ENEMY))
        self._touch()

    def _dive(self, e: Body) -> None:
        """An enemy steps toward the nearest truck (the world wraps; the first of equals)."""
        p = self.params
        if not self.trucks:
            return
        w, c = p.world, e.c
        target, near = 0, w
        for t in self.trucks:
            d = (t - c) % w
            d = w - d if d + d > w else d
            if d < near:
                target, near = t, d
        dx = (target - c) % w
        dx = dx - w if dx > w // 2 else dx
        dr, dc = chase(e.r, 0, p.height - 1, dx)
        e.r, e.c = e.r + dr, (c + dc) % w
        if e.r == p.height - 1 and e.c in self.trucks:
            self.trucks.remove(e.c)
            e.r = 0
            self.say("A truck was destroyed!")

    def _shots(self) -> bool:
        fly_shots(self.gun, self._shot_hits, self._shot_down)
        return self.done

    def _shot_down(self, r: int, c: int) -> None:
        self._drop(r, c % self.params.world)
        self.score.gain()
        self.say("Enemy down!")
        self.left_in_wave -= 1
        if not self.left_in_wave and not self.done:
            self.level += 1
            self.left_in_wave = self.to_launch = self.params.wave + self.level

    def _drop(self, r: int, c: int) -> None:
        """One enemy at (r, c) is gone (two may share a cell)."""
        for i, e in enumerate(self.enemies):
            if e.r == r and e.c == c:
                del self.enemies[i]
                return

    def _touch(self) -> bool:
        r, x = self.r, self.x
        for e in self.enemies:
            if e.c == x and e.r == r:
                self._drop(r, x)
                self.to_launch += 1
                return self.lose_life("An enemy hit you!")
        return False

    def _grid(self) -> list[str]:
        rows, left, w, view = self.fly_view()
        key = (left, *self.trucks)
        if key != self._ground_key:            # the trucks seldom move: their row is kept
            ground = rows[-1]
            for t in self.trucks:
                c = (t - left) % w
                if c < view:
                    ground = ground[:c] + TRUCK + ground[c + 1:]
            self._ground_key, self._ground = key, ground
        rows[-1] = self._ground
        drawn = self._drawn   # (each row remembered: see ``_draw``)
        for e in self.enemies:                 # (enemies fly between the top and the ground)
            c = (e.c - left) % w
            if c < view:
                key = (rows[e.r], c, ENEMY)
                rows[e.r] = drawn.get(key) or self._draw(key)
        return self.fly_draw(rows)


register_arcade(ChopperCommand, "choppercommand",
                mini=dict(max_turns=200),
                atari=dict(width=30, height=16, world=60, lives=3, goal=60, unit=1.0, trucks=6,
                           wave=4, active=2, dive=3, convoy=6, reach=12, max_turns=10000))
