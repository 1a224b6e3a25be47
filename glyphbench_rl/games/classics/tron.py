"""Tron light cycles: two bikes move at once and leave walls behind; the first to crash loses.

Occupancy is one Python int bitmask over a board padded with a ring of blocked cells (index
(r + 1) * W + c + 1), so the opponent's flood fill is a few shifts per BFS layer over the whole
board instead of a walk over cells. Most turns need no fill: a table over the 8 cells round
the opponent's head gives its safe moves and whether the free cells among those 8 already join
them all (then the moves lead into one region). The bikes' heads are kept as such indices; the
picture is ``cells`` (a list of glyphs per row) and ``rows`` (each row joined), a row joined
again when a bike changes it.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from ...core import register_variants
from ...core.params import param
from ..common.grid import DELTAS, move_actions
from ..common.palette import FLOOR, PLAYER, WALL
from .versus import DRAW, LOSS, OUTCOME_REWARDS, WIN, VersusTask, choose

TRAIL, RIVAL, RIVAL_TRAIL, CRASH = "o", "E", "e", "*"
ANY_MOVE = tuple(range(len(DELTAS)))
RING = ((-1, -1), (-1, 0), (-1, 1), (0, 1), (1, 1), (1, 0), (1, -1), (0, -1))   # round a cell, clockwise


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


@lru_cache(maxsize=None)
def ring_moves(width: int) -> dict[int, tuple[tuple[int, ...], bool]]:
    """For every way the ring of 8 cells round a head can be blocked, keyed by its bits of the
    padded board shifted down to the ring's top-left corner (``Tron.around``): the safe moves
    (in action order), and whether the ring's free cells join every one of them (then those
    moves lead into one region, whatever lies beyond)."""
    table = {}
    for blocked in itertools.product((False, True), repeat=len(RING)):
        key = sum(1 << (dr + 1) * width + dc + 1 for (dr, dc), b in zip(RING, blocked) if b)
        safe = tuple(d for d, delta in enumerate(DELTAS) if not blocked[RING.index(delta)])
        joined = True
        if safe:   # walk the free ring both ways from the first safe move
            start = RING.index(DELTAS[safe[0]])
            reached = {start}
            for way in (1, -1):
                i = (start + way) % len(RING)
                while not blocked[i] and i not in reached:
                    reached.add(i)
                    i = (i + way) % len(RING)
            joined = all(RING.index(DELTAS[d]) in reached for d in safe)
        table[key] = safe, joined
    return table


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
        self.inside = sum(1 << (r + 1) * W + c + 1 for r in range(n) for c in range(n))
        self.border = ((1 << (n + 2) * W) - 1) & ~self.inside
        self.steps = tuple(dr * W + dc for dr, dc in DELTAS)
        self.ring, self.ring_mask = ring_moves(W), sum(1 << (dr + 1) * W + dc + 1 for dr, dc in RING)

    def index(self, r: int, c: int) -> int:
        return (r + 1) * self.W + c + 1

    @property
    def pos(self) -> list[tuple[int, int]]:
        """The cells (row, column) of your head and the opponent's."""
        return [(i // self.W - 1, i % self.W - 1) for i in self.heads]

    @pos.setter
    def pos(self, cells: list[tuple[int, int]]) -> None:
        self.heads = [self.index(r, c) for r, c in cells]

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
        for head in self.heads:
            self.blocked |= 1 << head
        self.redraw()
        self.outcome = None

    def redraw(self) -> None:
        """Join every row of ``cells`` again (after changing cells other than through a move)."""
        self.rows = list(map("".join, self.cells))

    def cells_of(self, glyph: str) -> list[tuple[int, int]]:
        return [(r, c) for r, row in enumerate(self.cells) for c, x in enumerate(row) if x == glyph]

    def around(self, head: int) -> int:
        """The blocked cells of the ring round ``head``: a key of ``self.ring``."""
        return self.blocked >> head - self.W - 1 & self.ring_mask

    def opponent_safe(self) -> tuple[int, ...]:
        """The directions in which the opponent does not crash at once (ignoring your move)."""
        return self.ring[self.around(self.heads[1])][0]

    def opponent_best(self, safe: tuple[int, ...], joined: bool = False) -> list[int]:
        """The safe directions into the largest open region, keeping out of reach of your head
        when regions tie (flood fill). ``joined``: the ring round the opponent's head joins
        every safe move (``ring_moves``); else the fill finds out."""
        if len(safe) < 2:
            return list(safe)
        if joined:
            return self.out_of_reach(safe)
        you, o = self.heads
        width, steps = self.W, self.steps
        targets = [o + steps[d] for d in safe]
        every = sum(1 << target for target in targets)
        free = self.inside & ~self.blocked
        filled = flood(1 << targets[0], free, width, until=every)
        if filled & every == every:
            return self.out_of_reach(safe)   # (the fill stopped once it held every move)
        best, best_score, area = [], -1, filled.bit_count()   # (that fill ran to the end)
        for d, target in zip(safe, targets):
            if not filled >> target & 1:   # moves into one region share its size: fill it once
                filled = flood(1 << target, free, width)
                area = filled.bit_count()
            score = 2 * area - (abs(target - you) in (1, width))   # a cell next to your head: -1
            if score > best_score:
                best, best_score = [d], score
            elif score == best_score:
                best.append(d)
        return best

    def out_of_reach(self, moves: tuple[int, ...]) -> list[int]:
        """The opponent's ``moves`` into one region (their sizes tie): those not next to your
        head, or all of them when every one is."""
        you, o = self.heads
        width, steps = self.W, self.steps
        if abs(o - you) > 2 * width:   # (too far apart for a move to end next to your head)
            return list(moves)
        return [d for d in moves if abs(o + steps[d] - you) not in (1, width)] or list(moves)

    def _agent_move(self, action: int) -> str | None:
        self.planned = action
        return None

    def _opponent_move(self) -> None:
        you, rival = self.heads
        safe, joined = self.ring[self.around(rival)]
        heading = choose(self.rng, self.params.strength, lambda: self.opponent_best(safe, joined),
                         safe or ANY_MOVE)
        you_to, rival_to = you + self.steps[self.planned], rival + self.steps[heading]
        blocked = self.blocked
        you_crash = you_to == rival_to or blocked >> you_to & 1
        rival_crash = you_to == rival_to or blocked >> rival_to & 1
        self.heads = [self._ride(you, you_to, you_crash, PLAYER, TRAIL),
                      self._ride(rival, rival_to, rival_crash, RIVAL, RIVAL_TRAIL)]
        if you_crash or rival_crash:
            self.say("Both bikes crashed." if you_crash and rival_crash else
                     "You crashed." if you_crash else "The opponent crashed.")
            self.outcome = DRAW if you_crash and rival_crash else LOSS if you_crash else WIN

    def _ride(self, head: int, to: int, crash: bool, glyph: str, trail: str) -> int:
        """Move a bike from ``head`` to ``to`` leaving ``trail``, or crash it where it is; its
        new head."""
        width, cells, rows = self.W, self.cells, self.rows
        r, c = divmod(head, width)
        row = cells[r - 1]
        if crash:
            row[c - 1] = CRASH
            rows[r - 1] = "".join(row)
            return head
        row[c - 1] = trail
        r2, c2 = divmod(to, width)
        if r2 != r:
            rows[r - 1] = "".join(row)
            row = cells[r2 - 1]
        row[c2 - 1] = glyph
        rows[r2 - 1] = "".join(row)
        self.blocked |= 1 << to
        return to

    def _result(self) -> str | None:
        return self.outcome

    def _grid(self) -> list[str]:
        return self.rows


register_variants(Tron, "Classics", {
    "glyphbench/classics-tron-v0": dict(size=12, walls=4, strength=0.9, max_turns=100),
})
