"""Artillery: aim a cannon over a hill, in the wind, and hit the enemy cannon before it hits you."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...core import ActionSet, register_variants
from ...core.params import param
from ..common.palette import FLOOR, PLAYER, WALL
from ..common.physics import flight, launch_velocity
from .versus import LOSS, OUTCOME_REWARDS, WIN, VersusTask

ENEMY, PATH, LANDED, ENEMY_LANDED = "E", "*", "x", "o"
MIN_ANGLE, MAX_ANGLE = 5, 85
_TRIES = 200    # terrains tried per reset before the parameters are declared impossible


@dataclass(frozen=True)
class ArtilleryParams:
    width: int = param(28, 16, 60)
    height: int = param(10, 8, 30)
    # wind is drawn from [-max_wind, max_wind], in cells/s^2 (gravity is 1)
    max_wind: float = param(0.3, 0, 1)
    angle_step: int = param(5, 1, 20)        # degrees per RAISE / LOWER
    # power runs 1..max_power; a shell leaves at power x speed_step cells/s
    max_power: int = param(30, 5, 100)
    speed_step: float = param(0.25, 0.05, 2)
    # a shell landing within this many cells (any direction) hits a cannon
    blast: int = param(1, 0, 3)
    # spread (power levels) of the enemy's first shot around a hitting power
    aim_error: float = param(6.0, 0, 50)
    # the enemy's spread is multiplied by this after every shot it fires
    aim_decay: float = param(0.75, 0, 1)


class Artillery(VersusTask):
    title = "Artillery"
    rules = ("You ({you}) and an enemy cannon ({enemy}) stand on either side of a hill. Aim by "
             "changing the barrel angle ({min_angle}..{max_angle} degrees above the horizontal, "
             "towards the enemy) and the power (1..{max_power}), then fire. Shells fly in an arc "
             "under gravity, are pushed sideways by the wind (in the status line; positive blows "
             "to the right) and explode where they first touch the ground or a cannon; a cannon whose "
             "column and row each differ from the explosion's by at most {blast} is destroyed. "
             "After each of your shots the enemy fires back; its aim starts rough and improves "
             "with every shot. Aiming past the limits wastes the turn.")
    rewards = OUTCOME_REWARDS
    ends = "when a cannon is destroyed"
    Params = ArtilleryParams
    glyphs = {FLOOR: "sky", WALL: "ground", PLAYER: "you", ENEMY: "enemy cannon",
              PATH: "your last shell's path", LANDED: "your last shell hit",
              ENEMY_LANDED: "enemy shell hit"}
    default_max_turns = 100

    def prompt_fields(self) -> dict:
        return super().prompt_fields() | {"you": PLAYER, "enemy": ENEMY, "min_angle": MIN_ANGLE,
                                          "max_angle": MAX_ANGLE}

    def _make_actions(self) -> ActionSet:
        step = self.params.angle_step
        return ActionSet([("RAISE", f"raise the barrel {step} degrees"),
                          ("LOWER", f"lower the barrel {step} degrees"),
                          ("MORE", "power +1"), ("LESS", "power -1"),
                          ("FIRE", "fire a shell; the enemy fires back")])

    # -- level ------------------------------------------------------------------------------------
    def _setup(self, rng: np.random.Generator) -> None:
        p = self.params
        self.rng = rng
        self.cols = (2, p.width - 3)    # you, enemy
        for _ in range(_TRIES):
            self.heights = self._terrain(rng)
            self.wind = round(float(rng.uniform(-p.max_wind, p.max_wind)), 2)
            self.cannons = [(c, self.heights[c]) for c in self.cols]
            # Both sides need a setting that hits: the enemy aims at one, you can find one.
            self.enemy_aim = self.find_aim(1)
            if self.enemy_aim is not None and self.find_aim(0) is not None:
                break
        else:
            raise RuntimeError(f"{self.task_id}: no terrain where both cannons can hit; "
                               "lower the hill or the wind")
        self.angle, self.power = 45, p.max_power // 2
        self.enemy_shots = 0
        self.path, self.landed, self.enemy_landed = [], None, None
        self.outcome = None
        self.fired = False
        self._base = [[WALL if r < h else FLOOR for h in self.heights] for r in range(p.height)]
        for (c, r), glyph in zip(self.cannons, (PLAYER, ENEMY)):
            self._base[r][c] = glyph
        self._draw()

    def _terrain(self, rng: np.random.Generator) -> list[int]:
        p = self.params
        level = int(rng.integers(2, 4))
        centre = int(rng.integers(p.width // 3, 2 * p.width // 3 + 1))
        peak = int(rng.integers(p.height // 3, p.height - 3))
        spread = float(rng.uniform(2.0, p.width / 6))
        heights = []
        for c in range(p.width):
            level = min(max(level + int(rng.integers(-1, 2)), 1), p.height // 3)
            heights.append(max(level, round(peak * math.exp(-((c - centre) / spread) ** 2))))
        for c in self.cols:   # a flat pad under each cannon
            heights[c - 1] = heights[c + 1] = heights[c]
        return heights

    def shoot(self, side: int, angle: float, power: float) -> tuple[list, tuple[int, int] | None]:
        """Fly a shell from cannon ``side`` (0 you, 1 the enemy): (path cells, impact or None)."""
        c, r = self.cannons[side]
        vx, vy = launch_velocity(angle, power * self.params.speed_step, leftward=side == 1)
        return flight(c + 0.5, r + 0.5, vx, vy, self.wind, -1.0, self.heights, (self.cannons[1 - side],))

    def hit(self, impact: tuple[int, int] | None, side: int) -> bool:
        c, r = self.cannons[side]
        b = self.params.blast
        return impact is not None and abs(impact[0] - c) <= b and abs(impact[1] - r) <= b

    def find_aim(self, side: int) -> tuple[int, int] | None:
        """A setting (angle, power) on the action grid that destroys the other cannon, trying
        angles from 45 degrees outwards and powers upwards until the shell flies past."""
        step = self.params.angle_step
        reachable = (45 + k * step for k in range(-90 // step, 90 // step + 1))   # from the start, 45
        angles = sorted((a for a in reachable if MIN_ANGLE <= a <= MAX_ANGLE), key=lambda a: (abs(a - 45), a))
        target = self.cannons[1 - side][0]
        for angle in angles:
            for power in range(1, self.params.max_power + 1):
                _, impact = self.shoot(side, angle, power)
                if self.hit(impact, 1 - side) and not self.hit(impact, side):
                    return angle, power
                if impact is None or (impact[0] - target) * (1 if side == 0 else -1) > self.params.blast:
                    break   # past the target: more power flies further still
        return None

    # -- turns --------------------------------------------------------------------------------------
    def _agent_move(self, action: int) -> str | None:
        p = self.params
        name = self.actions[action].name
        self.fired = name == "FIRE"
        if name == "RAISE" or name == "LOWER":
            angle = self.angle + (p.angle_step if name == "RAISE" else -p.angle_step)
            if not MIN_ANGLE <= angle <= MAX_ANGLE:
                return f"The angle stays within {MIN_ANGLE}..{MAX_ANGLE}."
            self.angle = angle
        elif name == "MORE" or name == "LESS":
            power = self.power + (1 if name == "MORE" else -1)
            if not 1 <= power <= p.max_power:
                return f"The power stays within 1..{p.max_power}."
            self.power = power
        else:
            self.path, self.landed = self.shoot(0, self.angle, self.power)
            self._report(0, self.landed)
            self._draw()
        return None

    def _opponent_move(self) -> None:
        if not self.fired:   # the enemy answers shots, not aiming
            return
        p = self.params
        angle, power = self.enemy_aim
        spread = p.aim_error * p.aim_decay ** self.enemy_shots
        power = min(max(power + float(self.rng.normal(0.0, spread)), 1.0), float(p.max_power))
        self.enemy_shots += 1
        _, self.enemy_landed = self.shoot(1, angle, power)
        self._report(1, self.enemy_landed)
        self._draw()

    def _report(self, side: int, impact: tuple[int, int] | None) -> None:
        """Decide the outcome of a shell from ``side`` and describe where it landed."""
        if self.hit(impact, 1 - side) or self.hit(impact, side):
            you_win = self.hit(impact, 1 - side) == (side == 0)
            self.outcome = WIN if you_win else LOSS
            self.say("The enemy cannon is destroyed." if you_win else "Your cannon is destroyed.")
            return
        who = "Your" if side == 0 else "The enemy"
        if impact is None:
            self.say(f"{who} shell flew off the field.")
            return
        gap = (impact[0] - self.cannons[1 - side][0]) * (1 if side == 0 else -1)
        self.say(f"{who} shell landed {abs(gap)} columns {'short' if gap < 0 else 'long'}.")

    def _result(self) -> str | None:
        return self.outcome

    def _draw(self) -> None:
        rows = [row[:] for row in self._base]
        top = self.params.height
        for c, r in self.path:
            if r < top and rows[r][c] == FLOOR:
                rows[r][c] = PATH
        for impact, glyph in ((self.landed, LANDED), (self.enemy_landed, ENEMY_LANDED)):
            if impact is not None and impact[1] < top and rows[impact[1]][impact[0]] in (FLOOR, WALL, PATH):
                rows[impact[1]][impact[0]] = glyph
        self._rows = ["".join(row) for row in reversed(rows)]

    def _grid(self) -> list[str]:
        return self._rows

    def _hud(self) -> str:
        return f"Angle {self.angle} | Power {self.power} | Wind {self.wind:+.2f}"


register_variants(Artillery, "Classics", {
    "glyphbench/classics-artillery-v0": dict(max_turns=100),
})
