"""Centipede: a centipede (head O, body o) winds across the field, a row down and back each time
it meets an edge or a mushroom (#); a shot segment leaves a mushroom and splits the centipede
(the segment behind becomes a head). You move in a zone of bottom rows and shoot up. On the
Atari preset a spider (X) zigzags through your zone, mushrooms score when shot down, and the
centipede climbs back up from the bottom.
Balance: mini: free fire, 12 mushrooms, two centipedes to clear; Atari: mushrooms no longer score."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.params import param, require
from .bodies import Body
from .engine import EMPTY, register_arcade
from .shooter import BOMB, CANNON, SHOT, Shooter, ShooterParams, per, shooter_actions

HEAD, BODY, MUSH, SPIDER = "O", "o", "#", "X"
UP, DOWN = 4, 5


@dataclass(frozen=True)
class CentipedeParams(ShooterParams):
    width: int = param(16, 8, 60)
    height: int = param(10, 8, 40)
    goal: int = param(16, 1, 300)
    unit: float = param(0.0625, 0, 100)
    cooldown: int = param(1, 1, 20)
    segments: int = param(8, 1, 20)
    crawl: int = param(2, 1, 10)          # turns per centipede step
    mushrooms: int = param(12, 0, 80)     # mushrooms at the start, above your zone
    zone: int = param(2, 1, 10)           # bottom rows you move in
    land: bool = param(True)              # a segment reaching the bottom row ends the game
    spider: int = param(0, 0, 200)        # turns between spiders (0: none)
    shrooms_count: bool = param(False)    # a shot mushroom counts toward the goal

    def check(self) -> None:
        require(self.segments < self.width, "segments", "be fewer than the columns", self.segments)
        require(self.zone + 3 < self.height, "zone", "leave rows above it", self.zone)


class Centipede(Shooter):
    title = "Centipede"
    rules = ("You (A) move in the bottom {zone} rows of a {width}x{height} field, with {lives_text}. "
             "A centipede of {segments} segments (head O, body o) enters at the top left and moves a "
             "cell every {crawl_text}; meeting an edge or a mushroom (#) it moves a row down and "
             "turns. {gun_text} A shot segment becomes a mushroom, and the one behind it becomes a "
             "head; when every segment is shot a new centipede enters. A shot mushroom is gone. A "
             "segment touching you costs a life.{land_text}"
             "{spider_text}")
    rewards = "+{unit} for each {counted} shot."
    ends = "when you have shot {goal} {things} or the game is lost"
    ACTIONS = shooter_actions(("UP", "move one row up (within your zone)"),
                              ("DOWN", "move one row down"))
    Params = CentipedeParams
    pattern = "A"
    glyphs = {EMPTY: "empty", MUSH: "mushroom", HEAD: "centipede head", BODY: "centipede body",
              SPIDER: "spider", SHOT: "your shot", CANNON: "you"}

    def prompt_fields(self) -> dict:
        p = self.params
        return {**super().prompt_fields(),
                "land_text": " A segment reaching the bottom row ends the game." if p.land else
                " At the bottom the centipede turns back up, to the top of your zone.",
                "spider_text": (f" Every {p.spider} turns a spider (X) zigzags through your zone "
                                "(a life if it touches you).") if p.spider else "",
                "counted": " or ".join(["segment"] + ["mushroom"] * p.shrooms_count + ["spider"] * bool(p.spider)),
                "crawl_text": per(p.crawl, "turn").removeprefix("a "),
                "things": "things" if p.shrooms_count or p.spider else "segments"}

    def _still(self) -> list[str]:
        rows = super()._still()
        p, d = self.params, self.draws
        for _ in range(p.mushrooms):
            r, c = 1 + d.below(p.height - p.zone - 2), d.below(p.width)
            rows[r] = rows[r][:c] + MUSH + rows[r][c + 1:]
        return rows

    def _setup(self, rng) -> None:
        self.arm(rng)
        self.bug = None
        self._hatch()

    def _hatch(self) -> None:
        n = self.params.segments
        for k in range(n):
            self.pack.add(0, n - 1 - k, HEAD if k == 0 else BODY, dr=1, dc=1)

    def steer(self, action: int) -> None:
        if action == UP or action == DOWN:
            p = self.params
            self.row = min(p.height - 1, max(p.height - p.zone, self.row + (1 if action == DOWN else -1)))
        else:
            super().steer(action)

    def _blocks(self, r: int, c: int) -> bool:
        return 0 <= r < self.params.height and self.still[r][c] == MUSH

    def _struck(self, r: int, c: int) -> None:
        self.set_still(r, c, EMPTY)
        if self.params.shrooms_count:
            self.score.gain()

    def _foe(self, r: int, c: int):
        bug = self.bug
        return bug if bug is not None and bug.r == r and bug.c == c else self.pack.at(r, c)

    def _play(self, action: int) -> None:
        p = self.params
        self.steer(action)
        bodies = self.pack.bodies
        if self.tick % p.crawl == 0:   # (_crawl written out for every segment)
            w, h, top, still = p.width, p.height, p.height - p.zone - 1, self.still
            for b in bodies:
                c = b.c + b.dc
                if 0 <= c < w and still[b.r][c] != MUSH:
                    b.c = c
                    continue
                b.dc = -b.dc
                r = b.r + b.dr
                if r >= h or (b.dr < 0 and r < top):
                    b.dr = -b.dr
                    r = b.r + b.dr
                b.r = r
        if p.land and self.pack.lowest() >= p.height - 1:
            self.lives = 1
            self.lose_life("The centipede reached the bottom.")
            return
        self._spider()
        hits = ()
        if self.gun.shots:   # (_foe on the pack indexed by cell: it holds still while shots fly)
            cells = {}
            for b in reversed(bodies):   # (the first body on a cell wins, as in Pack.at)
                cells[b.r, b.c] = b
            bug, find = self.bug, cells.get

            def foe_at(r: int, c: int):
                return bug if bug is not None and bug.r == r and bug.c == c else find((r, c))

            hits = self.volley(foe_at)
        for foe, cell in hits:
            if foe is self.bug:
                self.bug = None
            else:
                i = self.pack.bodies.index(foe)
                self.pack.kill(foe)
                if i < len(self.pack.bodies):
                    self.pack.bodies[i].glyph = HEAD
                if cell[0] < p.height - p.zone:
                    self.set_still(*cell, MUSH)
            self.say("Spider hit!" if foe.glyph == SPIDER else "Segment hit!")
            self.score.gain()
            if self.done:
                return
        if not self.pack.bodies:
            self._hatch()
        bug = self.bug
        if self.touches() or (bug is not None and (bug.r, bug.c) == (self.row, self.col)):
            self.bug = None
            self.lose_life("You were bitten.")

    def _crawl(self, b) -> None:
        p = self.params
        c = b.c + b.dc
        if 0 <= c < p.width and self.still[b.r][c] != MUSH:
            b.c = c
            return
        b.dc = -b.dc
        r = b.r + b.dr
        if r >= p.height or (b.dr < 0 and r < p.height - p.zone - 1):
            b.dr = -b.dr
            r = b.r + b.dr
        b.r = r

    def _spider(self) -> None:
        p, bug = self.params, self.bug
        if bug is None:
            if p.spider and self.tick % p.spider == 0:
                self.bug = Body(p.height - p.zone, 0, 1, 1, SPIDER)
            return
        bug.r += bug.dr
        if not p.height - p.zone <= bug.r < p.height:
            bug.dr = -bug.dr
            bug.r += 2 * bug.dr
        bug.c += bug.dc
        if not 0 <= bug.c < p.width:
            self.bug = None

    def _respawn(self) -> None:
        self.row = self.params.height - 1

    def _grid(self) -> list[str]:
        """``_sprites`` drawn straight from the bodies, in the same order."""
        rows = self._rows() if self._slides else self.still[:]
        self._grids += 1
        bug = self.bug
        if bug is not None:
            self._put(rows, bug.r, bug.c, SPIDER)
        self._paint(rows, self.pack.bodies)
        if self.gun.shots:
            self._paint(rows, self.gun.shots, SHOT)
        if self.bombs.shots:
            self._paint(rows, self.bombs.shots, BOMB)
        self._put(rows, self.row, self.col, self.cannon)
        return rows

    def _sprites(self):
        out = super()._sprites()
        if self.bug is not None:
            out.insert(0, (self.bug.r, self.bug.c, SPIDER))
        return out


register_arcade(Centipede, "centipede",
                mini=dict(max_turns=300),
                atari=dict(width=20, height=20, lives=3, goal=30, unit=10.0, segments=10, crawl=1, zone=4,
                           mushrooms=25, land=False, spider=40, shrooms_count=False, cooldown=2,
                           max_turns=10000))
