"""Arena: the free-roam shooter family (alien, berzerk, wizard of wor, battlezone, robotank, time
pilot, asteroids, yars' revenge, seaquest).

A player moves 4 (or 8) ways on a field of walls, facing the way it last moved (its glyph is an
arrow: ``^ v < >``, or ``@`` for 8-way ships), and FIRE sends a shot that way for ``reach``
cells. Foes (``Body`` list ``self.foes``) close in on the dominant axis every ``every`` ticks
(or drift on their own velocity: ``drift``), may fire shells along a row or column every
``volley`` ticks, and a foe that meets the player costs a life. The field may wrap
(``wrap=1``); a countdown (``air``: oxygen or fuel) ends a life when it runs out.

A game subclasses ``ArenaTask`` with a Params derived from ``ArenaParams``, draws its walls in
``_still()`` (``#`` blocks everything; ``SOLID`` is the set), and overrides the hooks it needs:
``_place()`` (the opening foes), ``_hit(foe)`` (a shot struck a foe: scores by default),
``_enter(r, c)`` (the player stepped on a cell: pick-ups, electrified walls), ``_turn()`` (the
game's own per-tick work, after the foes) and ``_respawn()``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from ...core.actions import ActionSet
from ...core.params import param
from .bodies import Body, Countdown, Gun, chase
from .engine import EMPTY, ArcadeParams, ArcadeTask

WALL, SHOT, SHELL, SHIP = "#", "*", "!", "@"
ARROWS = {(-1, 0): "^", (1, 0): "v", (0, -1): "<", (0, 1): ">"}
FOUR = [("NOOP", "wait a turn"), ("UP", "move up a cell (and face up)"),
        ("DOWN", "move down a cell (and face down)"), ("LEFT", "move left a cell (and face left)"),
        ("RIGHT", "move right a cell (and face right)"), ("FIRE", "shoot the way you face")]
ACTIONS4 = ActionSet(FOUR, noop="NOOP")
MOVES4 = (None, (-1, 0), (1, 0), (0, -1), (0, 1), None)
ACTIONS8 = ActionSet(FOUR + [(f"{a}{b}", f"move {a.lower()}-{b.lower()} a cell (and face that way)")
                             for a in ("UP", "DOWN") for b in ("LEFT", "RIGHT")], noop="NOOP")
MOVES8 = MOVES4 + ((-1, -1), (-1, 1), (1, -1), (1, 1))
FIRE = 5


@dataclass(frozen=True)
class ArenaParams(ArcadeParams):
    foes: int = param(4, 0, 40)          # foes on the field at once (at most)
    every: int = param(3, 1, 50)         # ticks per foe step
    reach: int = param(4, 1, 60)         # cells your shot flies
    shot_speed: int = param(2, 1, 4)
    volley: int = param(0, 0, 100)       # ticks between foe shells (0: foes do not shoot)
    wrap: int = param(0, 0, 1)           # 1: the field wraps around at its edges
    air: int = param(0, 0, 10000)        # oxygen or fuel in ticks (0: none)
    hp: int = param(1, 1, 9)             # shots that kill a foe
    reinforce: int = param(0, 0, 500)    # ticks between reinforcements up to ``foes`` (0: on a kill)


class ArenaTask(ArcadeTask):
    Params: ClassVar[type] = ArenaParams
    ACTIONS = ACTIONS4
    MOVES: ClassVar[tuple] = MOVES4
    SOLID: ClassVar[frozenset] = frozenset(WALL)
    FOE: ClassVar[str] = "X"
    arrows: ClassVar[bool] = True         # draw the player as the arrow it faces (else SHIP)
    drift: ClassVar[bool] = False         # foes keep their own velocity instead of chasing

    def prompt_fields(self) -> dict:
        p = self.params
        return {**super().prompt_fields(),
                "volley_text": (f" Every {p.volley} turns a foe in line with you fires a shell "
                                f"({SHELL}) at you; a shell that hits you costs a life.") if p.volley else "",
                "wrap_text": " The field wraps around at its edges." if p.wrap else "",
                "turn_text": " A move into a wall or a foe only turns you to face it."}

    # -- set-up --------------------------------------------------------------------------------------
    def start_arena(self, rng, r: int, c: int) -> None:
        """Call first in ``_setup``: the arcade start, the player at (r, c) facing up, the guns."""
        self.start(rng)
        p = self.params
        self.home = (r, c)
        self.r, self.c, self.face = r, c, (-1, 0)
        self.gun = Gun(cooldown=1, speed=p.shot_speed, reach=p.reach, limit=1)
        self.shells = Gun(cooldown=max(1, p.volley), speed=1, reach=max(p.width, p.height), limit=2)
        self.air = Countdown(p.air) if p.air else None
        self.foes: list[Body] = []
        self.kills = 0

    def free(self, r: int, c: int) -> bool:
        return self.still[r][c] not in self.SOLID and not any(f.r == r and f.c == c for f in self.foes)

    def spot(self, far: int = 4, rows: range | None = None, cols: range | None = None) -> tuple[int, int]:
        """A random free cell at least ``far`` steps (row plus column) from the player."""
        p = self.params
        rows = rows or range(p.height)
        cols = cols or range(p.width)
        for _ in range(200):
            r, c = rows[self.draws.below(len(rows))], cols[self.draws.below(len(cols))]
            if self.free(r, c) and abs(r - self.r) + abs(c - self.c) >= far:
                return r, c
        return next((r, c) for r in rows for c in cols if self.free(r, c) and (r, c) != (self.r, self.c))

    def add_foe(self, r: int, c: int, dr: int = 0, dc: int = 0, glyph: str | None = None, data=None) -> Body:
        foe = Body(r, c, dr, dc, glyph or self.FOE, self.params.hp if data is None else data)
        self.foes.append(foe)
        return foe

    # -- one tick ------------------------------------------------------------------------------------
    def _play(self, action: int) -> None:
        p = self.params
        d = self.MOVES[action]
        if d is not None:
            self.face = d
            r, c = self.r + d[0], self.c + d[1]
            if p.wrap:
                r, c = r % p.height, c % p.width
            if 0 <= r < p.height and 0 <= c < p.width:
                if self._enter(r, c) or self.done:
                    return
                if self.still[r][c] not in self.SOLID and not any(f.r == r and f.c == c for f in self.foes):
                    self.r, self.c = r, c
        if action == FIRE:
            self.gun.fire(self.tick, self.r, self.c, *self.face, SHOT)
        self._shots()
        if self.done:
            return
        if self.tick % p.every == 0 and self._march():
            return
        if p.volley and self._volley():
            return
        if self.air is not None and self.air.tick() and self.lose_life(self.air_out):
            return
        if p.reinforce and self.tick % p.reinforce == 0 and len(self.foes) < p.foes:
            self.stock(one=True)
        self._turn()

    air_out = "You ran out of air."

    def _where(self, r: int, c: int) -> tuple[int, int]:
        p = self.params
        return (r % p.height, c % p.width) if p.wrap else (r, c)

    def _struck(self, r: int, c: int) -> bool:
        p = self.params
        if p.wrap:
            r, c = r % p.height, c % p.width
        elif not (0 <= r < p.height and 0 <= c < p.width):
            return True
        return self.still[r][c] in self.SOLID or any(f.r == r and f.c == c for f in self.foes)

    def _shots(self) -> None:
        if not self.gun.shots:
            return
        for shot, cell in self.gun.advance(self._struck):
            if cell is None:
                continue
            r, c = self._where(*cell)
            foe = next((f for f in self.foes if f.r == r and f.c == c), None)
            if foe is not None:
                self._hit(foe)
            else:
                self._wall_hit(r, c)
        if self.params.wrap:
            for s in self.gun.shots:
                s.r, s.c = self._where(s.r, s.c)

    def _march(self) -> bool:
        """Every foe takes a step; True when one caught the player and the game is over."""
        p = self.params
        for foe in self.foes:
            if self.drift:
                r, c = self._where(foe.r + foe.dr, foe.c + foe.dc)
                if not (0 <= r < p.height and 0 <= c < p.width) or self.still[r][c] in self.SOLID:
                    foe.dr, foe.dc = -foe.dr, -foe.dc
                    continue
                foe.r, foe.c = r, c
                continue
            dr, dc = chase(foe.r, foe.c, self.r, self.c)
            if not (dr or dc):
                continue
            if dr:       # blocked on the long axis: slide the way it slid before, else toward you
                s = foe.dc or (self.c > foe.c) - (self.c < foe.c) or 1
                steps = ((dr, 0), (0, s), (0, -s))
            else:
                s = foe.dr or (self.r > foe.r) - (self.r < foe.r) or 1
                steps = ((0, dc), (s, 0), (-s, 0))
            for k, (sr, sc) in enumerate(steps):
                r, c = foe.r + sr, foe.c + sc
                if (r, c) == (self.r, self.c) or (0 <= r < p.height and 0 <= c < p.width and self.free(r, c)):
                    foe.r, foe.c = r, c
                    foe.dr, foe.dc = (sr, sc) if k else (0, 0)
                    break
        return self._caught()

    def _caught(self) -> bool:
        if any(f.r == self.r and f.c == self.c for f in self.foes):
            return self._killed(self.caught_text)
        return False

    caught_text = "A foe caught you."

    def _killed(self, why: str) -> bool:
        return self.lose_life(why)

    def _volley(self) -> bool:
        if not self.shells.shots and self.tick < self.shells.ready:
            return False
        if self.shells.ready_at(self.tick):
            for foe in self.foes:
                if foe.r == self.r or foe.c == self.c:
                    dr, dc = chase(foe.r, foe.c, self.r, self.c)
                    self.shells.fire(self.tick, foe.r, foe.c, dr, dc, SHELL)
                    break
        me = (self.r, self.c)
        for shell, cell in self.shells.advance(
                lambda r, c: not (0 <= r < self.params.height and 0 <= c < self.params.width)
                or self.still[r][c] in self.SOLID or (r, c) == me):
            if cell == me:
                return self._killed("A shell hit you.")
        return False

    # -- hooks ---------------------------------------------------------------------------------------
    def stock(self, far: int = 6, one: bool = False) -> None:
        """Bring the foes up to ``foes`` on the field (or add ``one``), never more than the kills
        left to ``goal``."""
        p = self.params
        while len(self.foes) < p.foes and self.kills + len(self.foes) < p.goal:
            self.add_foe(*self.spot(far))
            if one:
                break

    def _hit(self, foe: Body) -> None:
        """Your shot struck ``foe``: it loses a hit point; at none it dies and scores one unit."""
        foe.data -= 1
        if foe.data > 0:
            self.say(f"{self.foe_name.capitalize()} hit!")
            return
        self.foes.remove(foe)
        self.kills += 1
        self.say(f"{self.foe_name.capitalize()} destroyed!")
        self.score.gain()

    foe_name = "foe"

    def _wall_hit(self, r: int, c: int) -> None:
        """Your shot stopped on a solid cell (or the edge)."""

    def _enter(self, r: int, c: int) -> bool:
        """The player steps toward (r, c); True when that ended the move (and the tick)."""
        return False

    def _turn(self) -> None:
        """The game's own work at the end of a tick."""

    def _respawn(self) -> None:
        """After a life lost: the player home, shells gone, foes too close moved away."""
        self.r, self.c = self.home
        self.shells.shots, self.gun.shots = [], []
        for foe in self.foes:
            if abs(foe.r - self.r) + abs(foe.c - self.c) < 4:
                foe.r, foe.c = self.spot(5)
        if self.air is not None:
            self.air.refill()

    # -- drawing -------------------------------------------------------------------------------------
    def _sprites(self):
        out = [(f.r, f.c, f.glyph) for f in self.foes]
        out += [(s.r, s.c, SHOT) for s in self.gun.shots]
        out += [(s.r, s.c, SHELL) for s in self.shells.shots]
        out.append((self.r, self.c, ARROWS.get(self.face, SHIP) if self.arrows else SHIP))
        return out

    def _extra_hud(self) -> str:
        return f"{self.air_name} {self.air.left}" if self.air is not None else ""

    air_name = "Air"


def you_glyphs(arrows: bool = True) -> dict[str, str]:
    """Legend entries for the player."""
    if not arrows:
        return {SHIP: "you"}
    return {g: f"you (facing {w})" for g, w in zip("^v<>", ("up", "down", "left", "right"))}


__all__ = ["ACTIONS4", "ACTIONS8", "ArenaParams", "ArenaTask", "EMPTY", "FIRE", "MOVES4", "MOVES8",
           "SHELL", "SHIP", "SHOT", "WALL", "you_glyphs"]
