"""Warehouse: drive a forklift between the racks, pick up packages and deliver each to its dock.

Every level is solvable by construction: the racks always leave the side aisles and one gap
each open, so every floor cell is reachable (the generator checks it with a flood fill).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import ActionSet, GlyphTask, register_variants
from ...core.params import param
from ..common.grid import DELTAS, MOVES, Board, bfs_distances
from ..common.palette import FLOOR, PLAYER, WALL

FILLED = "■"
Cell = tuple[int, int]


@dataclass(frozen=True)
class WarehouseParams:
    size: int = param(9, 5, 20)              # the floor is size x size inside the outer wall
    packages: int = param(3, 1, lambda p: min(8, (p.size + 1) // 2))   # packages, each with its own dock
    rack_gap: int = param(2, 1, lambda p: p.size)   # floor rows between two rows of racks
    # part of the return shared by the deliveries; the rest is the finish bonus
    delivery_share: float = param(0.5, 0, 1, open_lo=True, open_hi=True)
    time_weight: float = param(0.5, 0, 1, open_hi=True)   # share of the finish bonus lost by using every turn


class Warehouse(GlyphTask):
    title = "Warehouse"
    rules = ("You drive a forklift in a {size}x{size} warehouse with rows of racks. Packages "
             "(lowercase letters) lie on the floor; each belongs to the dock with the same "
             "capital letter. Drive onto a package and PICK it up (you carry one at a time), drive "
             "onto its dock and DROP it to deliver it. Dropping on plain floor sets the package "
             "down there; a dock refuses other packages. You can drive over packages and docks.")
    rewards = ("+{delivery_reward:.4g} per delivery; delivering the last package adds "
               "{finish_bonus:g} x (1 - {time_weight:g} x turns used / {max_turns}).")
    ends = "when every package is delivered"
    Params = WarehouseParams
    ACTIONS = ActionSet([*[(n, f"drive one cell {n.lower()}") for n in MOVES],
                         ("PICK", "pick up the package you are on"),
                         ("DROP", "put down the package you carry")])
    default_max_turns = 150

    def _init(self) -> None:
        n = self.params.packages
        self.letters = "abcdefgh"[:n]
        self._vocab = {WALL: "wall or rack", FLOOR: "floor", PLAYER: "forklift",
                       **{x: "package" for x in self.letters},
                       **{x.upper(): f"dock for {x}" for x in self.letters}, FILLED: "full dock"}

    def vocab(self) -> dict[str, str]:
        return self._vocab

    def prompt_fields(self) -> dict:
        p = self.params
        return super().prompt_fields() | {"delivery_reward": p.delivery_share / p.packages,
                                          "finish_bonus": 1 - p.delivery_share}

    # -- generation -------------------------------------------------------------------------------
    def _setup(self, rng: np.random.Generator) -> None:
        p = self.params
        n = p.size
        board = Board(n + 2, n + 2, FLOOR)
        for i in range(n + 2):
            board[0, i] = board[n + 1, i] = board[i, 0] = board[i, n + 1] = WALL
        # racks: every (rack_gap + 1)-th row, leaving the two side aisles, one random gap, and the
        # two bottom rows (the docks and the lane in front of them) free
        for r in range(p.rack_gap + 1, n - 1, p.rack_gap + 1):
            gap = int(rng.integers(2, n))
            for c in range(2, n):
                if c != gap:
                    board[r, c] = WALL
        self.board = board
        dock_cols = sorted(rng.choice(np.arange(1, n + 1), size=p.packages, replace=False).tolist())
        self.docks = {x: (n, c) for x, c in zip(self.letters, dock_cols)}
        floor = [(r, c) for r in range(1, n - 1) for c in range(1, n + 1) if board[r, c] == FLOOR]
        picks = rng.choice(len(floor), size=p.packages + 1, replace=False).tolist()
        self.items = {x: floor[i] for x, i in zip(self.letters, picks)}   # package -> cell on the floor
        self.pos = floor[picks[-1]]
        reach = bfs_distances(self.pos, lambda r, c: board.rows[r][c] != WALL)
        assert all(cell in reach for cell in [*self.items.values(), *self.docks.values()])
        self.carrying: str | None = None
        self.delivered: set[str] = set()
        self.rows = [row.copy() for row in board.rows]   # the board with docks and packages drawn
        for x in self.letters:
            self._paint(self.docks[x], x.upper())
            self._paint(self.items[x], x)

    def _paint(self, cell: Cell, ch: str) -> None:
        self.rows[cell[0]][cell[1]] = ch

    # -- play ---------------------------------------------------------------------------------------
    def _here(self) -> tuple[str | None, str | None]:
        """The package lying here and the dock here (letters), if any."""
        item = next((x for x, cell in self.items.items() if cell == self.pos), None)
        dock = next((x for x, cell in self.docks.items() if cell == self.pos), None)
        return item, dock

    def _act(self, action: int) -> None:
        if action < 4:
            dr, dc = DELTAS[action]
            r, c = self.pos[0] + dr, self.pos[1] + dc
            if self.board.rows[r][c] == WALL:
                self.say("Blocked by a rack or wall.")
            else:
                self.pos = (r, c)
            return
        item, dock = self._here()
        if action == 4:   # PICK
            if self.carrying is not None:
                self.say("You already carry a package.")
            elif item is None:
                self.say("There is no package here.")
            else:
                self.carrying = item
                del self.items[item]
                self._paint(self.pos, FLOOR)   # packages never lie on docks
            return
        if self.carrying is None:   # DROP
            self.say("You carry nothing.")
        elif dock is not None and dock != self.carrying:
            self.say(f"Dock {dock.upper()} takes only package {dock}.")
        elif item is not None:
            self.say("A package already lies here.")
        elif dock == self.carrying:
            p = self.params
            self.delivered.add(dock)
            self.carrying = None
            self._paint(self.pos, FILLED)
            self.reward(p.delivery_share / p.packages)
            self.say(f"Delivered {dock}.")
            if len(self.delivered) == p.packages:
                self.reward((1 - p.delivery_share) * self.time_bonus(p.time_weight))
                self.say("Every package is delivered.")
                self.finish(won=True)
        else:
            self.items[self.carrying] = self.pos
            self._paint(self.pos, self.carrying)
            self.carrying = None

    def _grid(self) -> list[str]:
        rows = ["".join(row) for row in self.rows]
        r, c = self.pos
        rows[r] = rows[r][:c] + PLAYER + rows[r][c + 1:]
        return rows

    def _hud(self) -> str:
        parts = [f"Delivered {len(self.delivered)}/{self.params.packages}",
                 f"Carrying {self.carrying or 'nothing'}"]
        item, dock = self._here()
        if item is not None:
            parts.append(f"On package {item}")
        if dock is not None:
            parts.append("On full dock" if dock in self.delivered else f"On dock {dock.upper()}")
        return " | ".join(parts)


register_variants(Warehouse, "Classics", {
    "glyphbench/classics-warehouse-v0": dict(size=9, packages=3, max_turns=150),
})
