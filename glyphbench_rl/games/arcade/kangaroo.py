"""Kangaroo: a mother kangaroo climbs floors joined by ladders (one a floor, on alternate sides)
to reach her joey at the top while coconuts drop from the sky, falling straight down through
everything. FIRE punches the cell you face and the cell above you, breaking a coconut or knocking
out a monkey there. Mini preset: each new floor scores, the top one wins. Atari preset: fruit on
the floors scores, reaching the top rescues the joey (scores, and the climb starts again) and
monkeys pace the floors (pattern D)."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param, require
from .chase import COMPASS, STEPS
from .engine import EMPTY, ArcadeParams, ArcadeTask, register_arcade
from .hopping import Ladders

FLOOR, LADDER, YOU, NUT, FRUIT, MONKEY, JOEY = "=", "H", "K", "o", "%", "M", "J"
ACTIONS = ActionSet(COMPASS + [("FIRE", "punch the cell you face and the cell above you")], noop="NOOP")
FIRE = 5


@dataclass(frozen=True)
class KangarooParams(ArcadeParams):
    width: int = param(12, 6, 60)
    height: int = param(12, 6, 60)
    goal: int = param(3, 1, 1000)
    unit: float = param(1 / 3, 0, 10)
    floors: int = param(4, 2, 12)
    gap: int = param(3, 2, 8)           # rows from one floor to the next
    drop: int = param(4, 1, 50)         # a coconut drops every this many turns
    aim: float = param(0.5, 0, 1)       # chance a coconut drops right above you
    floors_pay: bool = param(True)      # each new floor of a climb scores (else fruit and rescues do)
    fruit: int = param(0, 0, 20)        # fruit per climb
    monkeys: int = param(0, 0, 12)
    pace: int = param(2, 1, 8)          # a monkey steps every this many turns

    def check(self) -> None:
        require(self.gap * (self.floors - 1) + 2 <= self.height, "height", "room for the floors", self.height)


class Kangaroo(ArcadeTask):
    title = "Kangaroo"
    rules = ("A {width}x{height} building of {floors} floors (=), {gap} rows apart, joined by "
             "ladders (H), one from each floor to the next. You (K) walk along a floor, and climb "
             "with UP and DOWN on a ladder. Every {drop} turns a coconut (o) drops from the top row, "
             "right above you with chance {aim} (else anywhere), and falls a row a turn through everything. FIRE "
             "punches the cell you face and the cell above you, breaking a coconut there. A coconut "
             "that hits you costs a life; you have {lives_text}.{goal_text}")
    rewards = "{pay_text}; -1 when your last life is lost."
    ends = "when you have scored {goal} times, or you lose your last life"
    ACTIONS = ACTIONS
    Params = KangarooParams
    pattern = "D"
    glyphs = {EMPTY: "air", FLOOR: "floor", LADDER: "ladder", YOU: "you", NUT: "coconut",
              FRUIT: "fruit", MONKEY: "monkey", JOEY: "your joey"}

    def prompt_fields(self) -> dict:
        p = self.params
        if p.floors_pay:
            goal, pay = " Each floor you reach for the first time scores.", f"+{round(p.unit, 4)} for each new floor"
        else:
            goal = (f" {p.fruit} fruit (%) lie on the floors and {p.monkeys} monkeys (M) pace them; "
                    "touching a monkey costs a life and a punch knocks one out. Reaching the top floor, "
                    "where your joey (J) waits, rescues it and the climb starts again with new fruit.")
            pay = f"+{round(p.unit, 4)} for each fruit and for each rescue"
        return {**super().prompt_fields(), "goal_text": goal, "pay_text": pay}

    def _setup(self, rng) -> None:
        p = self.params
        stand = [p.height - 2 - p.gap * j for j in range(p.floors)]
        third = max(1, p.width // 3)
        cols = [[int(rng.integers(1, third + 1)) if j % 2 == 0 else int(rng.integers(p.width - 1 - third, p.width - 1))]
                for j in range(p.floors - 1)]
        self.ladders = Ladders(stand, cols)
        self.start(rng)
        self.face, self.nuts = 1, []
        self._climb()

    def _still(self) -> list[str]:
        p, lad = self.params, self.ladders
        rows = [EMPTY * p.width] * p.height
        for s in lad.floors:
            rows[s + 1] = FLOOR * p.width
        rows = [list(row) for row in rows]
        for r, c in lad.cells:
            rows[r][c] = LADDER
        return ["".join(row) for row in rows]

    def _climb(self) -> None:
        """Start a climb: you at the bottom, fresh fruit and monkeys."""
        p, lad = self.params, self.ladders
        self.r, self.c, self.best = lad.floors[0], 0, 0
        self.fruit = {(lad.floors[1 + self.draws.below(p.floors - 1)], 1 + self.draws.below(p.width - 2))
                      for _ in range(p.fruit)}
        self.monkeys = [[lad.floors[1 + k % (p.floors - 1)], p.width - 1, -1] for k in range(p.monkeys)]

    def _respawn(self) -> None:
        self.nuts = []
        self.r, self.c = self.ladders.floors[0], 0

    def _hit(self) -> bool:
        here = (self.r, self.c)
        if here in self.nuts or (self.monkeys and any((m[0], m[1]) == here for m in self.monkeys)):
            self.nuts = [n for n in self.nuts if n != here]
            return self.lose_life("Ouch!")
        return False

    def _move(self, action: int) -> None:
        p, lad = self.params, self.ladders
        if action == FIRE:
            hits = {(self.r, self.c + self.face), (self.r - 1, self.c)}
            self.nuts = [n for n in self.nuts if n not in hits]
            self.monkeys = [m for m in self.monkeys if (m[0], m[1]) not in hits]
            return
        dr, dc = STEPS[action]
        levels = lad.levels   # (``floor_of`` looked up without a call: this runs every turn)
        if dc:
            self.face = dc
            if self.r in levels:
                c = self.c + dc
                self.c = 0 if c < 0 else c if c < p.width else p.width - 1
        elif dr and lad.climb(self.r, self.c, dr):
            self.r += dr
        floor = levels.get(self.r)
        if self.fruit and (self.r, self.c) in self.fruit:
            self.fruit.discard((self.r, self.c))
            self.say("Fruit!")
            self.score.gain()
        if floor is not None and floor > self.best:
            self.best = floor
            if p.floors_pay:
                self.score.gain()
            elif floor == p.floors - 1:
                self.say("You rescued your joey!")
                self.score.gain()
                self._climb()

    def _play(self, action: int) -> None:
        p = self.params
        self._move(action)
        if self.done or self._hit():
            return
        self.nuts = [(r + 1, c) for r, c in self.nuts if r + 1 < p.height]
        if self.tick % p.drop == 0:
            self.nuts.append((0, self.c if self.draws.random() < p.aim else self.draws.below(p.width)))
        if self.tick % p.pace == 0:
            for m in self.monkeys:
                if not 0 <= m[1] + m[2] < p.width:
                    m[2] = -m[2]
                m[1] += m[2]
        self._hit()

    def _sprites(self):
        out = [(r, c, FRUIT) for r, c in self.fruit]
        if not self.params.floors_pay:
            out.append((self.ladders.floors[-1], self.params.width - 1, JOEY))
        out += [(m[0], m[1], MONKEY) for m in self.monkeys]
        out += [(r, c, NUT) for r, c in self.nuts]
        out.append((self.r, self.c, YOU))
        return out

    def _grid(self) -> list[str]:
        """``_sprites()`` drawn straight from the positions (all inside the building), each row
        remembered (``_draw``)."""
        rows = self.still[:]
        self._grids += 1
        drawn = self._drawn
        for r, c in self.fruit:
            key = (rows[r], c, FRUIT)
            rows[r] = drawn.get(key) or self._draw(key)
        if not self.params.floors_pay:
            r = self.ladders.floors[-1]
            rows[r] = rows[r][:-1] + JOEY
        for r, c, _ in self.monkeys:
            key = (rows[r], c, MONKEY)
            rows[r] = drawn.get(key) or self._draw(key)
        for r, c in self.nuts:
            key = (rows[r], c, NUT)
            rows[r] = drawn.get(key) or self._draw(key)
        r = self.r
        key = (rows[r], self.c, YOU)
        rows[r] = drawn.get(key) or self._draw(key)
        return rows


register_arcade(Kangaroo, "kangaroo",
                mini=dict(max_turns=300),
                atari=dict(width=20, height=20, floors=4, gap=4, drop=5, goal=20, unit=1.0, lives=3,
                           floors_pay=False, fruit=3, monkeys=2, pace=2, max_turns=1000))
