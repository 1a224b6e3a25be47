"""Tron light cycles: two bikes move at once and leave walls behind; the first to crash loses.

Occupancy is one Python int bitmask over a board padded with a ring of blocked cells (index
(r + 1) * W + c + 1), so the opponent's flood fill is a few shifts per BFS layer over the whole
board instead of a walk over cells.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from ..common.grid import DELTAS, move_actions
from ..common.palette import FLOOR, PLAYER, WALL
from .versus import DRAW, LOSS, OUTCOME_REWARDS, WIN, VersusTask, choose

TRAIL, RIVAL, RIVAL_TRAIL, CRASH = "o", "E", "e", "*"


@dataclass(frozen=True)
class TronParams:
    size: int = param(12, 6, 26)             # the arena is size x size; leaving it crashes
    # wall pairs placed point-symmetrically, so neither side is favoured
    walls: int = param(4, 0, lambda p: p.size * p.size // 8)
    # probability that the opponent takes its flood-fill move, else a random safe one
    strength: float = param(0.9, 0, 1)


def flood(start: int, free: int, width: int, until: int = 0) -> int:
    """The cells (bits) of ``free`` 4-connected to ``start`` (which must be in ``free``); with
    ``until``, possibly only part of them once that part holds every cell of ``until``."""
    f = start
    while True:
        # a step sideways then a step up or down: a region fills in about half the rounds
        g = (f | f << 1 | f >> 1) & free
        g = (g | g << width | g >> width) & free
        if g == f or until and g & until == until:
            return g
        f = g


class Tron(VersusTask):
    title = "Tron"
    rules = ("You ({you}) and the opponent ({rival}) ride light cycles on a {size}x{size} arena. "
             "Each turn both bikes move one cell at once, you in the direction you choose, and "
             "every cell a bike leaves becomes a wall of its trail. A bike crashes when it leaves "
             "the arena or enters a wall, a trail or a bike; two bikes entering the same cell both "
             "crash. Turning back the way you came (reversing) enters your own trail: a crash. With probability {strength:g} the opponent moves towards the most open "
             "space it can reach (flood fill), otherwise in a random safe direction.")
    rewards = OUTCOME_REWARDS + " Both crashing at once is a draw."
    ends = "when a bike crashes"
    Params = TronParams
    ACTIONS = move_actions()
    glyphs = {FLOOR: "empty", WALL: "wall", PLAYER: "you", TRAIL: "your trail",
              RIVAL: "opponent", RIVAL_TRAIL: "opponent trail", CRASH: "crashed bike"}
    default_max_turns = 100

    def prompt_fields(self) -> dict:
        return super().prompt_fields() | {"you": PLAYER, "rival": RIVAL}

    def _init(self) -> None:
        n = self.params.size
        self.W = W = n + 2
        inside = sum(1 << (r + 1) * W + c + 1 for r in range(n) for c in range(n))
        self.border = ((1 << (n + 2) * W) - 1) & ~inside
        self.steps = tuple(dr * W + dc for dr, dc in DELTAS)

    def index(self, r: int, c: int) -> int:
        return (r + 1) * self.W + c + 1

    def _setup(self, rng: np.random.Generator) -> None:
        n = self.params.size
        self.rng = rng
        r = int(rng.integers(1, n - 1))
        self.pos = [(r, 1), (n - 1 - r, n - 2)]     # you, opponent: mirror images through the centre
        self.cells = [[FLOOR] * n for _ in range(n)]
        keep_clear = {(a + dr, b + dc) for a, b in self.pos for dr in (-1, 0, 1) for dc in (-1, 0, 1)}
        placed = 0
        while placed < self.params.walls:
            a, b = int(rng.integers(n)), int(rng.integers(n))
            twin = (n - 1 - a, n - 1 - b)
            if (a, b) in keep_clear or twin in keep_clear or self.cells[a][b] == WALL or (a, b) == twin:
                continue
            self.cells[a][b] = self.cells[twin[0]][twin[1]] = WALL
            placed += 1
        self.blocked = self.border | sum(1 << self.index(a, b) for a, b in self.cells_of(WALL))
        for (a, b), glyph in zip(self.pos, (PLAYER, RIVAL)):
            self.cells[a][b] = glyph
            self.blocked |= 1 << self.index(a, b)
        self.outcome = None

    def cells_of(self, glyph: str) -> list[tuple[int, int]]:
        return [(r, c) for r, row in enumerate(self.cells) for c, x in enumerate(row) if x == glyph]

    def opponent_safe(self) -> list[int]:
        """The directions in which the opponent does not crash at once (ignoring your move)."""
        o, blocked = self.index(*self.pos[1]), self.blocked
        return [d for d, s in enumerate(self.steps) if not blocked >> (o + s) & 1]

    def opponent_best(self, safe: list[int]) -> list[int]:
        """The safe directions into the largest open region, keeping out of reach of your head
        when regions tie (flood fill)."""
        if len(safe) < 2:
            return safe
        o, you, free, width = self.index(*self.pos[1]), self.index(*self.pos[0]), ~self.blocked, self.W
        targets, near, every = [], [], 0
        for d in safe:
            target = o + self.steps[d]
            targets.append(target)
            near.append(abs(target - you) in (1, width))
            every |= 1 << target
        filled = flood(1 << targets[0], free, width, until=every)
        if filled & every == every:
            # every move leads into one region (the fill stopped once it held them all): the
            # sizes tie, so keeping out of reach of your head decides
            least = min(near)
            return [d for d, n in zip(safe, near) if n == least]
        best, best_score, area = [], -1, filled.bit_count()   # (that fill ran to the end)
        for d, target, n in zip(safe, targets, near):
            if not filled >> target & 1:   # moves into one region share its size: fill it once
                filled = flood(1 << target, free, self.W)
                area = filled.bit_count()
            score = 2 * area - n
            if score > best_score:
                best, best_score = [d], score
            elif score == best_score:
                best.append(d)
        return best

    def _agent_move(self, action: int) -> str | None:
        self.planned = action
        return None

    def _opponent_move(self) -> None:
        safe = self.opponent_safe()
        heading = choose(self.rng, self.params.strength, lambda: self.opponent_best(safe),
                         safe or [0, 1, 2, 3])
        targets = []
        for (r, c), d in zip(self.pos, (self.planned, heading)):
            dr, dc = DELTAS[d]
            targets.append((r + dr, c + dc))
        width, blocked, cells, same = self.W, self.blocked, self.cells, targets[0] == targets[1]
        crashed = [blocked >> (r + 1) * width + c + 1 & 1 or same for r, c in targets]   # (self.index)
        for i, (glyph, trail) in enumerate(((PLAYER, TRAIL), (RIVAL, RIVAL_TRAIL))):
            r, c = self.pos[i]
            if crashed[i]:
                cells[r][c] = CRASH
                continue
            cells[r][c] = trail
            r, c = self.pos[i] = targets[i]
            cells[r][c] = glyph
            self.blocked |= 1 << (r + 1) * width + c + 1
        if crashed[0] or crashed[1]:
            self.say("Both bikes crashed." if crashed[0] and crashed[1] else
                     "You crashed." if crashed[0] else "The opponent crashed.")
            self.outcome = DRAW if crashed[0] and crashed[1] else LOSS if crashed[0] else WIN

    def _result(self) -> str | None:
        return self.outcome

    def _grid(self) -> list[str]:
        return list(map("".join, self.cells))


register_variants(Tron, "Classics", {
    "glyphbench/classics-tron-v0": dict(size=12, walls=4, strength=0.9, max_turns=100),
})
