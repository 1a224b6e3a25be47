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
from .climbing import ClimbTask, Tower, thrust
from .engine import EMPTY, ArcadeParams, register_atari
from .rooms import LEGEND, RoomMap

ROCK, WALL, LAVA, YOU, MINER, TNT, BLAST, BEAM = "#", "%", "~", "R", "M", "!", "*", "-"
BAT, SPIDER, SNAKE = "B", "X", "S"
ACTIONS = ActionSet([("NOOP", "hover off: fall, or stand"), ("FIRE", "shoot your helmet laser ahead"),
                     ("UP", "lift a row with the helicopter pack"), ("RIGHT", "move and face right"),
                     ("LEFT", "move and face left"),
                     ("DOWN", "standing: lay dynamite; in the air: drop two rows")], noop="NOOP")
FIRE, UP, RIGHT, LEFT, DOWN = 1, 2, 3, 4, 5
BANDS = 3   # floors a screen


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
             "{depth} screens deep and each level is {deeper} deeper. Each screen has three rock (#) "
             "floors, each with a gap to drop through; the miner (M) waits on the shaft's bottom floor. "
             "UP lifts you a row; else gravity pulls you down a row a turn (DOWN in the air: two). "
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

    def _setup(self, rng) -> None:
        self.climb_start(rng)
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
        rows = [list(ROCK + EMPTY * (w - 2) + ROCK) for _ in range(depth * h)]
        floors = [h - 1 - (h - 1) // BANDS * j for j in range(BANDS)][::-1]
        self.critters: list[list] = []
        a = 1 + d.below(w - 3)
        self.r, self.c, self.face = 0, a, 1
        for s in range(depth):
            for j, f in enumerate(floors):
                top, floor = s * h + (floors[j - 1] + 1 if j else 0), s * h + f
                rows[floor] = list(ROCK * w)
                holes = [b for b in range(1, w - 2) if b >= a + 6 or b <= a - 6]
                b = holes[d.below(len(holes))]
                step = 1 if b > a else -1
                near, far = (b, b + 1) if step > 0 else (b + 1, b)
                mid = list(range(a + 1 + step if step > 0 else a - 1, near, step))
                last = s == depth - 1 and j == BANDS - 1
                if last:
                    self.miner = (floor - 1, near)
                else:
                    rows[floor][b] = rows[floor][b + 1] = EMPTY
                    if lava:
                        for x in range(far + step, 0 if step < 0 else w - 1, step):
                            rows[floor][x] = LAVA
                free = mid[1:-1]
                if d.random() < p.walls:
                    x = free.pop(d.below(len(free) - 1))
                    for r in range(top, floor):
                        rows[r][x] = WALL
                    free = [y for y in free if (y - x) * step > 1]
                if free and d.random() < p.critters:
                    x = free.pop(d.below(len(free)))
                    kind = d.below(3)
                    self.critters.append([floor - 1, x, 0, step, BAT] if kind == 0 else
                                         [top + 1, x, 1, 0, SPIDER] if kind == 1 else
                                         [floor - 1, x, 0, 0, SNAKE])
                if lava and free and floor - top >= 4:
                    x = free[d.below(len(free))]
                    rows[top][x] = rows[top + 1][x] = LAVA
                a = b
        self.tower = Tower(["".join(row) for row in rows], h)
        self.map = RoomMap(["#"] * depth)
        self.map.enter(0, 0)
        self.entry = {0: (self.r, self.c)}
        self.power = Countdown(p.power * depth)
        self._lives_reset()

    def _lives_reset(self) -> None:
        self.sticks, self.tnt, self.flash, self.burnt = self.params.dynamite, None, [], {}
        self.power.refill()

    def _respawn(self) -> None:
        self.r, self.c = self.entry[self.tower.top // self.params.height]
        self._lives_reset()

    def _open(self, r: int) -> bool:
        return self.tower.get(r, self.c) == EMPTY

    def _play(self, action: int) -> None:
        p, tower = self.params, self.tower
        self.flash = []
        standing = tower.get(self.r + 1, self.c) != EMPTY
        if action in (LEFT, RIGHT):
            self.face = 1 if action == RIGHT else -1
            ahead = tower.get(self.r, self.c + self.face)
            if ahead == LAVA:
                return self._hurt("You touched lava.")
            if ahead == EMPTY:
                self.c += self.face
        elif action == FIRE:
            self._laser()
        elif action == DOWN and standing:
            if self.sticks and self.tnt is None:
                self.sticks -= 1
                self.tnt = (self.r, self.c, self.tick + p.fuse)
        up = action == UP
        r = thrust(self.r, up, 0 if up or tower.get(self.r + 1, self.c) != EMPTY else
                   2 if action == DOWN else 1, lambda y: tower.get(y, self.c) != EMPTY)
        near = tower.get(r - 1 if up else r + 1, self.c)
        self.r = r
        if near == LAVA:
            return self._hurt("You touched lava.")
        if tower.page(self.r):
            screen = tower.top // p.height
            self.map.enter(screen, 0)
            self.entry.setdefault(screen, (self.r, self.c))
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
            self._crawl()
            if self._touched():
                return
        if self.power.tick():
            self._hurt("Your power ran out.")

    def _hurt(self, why: str) -> bool:
        return self.lose_life(why)

    def _touched(self) -> bool:
        here = (self.r, self.c)
        return any((k[0], k[1]) == here for k in self.critters) and self._hurt("A critter got you.")

    def _laser(self) -> None:
        tower, r = self.tower, self.r
        for k in range(1, self.params.reach + 1):
            x = self.c + self.face * k
            hit = [m for m in self.critters if m[0] == r and m[1] == x]
            if hit:
                self.critters.remove(hit[0])
                self.score.bonus(self.params.critter_points)
                return
            cell = tower.get(r, x)
            if cell == WALL:
                n = self.burnt[(r, x)] = self.burnt.get((r, x), 0) + 1
                if n >= self.params.burn:
                    tower.put(r, x, EMPTY)
                    self.score.bonus(self.params.wall_points)
                return
            if cell != EMPTY:
                return
            self.flash.append((r, x, BEAM))

    def _fuse(self) -> bool:
        """The dynamite blows when its fuse is out: walls and critters next to it go, and so do
        you if you are there."""
        if self.tnt is None or self.tick < self.tnt[2]:
            return False
        tr, tc, _ = self.tnt
        self.tnt, tower = None, self.tower
        for x in (tc - 1, tc + 1):
            if tower.get(tr, x) == WALL:
                y = tr
                while tower.get(y - 1, x) == WALL:
                    y -= 1
                while tower.get(y, x) == WALL:
                    tower.put(y, x, EMPTY)
                    y += 1
                self.score.bonus(self.params.wall_points)
        blast = [(tr + dr, tc + dc) for dr in (-1, 0, 1) for dc in (-1, 0, 1)]
        for k in [k for k in self.critters if (k[0], k[1]) in blast]:
            self.critters.remove(k)
            self.score.bonus(self.params.critter_points)
        self.flash = [(y, x, BLAST) for y, x in blast if tower.get(y, x) == EMPTY]
        return (self.r, self.c) in blast and self._hurt("The blast got you.")

    def _crawl(self) -> None:
        """Critters on this screen move a cell: bats along their row, spiders up and down their
        thread, turning at anything solid; snakes stay."""
        top, bottom, tower = self.tower.top, self.tower.top + self.params.height, self.tower
        for k in self.critters:
            if top <= k[0] < bottom and (k[2] or k[3]):
                if tower.get(k[0] + k[2], k[1] + k[3]) != EMPTY:
                    k[2], k[3] = -k[2], -k[3]
                if tower.get(k[0] + k[2], k[1] + k[3]) == EMPTY:
                    k[0] += k[2]
                    k[1] += k[3]

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
