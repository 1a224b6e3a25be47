"""Atlantis: three fixed turrets (T) guard a city on the bottom row. Raiders (> and <) cross the
sky one cell a turn, dropping a row lower at each edge; one that gets down to the city wrecks
it (the Atari preset's city has several buildings, H, each a life). The left turret shoots up
and to the right, the centre one straight up, the right one up and to the left.
Balance: Atari raiders drop 5 rows a pass (the few altitude lanes) on 4 buildings, not 1 row on 6."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param, require
from .bodies import Gun
from .engine import EMPTY, register_arcade
from .shooter import Shooter, ShooterParams, per

TURRET, BUILDING, SHOT, EAST, WEST = "T", "H", "*", ">", "<"
ACTIONS = ActionSet([("NOOP", "hold fire"), ("FIRE_LEFT", "the left turret shoots up and to the right"),
                     ("FIRE_CENTER", "the centre turret shoots straight up"),
                     ("FIRE_RIGHT", "the right turret shoots up and to the left")], noop="NOOP")
AIM = ((-1, 1), (-1, 0), (-1, -1))
WAVE_TEXT: dict[int, str] = {}


@dataclass(frozen=True)
class AtlantisParams(ShooterParams):
    width: int = param(16, 10, 60)
    height: int = param(8, 6, 40)
    goal: int = param(3, 1, 300)
    unit: float = param(1 / 3, 0, 100)
    shot_speed: int = param(1, 1, 4)
    wave: int = param(5, 1, 30)           # raiders in a wave
    gap: int = param(4, 1, 30)            # turns between raiders entering
    per_raider: bool = param(False)       # the goal counts raiders (else whole waves)
    drop: int = param(1, 1, 10)           # rows a raider drops at each edge

    def check(self) -> None:
        require(self.lives <= self.width // 5, "lives", "be at most one building per 5 columns", self.lives)


class Atlantis(Shooter):
    title = "Atlantis"
    rules = ("You command three turrets (T) in the city on the bottom row of a {width}x{height} "
             "field{city_text}. Raiders come in waves of {wave}, one every {gap} turns, entering at "
             "the top from alternate sides; each crosses a cell a turn (> east, < west) and drops "
             "{drop_text} at the far edge. A raider that reaches the city row {hit_text}. Each turret "
             "shoots (*) {speed_text} a turn, one shot in flight per turret.")
    rewards = "+{unit} for each {counted}{death_text}."
    ends = "when you have {goal_text} or the city falls"
    ACTIONS = ACTIONS
    Params = AtlantisParams
    pattern = "D"
    glyphs = {EMPTY: "sky", TURRET: "turret", BUILDING: "building", EAST: "raider flying east",
              WEST: "raider flying west", SHOT: "your shot"}

    def prompt_fields(self) -> dict:
        p = self.params
        return {**super().prompt_fields(), "speed_text": per(p.shot_speed, "cell"),
                "counted": "raider shot down" if p.per_raider else "wave shot down to the last raider",
                "goal_text": f"shot down {p.goal} raiders" if p.per_raider else f"cleared {p.goal} waves",
                "city_text": f", among {p.lives} buildings (H)" if p.lives > 1 else "",
                "drop_text": "a row" if p.drop == 1 else f"{p.drop} rows (no lower than the city row)",
                "hit_text": "wrecks the nearest building" if p.lives > 1 else "ends the game"}

    def _towers(self) -> tuple[int, int, int]:
        w = self.params.width
        return w // 5, w // 2, w - w // 5

    def _homes(self) -> list[int]:
        p = self.params
        if p.lives == 1:
            return []
        spots = [(k + 1) * p.width // (p.lives + 1) + (k % 2) for k in range(p.lives)]
        towers = self._towers()
        return [c + 1 if c in towers else c for c in spots]       # a building beside a turret, not under it

    def _still(self) -> list[str]:
        p = self.params
        line = [EMPTY] * p.width
        for c in self._homes():
            line[c] = BUILDING
        for c in self._towers():
            line[c] = TURRET
        return [EMPTY * p.width] * (p.height - 1) + ["".join(line)]

    def _setup(self, rng) -> None:
        self.arm(rng)
        self.guns = [Gun(1, self.params.shot_speed, self.params.height, 1) for _ in range(3)]
        self.waves, self.sent, self.kills = 1, 0, 0

    def _play(self, action: int) -> None:
        p = self.params
        if action:
            dr, dc = AIM[action - 1]
            self.guns[action - 1].fire(self.tick, p.height - 1, self._towers()[action - 1], dr, dc, SHOT)
        w, bodies = p.width, self.pack.bodies
        for b in bodies:
            c = b.c + b.dc
            if 0 <= c < w:
                b.c = c
            else:
                b.dc, b.r = -b.dc, min(p.height - 1, b.r + p.drop)
                b.glyph = EAST if b.dc > 0 else WEST
        for gun in self.guns:
            if gun.shots:
                self._fly(gun, w, bodies)
        bottom = p.height - 1
        for b in bodies:   # (the list of those down below is made only when there is one)
            if b.r >= bottom:
                for b in [b for b in bodies if b.r >= bottom]:
                    self.pack.kill(b)
                    if self._wreck(b.c):
                        return
                break
        if self.done:
            return
        if self.sent < p.wave and self.tick % p.gap == 1 % p.gap:
            left = self.sent % 2 == 0
            self.pack.add(0, 0 if left else p.width - 1, EAST if left else WEST, dc=1 if left else -1)
            self.sent += 1
        elif self.sent >= p.wave and not self.pack.bodies:
            if not p.per_raider:
                self.say(f"Wave {self.waves} repelled!")
                self.score.gain()
            self.waves, self.sent = self.waves + 1, 0

    def _fly(self, gun: Gun, w: int, bodies: list) -> None:
        """``gun``'s shots fly a cell at a time (each a unit step) and stop off the field or on
        a raider, who falls (Gun.advance and sweep written out, each hit dealt with before the
        next shot moves)."""
        p, speed, kept = self.params, gun.speed, []
        for shot in gun.shots:
            dr, dc, r, c = shot.dr, shot.dc, shot.r, shot.c
            foe, stopped = None, False
            for _ in range(speed):
                r += dr
                c += dc
                if r < 0 or not 0 <= c < w:
                    stopped = True
                    break
                for b in bodies:
                    if b.c == c and b.r == r:
                        foe = b
                        break
                if foe is not None:
                    stopped = True
                    break
                shot.r, shot.c = r, c
            shot.data -= speed
            if stopped:
                shot.alive = False
                if foe is not None:
                    self.pack.kill(foe)
                    self.kills += 1
                    self.say("Raider down!")
                    if p.per_raider:
                        self.score.gain()
            elif shot.data <= 0:
                shot.alive = False
            else:
                kept.append(shot)
        gun.shots = kept

    def _wreck(self, c: int) -> bool:
        """A raider got down to the city at column ``c``: the nearest building falls (a life)."""
        homes = [k for k, ch in enumerate(self.still[-1]) if ch == BUILDING]
        if homes:
            self.set_still(self.params.height - 1, min(homes, key=lambda k: abs(k - c)), EMPTY)
        return self.lose_life("A raider reached the city.")

    def _extra_hud(self) -> str:
        text = WAVE_TEXT.get(self.waves)
        if text is None:
            text = WAVE_TEXT[self.waves] = f"Wave {self.waves}"
        return text

    def _grid(self) -> list[str]:
        """``_sprites`` drawn straight from the bodies, in the same order."""
        rows = self.still[:]
        self._grids += 1
        self._paint(rows, self.pack.bodies)
        for gun in self.guns:
            if gun.shots:
                self._paint(rows, gun.shots, SHOT)
        return rows

    def _sprites(self):
        out = [(b.r, b.c, b.glyph) for b in self.pack.bodies]
        for gun in self.guns:
            out += [(s.r, s.c, SHOT) for s in gun.shots]
        return out


register_arcade(Atlantis, "atlantis",
                mini=dict(max_turns=300),
                atari=dict(width=30, height=16, lives=4, goal=30, unit=10.0, death=0.0, wave=8,
                           gap=3, shot_speed=2, per_raider=True, drop=5, max_turns=10000))
