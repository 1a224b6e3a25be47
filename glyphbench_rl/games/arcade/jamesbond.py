"""James Bond 007: 007's multi-purpose vehicle drives right across a stage longer than the screen,
over land with craters and water with frogmen, under helicopters that drop bombs (a bomb that
hits the ground leaves a new crater) and, from the third mission, a satellite that fires a laser
straight down after a warning. Kept from the original: the jump over craters, the flare fired
diagonally up at what flies and the low shot at what swims (the original's diagonal down shot,
made forward on a one-row road), the four missions in a row, each ended by shooting its target,
five vehicles (lives). The reference's N is kept: a mission is a unit (pattern D)."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param, require
from .bodies import Body, Gun
from .engine import EMPTY, ArcadeParams, register_atari
from .scroller import fly_shots
from .sidescroll import Course, Leap, ScrollTask, fall, jump_text, lay

CAR, GROUND, CRATER, WATER, TARGET = "B", "#", "U", "~", "X"
HELI, BOMB, FROG, SAT, WARN, BEAM, FLARE, SHOT = "H", "o", "f", "S", "!", "|", "/", "-"
ACTIONS = ActionSet([("NOOP", "hold your place"), ("LEFT", "back up one cell"),
                     ("RIGHT", "drive one cell right"), ("UP", "jump (keep driving to clear a crater)"),
                     ("DOWN", "fire a low shot straight ahead"),
                     ("FIRE", "fire a flare diagonally up and ahead")], noop="NOOP")
LEFT, RIGHT, UP, DOWN, FIRE = range(1, 6)
ROAD = 5                                  # the row you drive on; the ground is the row below


@dataclass(frozen=True)
class JamesBondParams(ArcadeParams):
    width: int = param(30, 16, 60)
    height: int = param(7, 7, 7)           # satellite, helicopters, air, road, ground
    stage: int = param(250, 60, 2000)      # a mission's length
    lead: int = param(20, 6, 50)           # view columns ahead of you
    gap: int = param(9, 3, 40)             # columns between craters or pools (on average)
    heli: float = param(0.05, 0, 1)        # chance a helicopter comes in each turn
    bomb: float = param(0.5, 0, 1)         # chance a helicopter over you drops its bomb
    laser: int = param(16, 4, 100)         # turns between the satellite's shots (mission 3 on)
    warn: int = param(3, 1, 10)            # turns its warning shows first
    pools_from: int = param(2, 1, 99)      # the first mission with pools and frogmen
    laser_from: int = param(3, 1, 99)      # the first mission with the satellite
    hard_from: int = param(4, 1, 99)       # the first with wide craters and twice the helicopters

    def check(self) -> None:
        require(self.lead < self.width - 4, "lead", "leave room behind you", self.lead)
        require(self.stage >= self.width + 20, "stage", "be longer than the view", self.stage)


class JamesBond(ScrollTask):
    title = "James Bond 007"
    rules = ("You drive 007's vehicle (B) right along a road {stage} columns long per mission (the "
             "view, {width} columns, follows you), with {lives_text}. The ground row under you has "
             "craters (U): drive onto one and you lose a vehicle, so jump them (UP: {jump_text}; "
             "keep moving). From mission {pools_from} pools of water (~) hold frogmen (f) "
             "swimming at you: shoot them with the low shot (DOWN, straight ahead) or jump them. "
             "Helicopters (H) cross the sky and drop bombs (o) that fall a row a turn and crater "
             "the ground: the flare (FIRE, diagonally up and ahead) downs them. From mission "
             "{laser_from} a satellite (S) marks a column (!) every {laser} turns and fires a laser "
             "(|) down it {warn} turns later (a flare can knock it out for a while). From mission "
             "{hard_from} craters are wider and helicopters come twice as often. Each mission ends "
             "at its target (X): shoot it with the low shot to start the next mission.")
    rewards = "+{unit} for each mission accomplished; {death} when the game is lost."
    ends = "when {goal} missions are accomplished or the game is lost"
    ACTIONS = ACTIONS
    Params = JamesBondParams
    pattern = "D"
    glyphs = {EMPTY: "sky", GROUND: "ground", CRATER: "crater", WATER: "water", TARGET: "mission target",
              HELI: "helicopter", BOMB: "bomb", FROG: "frogman", SAT: "satellite", WARN: "laser warning",
              BEAM: "laser", FLARE: "your flare", SHOT: "your low shot", CAR: "you"}

    def prompt_fields(self) -> dict:
        return {**super().prompt_fields(), "jump_text": jump_text()}

    def _setup(self, rng) -> None:
        self.start(rng)
        self.mission = 0
        self.leap = Leap()
        self._next_mission()

    def _next_mission(self) -> None:
        p, draws = self.params, self.draws
        self.mission += 1
        m = self.mission
        cells = lay([EMPTY] * ROAD + [EMPTY, GROUND], p.stage)
        self.frogs: list[Body] = []
        x = p.width - p.lead + 4
        while x < p.stage - 12:
            x += max(3, p.gap - 3 + draws.below(7))
            if m >= p.pools_from and draws.random() < 0.35:
                n = 5 + draws.below(5)
                cells[ROAD + 1][x:x + n] = [WATER] * n
                self.frogs.append(Body(ROAD, x + n - 1, dc=-1))
                x += n
            else:
                n = 1 + (m >= p.hard_from and draws.random() < 0.5)
                cells[ROAD + 1][x:x + n] = [CRATER] * n
                x += n
        cells[ROAD][p.stage - 3] = TARGET
        self.course = Course(cells, p.width)
        self.x = 3
        self._respawn()
        if m > 1:
            self.say(f"Mission {m}!")

    def _respawn(self) -> None:
        course = self.course
        while self.x > 0 and course.get(ROAD + 1, self.x) != GROUND:
            self.x -= 1
        self.leap.land()
        self.row = ROAD
        course.follow(self.x, self.params.lead)
        self.helis: list[Body] = []
        self.bombs: list[Body] = []
        self.flares, self.lows = Gun(cooldown=2, speed=1, reach=6, limit=2), Gun(cooldown=2, speed=2, reach=10)
        self.sat, self.aim, self.beam = self.x + 4, -1, -1
        self.frogs = [f for f in self.frogs if abs(f.c - self.x) > 3]

    def _play(self, action: int) -> None:
        p, course, x = self.params, self.course, self.x
        lift = self.leap.lift(self.tick)
        if action == RIGHT and course.get(ROAD, x + 1) != TARGET:
            self.x = x + 1
        elif action == LEFT and x > course.left:
            self.x = x - 1
        elif action == UP:
            self.leap.start(self.tick)
        elif action == DOWN:
            self.lows.fire(self.tick, ROAD - lift, self.x, 0, 1, SHOT)
        elif action == FIRE:
            self.flares.fire(self.tick, ROAD - lift, self.x, -1, 1, FLARE)
        course.follow(self.x, p.lead)
        self.row = ROAD - self.leap.lift(self.tick)
        if self.lows.shots:
            fly_shots(self.lows, self._low_hit, self._low_strike)
            if self.done or self.course is not course:
                return
        if self.flares.shots:
            fly_shots(self.flares, self._air_hit, self._air_strike)
        if (self.frogs and self._frogmen()) or self._sky() or (self.mission >= p.laser_from and self._satellite()):
            return
        if self.row == ROAD and course.get(ROAD + 1, self.x) == CRATER:
            self.lost("You drove into a crater!")

    def _low_hit(self, r: int, c: int) -> bool:
        if self.course.get(r, c) == TARGET:
            return True
        for f in self.frogs:
            if r == ROAD and c - 1 <= f.c <= c:          # (or one that swam through the shot)
                return True
        return c >= self.course.left + self.params.width

    def _low_strike(self, r: int, c: int) -> bool:
        if self.course.get(r, c) == TARGET:
            self.score.gain()
            if not self.done:
                self.say("Mission accomplished!")
                self._next_mission()
            return True
        self.frogs = [f for f in self.frogs if not (r == ROAD and c - 1 <= f.c <= c)]
        return False

    def _air_hit(self, r: int, c: int) -> bool:
        if r < 0:
            return True
        for t in self.helis:
            if t.r == r and -1 <= t.c - c <= 1:          # (a flare bursts beside it too)
                return True
        for b in self.bombs:
            if b.c == c and b.r in (r, r + 1):
                return True
        return r == 0 and c == self.sat and self.mission >= self.params.laser_from

    def _air_strike(self, r: int, c: int) -> bool:
        if r == 0 and c == self.sat:
            self.sat, self.aim = self.course.left + self.params.width + 8, -1   # a new one comes in
        self.helis = [t for t in self.helis if not (t.r == r and -1 <= t.c - c <= 1)]
        self.bombs = [b for b in self.bombs if not (b.c == c and b.r in (r, r + 1))]
        return False

    def _frogmen(self) -> bool:
        course, x, row = self.course, self.x, self.row
        for f in self.frogs:
            if course.seen(f.c):
                met = f.c == x
                if self.tick % 2 == 0:
                    if course.get(ROAD + 1, f.c + f.dc) != WATER:
                        f.dc = -f.dc
                    f.c += f.dc
                if (met or f.c == x) and row == ROAD:
                    return self.lost("A frogman got you!")
        return False

    def _sky(self) -> bool:
        p, course, x = self.params, self.course, self.x
        if self.draws.random() < p.heli * (1 + (self.mission >= p.hard_from)):
            self.helis.append(Body(1, course.left + p.width - 1, dc=-1, data=True))
        if self.bombs:
            hit, landed = fall(self.bombs, self.row, x, ROAD + 1)
            if hit:
                self.bombs = []
                return self.lost("A bomb hit you!")
            for b in landed:
                if course.get(ROAD + 1, b.c) == GROUND:
                    course.put(ROAD + 1, b.c, CRATER)
        if not self.helis:
            return False
        kept = []
        for t in self.helis:
            t.c -= 1
            if t.data and 2 <= t.c - x <= 5 and self.draws.random() < p.bomb:
                t.data = False
                self.bombs.append(Body(2, t.c))
            if t.c >= course.left:
                kept.append(t)
        self.helis = kept
        return False

    def _satellite(self) -> bool:
        p, t = self.params, self.tick
        if self.beam == t - 1:
            self.beam = self.aim = -1
        if self.aim < 0:
            ahead = self.x + p.warn                  # it aims where you will be
            self.sat += 1 if self.sat < ahead else -1 if self.sat > ahead else 0
            if t % p.laser == 0:
                self.aim, self.fire_at = self.sat, t + p.warn
        elif t >= self.fire_at:
            self.beam = t
            if self.x == self.aim:
                return self.lost("The satellite's laser hit you!")
        return False

    def _movers(self):
        return ((self.helis, HELI), (self.bombs, BOMB), (self.frogs, FROG), (self.flares.shots, FLARE),
                (self.lows.shots, SHOT))

    def _marks(self):
        me = (self.row, self.x, CAR)
        if self.mission < self.params.laser_from:
            return (me,)
        if self.aim < 0:
            return (0, self.sat, SAT), me
        if self.beam == self.tick:
            return [(0, self.sat, SAT)] + [(r, self.aim, BEAM) for r in range(1, ROAD + 1)] + [me]
        return (0, self.sat, SAT), (1, self.aim, WARN), me

    def note_key(self):
        return self.mission, self.x

    def note_text(self) -> str:
        return f"Mission {self.mission}/{self.params.goal} | Road {self.x}/{self.params.stage}"


register_atari(JamesBond, "jamesbond", lives=5, goal=4, unit=1000.0, max_turns=10000)
