"""Duel engine for the paddle/ball and sports family (breakout, tennis, icehockey, doubledunk,
boxing, fishingderby, surround, bowling): integer ball physics, serves, possession, a score of
games over points, and scripted opponents that close in with a probability::

    ball = Ball(5, 8, dr=1, dc=-1)
    side = ball.advance(top=1, bottom=h - 2, left=0, right=w - 1)   # walls reflect; "" or an edge
    ball.dc = deflect(col - paddle_left, paddle_width)               # -1, 0 or +1 by the third hit
    serve(ball, r, c, toward=-1, draws=self.draws)                   # centre spot, a random slant
    dr, dc = pursue(r, c, tr, tc, chance, self.draws)                # one step toward a target
    match = Match(points_per_game=2, lead=1)                         # tennis points into games

The score pair itself (first to W, +-unit) is the core's ``Duel`` (pattern C); ``Possession``
says who holds the ball and flips it after a score or a shot.
"""

from __future__ import annotations

from .bodies import Body


class Ball(Body):
    """A ball with an integer velocity that reflects off walls."""
    __slots__ = ()

    def advance(self, top: int, bottom: int, left: int, right: int, walls: str = "tblr") -> str:
        """Move one step; a wall named in ``walls`` (t, b, l, r) reflects the ball back inside;
        a crossed edge not in ``walls`` is returned ("t", "b", "l" or "r"; "" if none) with the
        ball left on the edge cell."""
        r, c = self.r + self.dr, self.c + self.dc
        out = ""
        if r < top:
            if "t" in walls:
                self.dr, r = -self.dr, 2 * top - r
            else:
                out, r = "t", top
        elif r > bottom:
            if "b" in walls:
                self.dr, r = -self.dr, 2 * bottom - r
            else:
                out, r = "b", bottom
        if c < left:
            if "l" in walls:
                self.dc, c = -self.dc, 2 * left - c
            else:
                out, c = out or "l", left
        elif c > right:
            if "r" in walls:
                self.dc, c = -self.dc, 2 * right - c
            else:
                out, c = out or "r", right
        self.r, self.c = r, c
        return out


def deflect(offset: int, size: int) -> int:
    """The cross velocity off a paddle ``size`` cells long struck ``offset`` cells from its
    start: -1 in the first third, 0 in the middle, +1 in the last (a one-cell paddle: 0)."""
    if size <= 1:
        return 0
    return offset * 3 // size - 1


def serve(ball: Body, r: int, c: int, toward: int, draws, rows: bool = False) -> None:
    """Put the ball on (r, c) moving ``toward`` (+1/-1) along columns (or rows when ``rows``),
    slanting -1, 0 or +1 on the other axis at random."""
    slant = draws.below(3) - 1
    ball.r, ball.c = r, c
    ball.dr, ball.dc = (toward, slant) if rows else (slant, toward)


def pursue(r: int, c: int, tr: int, tc: int, chance: float, draws) -> tuple[int, int]:
    """A scripted opponent's step: with probability ``chance`` one cell toward (tr, tc) along
    the longer axis (rows on a tie), else stay."""
    if (r == tr and c == tc) or draws.random() >= chance:
        return 0, 0
    dr, dc = tr - r, tc - c
    if abs(dr) >= abs(dc):
        return (1 if dr > 0 else -1), 0
    return 0, (1 if dc > 0 else -1)


_VELOCITY: dict[tuple[int, int], str] = {}


def velocity_text(ball: Body) -> str:
    """``Ball v +1,-1``: the HUD's note of a ball's velocity, formatted once per velocity (a
    signed format costs more than the rest of a HUD)."""
    key = (ball.dr, ball.dc)
    text = _VELOCITY.get(key)
    if text is None:
        text = _VELOCITY[key] = f"Ball v {ball.dr:+d},{ball.dc:+d}"
    return text


def clamp(v: int, lo: int, hi: int) -> int:
    return lo if v < lo else hi if v > hi else v


class Possession:
    """Who holds the ball: ``"you"``, ``"cpu"`` or ``None`` (loose)."""
    __slots__ = ("holder",)

    def __init__(self, holder: str | None = None) -> None:
        self.holder = holder

    def give(self, side: str | None) -> None:
        self.holder = side

    def flip(self) -> str:
        self.holder = "cpu" if self.holder == "you" else "you"
        return self.holder

    def mine(self) -> bool:
        return self.holder == "you"


class Match:
    """Points into games (tennis): a game goes to the first side with ``points`` points and a
    lead of ``lead``; ``point(mine)`` returns True (you), False (them) or None (game goes on)."""
    __slots__ = ("points", "lead", "mine", "theirs")
    CALLS = ("0", "15", "30", "40")

    def __init__(self, points: int, lead: int = 1) -> None:
        self.points, self.lead, self.mine, self.theirs = points, lead, 0, 0

    def point(self, mine: bool) -> bool | None:
        if mine:
            self.mine += 1
        else:
            self.theirs += 1
        a, b = self.mine, self.theirs
        if max(a, b) >= self.points and abs(a - b) >= self.lead:
            self.mine = self.theirs = 0
            return a > b
        return None

    def call(self) -> str:
        """The game's running score, tennis-style where it fits (0/15/30/40), else counts."""
        a, b = self.mine, self.theirs
        if self.points == 4 and max(a, b) <= 3:
            return f"{self.CALLS[a]}-{self.CALLS[b]}"
        return f"{a}-{b}"
