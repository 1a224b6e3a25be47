"""Lunar Lander: fight gravity with limited fuel and touch down softly on the pad.

Positions and speeds are integers in tenths of a cell (per turn), so play is exact and the HUD
can state the speeds the grid cannot show.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import ActionSet, GlyphTask, register_variants
from ...core.params import param
from ..common.palette import FLOOR, PLAYER, WALL
from ..common.view import overlay, signed

PAD = "="
UNIT = 10          # tenths per cell


@dataclass(frozen=True)
class LunarLanderParams:
    width: int = param(14, 8, 30)
    height: int = param(9, 7, 20)
    gravity: int = param(1, 1, 5)            # tenths of a cell per turn, added to Vy every turn
    # subtracted from Vy by the main engine
    main_thrust: int = param(3, lambda p: p.gravity + 1, lambda p: 5 * p.gravity)
    side_thrust: int = param(2, 1, 5)        # added to or subtracted from Vx by a side thruster
    fuel: int = param(40, 1, 200)            # turns of thrust
    safe_vy: int = param(3, 0, 10)           # the fastest touchdown that does not crash
    safe_vx: int = param(2, 0, 10)
    pad_width: int = param(4, 1, lambda p: p.width - 2)
    max_hill: int = param(4, 1, lambda p: p.height - 4)   # terrain rises at most this many rows
    crash_penalty: float = param(0.5, 0, 1)


class LunarLander(GlyphTask):
    title = "Lunar Lander"
    rules = ("Land the lander on the pad. Positions and speeds are in tenths of a cell: Vx "
             "(positive = right) and Vy (positive = down) in the status line are your speeds per "
             "turn, Alt is your height above the ground right below you. Every turn gravity adds "
             "{gravity} to Vy; MAIN subtracts {main_thrust} from Vy, LEFT and RIGHT push Vx by "
             "{side_thrust}; each thrust burns 1 fuel and does nothing without fuel. Then the "
             "lander moves by its speeds. Touching down on the pad with Vy at most {safe_vy} and "
             "Vx at most {safe_vx} either way lands; touching anything else or touching down "
             "faster crashes. The top edge stops you; leaving by a side is lost.")
    rewards = ("landing gives +{land_reward:g} plus up to +{fuel_bonus:g} more in proportion to the "
               "fuel left; crashing or getting lost costs {crash_penalty:g}.")
    ends = "when you land, crash or leave by a side"
    Params = LunarLanderParams
    ACTIONS = ActionSet([("NOOP", "fire nothing"), ("MAIN", "fire the main engine (slows falling)"),
                         ("LEFT", "fire the thruster that pushes you left"),
                         ("RIGHT", "fire the thruster that pushes you right")], noop="NOOP")
    glyphs = {FLOOR: "space", WALL: "rock", PAD: "landing pad", PLAYER: "lander"}
    default_max_turns = 150
    LAND_REWARD = 0.5

    def prompt_fields(self) -> dict:
        return super().prompt_fields() | {"land_reward": self.LAND_REWARD, "fuel_bonus": 1 - self.LAND_REWARD}

    def _setup(self, rng: np.random.Generator) -> None:
        p = self.params
        w, h = p.width, p.height
        start = int(rng.integers(1, w - p.pad_width))
        self.pad = range(start, start + p.pad_width)
        top = [0] * w                                    # first rock row of each column
        low = h - p.max_hill
        level = int(rng.integers(low, h))
        for c in self.pad:
            top[c] = level
        for c in range(start - 1, -1, -1):               # hills walk away from the pad
            top[c] = min(h - 1, max(low, top[c + 1] + int(rng.integers(-1, 2))))
        for c in range(start + p.pad_width, w):
            top[c] = min(h - 1, max(low, top[c - 1] + int(rng.integers(-1, 2))))
        self.top = top
        self.rows = ["".join(WALL if r > top[c] or (r == top[c] and c not in self.pad)
                             else PAD if r == top[c] else FLOOR for c in range(w)) for r in range(h)]
        self.x = int(rng.integers(1, w - 1)) * UNIT
        self.y = 0
        self.vx, self.vy = int(rng.integers(-2, 3)), 0
        self.fuel = p.fuel
        self.landed = False

    def column(self, x: int) -> int:
        return (x + UNIT // 2) // UNIT

    def _act(self, action: int) -> None:
        p = self.params
        ax, ay = 0, p.gravity
        if action:
            if self.fuel > 0:
                self.fuel -= 1
                if action == 1:
                    ay -= p.main_thrust
                else:
                    ax = p.side_thrust if action == 3 else -p.side_thrust
            else:
                self.say("Out of fuel.")
        self.vx += ax
        self.vy += ay
        # Sweep the move in sub-steps no longer than a cell, so no hill is jumped through.
        x0, y0 = self.x, self.y
        n = max(1, (max(abs(self.vx), abs(self.vy)) + UNIT - 1) // UNIT)
        for k in range(1, n + 1):
            x, y = x0 + self.vx * k // n, y0 + self.vy * k // n
            c = self.column(x)
            if not 0 <= c < p.width:
                self.x, self.y = x, y
                return self._end(-p.crash_penalty, "The lander left the screen.", False)
            if y < 0:                                     # the top edge stops the lander
                self.vy, y = 0, 0
            surface = (self.top[c] - 1) * UNIT
            if y >= surface:
                self.x, self.y = c * UNIT, surface
                if c in self.pad and self.vy <= p.safe_vy and abs(self.vx) <= p.safe_vx:
                    self.landed = True
                    bonus = (1 - self.LAND_REWARD) * self.fuel / p.fuel
                    return self._end(self.LAND_REWARD + bonus, "Landed!", True)
                return self._end(-p.crash_penalty, "The lander crashed.", False)
        self.x, self.y = x, y

    def _end(self, reward: float, message: str, won: bool) -> None:
        self.reward(reward)
        self.say(message)
        self.finish(won=won)

    def _grid(self) -> list[str]:
        rows = self.rows[:]
        overlay(rows, self.y // UNIT, self.column(self.x), PLAYER)
        return rows

    def _hud(self) -> str:
        c = self.column(self.x)
        alt = (self.top[c] - 1) * UNIT - self.y if 0 <= c < self.params.width else 0
        return (f"Vx {signed(self.vx)} | Vy {signed(self.vy)} | Alt {max(alt, 0)} | "
                f"Fuel {self.fuel}/{self.params.fuel}")


register_variants(LunarLander, "Classics", {
    "glyphbench/classics-lunarlander-v0": dict(max_turns=150),
})
