"""Road Runner: you are the Road Runner, running left along a desert road that scrolls past, with
Wile E. Coyote chasing from the right. Kept from the original: birdseed piles on the road (eat
them; miss five in a row and you faint), trucks speeding along the lanes (they flatten you, or
the Coyote), the Coyote's land mines from level 2 (they blow up only him: lure him over them),
falling rocks from level 3 (a shadow marks where one lands), levels reached by running to the
end of the road, three lives. The joystick's road is two-dimensional, so the actions are the
four directions (the reference's JUMP is dropped: the original has none) (pattern D)."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param, require
from .bodies import Body
from .engine import EMPTY, ArcadeParams, register_atari
from .sidescroll import Course, ScrollTask, lay

RUNNER, COYOTE, SEED, MINE, TRUCK, SHADOW, VERGE = "R", "C", ":", "x", "T", "o", "="
ACTIONS = ActionSet([("NOOP", "stand still"), ("LEFT", "run one cell left (onward)"),
                     ("RIGHT", "step one cell right (back)"), ("UP", "move up a lane"),
                     ("DOWN", "move down a lane")], noop="NOOP")
MOVES = ((0, 0), (0, 1), (0, -1), (-1, 0), (1, 0))   # (lane, distance) per action


@dataclass(frozen=True)
class RoadRunnerParams(ArcadeParams):
    width: int = param(30, 12, 60)
    height: int = param(7, 4, 12)          # lanes = height - 2 (a verge above and below)
    stage: int = param(150, 40, 2000)      # the road's length per level
    spacing: int = param(8, 2, 30)         # columns between seed piles (on average)
    faint: int = param(5, 2, 20)           # seed piles missed in a row that make you faint
    pace: float = param(0.85, 0, 1)         # the Coyote's chance to step each turn
    trucks: float = param(0.08, 0, 1)      # chance a truck comes along each turn
    mines: int = param(3, 0, 30)           # mines per 100 columns from level 2
    rocks: float = param(0.05, 0, 1)       # chance a rock starts falling each turn from level 3
    warn: int = param(3, 1, 10)            # turns a rock's shadow shows before it lands
    daze: int = param(8, 1, 50)            # turns the Coyote is out after a mishap
    lead: int = param(12, 3, 40)           # view columns ahead of you
    mines_from: int = param(2, 1, 99)      # the first level with the Coyote's mines
    rocks_from: int = param(3, 1, 99)      # the first level with falling rocks

    def check(self) -> None:
        require(self.lead < self.width - 2, "lead", "leave room behind you", self.lead)
        require(self.stage >= self.width, "stage", "be at least the view's width", self.stage)


class RoadRunner(ScrollTask):
    title = "Road Runner"
    rules = ("You are the Road Runner (R) running left along a road of {lanes} lanes (the view, "
             "{width} columns, follows you; you see {lead} columns ahead), with {lives_text}. Wile "
             "E. Coyote (C) chases you from the right; if he reaches your cell you lose a life. "
             "Eat birdseed piles (:) by running over them; missing {faint} piles in a row makes you "
             "faint (a life lost). Trucks (T) drive right along the lanes: one that hits you costs "
             "a life, one that hits the Coyote knocks him out. Reach the road's end ({stage} "
             "columns) for the next level. From level {mines_from} the Coyote's mines (x) lie on "
             "the road: they blow up only him, so lead him over them. From level {rocks_from} rocks fall where a "
             "shadow (o) shows, {warn} turns later, on you or on him.")
    rewards = ("+{unit} for each seed pile eaten and each time the Coyote is knocked out (truck, "
               "mine or rock); {death} when the game is lost.")
    ends = "when you have scored {goal} such events or the game is lost"
    ACTIONS = ACTIONS
    Params = RoadRunnerParams
    pattern = "D"
    glyphs = {EMPTY: "road", VERGE: "verge", SEED: "birdseed", MINE: "mine", TRUCK: "truck",
              SHADOW: "falling rock's shadow", COYOTE: "Coyote", RUNNER: "you"}

    def prompt_fields(self) -> dict:
        return {**super().prompt_fields(), "lanes": self.params.height - 2}

    def _setup(self, rng) -> None:
        self.start(rng)
        self.level, self.misses = 0, 0
        self._next_level()

    def _next_level(self) -> None:
        p, draws = self.params, self.draws
        self.level += 1
        lanes = p.height - 2
        cells = lay([VERGE] + [EMPTY] * lanes + [VERGE], p.stage)
        self.seeds: list[tuple[int, int]] = []           # (distance, lane), in running order
        x = p.width
        while x < p.stage - 1:
            lane = 1 + draws.below(lanes)
            cells[lane][x] = SEED
            self.seeds.append((x, lane))
            x += max(1, p.spacing - 2 + draws.below(5))
        if self.level >= p.mines_from:
            for _ in range(p.mines * p.stage // 100):
                x, lane = p.width + draws.below(p.stage - p.width - 1), 1 + draws.below(lanes)
                if cells[lane][x] == EMPTY:
                    cells[lane][x] = MINE
        self.course = Course(cells, p.width, backward=True)
        self.d, self.lane = p.width - 1 - p.lead, 1 + lanes // 2
        self.passed = 0
        self._respawn()
        if self.level > 1:
            self.say(f"Level {self.level}!")

    def _respawn(self) -> None:
        self.course.follow(self.d, self.params.lead)
        self.trucks: list[Body] = []
        self.falling: list[Body] = []
        self.misses = 0
        self._coyote_back(0)

    def _coyote_back(self, out: int) -> None:
        """The Coyote re-enters at the view's trailing edge after ``out`` turns."""
        self.cd, self.cl, self.out = self.course.left, self.lane, self.tick + out

    def _play(self, action: int) -> None:
        p, course = self.params, self.course
        dl, dd = MOVES[action]
        lane, d = self.lane + dl, self.d + dd
        if 1 <= lane <= p.height - 2 and 0 <= d:
            self.lane, self.d = lane, d
        if self.d >= p.stage - 1:
            return self._next_level()
        course.follow(self.d, p.lead)
        if course.get(self.lane, self.d) == SEED:
            course.put(self.lane, self.d, EMPTY)
            self.misses = 0
            self.score.gain()
            if self.done:
                return
        if self._pass_seeds() or self._caught():
            return
        if self.trucks or self.draws.random() < p.trucks:
            if self._drive():
                return
        if self.level >= p.rocks_from and (self.falling or self.draws.random() < p.rocks):
            if self._rocks():
                return
        if self.tick >= self.out:
            self._chase()

    def _pass_seeds(self) -> bool:
        seeds, course = self.seeds, self.course
        while self.passed < len(seeds) and seeds[self.passed][0] < self.d:
            x, lane = seeds[self.passed]
            self.passed += 1
            if course.get(lane, x) == SEED:
                self.misses += 1
                if self.misses >= self.params.faint:
                    return self.lost("You missed too many seeds and fainted!")
        return False

    def _caught(self) -> bool:
        if self.tick >= self.out and self.cd == self.d and self.cl == self.lane:
            return self.lost("The Coyote caught you!")
        return False

    def _knocked(self, why: str) -> None:
        self.say(why)
        self._coyote_back(self.params.daze)
        self.score.gain()

    def _chase(self) -> None:
        draws, course = self.draws, self.course
        if draws.random() < self.params.pace:
            if self.cd != self.d:
                self.cd += 1 if self.d > self.cd else -1
            if self.cl != self.lane and (self.cd == self.d or draws.random() < 0.5):
                self.cl += 1 if self.lane > self.cl else -1
        self.cd = max(self.cd, course.left)            # he never falls out of sight
        if course.get(self.cl, self.cd) == MINE:
            course.put(self.cl, self.cd, EMPTY)
            return self._knocked("The Coyote stepped on his own mine!")
        self._caught()

    def _drive(self) -> bool:
        course, p = self.course, self.params
        if not self.trucks or self.draws.random() < p.trucks:
            self.trucks.append(Body(1 + self.draws.below(p.height - 2), course.left + p.width - 1))
        kept = []
        for t in self.trucks:
            hit = t.r == self.lane and self.d in (t.c, t.c - 1)   # (it may pass through you)
            t.c -= 1
            if hit:
                self.trucks = []
                return self.lost("A truck ran you over!")
            if self.tick >= self.out and t.r == self.cl and self.cd in (t.c, t.c + 1):
                self._knocked("A truck flattened the Coyote!")
            if t.c >= course.left:
                kept.append(t)
        self.trucks = kept
        return self.done

    def _rocks(self) -> bool:
        p, course = self.params, self.course
        if not self.falling or self.draws.random() < p.rocks:   # a new shadow in the view ahead
            ahead = self.d + 1 + self.draws.below(max(1, course.left + p.width - 1 - self.d))
            self.falling.append(Body(1 + self.draws.below(p.height - 2), ahead, data=self.tick + p.warn))
        kept = []
        for rock in self.falling:
            if rock.data > self.tick:
                kept.append(rock)
            elif rock.r == self.lane and rock.c == self.d:
                self.falling = []
                return self.lost("A rock fell on you!")
            elif self.tick >= self.out and rock.r == self.cl and rock.c == self.cd:
                self._knocked("A rock fell on the Coyote!")
        self.falling = kept
        return self.done

    def _movers(self):
        return (self.trucks, TRUCK), (self.falling, SHADOW)

    def _marks(self):
        me = (self.lane, self.d, RUNNER)
        return ((self.cl, self.cd, COYOTE), me) if self.tick >= self.out else (me,)

    def note_key(self):
        return self.level, self.d, self.misses

    def note_text(self) -> str:
        p = self.params
        return f"Level {self.level} | Road {self.d}/{p.stage} | Missed {self.misses}/{p.faint}"


register_atari(RoadRunner, "roadrunner", lives=3, goal=50, unit=100.0, max_turns=10000)
