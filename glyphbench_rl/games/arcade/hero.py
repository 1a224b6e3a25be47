"""H.E.R.O.: Roderick Hero flies a helicopter pack down a mine shaft, screen by screen, to rescue
a trapped miner at its bottom. Kept from the original: the shaft seen one screen at a time (and a
map of its screens in the HUD), the pack that lifts against gravity, floors with gaps to drop
through, breakable walls blown by dynamite (laid with DOWN while standing, as the original's
joystick-down; the blast hurts you if you stand next to it) or slowly burned by the helmet laser,
critters (spiders, bats, snakes) shot by the laser, lava that kills on touch, the power meter
that drains each turn, levels that grow deeper, and the scoring (critters, walls, a rescue plus
the power left). Dropped: lanterns, rafts, tentacles and the water."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param
from .bodies import Countdown
from .climbing import ClimbTask, crawl, shaft, thrust
from .engine import EMPTY, ArcadeParams, register_atari
from .rooms import LEGEND

ROCK, WALL, LAVA, YOU, MINER, TNT, BLAST, BEAM = "#", "%", "~", "R", "M", "!", "*", "-"
BAT, SPIDER, SNAKE = "B", "X", "S"
ACTIONS = ActionSet([("NOOP", "hover off: fall, or stand"), ("FIRE", "shoot your helmet laser ahead"),
                     ("UP", "lift a row with the helicopter pack"), ("RIGHT", "move and face right"),
                     ("LEFT", "move and face left"),
                     ("DOWN", "standing: lay dynamite; in the air: drop faster")], noop="NOOP")
FIRE, UP, RIGHT, LEFT, DOWN = 1, 2, 3, 4, 5
BANDS, DIVE = 3, 2   # floors a screen; rows a DOWN in the air drops


@dataclass(frozen=True)
class HeroParams(ArcadeParams):
    width: int = param(20, 14, 40)
    height: int = param(16, 13, 30)     # one screen of the shaft
    lives: int = param(4, 1, 9)
    goal: int = param(5, 1, 100)
    unit: float = param(1000.0, 0, 10000)
    depth: int = param(2, 1, 10)        # screens in level 1's shaft
    deeper: int = param(1, 0, 4)        # screens added each level
    power: int = param(120, 20, 2000)   # power a screen of the shaft, drained a unit a turn
    dynamite: int = param(6, 0, 20)     # sticks a level (and a life)
    fuse: int = param(3, 1, 10)
    reach: int = param(3, 1, 10)        # laser reach in cells
    burn: int = param(5, 1, 50)         # laser hits that burn through a wall cell
    walls: float = param(0.6, 0, 1)     # chance a band has a breakable wall
    critters: float = param(0.7, 0, 1)  # chance a band has a critter
    lava_from: int = param(2, 1, 100)   # the first level with lava
    pace: int = param(2, 1, 8)          # critters move every this many turns
    critter_points: int = param(50, 0, 1000)
    wall_points: int = param(75, 0, 1000)


class Hero(ClimbTask):
    title = "H.E.R.O"
    rules = ("You are R, a hero with a helicopter pack, going down a mine shaft to rescue trapped "
             "miners. The field is one {width}x{height} screen of the shaft; level 1's shaft is "
             "{depth} screens deep and each level is {deeper} deeper. Each screen has {bands} rock (#) "
             "floors, each with a gap to drop through; the miner (M) waits on the shaft's bottom floor. "
             "UP lifts you a row; else gravity pulls you down a row a turn (DOWN in the air: {dive}). "
             "LEFT and RIGHT move and turn you. FIRE shoots your laser {reach} cells ahead: it kills "
             "a critter (spider X climbing its thread, bat B, snake S) and {burn} hits burn through a "
             "wall (%) cell. DOWN while standing lays dynamite (!; {dynamite} sticks a level and a "
             "life): after {fuse} turns it blows up walls and critters next to it, and you too if you "
             "are next to it. Touching a critter or lava (~) costs a life (from level {lava_from} lava "
             "lines floors and ceilings), and so does running out of power: {power} a screen of the "
             "shaft, a unit a turn. You have {lives_text}. " + LEGEND + ".")
    rewards = ("+{critter_points} a critter, +{wall_points} a wall blown up or a wall cell burned "
               "through, +{unit:g} a rescue plus the power left; -1 when your last life is lost.")
    ends = "when you have rescued {goal} miners, or you lose your last life"
    ACTIONS = ACTIONS
    Params = HeroParams
    pattern = "D"
    glyphs = {EMPTY: "air", ROCK: "rock", WALL: "breakable wall", LAVA: "lava", YOU: "you",
              MINER: "trapped miner", SPIDER: "spider", BAT: "bat", SNAKE: "snake", TNT: "dynamite",
              BLAST: "blast", BEAM: "laser"}

    def prompt_fields(self) -> dict:
        return {**super().prompt_fields(), "bands": BANDS, "dive": DIVE}

    def _setup(self, rng) -> None:
        self.start(rng)
        self.level = 0
        self._shaft()

    def _shaft(self) -> None:
        """Lay out the level's shaft: per band of each screen a floor with a gap (the last band
        holds the miner), and on the way from where you drop in to the gap a wall, a critter,
        lava."""
        p, d = self.params, self.draws
        w, h = p.width, p.height
        depth = p.depth + self.level * p.deeper
        lava = self.level + 1 >= p.lava_from
        self.critters: list[list] = []
        self.r, self.c, self.face = 0, 1 + d.below(w - 3), 1
        rows, bands = shaft(d, w, h, depth, BANDS, self.c, ROCK, EMPTY)
        for band in bands:
            top, floor, step = band.top, band.floor, band.step
            if band.last:
                self.miner = (floor - 1, band.near)
            elif lava:
                for x in range(band.far + step, 0 if step < 0 else w - 1, step):
                    rows[floor][x] = LAVA
            free = band.between[1:-1]
            if d.random() < p.walls:
                x = free.pop(d.below(len(free) - 1))
                for r in range(top, floor):
                    rows[r][x] = WALL
                free = [y for y in free if (y - x) * step > 1]
            if free and d.random() < p.critters:
                x, kind = free.pop(d.below(len(free))), d.below(3)
                self.critters.append([floor - 1, x, 0, step, BAT] if kind == 0 else
                                     [top + 1, x, 1, 0, SPIDER] if kind == 1 else
                                     [floor - 1, x, 0, 0, SNAKE])
            if lava and free and floor - top >= 4 and top > 0:
                x = free[d.below(len(free))]
                rows[top][x] = rows[top + 1][x] = LAVA
        self.screens(["".join(row) for row in rows])
        self.power = Countdown(p.power * depth)
        self._lives_reset()

    def _lives_reset(self) -> None:
        self.sticks, self.tnt, self.flash, self.burnt = self.params.dynamite, None, [], {}
        self.power.refill()

    def _respawn(self) -> None:
        self.r, self.c = self.entry[self.tower.top // self.tower.view]
        self._lives_reset()

    def _play(self, action: int) -> None:
        p, tower = self.params, self.tower
        self.flash = []
        below = tower.get(self.r + 1, self.c)
        if action in (LEFT, RIGHT):
            self.face = 1 if action == RIGHT else -1
            ahead = tower.get(self.r, self.c + self.face)
            if ahead == LAVA:
                return self.lose_life("You touched lava.")
            if ahead == EMPTY:
                self.c += self.face
                below = tower.get(self.r + 1, self.c)
        elif action == FIRE:
            self._laser()
        elif action == DOWN and below != EMPTY and self.sticks and self.tnt is None:
            self.sticks -= 1
            self.tnt = (self.r, self.c, self.tick + p.fuse)
        up = action == UP
        if up or below == EMPTY:
            c = self.c
            self.r = thrust(self.r, up, DIVE if action == DOWN else 1, lambda y: tower.get(y, c) != EMPTY)
            below = tower.get(self.r - 1 if up else self.r + 1, c)
        if below == LAVA:
            return self.lose_life("You touched lava.")
        self.paged()
        if (self.r, self.c) == self.miner:
            self.say("You rescued the miner!")
            self.score.bonus(self.power.left)
            self.score.gain()
            if not self.done:
                self.level += 1
                self._shaft()
            return
        if self._touched() or self._fuse():
            return
        if self.tick % p.pace == 0:
            crawl(tower, self.critters, tower.top, tower.top + p.height, EMPTY)
            if self._touched():
                return
        if self.power.tick():
            self.lose_life("Your power ran out.")

    def _touched(self) -> bool:
        r, c = self.r, self.c
        return any(k[0] == r and k[1] == c for k in self.critters) and self.lose_life("A critter got you.")

    def _laser(self) -> None:
        """The laser kills the first critter in reach, or chips at the wall cell in its way."""
        p, r = self.params, self.r
        cells, critter, x = self.tower.beam(r, self.c, self.face, p.reach, EMPTY, self.critters)
        self.flash = [(r, y, BEAM) for y in cells]
        if critter is not None:
            self.critters.remove(critter)
            self.score.bonus(p.critter_points)
        elif x is not None and self.tower.get(r, x) == WALL:
            n = self.burnt[(r, x)] = self.burnt.get((r, x), 0) + 1
            if n >= p.burn:
                self.tower.put(r, x, EMPTY)
                self.score.bonus(p.wall_points)

    def _fuse(self) -> bool:
        """The dynamite blows when its fuse is out: walls and critters next to it go, and so do
        you if you are there."""
        if self.tnt is None or self.tick < self.tnt[2]:
            return False
        (tr, tc, _), tower, p = self.tnt, self.tower, self.params
        self.tnt = None
        for x in (tc - 1, tc + 1):
            if tower.clear_run(tr, x, WALL, EMPTY):
                self.score.bonus(p.wall_points)
        blast = [(tr + dr, tc + dc) for dr in (-1, 0, 1) for dc in (-1, 0, 1)]
        for k in [k for k in self.critters if (k[0], k[1]) in blast]:
            self.critters.remove(k)
            self.score.bonus(p.critter_points)
        self.flash = [(y, x, BLAST) for y, x in blast if tower.get(y, x) == EMPTY]
        return (self.r, self.c) in blast and self.lose_life("The blast got you.")

    def _movers(self):
        out = [(k[0], k[1], k[4]) for k in self.critters]
        out.append((*self.miner, MINER))
        if self.tnt is not None:
            out.append((self.tnt[0], self.tnt[1], TNT))
        out += self.flash
        out.append((self.r, self.c, YOU))
        return out

    def _extra_hud(self) -> str:
        return f"Level {self.level + 1} | Power {self.power.left} | TNT {self.sticks} | {self.map.hud()}"


register_atari(Hero, "hero", max_turns=10000)
