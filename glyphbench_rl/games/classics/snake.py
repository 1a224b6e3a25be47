"""Snake: steer a growing snake to food without hitting the edge or itself."""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass

import numpy as np

from ...core import GlyphTask, register_variants
from ...core.params import param
from ..common.grid import DELTAS, OPPOSITE, move_actions
from ..common.palette import FLOOR

HEADS = "▲▼◀▶"  # indexed like DELTAS: up, down, left, right


@dataclass(frozen=True)
class SnakeParams:
    size: int = param(8, 5, 26)              # the board is size x size cells
    target: int = param(8, 1, lambda p: p.size * p.size - p.start_length)   # food eaten to win
    death_penalty: float = param(0.5, 0, 1)
    start_length: int = param(3, 1, lambda p: p.size // 2)


class Snake(GlyphTask):
    title = "Snake"
    rules = ("The grid is the whole {size}x{size} board. The snake moves one cell per turn in "
             "its heading; an action sets a new heading (turning straight back is ignored). "
             "Eating food grows the snake by one cell and new food appears on a random empty "
             "cell. Leaving the board or running into the snake's own body kills it.")
    rewards = "+{food_reward:.4g} per food eaten; {target} food wins; dying costs {death_penalty:g}."
    ends = "when the snake dies or has eaten {target} food"
    Params = SnakeParams
    ACTIONS = move_actions("turn and move")
    glyphs = {FLOOR: "empty", "▲": "head moving up", "▼": "head moving down",
              "◀": "head moving left", "▶": "head moving right", "●": "body", "*": "food"}
    default_max_turns = 128

    def prompt_fields(self) -> dict:
        return super().prompt_fields() | {"food_reward": 1 / self.params.target}

    def _setup(self, rng: np.random.Generator) -> None:
        p = self.params
        mid = p.size // 2
        self.heading = 3  # right
        self.body = deque((mid, mid - i) for i in range(p.start_length))  # head first
        self.occupied = set(self.body)
        self.eaten = 0
        self.rng = rng
        self.food = self._place_food()

    def _place_food(self) -> tuple[int, int] | None:
        size = self.params.size
        free = size * size - len(self.occupied)
        if free == 0:
            return None
        k = int(self.rng.integers(free))
        for r in range(size):  # k-th free cell in row-major order
            for c in range(size):
                if (r, c) not in self.occupied:
                    if k == 0:
                        return (r, c)
                    k -= 1
        raise AssertionError("unreachable")

    def _act(self, action: int) -> None:
        if action != OPPOSITE[self.heading] or len(self.body) == 1:
            self.heading = action
        dr, dc = DELTAS[self.heading]
        hr, hc = self.body[0]
        head = (hr + dr, hc + dc)
        size = self.params.size
        grows = head == self.food
        tail = self.body[-1]
        hits_body = head in self.occupied and (grows or head != tail)
        if not (0 <= head[0] < size and 0 <= head[1] < size) or hits_body:
            self.reward(-self.params.death_penalty)
            self.say("The snake crashed." if not hits_body else "The snake bit itself.")
            self.finish(won=False)
            return
        if not grows:
            self.occupied.discard(self.body.pop())
        self.body.appendleft(head)
        self.occupied.add(head)
        if grows:
            self.eaten += 1
            self.reward(1 / self.params.target)
            self.say("Ate food.")
            if self.eaten >= self.params.target:
                self.finish(won=True)
                return
            self.food = self._place_food()
            if self.food is None:
                self.finish(won=True)

    def _grid(self) -> list[str]:
        size = self.params.size
        blank = FLOOR * size
        rows = [blank] * size
        drawn: dict[int, list[str]] = {}   # the rows with something on them, as lists of glyphs
        for r, c in self.body:
            row = drawn.get(r)
            if row is None:
                row = drawn[r] = list(blank)
            row[c] = "●"
        if self.food is not None:
            r, c = self.food
            row = drawn.get(r)
            if row is None:
                row = drawn[r] = list(blank)
            row[c] = "*"
        hr, hc = self.body[0]
        if 0 <= hr < size and 0 <= hc < size:
            row = drawn.get(hr)
            if row is None:
                row = drawn[hr] = list(blank)
            row[hc] = HEADS[self.heading]
        for r, row in drawn.items():
            rows[r] = "".join(row)
        return rows

    def _hud(self) -> str:
        return f"Food {self.eaten}/{self.params.target} | Length {len(self.body)}"


register_variants(Snake, "Classics", {
    "glyphbench/classics-snake-easy-v0": dict(size=8, target=8, max_turns=128),
    "glyphbench/classics-snake-medium-v0": dict(size=10, target=12, max_turns=256),
    "glyphbench/classics-snake-hard-v0": dict(size=14, target=20, max_turns=512),
})
