"""Farm: till, plant, water and harvest crops on a small field until the harvest target is met.

A crop goes seed -> sprout -> ripe; each stage needs watering and then ``grow_time`` turns to
grow. The watering can holds ``can_size`` waterings and is refilled by walking into the pond.
Play is deterministic; the pond's place and your start come from the seed.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import ActionSet, GlyphTask, register_variants
from ...core.params import param
from ..common.grid import DELTAS, MOVES
from ..common.palette import PLAYER, WALL

GRASS, TILLED, SEED, SEED_WET, SPROUT, SPROUT_WET, RIPE = "·", "=", "s", "S", "p", "P", "♣"
POND = "≈"
GROWING = {SEED_WET: SPROUT, SPROUT_WET: RIPE}   # a watered stage and what it grows into
WATERED = {SEED: SEED_WET, SPROUT: SPROUT_WET}
NAMES = {GRASS: "grass", TILLED: "tilled soil", SEED: "dry seed", SEED_WET: "watered seed",
         SPROUT: "dry sprout", SPROUT_WET: "watered sprout", RIPE: "ripe crop"}
TILL, PLANT, WATER, HARVEST = range(4, 8)
Cell = tuple[int, int]


@dataclass(frozen=True)
class FarmParams:
    size: int = param(7, 4, 16)              # the field is size x size inside the fence
    target: int = param(8, 1, 100)           # harvests that win
    grow_time: int = param(4, 1, 20)         # turns a watered seed or sprout takes to grow a stage
    can_size: int = param(4, 1, 20)          # waterings a full can holds
    pond: int = param(2, 1, lambda p: p.size - 1)   # pond cells, in a row along one fence


class Farm(GlyphTask):
    title = "Farm"
    rules = ("You farm a fenced {size}x{size} field. Actions work on the cell you stand on: TILL "
             "grass into soil, PLANT a seed in tilled soil, WATER a dry seed or sprout, HARVEST a "
             "ripe crop (the soil stays tilled). A watered seed grows into a sprout after "
             "{grow_time} turns and a watered sprout ripens after {grow_time} more; each stage must "
             "be watered again. Your can holds {can_size} waterings; walk into the pond to refill "
             "it. Seeds are unlimited.")
    rewards = "+{harvest_reward:.4g} per harvest; {target} harvests win."
    ends = "when you have harvested {target} crops"
    Params = FarmParams
    ACTIONS = ActionSet([*[(n, f"walk one cell {n.lower()}") for n in MOVES],
                         ("TILL", "till the grass you stand on"),
                         ("PLANT", "plant a seed in the tilled soil you stand on"),
                         ("WATER", "water the dry seed or sprout you stand on"),
                         ("HARVEST", "harvest the ripe crop you stand on")])
    glyphs = {WALL: "fence", POND: "pond", **NAMES, PLAYER: "you"}
    default_max_turns = 150

    def prompt_fields(self) -> dict:
        return super().prompt_fields() | {"harvest_reward": 1 / self.params.target}

    def _setup(self, rng: np.random.Generator) -> None:
        p = self.params
        n = p.size
        self.rows = [[WALL] * (n + 2)] + [[WALL] + [GRASS] * n + [WALL] for _ in range(n)] + [[WALL] * (n + 2)]
        side = int(rng.integers(4))                    # the pond lies along this fence
        start = int(rng.integers(1, n - p.pond + 2))
        for i in range(start, start + p.pond):
            r, c = {0: (1, i), 1: (n, i), 2: (i, 1), 3: (i, n)}[side]
            self.rows[r][c] = POND
        free = [(r, c) for r in range(1, n + 1) for c in range(1, n + 1) if self.rows[r][c] == GRASS]
        self.pos = free[int(rng.integers(len(free)))]
        self.timers: dict[Cell, int] = {}              # watered cell -> turns it has grown
        self.water = p.can_size
        self.harvested = 0

    def _act(self, action: int) -> None:
        self._grow()   # first, so a crop watered this turn has grown a stage after grow_time more
        if action < 4:
            self._walk(action)
        else:
            self._work(action)

    def _walk(self, action: int) -> None:
        dr, dc = DELTAS[action]
        r, c = self.pos[0] + dr, self.pos[1] + dc
        ch = self.rows[r][c]
        if ch == POND:
            self.water = self.params.can_size
            self.say("You filled the can.")
        elif ch == WALL:
            self.say("The fence is in the way.")
        else:
            self.pos = (r, c)

    def _work(self, action: int) -> None:
        r, c = self.pos
        here = self.rows[r][c]
        if action == TILL and here == GRASS:
            self.rows[r][c] = TILLED
        elif action == PLANT and here == TILLED:
            self.rows[r][c] = SEED
        elif action == WATER and here in WATERED:
            if self.water == 0:
                self.say("The can is empty.")
                return
            self.water -= 1
            self.rows[r][c] = WATERED[here]
            self.timers[self.pos] = 0
        elif action == HARVEST and here == RIPE:
            self.rows[r][c] = TILLED
            self.harvested += 1
            self.reward(1 / self.params.target)
            self.say("Harvested a crop.")
            if self.harvested >= self.params.target:
                self.finish(won=True)
        else:
            self.say(f"Nothing to {self.actions[action].name.lower()} here.")

    def _grow(self) -> None:
        for cell in list(self.timers):
            self.timers[cell] += 1
            if self.timers[cell] >= self.params.grow_time:
                del self.timers[cell]
                r, c = cell
                self.rows[r][c] = GROWING[self.rows[r][c]]

    def _grid(self) -> list[str]:
        r, c = self.pos
        rows = ["".join(row) for row in self.rows]
        rows[r] = rows[r][:c] + PLAYER + rows[r][c + 1:]
        return rows

    def _hud(self) -> str:
        r, c = self.pos
        return (f"Harvested {self.harvested}/{self.params.target} | Can {self.water}/{self.params.can_size} | "
                f"On {NAMES[self.rows[r][c]]}")


register_variants(Farm, "Classics", {
    "glyphbench/classics-farm-v0": dict(size=7, target=8, grow_time=4, can_size=4, max_turns=150),
})
