"""Boxing, seen from above: you and a scripted boxer in a ring. A punch lands when the other
boxer stands right beside you on your row, and knocks them back a column; after a punch a boxer
must wait ``cooldown`` turns to punch again. The opponent steps toward you with a probability
and, once beside you and ready, punches with another. Pattern C: first to land ``goal``
punches (the Atari preset: the hundred-punch knockout)."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param
from .duel import clamp, pursue
from .engine import EMPTY, ArcadeParams, ArcadeTask, register_arcade

YOU, CPU = "Y", "X"
ACTIONS = ActionSet([("NOOP", "stand your ground"), ("UP", "step one row up"), ("DOWN", "step one row down"),
                     ("LEFT", "step one column left"), ("RIGHT", "step one column right"),
                     ("PUNCH", "punch the boxer beside you on your row")], noop="NOOP")
MOVES = ((0, 0), (-1, 0), (1, 0), (0, -1), (0, 1), (0, 0))
PUNCH = 5
WAIT_TEXT: dict[int, str] = {}             # the HUD's punch countdown, by turns left


@dataclass(frozen=True)
class BoxingParams(ArcadeParams):
    width: int = param(12, 5, 60)
    height: int = param(8, 3, 40)
    goal: int = param(5, 1, 200)
    unit: float = param(0.2, 0, 10)
    cooldown: int = param(2, 1, 10)       # turns from one punch to the next
    chance: float = param(0.7, 0, 1)      # the opponent steps toward you this often
    jab: float = param(0.5, 0, 1)         # beside you and ready, it punches this often


class Boxing(ArcadeTask):
    title = "Boxing"
    rules = ("A {width}x{height} ring seen from above. You (Y) and the opponent (X) move a cell a "
             "turn. A punch lands when the other boxer is right beside you on your row (one column "
             "away) and knocks them back a column; after punching, a boxer waits {cooldown} turns "
             "before the next punch. The opponent steps toward you with chance {chance} a turn and, "
             "beside you and ready, punches with chance {jab}.")
    rewards = "+{unit} for each punch you land, -{unit} for each punch you take."
    ends = "when either boxer has landed {goal} punches"
    ACTIONS = ACTIONS
    Params = BoxingParams
    pattern = "C"
    glyphs = {EMPTY: "ring", YOU: "you", CPU: "opponent"}

    def _setup(self, rng) -> None:
        self.start(rng)
        p = self.params
        mid = p.height // 2
        self.me, self.cpu = [mid, p.width - 3], [mid - 1 + self.draws.below(2), 2]
        self.ready = {"you": 0, "cpu": 0}           # the tick each boxer may punch again

    def _move(self, who: list, other: list, dr: int, dc: int) -> None:
        if not dr and not dc:                      # (a boxer is always in the ring)
            return
        p = self.params
        r, c = clamp(who[0] + dr, 0, p.height - 1), clamp(who[1] + dc, 0, p.width - 1)
        if r != other[0] or c != other[1]:
            who[0], who[1] = r, c

    def _punch(self, side: str, who: list, other: list) -> bool:
        """Throw a punch if ready; True when it lands (the other is knocked back)."""
        if self.tick < self.ready[side]:
            return False
        self.ready[side] = self.tick + self.params.cooldown
        if who[0] != other[0] or abs(who[1] - other[1]) != 1:
            return False
        back = other[1] + (other[1] - who[1])
        other[1] = clamp(back, 0, self.params.width - 1)
        mine = side == "you"
        self.say("You land a punch." if mine else "The opponent lands a punch.")
        self.score.point(mine)
        return True

    def _play(self, action: int) -> None:
        p, me, cpu = self.params, self.me, self.cpu
        if action == PUNCH:
            self._punch("you", me, cpu)
        else:
            self._move(me, cpu, *MOVES[action])
        if self.done:
            return
        lined = cpu[0] == me[0] and abs(cpu[1] - me[1]) == 1
        if lined:
            if self.tick >= self.ready["cpu"] and self.draws.random() < p.jab:
                self._punch("cpu", cpu, me)
            return
        side = 1 if cpu[1] > me[1] else -1           # it squares up beside you, on your row
        self._move(cpu, me, *pursue(cpu[0], cpu[1], me[0], me[1] + side, p.chance, self.draws))

    def _sprites(self):
        return ((self.cpu[0], self.cpu[1], CPU), (self.me[0], self.me[1], YOU))

    def _extra_hud(self) -> str:
        wait = self.ready["you"] - self.tick
        if wait <= 0:
            return "Punch ready"
        text = WAIT_TEXT.get(wait)
        if text is None:
            text = WAIT_TEXT[wait] = f"Punch in {wait}"
        return text


register_arcade(Boxing, "boxing",
                mini=dict(max_turns=200),
                atari=dict(width=20, height=20, goal=100, unit=1.0, max_turns=10000))
