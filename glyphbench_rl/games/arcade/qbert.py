"""Q*bert: hop diagonally from cube to cube down a pyramid, changing the colour of each cube you
land on. Hopping off an edge loses a life. On the Atari preset red balls drop onto the second
row and bounce down one row at a time, left or right at random, until they fall off the bottom;
one that meets you costs a life (pattern A on the mini preset, D on the Atari one)."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.params import param, require
from .engine import EMPTY, ArcadeParams, ArcadeTask, register_arcade
from .hopping import DIAGONALS, Pyramid

CUBE, DONE, YOU, BALL = "o", "#", "Q", "*"


@dataclass(frozen=True)
class QbertParams(ArcadeParams):
    width: int = param(9, 3, 41)
    height: int = param(6, 3, 30)
    goal: int = param(10, 1, 1000)
    unit: float = param(0.1, 0, 10)
    death: float = param(0.0, -1, 0)
    levels: int = param(4, 2, 20)          # rows of cubes: row k holds k + 1
    balls: int = param(0, 0, 6)            # red balls bouncing down at once
    pace: int = param(2, 1, 8)             # a ball bounces every this many turns

    def check(self) -> None:
        require(self.width >= 2 * self.levels - 1 and self.height > self.levels, "width, height",
                "room for the pyramid", (self.width, self.height))
        require(self.goal <= self.levels * (self.levels + 1) // 2, "goal", "at most the cubes", self.goal)


class Qbert(ArcadeTask):
    title = "Q*bert"
    rules = ("A pyramid of {levels} rows of cubes (o), the top row holding one cube and each row "
             "below one more; diagonal neighbours share a corner on the grid. You (Q) start on the "
             "top cube and hop diagonally one row up or down a turn. Landing on a cube paints it "
             "(#). Hopping off the pyramid's edge costs a life.{balls_text} You have {lives_text}.")
    rewards = "+{unit} for each cube you paint{death_text}."
    ends = "when you have painted {goal} cubes, or you lose your last life"
    ACTIONS = DIAGONALS
    Params = QbertParams
    glyphs = {EMPTY: "air", CUBE: "unpainted cube", DONE: "painted cube", YOU: "you", BALL: "red ball"}

    pattern = "D"                          # with death 0 (the mini preset) it pays as pattern A

    def prompt_fields(self) -> dict:
        p = self.params
        balls = (f" Up to {p.balls} red balls (*) drop onto the second row and bounce one row down "
                 f"every {p.pace} turns, left or right at random, until they fall off the bottom; "
                 "a ball that meets you costs a life." if p.balls else "")
        death = f"; {p.death:g} when your last life is lost" if p.death else ""
        return {**super().prompt_fields(), "balls_text": balls, "death_text": death}

    def _setup(self, rng) -> None:
        p = self.params
        self.pyramid = Pyramid(p.levels, (p.height - p.levels) // 2, p.width // 2)
        self.start(rng)
        self.painted: set = set()
        self.cube = (0, 0)
        self.balls: list[tuple[int, int]] = []

    def _still(self) -> list[str]:
        p = self.params
        rows = [list(EMPTY * p.width) for _ in range(p.height)]
        for cube in self.pyramid.cubes:
            r, c = self.pyramid.cell(cube)
            rows[r][c] = CUBE
        return ["".join(row) for row in rows]

    def _respawn(self) -> None:
        self.cube, self.balls = (0, 0), []

    def _hit(self) -> bool:
        return self.cube in self.balls and self.lose_life("A red ball hit you!")

    def _play(self, action: int) -> None:
        p = self.params
        if action:
            cube = self.pyramid.hop(self.cube, action)
            if cube is None:
                self.lose_life("You hopped off the pyramid!")
                return
            self.cube = cube
            if cube not in self.painted:
                self.painted.add(cube)
                self.set_still(*self.pyramid.cell(cube), DONE)
                self.score.gain()
                if self.done:
                    return
            if self._hit():
                return
        if p.balls and self.tick % p.pace == 0:
            self.balls = [(k + 1, i + self.draws.below(2)) for k, i in self.balls if k + 1 < p.levels]
            if len(self.balls) < p.balls and self.draws.random() < 0.5:
                self.balls.append((1, self.draws.below(2)))
            self._hit()

    def _sprites(self):
        out = [(*self.pyramid.cell(b), BALL) for b in self.balls]
        out.append((*self.pyramid.cell(self.cube), YOU))
        return out

    def _grid(self) -> list[str]:
        """``_sprites()`` drawn straight from the cubes (balls and you are always on one), each
        row remembered (``_draw``)."""
        rows, top, apex = self.still[:], self.pyramid.top, self.pyramid.apex
        self._grids += 1
        drawn = self._drawn
        for k, i in self.balls:
            r = top + k
            key = (rows[r], apex - k + 2 * i, BALL)
            rows[r] = drawn.get(key) or self._draw(key)
        k, i = self.cube
        r = top + k
        key = (rows[r], apex - k + 2 * i, YOU)
        rows[r] = drawn.get(key) or self._draw(key)
        return rows


register_arcade(Qbert, "qbert",
                mini=dict(max_turns=300),
                atari=dict(width=15, height=9, levels=7, goal=28, unit=1.0, death=-1.0, lives=3,
                           balls=2, pace=2, max_turns=10000))
