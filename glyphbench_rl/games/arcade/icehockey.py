"""Ice Hockey, 1 on 1: the rink's end boards have a goal mouth each; you attack the top one,
a scripted skater the bottom one. The puck is loose or carried: a skater who reaches a loose
puck takes it, a skater next to the carrier can poke it away, and SHOOT sends it straight up
(or down) the rink, slanting toward the mouth. The side boards and the end boards outside the
mouth reflect the puck; a skater in its path stops it. A puck in a mouth is a goal; a face-off
at centre follows. Pattern C, first to ``goal`` goals."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param, require
from .duel import Ball, Possession, clamp, pursue
from .engine import EMPTY, ArcadeParams, ArcadeTask, register_arcade

BOARD, MOUTH, PUCK, YOU, CPU = "=", "_", "*", "Y", "X"
ACTIONS = ActionSet([("NOOP", "glide in place"), ("UP", "skate one row up"), ("DOWN", "skate one row down"),
                     ("LEFT", "skate one column left"), ("RIGHT", "skate one column right"),
                     ("SHOOT", "shoot the puck you carry; next to the carrier, poke it away")], noop="NOOP")
MOVES = ((0, 0), (-1, 0), (1, 0), (0, -1), (0, 1), (0, 0))
SHOOT = 5


@dataclass(frozen=True)
class HockeyParams(ArcadeParams):
    width: int = param(16, 8, 60)
    height: int = param(10, 7, 40)
    goal: int = param(3, 1, 50)
    unit: float = param(1 / 3, 0, 10)
    mouth: int = param(4, 1, 20)           # goal mouth width
    chance: float = param(0.6, 0, 1)       # the opponent skates toward its target this often
    poke: float = param(0.3, 0, 1)         # beside your carrier, it pokes the puck away this often
    reach: int = param(3, 1, 30)           # it shoots from this many rows out

    def check(self) -> None:
        require(self.mouth <= self.width - 2, "mouth", "fit the end boards", self.mouth)


class IceHockey(ArcadeTask):
    title = "Ice Hockey"
    rules = ("A {width}x{height} rink; each end board (=) has a goal mouth (_) {mouth} wide. You (Y) "
             "attack the top mouth, the opponent (X) the bottom one; it skates toward the puck (or "
             "your goal) with chance {chance} a turn and, beside you while you carry the puck, pokes "
             "it away with chance {poke}. Reach the loose puck (*) to carry it. SHOOT sends a carried "
             "puck one row a turn toward the far end, slanting toward the mouth; beside the carrier "
             "SHOOT pokes the puck away. Boards reflect the puck; a skater in its path stops it. A puck "
             "in a mouth is a goal; then a face-off at centre.")
    rewards = "+{unit} for each goal you score, -{unit} for each goal the opponent scores."
    ends = "when either side has {goal} goals"
    ACTIONS = ACTIONS
    Params = HockeyParams
    pattern = "C"
    inside = True    # (skaters and puck stay on the rink)
    glyphs = {EMPTY: "ice", BOARD: "board", MOUTH: "goal mouth", PUCK: "puck", YOU: "you", CPU: "opponent"}

    def _still(self) -> list[str]:
        p = self.params
        left = (p.width - p.mouth) // 2
        end = BOARD * left + MOUTH * p.mouth + BOARD * (p.width - left - p.mouth)
        return [end] + [EMPTY * p.width] * (p.height - 2) + [end]

    def _setup(self, rng) -> None:
        self.start(rng)
        p = self.params
        self.left = (p.width - p.mouth) // 2
        self.puck = Ball(0, 0)
        self.has = Possession()
        self._faceoff()

    def _faceoff(self) -> None:
        p = self.params
        mid = p.height // 2
        self.me, self.cpu = [mid + 1, p.width // 2], [mid - 2, p.width // 2 - 1]
        self.puck.r, self.puck.c, self.puck.dr, self.puck.dc = mid, p.width // 2 - 1 + self.draws.below(2), 0, 0
        self.has.give(None)

    def _skate(self, who: list, other: list, dr: int, dc: int) -> None:
        if not dr and not dc:                              # (a skater is always on the ice)
            return
        p = self.params
        r, c, bottom, right = who[0] + dr, who[1] + dc, p.height - 2, p.width - 1
        r = 1 if r < 1 else bottom if r > bottom else r      # (clamp written out: a call a skate)
        c = 0 if c < 0 else right if c > right else c
        if r == other[0] and c == other[1] and who is self.cpu and dr:   # blocked head-on: it steps around
            r, c = who[0], clamp(who[1] + (1 if who[1] < p.width // 2 else -1), 0, p.width - 1)
        if r != other[0] or c != other[1]:
            who[0], who[1] = r, c

    def _shoot(self, who: list, toward: int) -> None:
        mid = self.left + self.params.mouth // 2
        pk = self.puck
        pk.r, pk.c, pk.dr = who[0] + toward, who[1], toward
        pk.dc = 0 if self.left <= who[1] < self.left + self.params.mouth else (1 if mid > who[1] else -1)
        self.has.give(None)

    def _play(self, action: int) -> None:
        p, pk, me, cpu, has = self.params, self.puck, self.me, self.cpu, self.has
        if action == SHOOT:
            if has.holder == "you":
                self._shoot(me, -1)
            elif has.holder == "cpu" and abs(me[0] - cpu[0]) + abs(me[1] - cpu[1]) == 1:   # beside
                has.give("you")
                self.say("You poke the puck away.")
        else:
            self._skate(me, cpu, *MOVES[action])
        if has.holder == "cpu":
            if cpu[0] >= p.height - 1 - p.reach and self.draws.random() < p.chance:
                self._shoot(cpu, 1)
            else:
                self._skate(cpu, me, *pursue(cpu[0], cpu[1], p.height - 2, self.left + p.mouth // 2, p.chance, self.draws))
        else:
            tr, tc = (me[0], me[1]) if has.holder == "you" else (pk.r, pk.c)
            self._skate(cpu, me, *pursue(cpu[0], cpu[1], tr, tc, p.chance, self.draws))
            if has.holder == "you" and abs(me[0] - cpu[0]) + abs(me[1] - cpu[1]) == 1 and self.draws.random() < p.poke:
                has.give("cpu")
                self.say("The opponent pokes the puck away.")
        if has.holder is None:
            self._glide()
        if has.holder:                      # a carried puck sits just ahead of its carrier
            who, ahead = (me, -1) if has.holder == "you" else (cpu, 1)
            pk.r, pk.c, pk.dr, pk.dc = who[0] + ahead, who[1], 0, 0

    def _glide(self) -> None:
        """A loose puck: taken by a skater on its cell, else one step (boards reflect it)."""
        p, pk = self.params, self.puck
        if self._pickup() or not (pk.dr or pk.dc):
            return
        edge = pk.advance(1, p.height - 2, 0, p.width - 1, walls="lr")
        if edge and self.left <= pk.c < self.left + p.mouth:
            self._goal(edge == "t")
            return
        if edge:
            pk.dr = -pk.dr
        self._pickup()

    def _pickup(self) -> bool:
        pk, me, cpu = self.puck, self.me, self.cpu
        side = ("you" if me[0] == pk.r and me[1] == pk.c else
                "cpu" if cpu[0] == pk.r and cpu[1] == pk.c else None)
        if side is None:
            return False
        self.has.give(side)
        return True

    def _goal(self, mine: bool) -> None:
        self.say("You score!" if mine else "The opponent scores.")
        self.score.point(mine)
        if not self.done:
            self._faceoff()

    def _sprites(self):
        pk = self.puck
        return ((pk.r, pk.c, PUCK), (self.cpu[0], self.cpu[1], CPU), (self.me[0], self.me[1], YOU))


register_arcade(IceHockey, "icehockey",
                mini=dict(max_turns=300),
                atari=dict(width=20, height=24, goal=21, unit=1.0, mouth=6, reach=5, max_turns=10000))
