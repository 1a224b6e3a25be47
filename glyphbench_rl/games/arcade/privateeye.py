"""Private Eye: detective Pierre Touche drives his car along a city street longer than the screen,
lined with lettered buildings. Kept from the original: each case's stolen item hidden in one of
the buildings (EXAMINE at a building; where it is hidden, it pops out of a ground-floor window for
a few turns and you jump to catch it), the item returned to the building it belongs to, then the
criminal, Le Fiend, showing at one window after another until you jump into him; a clock per
case; thugs on the street who mug you (a life) unless you jump them; flowerpots thrown from
upper windows that cost clock time; the car's speed (up to two cells a turn, braked with DOWN);
five cases, three lives (pattern D)."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param, require
from .bodies import Body, Countdown
from .engine import EMPTY, ArcadeParams, register_atari
from .sidescroll import Course, Leap, ScrollTask, fall, jump_text, lay

CAR, THUG, POT, ITEM, FIEND, WALL, WINDOW, DOOR, ROOF, KERB = "@", "t", "v", "$", "&", "#", "o", "n", "_", "="
SIGNS = "ABCDEFGHIJKLMNOPQRSTUVWXYZ"
FRONT = ("_?_____", "#o#o#o#", "#o#n#o#")   # a building's three rows (? its letter); windows at 1 and 5
STREET = 4                                   # the row you drive on
ACTIONS = ActionSet([("NOOP", "keep your speed"), ("LEFT", "speed up leftward (or slow a rightward car)"),
                     ("RIGHT", "speed up rightward (or slow a leftward car)"),
                     ("UP", "jump"), ("DOWN", "brake to a stop"),
                     ("EXAMINE", "stop and search the building you are at")], noop="NOOP")
LEFT, RIGHT, UP, DOWN, EXAMINE = range(1, 6)


@dataclass(frozen=True)
class PrivateEyeParams(ArcadeParams):
    width: int = param(30, 16, 60)
    height: int = param(6, 6, 6)           # roofs, windows, ground floor, air, street, kerb
    street: int = param(260, 60, 1000)     # the street's length
    clock: int = param(900, 50, 5000)      # turns per case before it costs a life
    pop: int = param(8, 2, 50)            # turns a found item shows at its window
    hop: int = param(12, 2, 50)            # turns Le Fiend stays at one window
    thugs: float = param(0.06, 0, 1)       # chance a thug comes along each turn
    pots: float = param(0.05, 0, 1)        # chance a flowerpot is thrown each turn
    penalty: int = param(40, 0, 500)       # clock turns a flowerpot costs
    speed: int = param(2, 1, 5)            # the car's top speed (cells a turn)

    def check(self) -> None:
        require(self.street >= self.width + 20, "street", "be longer than the view", self.street)


class PrivateEye(ScrollTask):
    title = "Private Eye"
    rules = ("You are detective Pierre Touche in your car (@) on a street {street} columns long "
             "(the view, {width} columns, follows you), with {lives_text}. Each building has its "
             "letter on the roof. A case: (1) find the stolen item: stop under a building and "
             "EXAMINE it; where the item hides it shows ($) at a ground-floor window for {pop} "
             "turns: jump (UP: {jump_text}) into it. (2) EXAMINE the building the HUD names to "
             "return it. (3) Le Fiend (&) then shows at windows near you, {hop} turns at each: "
             "jump into him to close the case. Each case has a {clock}-turn clock; when it runs "
             "out you lose a life and it restarts. Thugs (t) on the street mug you (a life) "
             "unless you jump them; a flowerpot (v) from a window costs {penalty} turns of clock. "
             "LEFT/RIGHT change your speed by one (at most {speed} cells a turn), NOOP keeps it, "
             "DOWN stops.")
    rewards = "+{unit} for each case closed; {death} when the game is lost."
    ends = "when {goal} cases are closed or the game is lost"
    ACTIONS = ACTIONS
    Params = PrivateEyeParams
    pattern = "D"
    glyphs = {EMPTY: "air", KERB: "kerb", ROOF: "roof", WALL: "wall", WINDOW: "window", DOOR: "door",
              **{s: f"building {s}'s sign" for s in SIGNS}, ITEM: "stolen item", FIEND: "Le Fiend",
              THUG: "thug", POT: "flowerpot", CAR: "you"}

    def prompt_fields(self) -> dict:
        return {**super().prompt_fields(), "jump_text": jump_text()}

    def _setup(self, rng) -> None:
        self.start(rng)
        p, draws = self.params, self.draws
        cells = lay([EMPTY] * (STREET + 1) + [KERB], p.street)
        self.fronts: list[int] = []                      # each building's first column
        x = 3 + draws.below(4)
        while x + 7 < p.street and len(self.fronts) < len(SIGNS):
            for r, row in enumerate(FRONT):
                cells[r][x:x + 7] = row.replace("?", SIGNS[len(self.fronts)])
            self.fronts.append(x)
            x += 9 + draws.below(4)
        self.course = Course(cells, p.width)
        self.x, self.v, self.case, self.leap = p.width // 2, 0, 0, Leap()
        self.clock = Countdown(p.clock)
        self._next_case()

    def _next_case(self) -> None:
        n = len(self.fronts)
        self.case += 1
        self.hide = self.draws.below(n)
        self.home = (self.hide + 1 + self.draws.below(n - 1)) % n
        self.phase, self.searched, self.shown = "find", "", None   # shown: (column, until tick)
        self.clock.refill()
        self._respawn()

    def _respawn(self) -> None:
        self.thugs: list[Body] = []
        self.pots: list[Body] = []
        self.v, self.row = 0, STREET
        self.leap.land()

    def _building(self) -> int:
        """The building whose front spans your column, or -1."""
        for i, b in enumerate(self.fronts):
            if b <= self.x < b + 7:
                return i
        return -1

    def _play(self, action: int) -> None:
        p, x0 = self.params, self.x
        lift = self.leap.lift(self.tick)
        if action == LEFT:
            self.v = max(-p.speed, self.v - 1)
        elif action == RIGHT:
            self.v = min(p.speed, self.v + 1)
        elif action == DOWN:
            self.v = 0
        elif action == UP:
            self.leap.start(self.tick)
        elif action == EXAMINE and not lift:
            self.v = 0
            self._examine()
        self.x = min(p.street - 1, max(0, self.x + self.v))
        if self.x in (0, p.street - 1):
            self.v = 0
        self.course.follow(self.x, p.width // 2)
        self.row = row = STREET - self.leap.lift(self.tick)
        if self.shown and self.shown[0] == self.x and row == 2:
            self._catch()
            if self.done:
                return
        if self.clock.tick():
            self.clock.refill()
            self.lost("Time ran out on the case!")
            return
        self._street(x0, row)

    def _examine(self) -> None:
        b = self._building()
        if b < 0:
            return self.say("There is no building here.")
        if self.phase == "find":
            if b == self.hide:
                front = self.fronts[b]
                self.shown = (front + 1 if self.x < front + 3 else front + 5, self.tick + self.params.pop)
                return self.say("Something shows at a window!")
            if SIGNS[b] not in self.searched:
                self.searched += SIGNS[b]
            self.say("Nothing here.")
        elif self.phase == "return" and b == self.home:
            self.phase = "catch"
            self.say("The item is back where it belongs. Now catch Le Fiend!")
            self._fiend_hops()

    def _catch(self) -> None:
        if self.phase == "find":
            self.phase, self.shown = "return", None
            self.say(f"You have the item: bring it to building {SIGNS[self.home]}.")
        else:
            self.say("You caught Le Fiend! Case closed.")
            self.score.gain()
            if not self.done:
                self._next_case()

    def _fiend_hops(self) -> None:
        """Le Fiend moves to a window of a building in view."""
        self.course.follow(self.x, self.params.width // 2)
        left = self.course.left
        near = [b for b in self.fronts if left <= b and b + 6 < left + self.params.width] or self.fronts
        b = near[self.draws.below(len(near))]
        self.shown = (b + (1 if self.draws.random() < 0.5 else 5), self.tick + self.params.hop)

    def _street(self, x0: int, row: int) -> None:
        p, draws, x, course = self.params, self.draws, self.x, self.course
        if self.shown and self.tick >= self.shown[1]:
            if self.phase == "catch":
                self._fiend_hops()
            else:
                self.shown = None
        if draws.random() < p.thugs:
            side = 1 if draws.random() < 0.5 else -1
            c = course.left + (p.width - 1 if side > 0 else 0)
            if abs(c - x) > 3:
                self.thugs.append(Body(STREET, c, dc=-side))
        lo, hi = min(x0, x), max(x0, x)
        kept = []
        for t in self.thugs:
            if self.tick % 2 == 0:
                t.c += t.dc
            if row == STREET and lo <= t.c <= hi:
                self.thugs = []
                self.lost("You were mugged!")
                return
            if course.seen(t.c):
                kept.append(t)
        self.thugs = kept
        if draws.random() < p.pots:
            c = x + self.v * 2 + draws.below(5) - 2
            if course.get(1, c) == WINDOW:
                self.pots.append(Body(1, c))
        if fall(self.pots, row, x, STREET + 1)[0]:
            self.say("A flowerpot hit you!")
            self.clock.tick(p.penalty)

    def _movers(self):
        return (self.thugs, THUG), (self.pots, POT)

    def _marks(self):
        me = (self.row, self.x, CAR)
        return ((2, self.shown[0], ITEM if self.phase == "find" else FIEND), me) if self.shown else (me,)

    def note_key(self):
        return self.clock.left, self.x, self.phase, self.searched

    def note_text(self) -> str:
        p, phase = self.params, self.phase
        task = ("Catch Le Fiend" if phase == "catch" else
                f"Find the item (searched: {self.searched or 'none'})" if phase == "find" else
                f"Return the item to {SIGNS[self.home]} at {self.fronts[self.home]}")
        return f"Case {self.case}/{p.goal} | Clock {self.clock.left} | Street {self.x}/{p.street} | {task}"


register_atari(PrivateEye, "privateeye", lives=3, goal=5, unit=1000.0, max_turns=10000)
