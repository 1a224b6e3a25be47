"""Double Dunk, one on one on a half court: the hoop at the top, the check spot at the bottom.
The side with the ball drives and shoots; a shot goes in with a chance that falls with the
distance to the hoop (halved when a defender stands beside the shooter), and possession changes
after every shot, made or missed, with a check at the bottom. A defender beside the carrier can
steal the ball. The scripted player drives at the hoop and shoots close in, or shadows you
between you and the hoop, each step with a probability. Pattern C: first to ``goal`` points
(Atari preset: two points inside the arc, three beyond it)."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param
from .duel import Possession, clamp, pursue
from .engine import EMPTY, ArcadeParams, ArcadeTask, register_arcade

HOOP, BALL, YOU, CPU = "U", "o", "Y", "X"
ACTIONS = ActionSet([("NOOP", "stand still"), ("UP", "step one row toward the hoop"), ("DOWN", "step one row away"),
                     ("LEFT", "step one column left"), ("RIGHT", "step one column right"),
                     ("SHOOT", "shoot with the ball; on defence, swipe at the ball beside you")], noop="NOOP")
MOVES = ((0, 0), (-1, 0), (1, 0), (0, -1), (0, 1), (0, 0))
SHOOT = 5
MAKES = (0.7, 0.45, 0.2)               # close, mid, long
CLOSE, MID = 2, 5                      # the close and mid ranges (cells from the hoop)


@dataclass(frozen=True)
class DunkParams(ArcadeParams):
    width: int = param(14, 8, 60)
    height: int = param(10, 6, 40)
    goal: int = param(4, 1, 100)
    unit: float = param(0.25, 0, 10)
    inside: int = param(1, 1, 3)          # points for a basket within the arc
    outside: int = param(1, 1, 4)         # points for a basket beyond it
    arc: int = param(5, 1, 30)            # the arc's distance from the hoop
    chance: float = param(0.7, 0, 1)      # the opponent steps this often
    steal: float = param(0.2, 0, 1)       # a swipe beside the carrier takes the ball this often


def distance(a: list, b: tuple) -> int:
    return max(abs(a[0] - b[0]), abs(a[1] - b[1]))


class DoubleDunk(ArcadeTask):
    title = "Double Dunk"
    rules = ("A {width}x{height} half court; the hoop (U) is at the top middle. The side with the "
             "ball (o, carried just above its player) drives; SHOOT scores with chance {close} within "
             "{near} cells of the hoop, {mid} within {midrange}, {far} beyond (halved with a defender beside the "
             "shooter); a basket is worth {inside} within {arc} cells, {outside} beyond. Made or "
             "missed, the other side then checks the ball at the bottom. On defence, SHOOT beside the "
             "carrier steals with chance {steal}. The opponent (X) steps with chance {chance} a turn, "
             "driving at the hoop or staying between you and it, and swipes beside you likewise.")
    rewards = "+{unit} for each point you score, -{unit} for each point the opponent scores."
    ends = "when either side reaches {goal} points"
    ACTIONS = ACTIONS
    Params = DunkParams
    pattern = "C"
    glyphs = {EMPTY: "court", HOOP: "hoop", BALL: "ball", YOU: "you", CPU: "opponent"}

    def prompt_fields(self) -> dict:
        return {**super().prompt_fields(), "close": MAKES[0], "mid": MAKES[1], "far": MAKES[2], "near": CLOSE,
                "midrange": MID}

    def _still(self) -> list[str]:
        p = self.params
        rows = [EMPTY * p.width] * p.height
        rows[0] = EMPTY * (p.width // 2) + HOOP + EMPTY * (p.width - p.width // 2 - 1)
        return rows

    def _setup(self, rng) -> None:
        self.start(rng)
        self.hoop = (0, self.params.width // 2)
        self.has = Possession("you" if rng.random() < 0.5 else "cpu")
        self._check()

    def _check(self) -> None:
        """The side with the ball checks it at the bottom; the defender stands above it."""
        p = self.params
        mid = p.width // 2
        off, dfn = [p.height - 1, mid], [p.height - 3, mid]
        self.me, self.cpu = (off, dfn) if self.has.mine() else (dfn, off)

    def _step(self, who: list, other: list, dr: int, dc: int) -> None:
        if not dr and not dc:                      # (a player is always on the court)
            return
        p = self.params
        r, c = clamp(who[0] + dr, 1, p.height - 1), clamp(who[1] + dc, 0, p.width - 1)
        if r != other[0] or c != other[1]:
            who[0], who[1] = r, c

    def _shoot(self, side: str, who: list, other: list) -> None:
        p, d = self.params, distance(who, self.hoop)
        make = MAKES[0 if d <= CLOSE else 1 if d <= MID else 2] / (2 if distance(who, tuple(other)) == 1 else 1)
        mine = side == "you"
        if self.draws.random() < make:
            pts = p.inside if d <= p.arc else p.outside
            self.say(f"{'You score' if mine else 'The opponent scores'} {pts}.")
            for _ in range(pts):
                if not self.done:
                    self.score.point(mine)
        else:
            self.say("You miss." if mine else "The opponent misses.")
        self.has.flip()
        self._check()

    def _swipe(self, thief: str) -> bool:
        if distance(self.me, tuple(self.cpu)) == 1 and self.draws.random() < self.params.steal:
            self.has.give(thief)
            self.say("You steal the ball." if thief == "you" else "The opponent steals the ball.")
            return True
        return False

    def _play(self, action: int) -> None:
        p, me, cpu = self.params, self.me, self.cpu
        if action == SHOOT:
            if self.has.holder == "you":
                self._shoot("you", me, cpu)
                return
            if self._swipe("you"):
                return
        else:
            self._step(me, cpu, *MOVES[action])
        if self.draws.random() >= p.chance:
            return
        if self.has.holder == "you":
            if not self._swipe("cpu"):
                guard = (me[0] - 1, me[1]) if me[0] > 1 else (me[0], me[1] + (1 if cpu[1] > me[1] else -1))
                self._step(cpu, me, *pursue(cpu[0], cpu[1], *guard, 1.0, self.draws))
        elif distance(cpu, self.hoop) <= CLOSE:
            self._shoot("cpu", cpu, me)
        else:
            dr, dc = pursue(cpu[0], cpu[1], 1, self.hoop[1], 1.0, self.draws)
            if [cpu[0] + dr, cpu[1] + dc] == me:          # blocked: go round
                dr, dc = 0, (1 if cpu[1] >= me[1] else -1)
            self._step(cpu, me, dr, dc)

    def _sprites(self):
        carrier = self.me if self.has.holder == "you" else self.cpu
        return ((carrier[0] - 1, carrier[1], BALL), (self.cpu[0], self.cpu[1], CPU), (self.me[0], self.me[1], YOU))


register_arcade(DoubleDunk, "doubledunk",
                mini=dict(max_turns=250),
                atari=dict(width=20, height=16, goal=24, unit=1.0, inside=2, outside=3, arc=6, max_turns=10000))
