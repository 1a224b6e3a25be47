"""Battleship, one-sided: find and sink a hidden fleet within the shot budget (the turn cap)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import ActionSet, cell_names, register_variants
from ...core.params import param, require
from ..common.palette import FLOOR
from .versus import WIN, VersusTask

MISS, HIT, SUNK = "~", "X", "#"
_TRIES = 10_000   # placement attempts per reset before the fleet is declared impossible to fit


@dataclass(frozen=True)
class BattleshipParams:
    size: int = param(10, 4, 26)
    fleet: tuple[int, ...] = param((5, 4, 3, 3, 2), 1, lambda p: p.size)   # ship lengths
    fleet_bonus: float = param(0.5, 0, 1)    # reward for sinking the whole fleet; hits share the rest

    def check(self) -> None:
        half = self.size * self.size // 2
        require(sum(self.fleet) <= half, "fleet", f"at most {half} cells of ships (half of the "
                f"{self.size}x{self.size} sea)", self.fleet)


class Battleship(VersusTask):
    title = "Battleship"
    rules = ("A fleet of ships of lengths {fleet_text} is hidden on the {size}x{size} sea, each ship "
             "a straight line across or down; ships never overlap but may touch. Each turn you fire "
             "at one cell: a miss shows {miss}, a hit {hit}, and once every cell of a ship is hit the "
             "ship is sunk and shows {sunk}. The status line lists the ships still afloat. Firing at "
             "a cell again wastes the turn; every turn is a shot, so the turn limit is your "
             "shot budget.")
    rewards = ("each hit gives {hit_reward:.4g}; sinking the whole fleet gives {fleet_bonus:g} more; "
               "there are no penalties.")
    ends = "when the whole fleet is sunk"
    Params = BattleshipParams
    glyphs = {FLOOR: "not fired at", MISS: "miss", HIT: "hit", SUNK: "sunk ship"}
    axes = True
    default_max_turns = 75

    def prompt_fields(self) -> dict:
        return super().prompt_fields() | {
            "fleet_text": " ".join(map(str, self.params.fleet)), "hit_reward": self.hit_reward,
            "miss": MISS, "hit": HIT, "sunk": SUNK}

    def _make_actions(self) -> ActionSet:
        n = self.params.size
        return ActionSet(groups=[("fire at that cell", cell_names(n, n))])

    def _init(self) -> None:
        p = self.params
        self.hit_reward = (1 - p.fleet_bonus) / sum(p.fleet)
        self.outcome_rewards = {WIN: p.fleet_bonus}

    def _setup(self, rng: np.random.Generator) -> None:
        n = self.params.size
        self.ship_at: dict[int, int] = {}           # cell index (row-major) -> ship number
        self.ships: list[list[int]] = []            # the cells of each ship
        for length in self.params.fleet:
            for _ in range(_TRIES):
                across = bool(rng.integers(2))
                r = int(rng.integers(n if across else n - length + 1))
                c = int(rng.integers(n - length + 1 if across else n))
                cells = [r * n + c + i if across else (r + i) * n + c for i in range(length)]
                if not any(x in self.ship_at for x in cells):
                    break
            else:
                raise RuntimeError(f"{self.task_id}: could not place the fleet; use fewer or shorter ships")
            for x in cells:
                self.ship_at[x] = len(self.ships)
            self.ships.append(cells)
        self.left = [len(cells) for cells in self.ships]   # unhit cells per ship
        self.cells = [[FLOOR] * n for _ in range(n)]

    def _agent_move(self, action: int) -> str | None:
        r, c = divmod(action, self.params.size)
        if self.cells[r][c] != FLOOR:
            return f"{self.actions[action].name} was already fired at."
        ship = self.ship_at.get(action)
        if ship is None:
            self.cells[r][c] = MISS
            self.say("Miss.")
            return None
        self.reward(self.hit_reward)
        self.left[ship] -= 1
        if self.left[ship]:
            self.cells[r][c] = HIT
            self.say("Hit.")
            return None
        for x in self.ships[ship]:
            self.cells[x // self.params.size][x % self.params.size] = SUNK
        self.say(f"Hit: you sank a ship of length {len(self.ships[ship])}.")
        return None

    def _result(self) -> str | None:
        return None if any(self.left) else WIN

    def _grid(self) -> list[str]:
        return ["".join(row) for row in self.cells]

    def _hud(self) -> str:
        return "Afloat " + (" ".join(str(len(s)) for s, k in zip(self.ships, self.left) if k) or "none")


register_variants(Battleship, "Classics", {
    "glyphbench/classics-battleship-v0": dict(size=10, fleet=(5, 4, 3, 3, 2), max_turns=75),
})
