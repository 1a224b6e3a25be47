"""Yars' Revenge: Yar, a flying insect, breaks through the shield that guards the Qotile and
then shoots the Qotile itself, dodging the Swirl that the Qotile launches at it. On the Atari
preset a Destroyer missile homes in on Yar all the time (it cannot be shot), and every Qotile
destroyed brings a new one behind a fresh shield."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.params import param, require
from .arena import EMPTY, SHOT, ArenaParams, ArenaTask, you_glyphs
from .bodies import Body, chase
from .engine import Milestones, register_arcade

SHIELD, QOTILE, SWIRL, DESTROYER = "#", "Q", "S", "d"


@dataclass(frozen=True)
class YarsParams(ArenaParams):
    width: int = param(14, 10, 40)
    height: int = param(10, 7, 30)
    goal: int = param(6, 1, 100)          # milestones: each shield block and each Qotile
    unit: float = param(1 / 6, 0, 10000)
    foes: int = param(0, 0, 1)            # 1: the Destroyer missile hunts you
    every: int = param(3, 1, 50)
    reach: int = param(5, 1, 40)
    shield: int = param(5, 1, 20)         # blocks in the shield column
    beam: int = param(6, 2, 100)          # ticks between Swirl launches
    block_pts: float = param(0.1, 0, 10000)
    qotile_pts: float = param(0.5, 0, 100000)
    rounds: int = param(1, 1, 10)         # Qotiles to destroy

    def check(self) -> None:
        require(self.shield <= self.height, "shield", "fit the column", self.shield)


class YarsRevenge(ArenaTask):
    title = "Yars' Revenge"
    rules = ("You are Yar ({lives_text}) in a {width}x{height} field. The Qotile (Q) sits at the "
             "right edge behind a shield of {shield} blocks (#); shots stop on the shield and each "
             "block they hit breaks. FIRE sends a shot (*) {reach} cells the way you face; a shot "
             "that reaches the Qotile destroys it. Every {beam} turns the Qotile launches a Swirl "
             "(S) that flies straight at where you are, a cell a turn; it kills you.{turn_text}"
             "{destroyer_text}{rounds_text}")
    rewards = "+{block_pts} for each shield block broken, +{qotile_pts} for each Qotile; {death} when the game is lost."
    ends = "when you have destroyed {rounds} Qotile(s) or the game is lost"
    Params = YarsParams
    pattern = "D"
    SOLID = frozenset(SHIELD + QOTILE)
    FOE, foe_name, caught_text = DESTROYER, "Destroyer", "The Destroyer missile got you."
    glyphs = {EMPTY: "space", SHIELD: "shield block", QOTILE: "the Qotile", SWIRL: "Swirl",
              DESTROYER: "Destroyer missile", SHOT: "your shot", **you_glyphs()}

    def prompt_fields(self) -> dict:
        p = self.params
        return {**super().prompt_fields(),
                "destroyer_text": (f" The Destroyer missile (d) moves a cell toward you every "
                                   f"{p.every} turns; it cannot be shot.") if p.foes else "",
                "rounds_text": (" Each destroyed Qotile is replaced by a new one behind a fresh "
                                "shield.") if p.rounds > 1 else ""}

    def _still(self) -> list[str]:
        p = self.params
        rows = [EMPTY * p.width] * p.height
        top = (p.height - p.shield) // 2
        self.qrow = p.height // 2
        for r in range(top, top + p.shield):
            rows[r] = EMPTY * (p.width - 3) + SHIELD + EMPTY * 2
        rows[self.qrow] = rows[self.qrow][:-1] + QOTILE
        return rows

    def _setup(self, rng) -> None:
        p = self.params
        self.start_arena(rng, p.height // 2, 1)
        self.score = Milestones(self, p.goal, p.unit)
        self.face, self.round, self.swirl = (0, 1), 0, None
        if p.foes:
            self.add_foe(0, 0)

    def _pay(self, key, pts: float) -> None:
        p = self.params
        self.score.reach(key, pts / (p.goal * p.unit))

    def _wall_hit(self, r: int, c: int) -> None:
        cell = self.still[r][c] if 0 <= r < self.params.height and 0 <= c < self.params.width else ""
        if cell == SHIELD:
            self.set_still(r, c, EMPTY)
            self.say("Shield block broken.")
            self._pay((self.round, r), self.params.block_pts)
        elif cell == QOTILE:
            self.say("The Qotile is destroyed!")
            self._pay((self.round, "Q"), self.params.qotile_pts)
            self.round += 1
            if self.round >= self.params.rounds:
                self.finish(won=True)
            elif not self.done:
                self.still = self._still()
                self.still_version += 1
                self.swirl = None

    def _hit(self, foe) -> None:
        self.say("Shots cannot hurt the Destroyer.")

    def _turn(self) -> None:
        p = self.params
        s = self.swirl
        if s is None and self.tick % p.beam == 0:
            s = self.swirl = Body(self.qrow, p.width - 2, *chase(self.qrow, p.width - 2, self.r, self.c))
        elif s is not None:
            s.r, s.c = s.r + s.dr, s.c + s.dc
            if not (0 <= s.r < p.height and 0 <= s.c < p.width):
                self.swirl = None
                return
        if s is not None and (s.r, s.c) == (self.r, self.c):
            self.swirl = None
            self._killed("The Swirl hit you.")

    def _respawn(self) -> None:
        super()._respawn()
        self.swirl, self.face = None, (0, 1)

    def _below(self):
        return () if self.swirl is None else ((self.swirl.r, self.swirl.c, SWIRL),)


register_arcade(YarsRevenge, "yarsrevenge",
                mini=dict(max_turns=300),
                atari=dict(width=20, height=20, goal=30, unit=1.0, lives=3, foes=1, every=3, shield=9,
                           beam=8, rounds=3, block_pts=69.0, qotile_pts=1000.0, max_turns=10000))
