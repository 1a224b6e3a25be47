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
    _own_movers: ClassVar[bool] = False   # set per game class: it draws movers of its own
    _own_enter: ClassVar[bool] = False    # ... overrides _enter
    _own_turn: ClassVar[bool] = False     # ... overrides _turn

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
        if type(self)._extra_hud is ArenaTask._extra_hud:   # (no air: nothing to add to the HUD)
            self._extra = self.air is not None
        self.foes: list[Body] = []
        self.kills = 0

    def free(self, r: int, c: int) -> bool:
        if self.still[r][c] in self.SOLID:
            return False
        for f in self.foes:           # (a plain loop: a generator costs more than a few foes)
            if f.r == r and f.c == c:
                return False
        return True

    def foe_at(self, r: int, c: int) -> Body | None:
        """The first foe on (r, c), or None."""
        for f in self.foes:
            if f.r == r and f.c == c:
                return f
        return None

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
                if self._own_enter and (self._enter(r, c) or self.done):   # (no call when a no-op)
                    return
                if self.free(r, c):
                    self.r, self.c = r, c
        if action == FIRE:
            self.gun.fire(self.tick, self.r, self.c, *self.face, SHOT)
        if self.gun.shots:
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
        if self._own_turn:
            self._turn()

    air_out = "You ran out of air."

    def _where(self, r: int, c: int) -> tuple[int, int]:
        p = self.params
        return (r % p.height, c % p.width) if p.wrap else (r, c)

    def _struck(self, r: int, c: int) -> bool:
        """What stops your shot: the field's edge (unless it wraps), a solid cell, a foe."""
        p = self.params
        if p.wrap:
            r, c = r % p.height, c % p.width
        elif not (0 <= r < p.height and 0 <= c < p.width):
            return True
        return not self.free(r, c)

    def _shots(self) -> None:
        """Your shots fly ``shot_speed`` cells, a cell at a time, and stop on what ``_struck``
        stops (the gun's ``advance`` written out: shots fly along a unit step, and this runs on
        most ticks, where a generator and a hit callback per cell cost more than the flight)."""
        gun, p = self.gun, self.params
        speed, struck, kept = gun.speed, self._struck, []
        h, w, still, solid, foes = p.height, p.width, self.still, self.SOLID, self.foes
        for shot in gun.shots:
            cell = None
            dr, dc = shot.dr, shot.dc
            if dr or dc:
                r, c = shot.r, shot.c
                for _ in range(speed):
                    r += dr
                    c += dc
                    if p.wrap:
                        if struck(r, c):
                            cell = r, c
                            break
                    elif not (0 <= r < h and 0 <= c < w) or still[r][c] in solid:
                        cell = r, c                        # (``_struck`` on a field that ends)
                        break
                    else:
                        for f in foes:                     # (``foe_at`` written out)
                            if f.r == r and f.c == c:
                                cell = r, c
                                break
                        if cell is not None:
                            break
                    shot.r, shot.c = r, c
            shot.data -= speed
            if cell is not None:
                shot.alive = False
                r, c = self._where(*cell)
                foe = self.foe_at(r, c)
                if foe is not None:
                    self._hit(foe)
                else:
                    self._wall_hit(r, c)
            elif shot.data <= 0:
                shot.alive = False
            else:
                kept.append(shot)
        gun.shots = kept
        if self.params.wrap:
            p = self.params
            for s in kept:
                s.r, s.c = s.r % p.height, s.c % p.width

    def _march(self) -> bool:
        """Every foe takes a step; True when one caught the player and the game is over."""
        p = self.params
        h, w = p.height, p.width
        still, solid, foes = self.still, self.SOLID, self.foes
        if self.drift:
            for foe in foes:
                r, c = foe.r + foe.dr, foe.c + foe.dc
                if p.wrap:
                    r, c = r % h, c % w
                if not (0 <= r < h and 0 <= c < w) or still[r][c] in solid:
                    foe.dr, foe.dc = -foe.dr, -foe.dc
                else:
                    foe.r, foe.c = r, c
            return self._caught()
        pr, pc = self.r, self.c
        at = [f.r * w + f.c for f in foes]      # where the foes stand (inside the field: one key a cell)
        for i, foe in enumerate(foes):
            fr, fc = foe.r, foe.c
            dr, dc = pr - fr, pc - fc
            if dr and (dr if dr > 0 else -dr) >= (dc if dc > 0 else -dc):
                r, c = fr + (1 if dr > 0 else -1), fc          # the long axis first
            elif dc:
                r, c = fr, fc + (1 if dc > 0 else -1)
            else:
                continue
            if (r == pr and c == pc) or (0 <= r < h and 0 <= c < w and still[r][c] not in solid
                                         and r * w + c not in at):
                foe.r, foe.c, foe.dr, foe.dc = r, c, 0, 0
                at[i] = r * w + c
                continue
            # blocked on the long axis: slide the way it slid before, else toward you
            if r != fr:
                s = foe.dc or (dc > 0) - (dc < 0) or 1
                steps = ((0, s), (0, -s))
            else:
                s = foe.dr or (dr > 0) - (dr < 0) or 1
                steps = ((s, 0), (-s, 0))
            for sr, sc in steps:
                r, c = fr + sr, fc + sc
                if (r == pr and c == pc) or (0 <= r < h and 0 <= c < w and still[r][c] not in solid
                                             and r * w + c not in at):
                    foe.r, foe.c, foe.dr, foe.dc = r, c, sr, sc
                    at[i] = r * w + c
                    break
        if pr * w + pc in at:
            return self._killed(self.caught_text)
        return False

    def _caught(self) -> bool:
        if self.foe_at(self.r, self.c) is not None:
            return self._killed(self.caught_text)
        return False

    caught_text = "A foe caught you."

    def _killed(self, why: str) -> bool:
        return self.lose_life(why)

    def _volley(self) -> bool:
        shells, tick = self.shells, self.tick
        if not shells.shots and tick < shells.ready:
            return False
        pr, pc = self.r, self.c
        if tick >= shells.ready and len(shells.shots) < shells.limit:   # (ready_at, no call)
            for foe in self.foes:
                if foe.r == pr or foe.c == pc:
                    dr, dc = chase(foe.r, foe.c, pr, pc)
                    shells.fire(tick, foe.r, foe.c, dr, dc, SHELL)
                    break
        # the shells' advance written out: a cell a turn along a unit step (see ``_shots``)
        p = self.params
        h, w, still, solid, kept = p.height, p.width, self.still, self.SOLID, []
        for shell in shells.shots:
            hit = False
            if shell.dr or shell.dc:
                r, c = shell.r + shell.dr, shell.c + shell.dc
                if r == pr and c == pc:
                    shell.data -= 1
                    shell.alive = False
                    return self._killed("A shell hit you.")   # (the rest fly on next turn)
                if not (0 <= r < h and 0 <= c < w) or still[r][c] in solid:
                    hit = True
                else:
                    shell.r, shell.c = r, c
            shell.data -= 1
            if hit or shell.data <= 0:
                shell.alive = False
            else:
                kept.append(shell)
        shells.shots = kept
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
    def __init_subclass__(cls, **kwargs) -> None:
        super().__init_subclass__(**kwargs)
        # whether the game draws movers of its own: else ``_grid`` skips asking (most turns of
        # most games, where two empty calls cost a tenth of the drawing)
        cls._own_movers = cls._below is not ArenaTask._below or cls._above is not ArenaTask._above
        cls._own_enter = cls._enter is not ArenaTask._enter   # (likewise for the hooks)
        cls._own_turn = cls._turn is not ArenaTask._turn

    def _below(self):
        """Movers of the game's own drawn under the foes: (row, col, glyph) each."""
        return ()

    def _above(self):
        """Movers of the game's own drawn over everything."""
        return ()

    def _you(self) -> str:
        return ARROWS.get(self.face, SHIP) if self.arrows else SHIP

    def _sprites(self):
        out = [*self._below(), *((f.r, f.c, f.glyph) for f in self.foes)]
        out += [(s.r, s.c, SHOT) for s in self.gun.shots]
        out += [(s.r, s.c, SHELL) for s in self.shells.shots]
        out.append((self.r, self.c, self._you()))
        out += self._above()
        return out

    def _grid(self) -> list[str]:
        """``_sprites()`` drawn on ``_rows()`` straight from the bodies: no (row, col, glyph)
        tuple per mover (that cost as much as the drawing) and no bounds test (every mover of an
        arena stays inside the field), each row remembered (``_draw``)."""
        rows = self._rows() if self._slides else self.still[:]
        self._grids += 1
        drawn = self._drawn
        if self._own_movers:
            for r, c, g in self._below():
                key = (rows[r], c, g)
                rows[r] = drawn.get(key) or self._draw(key)
        for f in self.foes:
            r = f.r
            key = (rows[r], f.c, f.glyph)
            rows[r] = drawn.get(key) or self._draw(key)
        for s in self.gun.shots:
            r = s.r
            key = (rows[r], s.c, SHOT)
            rows[r] = drawn.get(key) or self._draw(key)
        for s in self.shells.shots:
            r = s.r
            key = (rows[r], s.c, SHELL)
            rows[r] = drawn.get(key) or self._draw(key)
        r = self.r
        key = (rows[r], self.c, ARROWS.get(self.face, SHIP) if self.arrows else SHIP)
        rows[r] = drawn.get(key) or self._draw(key)
        if self._own_movers:
            for r, c, g in self._above():
                key = (rows[r], c, g)
                rows[r] = drawn.get(key) or self._draw(key)
        return rows

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
