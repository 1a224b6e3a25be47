"""Zaxxon: a ship flies into a fortress that scrolls in from the right. Gun turrets (T) ride in
with the scenery and fire back along their row; shoot them first. On the Atari preset the
fortress walls (#) leave one gap to fly through, and fuel tanks (F) refill the tank when shot;
running dry, a wall, a turret or a turret's shot costs a life (pattern D)."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param, require
from .bodies import Countdown, Gun
from .engine import EMPTY, ArcadeParams, ArcadeTask, register_arcade
from .scroller import Pacer, Strip, put_one

SHIP, TURRET, FUEL, WALL, SHOT, BULLET = ">", "T", "F", "#", "-", "~"
ACTIONS = ActionSet([("NOOP", "hold your altitude"), ("UP", "climb one row"),
                     ("DOWN", "dive one row"), ("FIRE", "shoot straight ahead (right)")], noop="NOOP")
MOVES, FIRE = (0, -1, 1, 0), 3


@dataclass(frozen=True)
class ZaxxonParams(ArcadeParams):
    width: int = param(14, 8, 60)
    height: int = param(8, 5, 30)
    goal: int = param(6, 1, 200)
    unit: float = param(1 / 6, 0, 100)
    every: int = param(2, 1, 6)           # turns per scroll
    spacing: int = param(4, 2, 20)        # columns between turrets
    fire_every: int = param(5, 2, 50)     # turns between turret volleys
    wall_every: int = param(0, 0, 60)     # columns between walls (0: none)
    gap: int = param(3, 1, 20)            # rows open in a wall
    fuel: int = param(0, 0, 500)          # turns of fuel (0: none)
    depot: int = param(0, 0, 20)          # every n-th thing spawned is a fuel tank

    def check(self) -> None:
        require(self.gap < self.height, "gap", "be smaller than the field", self.gap)


class Zaxxon(ArcadeTask):
    title = "Zaxxon"
    rules = ("You fly the ship (>) in column 1 of a {width}x{height} view, with {lives_text}; the "
             "fortress scrolls left one column every {every} turns, bringing a gun turret (T) every "
             "{spacing} columns. Every {fire_every} turns each turret in view fires a shot (~) left "
             "along its row, one cell a turn. FIRE sends your shot (-) right two cells a turn; it "
             "also stops turret shots.{wall_text}{fuel_text} A turret, a wall or a turret's shot "
             "meeting you costs a life.")
    rewards = "+{unit} for each turret destroyed; {death} when the game is lost."
    ends = "when you have destroyed {goal} turrets or the game is lost"
    ACTIONS = ACTIONS
    Params = ZaxxonParams
    pattern = "D"
    glyphs = {EMPTY: "open sky", WALL: "fortress wall", TURRET: "gun turret", FUEL: "fuel tank",
              SHOT: "your shot", BULLET: "turret shot", SHIP: "you (the ship)"}

    def prompt_fields(self) -> dict:
        p = self.params
        wall = (f" Every {p.wall_every} columns a wall (#) leaves {p.gap} open rows to fly through."
                if p.wall_every else "")
        fuel = (f" Fuel ({p.fuel} turns) burns one a turn; shooting a fuel tank (F) refills it."
                if p.fuel else "")
        return {**super().prompt_fields(), "wall_text": wall, "fuel_text": fuel}

    def _setup(self, rng) -> None:
        self.start(rng)
        p = self.params
        self.strip = Strip([EMPTY * p.width] * p.height, "left")
        self.r, self.col = p.height // 2, 1
        self.gun = Gun(cooldown=1, speed=2, reach=p.width, limit=2)
        self.flak = Gun(cooldown=0, speed=1, reach=p.width, limit=4 * p.height)
        self.pacer, self.fuel = Pacer(p.every), Countdown(p.fuel)
        self._extra = bool(p.fuel)   # (no fuel: nothing to add to the HUD)
        self.since = self.placed = self.walled = 0
        self.volley, self.bullets = Pacer(p.fire_every), set()
        self.strip.preroll(p.width // 2, self._column)

    def _column(self) -> str:
        p = self.params
        line = EMPTY * p.height
        self.since += 1
        self.walled += 1
        if p.wall_every and self.walled >= p.wall_every:
            self.walled = 0
            top = self.draws.below(p.height - p.gap + 1)
            return WALL * top + EMPTY * p.gap + WALL * (p.height - p.gap - top)
        if self.since < p.spacing or self.walled < 2 or p.wall_every and self.walled > p.wall_every - 2:
            return line
        self.since = 0
        self.placed += 1
        what = FUEL if p.fuel and p.depot and self.placed % (p.depot + 1) == 0 else TURRET
        return put_one(line, self.draws.below(p.height), what)

    def _shot_hits(self, r: int, c: int) -> bool:
        """What stops your shot at (r, c): the right edge, a turret shot (both are gone) or
        anything on the strip (your shots stay on the field's rows and right of column 0)."""
        if c >= self.params.width:
            return True
        bullets = self.bullets
        if bullets and (r, c) in bullets:
            self.flak.shots = [b for b in self.flak.shots if b.r != r or b.c != c]
            bullets.discard((r, c))
            return True
        return self.strip.rows[r][c] != EMPTY

    def _fly(self) -> None:
        """Your shots fly right two cells, cell by cell (``fly_shots`` with ``_shot_hits``
        written into the loop: this runs most turns)."""
        width, rows, bullets, kept = self.params.width, self.strip.rows, self.bullets, []
        for shot in self.gun.shots:
            r, c = shot.r, shot.c
            stop = 0                                # (shots fly right of column 1)
            for at in (c + 1, c + 2):
                if at >= width:
                    stop = at
                elif bullets and (r, at) in bullets:
                    self.flak.shots = [b for b in self.flak.shots if b.r != r or b.c != at]
                    bullets.discard((r, at))
                    stop = at
                elif rows[r][at] != EMPTY:
                    stop = at
                if stop:
                    break
                shot.c = at
            shot.data -= 2
            if stop:
                shot.alive = False
                self._strike(r, stop)
            elif shot.data <= 0:
                shot.alive = False
            else:
                kept.append(shot)
        self.gun.shots = kept

    def _strike(self, r: int, c: int) -> None:
        what = self.strip.get(r, c)
        if what in (TURRET, FUEL):
            self.strip.put(r, c, EMPTY)
            if what == TURRET:
                self.score.gain()
                self.say("Turret destroyed!")
            else:
                self.fuel.refill()

    def _flak_moves(self) -> bool:
        """Turret shots fly a cell left (gone at the edge or a wall); True if one meets you."""
        kept, rows, r0, c0 = [], self.strip.rows, self.r, self.col
        for b in self.flak.shots:
            c = b.c = b.c - 1
            if c < 0 or rows[b.r][c] == WALL:
                continue
            if c == c0 and b.r == r0:
                return True
            kept.append(b)
        self.flak.shots = kept
        return False

    def _play(self, action: int) -> None:
        p, gun = self.params, self.gun
        r = self.r + MOVES[action]
        self.r = r = 0 if r < 0 else r if r < p.height else p.height - 1
        if action == FIRE:
            gun.fire(self.tick, r, self.col + 1, 0, 1, SHOT)
        rows = self.strip.rows
        if (rows[r][self.col] != EMPTY or self.flak.shots) and self._crashed():   # (a call only then)
            return
        if gun.shots:
            flak = self.flak.shots
            self.bullets = {(b.r, b.c) for b in flak} if flak else None
            self._fly()
            if self.done:
                return
        if self.pacer.due(self.tick):
            self.strip.push(self._column())
            for shot in gun.shots:
                if self._shot_hits(shot.r, shot.c):
                    self._strike(shot.r, shot.c)
                    shot.data = 0
            if self._crashed():
                return
        if self.flak.shots and self._flak_moves():
            self.lose_life("A turret shot hit you!")
            return
        if self.volley.due(self.tick):           # new shots start moving next turn
            for r, row in enumerate(self.strip.rows):
                c = row.find(TURRET)
                while c >= 0:
                    if c > self.col + 1:
                        self.flak.fire(self.tick, r, c - 1, 0, -1, BULLET)
                    c = row.find(TURRET, c + 1)
        if p.fuel and self.fuel.tick():
            self.lose_life("Out of fuel!")

    def _crashed(self) -> bool:
        r, c = self.r, self.col
        if self.strip.rows[r][c] != EMPTY:
            self.lose_life("You crashed!")
            return True
        for b in self.flak.shots:
            if b.c == c and b.r == r:
                self.lose_life("A turret shot hit you!")
                return True
        return False

    def _respawn(self) -> None:
        self.flak.shots, self.gun.shots = [], []
        rows, k = self.strip.rows, self.col + 4       # a clear stretch to come back into
        for r, row in enumerate(rows):
            rows[r] = row[:k].replace(TURRET, EMPTY).replace(FUEL, EMPTY).replace(WALL, EMPTY) + row[k:]
        self.fuel.refill()

    def _grid(self) -> list[str]:
        """The strip with the shots and the ship drawn in (all inside the field, bar a turret
        shot that just left it on the turn it hit you), each row remembered (``_draw``: the
        strip's rows take few forms)."""
        rows = self.strip.rows[:]
        self._grids += 1
        drawn = self._drawn
        for b in self.flak.shots:
            if b.c >= 0:
                key = (rows[b.r], b.c, BULLET)
                rows[b.r] = drawn.get(key) or self._draw(key)
        for s in self.gun.shots:
            key = (rows[s.r], s.c, SHOT)
            rows[s.r] = drawn.get(key) or self._draw(key)
        key = (rows[self.r], self.col, SHIP)
        rows[self.r] = drawn.get(key) or self._draw(key)
        return rows

    def _extra_hud(self) -> str:
        return f"Fuel {self.fuel.left}" if self.params.fuel else ""


register_arcade(Zaxxon, "zaxxon",
                mini=dict(max_turns=300),
                atari=dict(width=24, height=20, lives=3, goal=20, unit=1.0, every=1, spacing=5,
                           fire_every=6, wall_every=15, gap=6, fuel=80, depot=3, max_turns=10000))
