"""Tennis, top down: you hold the bottom half of the court, a scripted player the top half, a
net across the middle. Either player returns a ball that comes onto its row within a column of
it; the ball leaves left, straight or right by which side of the player it met. The side walls
reflect the ball; a ball past a player's baseline is the other side's point. Points make games
(``points`` to win one, by ``lead``); the first to ``goal`` games wins (pattern C, a unit per
game). The serve alternates by game. Atari preset: a bigger court, 15/30/40 calls, deuce, a set."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param
from .duel import Ball, Match, clamp, deflect, pursue, serve
from .engine import EMPTY, ArcadeParams, ArcadeTask, register_arcade

NET, BALL, YOU, CPU = "-", "o", "Y", "X"
ACTIONS = ActionSet([("NOOP", "stand still"), ("UP", "step one row toward the net"),
                     ("DOWN", "step one row toward your baseline"), ("LEFT", "step one column left"),
                     ("RIGHT", "step one column right")], noop="NOOP")
MOVES = ((0, 0), (-1, 0), (1, 0), (0, -1), (0, 1))


@dataclass(frozen=True)
class TennisParams(ArcadeParams):
    width: int = param(18, 8, 60)
    height: int = param(10, 6, 40)
    goal: int = param(3, 1, 20)           # games to win the match
    unit: float = param(1 / 3, 0, 10)
    points: int = param(2, 1, 8)          # points that win a game
    lead: int = param(1, 1, 3)            # by at least this many
    chance: float = param(0.7, 0, 1)      # the opponent steps toward the ball this often


class Tennis(ArcadeTask):
    title = "Tennis"
    rules = ("A {width}x{height} court seen from above with a net (-) across the middle. You (Y) "
             "move in the bottom half, the opponent (X) in the top half; it steps toward the ball "
             "with chance {chance} a turn. The ball (o) moves one row a turn; a player returns it "
             "when it comes onto the player's row within one column, and it leaves left, straight or "
             "right by the side it met. The side walls reflect it. A ball past a baseline is a point "
             "for the other side. {points} points with a lead of {lead} win a game; the serve "
             "alternates each game.")
    rewards = "+{unit} for each game you win, -{unit} for each game the opponent wins."
    ends = "when either side has won {goal} games"
    ACTIONS = ACTIONS
    Params = TennisParams
    pattern = "C"
    glyphs = {EMPTY: "court", NET: "net", BALL: "ball", YOU: "you", CPU: "opponent"}

    def _still(self) -> list[str]:
        p = self.params
        rows = [EMPTY * p.width] * p.height
        rows[p.height // 2] = NET * p.width
        return rows

    def _setup(self, rng) -> None:
        self.start(rng)
        self.match = Match(self.params.points, self.params.lead)
        self.server = "you" if rng.random() < 0.5 else "cpu"
        self.ball = Ball(0, 0)
        self.game_text = None
        self._point()

    def _point(self) -> None:
        """Players back to their baselines; the server's ball leaves from in front of them."""
        p = self.params
        mid = p.width // 2
        self.me, self.cpu = [p.height - 1, mid], [0, mid]
        if self.server == "you":
            serve(self.ball, p.height - 2, mid, -1, self.draws, rows=True)
        else:
            serve(self.ball, 1, mid, 1, self.draws, rows=True)

    def _play(self, action: int) -> None:
        p, b, me, cpu = self.params, self.ball, self.me, self.cpu
        net = p.height // 2
        dr, dc = MOVES[action]
        if dr:
            me[0] = clamp(me[0] + dr, net + 1, p.height - 1)
        if dc:
            me[1] = clamp(me[1] + dc, 0, p.width - 1)
        dr, dc = pursue(0, cpu[1], 0, b.c, p.chance, self.draws)
        cpu[1] += dc
        if self._returned(me, 1) or self._returned(cpu, -1):
            return
        edge = b.advance(0, p.height - 1, 0, p.width - 1, walls="lr")
        if edge:
            self._score(edge == "t")
        elif not self._returned(me, 1):
            self._returned(cpu, -1)

    def _returned(self, who: list, toward: int) -> bool:
        """A ball heading to ``who`` on its row within a column goes back, slanted by the side."""
        b = self.ball
        if b.dr != toward or b.r != who[0] or abs(b.c - who[1]) > 1:
            return False
        b.dr, b.dc = -toward, deflect(b.c - who[1] + 1, 3)
        b.r -= toward
        return True

    def _score(self, mine: bool) -> None:
        self.game_text = None
        self.say("Your point." if mine else "The opponent's point.")
        game = self.match.point(mine)
        if game is not None:
            self.say("You win the game." if game else "The opponent wins the game.")
            self.score.point(game)
            self.server = "cpu" if self.server == "you" else "you"
        if not self.done:
            self._point()

    def _sprites(self):
        return ((self.cpu[0], self.cpu[1], CPU), (self.me[0], self.me[1], YOU), (self.ball.r, self.ball.c, BALL))

    def _extra_hud(self) -> str:
        if self.game_text is None:   # (the game's score and the server change only on a point)
            self.game_text = f"Game {self.match.call()} | Serve {self.server}"
        return self.game_text


register_arcade(Tennis, "tennis",
                mini=dict(max_turns=300),
                atari=dict(width=20, height=24, goal=6, unit=1.0, points=4, lead=2, max_turns=10000))
