"""River Raid: a jet flies up a river that scrolls down past it. Ships and helicopters sit on the
water; shoot them or steer around them (each one shot or passed counts), and a bridge marks the
end of the run. Touching a bank or an enemy crashes the jet; on the Atari preset the banks
wander, fuel burns every turn and depots (F) refill it when flown over (pattern D)."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param
from .bodies import Countdown, Gun
from .engine import EMPTY, ArcadeParams, ArcadeTask, register_arcade
from .scroller import Channel, Pacer, Strip, banks_fit, fly_shots, put_one

JET, SHIP, HELI, FUEL, BANK, BRIDGE, SHOT = "A", "S", "H", "F", "#", "=", "|"
ENEMIES = (SHIP, HELI)
CLEAR = EMPTY + BRIDGE   # what a shot flies through
ACTIONS = ActionSet([("NOOP", "fly straight"), ("LEFT", "bank one cell left"),
                     ("RIGHT", "bank one cell right"), ("FIRE", "shoot straight up the river")],
                    noop="NOOP")
MOVES, FIRE = (0, -1, 1, 0), 3


@dataclass(frozen=True)
class RiverParams(ArcadeParams):
    width: int = param(10, 8, 40)
    height: int = param(11, 8, 40)
    goal: int = param(9, 2, 200)          # enemies to shoot or pass, plus the bridge
    unit: float = param(1 / 9, 0, 100)
    every: int = param(2, 1, 6)           # turns per scroll
    spacing: int = param(3, 2, 10)        # rows between enemies
    narrow: int = param(8, 3, 38)        # the river's narrowest and widest span
    wide: int = param(8, 3, 38)
    fuel: int = param(0, 0, 500)          # turns of fuel (0: no fuel)
    depot: int = param(0, 0, 20)          # every n-th spawn is a fuel depot (0: none)

    check = banks_fit


class RiverRaid(ArcadeTask):
    title = "River Raid"
    rules = ("You fly the jet (A) up a river {narrow_text} on a {width}x{height} map, with "
             "{lives_text}; the river scrolls down one row every {every} turns. Enemy ships (S) and "
             "helicopters (H) sit on the water {spacing} rows apart: shoot them (FIRE sends a shot "
             "| up two cells a turn) or fly past them; each counts. After {enemies} enemies comes "
             "the bridge (=): reach it to finish.{fuel_text} Touching a bank (#) or an enemy "
             "crashes the jet.")
    rewards = "+{unit} for each enemy shot or passed and for the bridge; {death} when the game is lost."
    ends = "when you reach the bridge or the game is lost"
    ACTIONS = ACTIONS
    Params = RiverParams
    pattern = "D"
    glyphs = {EMPTY: "water", BANK: "river bank", SHIP: "enemy ship", HELI: "enemy helicopter",
              FUEL: "fuel depot", BRIDGE: "bridge (the end)", SHOT: "your shot", JET: "you (the jet)"}

    def prompt_fields(self) -> dict:
        p = self.params
        fuel = (f" Fuel ({p.fuel} turns) burns one a turn; flying over a depot (F) fills it, and "
                "running dry crashes." if p.fuel else "")
        span = f"{p.wide} cells wide" if p.narrow == p.wide else f"{p.narrow} to {p.wide} cells wide"
        return {**super().prompt_fields(), "fuel_text": fuel, "narrow_text": span,
                "enemies": p.goal - 1}

    def _setup(self, rng) -> None:
        self.start(rng)
        p = self.params
        self.channel = Channel(p.width, p.narrow, p.wide)
        self.strip = Strip([self.channel.line(BANK)] * p.height, "down")
        self.jet_r, self.col = p.height - 2, p.width // 2
        self.gun = Gun(cooldown=1, speed=2, reach=p.height, limit=1)
        self.pacer, self.fuel = Pacer(p.every), Countdown(p.fuel)
        self._extra = bool(p.fuel)   # (no fuel: nothing to add to the HUD)
        self.spawned = self.lost = self.since = self.placed = 0
        self.bridge_built = False
        self.strip.preroll(p.height - 4, self._line)

    def _line(self) -> str:
        p = self.params
        left, right, line = self.channel.step(self.draws, BANK)
        self.since += 1
        if self.spawned - self.lost >= p.goal - 1:
            if not self.bridge_built and self.since > p.spacing:
                self.bridge_built = True
                return BANK * left + BRIDGE * (right - left + 1) + BANK * (p.width - 1 - right)
            return line
        if self.since < p.spacing:
            return line
        self.since = 0
        c = left + self.draws.below(right - left + 1)
        self.placed += 1
        if p.fuel and p.depot and self.placed % (p.depot + 1) == 0:
            return put_one(line, c, FUEL)
        self.spawned += 1
        return put_one(line, c, SHIP if self.draws.random() < 0.5 else HELI)

    def _shot_at(self, r: int, c: int) -> None:
        if r >= 0:
            self._strike(r, c)

    def _strike(self, r: int, c: int) -> None:
        """A shot reached (r, c): an enemy there counts; a depot is just gone."""
        what = self.strip.get(r, c)
        if what in ENEMIES or what == FUEL:
            self.strip.put(r, c, EMPTY)
            if what != FUEL:
                self.score.gain()
                self.say("Enemy shot down!")

    def _play(self, action: int) -> None:
        p = self.params
        c = self.col + MOVES[action]
        self.col = 0 if c < 0 else c if c < p.width else p.width - 1
        gun = self.gun
        if action == FIRE:
            gun.fire(self.tick, self.jet_r - 1, self.col, -1, 0, SHOT)
        if gun.shots:   # (a shot flies up its column, stopped past the top or by what is not water)
            fly_shots(gun, None, self._shot_at, self.strip.rows, CLEAR)
        if self.done or (self.strip.rows[self.jet_r][self.col] != EMPTY and self._crashed()):
            return
        if self.pacer.due(self.tick):
            gone = self.strip.scroll(self._line())
            passed = gone.count(SHIP) + gone.count(HELI)
            if passed:
                self.score.gain(passed)
            rows = self.strip.rows
            for shot in gun.shots:   # (what scrolled onto a shot stops it)
                if rows[shot.r][shot.c] not in CLEAR:
                    self._strike(shot.r, shot.c)
                    shot.data = 0
            if self.done or self._crashed():
                return
        if p.fuel and self.fuel.tick():
            self.lose_life("Out of fuel!")

    def _crashed(self) -> bool:
        here = self.strip.rows[self.jet_r][self.col]
        if here == EMPTY:
            return False
        if here == FUEL:
            self.fuel.refill()
        elif here == BRIDGE:
            self.score.gain()
            self.say("You reached the bridge!")
            self.finish(won=True)
            return True
        elif here in ENEMIES or here == BANK:
            if here != BANK:
                self.strip.put(self.jet_r, self.col, EMPTY)
                self.lost += 1
            self.lose_life("You crashed!")
            return True
        return False

    def _respawn(self) -> None:
        for r in (self.jet_r - 1, self.jet_r):
            row = self.strip.rows[r]
            self.lost += sum(row.count(e) for e in ENEMIES)
            self.strip.rows[r] = row.replace(SHIP, EMPTY).replace(HELI, EMPTY)
        row = self.strip.rows[self.jet_r]
        self.col = (row.index(EMPTY) + row.rindex(EMPTY)) // 2 if EMPTY in row else self.col
        self.gun.shots = []
        self.fuel.refill()

    def _grid(self) -> list[str]:
        rows = self.strip.rows[:]
        self._grids += 1
        drawn = self._drawn   # (each row remembered: see ``_draw``)
        for s in self.gun.shots:               # (shots fly up inside the map)
            r = s.r
            key = (rows[r], s.c, SHOT)
            rows[r] = drawn.get(key) or self._draw(key)
        r = self.jet_r
        key = (rows[r], self.col, JET)
        rows[r] = drawn.get(key) or self._draw(key)
        return rows

    def _extra_hud(self) -> str:
        return f"Fuel {self.fuel.left}" if self.params.fuel else ""


register_arcade(RiverRaid, "riverraid",
                mini=dict(max_turns=300),
                atari=dict(width=20, height=24, lives=3, goal=31, unit=1.0, every=1, spacing=3,
                           narrow=6, wide=14, fuel=60, depot=4, max_turns=10000))
