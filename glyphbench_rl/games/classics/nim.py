"""Nim (normal play): take objects from one heap per turn; whoever takes the last object wins."""

from __future__ import annotations

from dataclasses import dataclass
from functools import reduce
from operator import xor

import numpy as np

from ...core import ActionSet, register_variants
from ...core.params import param
from ..common.palette import FLOOR
from .versus import LOSS, OUTCOME_REWARDS, WIN, VersusTask, choose

OBJECT = "●"


@dataclass(frozen=True)
class NimParams:
    heaps: int = param(3, 2, 9)
    max_heap: int = param(5, 2, 9)           # heap sizes are drawn from 1..max_heap; one turn takes 1..max_heap
    # probability that the opponent plays a nim-sum move when it has one
    strength: float = param(0.6, 0, 1)


def winning_moves(heaps: list[int]) -> list[tuple[int, int]]:
    """Every (heap, count) that leaves a nim-sum of zero; none when the nim-sum already is zero."""
    s = reduce(xor, heaps, 0)
    return [(h, n - (n ^ s)) for h, n in enumerate(heaps) if s and n ^ s < n]


class Nim(VersusTask):
    title = "Nim"
    rules = ("Each grid row is a heap of objects (heap 1 at the top, {heaps} heaps). You and the "
             "opponent take turns; a turn takes 1 or more objects from one heap. Whoever takes the "
             "last object wins. You move first; the opponent answers every move. With probability "
             "{strength:g} the opponent plays a move that leaves the XOR of the heap sizes at zero "
             "(when one exists), otherwise a random legal move. Taking more than a heap holds wastes "
             "your turn.")
    rewards = OUTCOME_REWARDS
    ends = "when the last object is taken"
    Params = NimParams
    glyphs = {OBJECT: "object", FLOOR: "empty"}
    default_max_turns = 30

    def _make_actions(self) -> ActionSet:
        p = self.params
        names = [f"H{h + 1}T{k}" for h in range(p.heaps) for k in range(1, p.max_heap + 1)]
        return ActionSet(groups=[("HhTk takes k objects from heap h", names)])

    def _init(self) -> None:
        m = self.params.max_heap
        self._rows = [OBJECT * n + FLOOR * (m - n) for n in range(m + 1)]

    def _setup(self, rng: np.random.Generator) -> None:
        p = self.params
        self.rng = rng
        while True:  # a start with a nonzero XOR: the first mover (you) can force a win
            self.heaps = [int(n) for n in rng.integers(1, p.max_heap + 1, size=p.heaps)]
            if reduce(xor, self.heaps, 0):
                break
        self.last_mover = None  # the result once the heaps are empty: whoever moved last won

    def _agent_move(self, action: int) -> str | None:
        h, k = divmod(action, self.params.max_heap)
        k += 1
        if k > self.heaps[h]:
            return f"Heap {h + 1} has only {self.heaps[h]}."
        self.heaps[h] -= k
        self.last_mover = WIN
        return None

    def _opponent_move(self) -> None:
        legal = [(h, k) for h, n in enumerate(self.heaps) for k in range(1, n + 1)]
        h, k = choose(self.rng, self.params.strength, winning_moves(self.heaps), legal)
        self.heaps[h] -= k
        self.last_mover = LOSS
        self.say(f"Opponent took {k} from heap {h + 1}.")

    def _result(self) -> str | None:
        return None if any(self.heaps) else self.last_mover

    def _grid(self) -> list[str]:
        return [self._rows[n] for n in self.heaps]


register_variants(Nim, "Classics", {
    "glyphbench/classics-nim-easy-v0": dict(heaps=3, max_heap=5, strength=0.6, max_turns=30),
    "glyphbench/classics-nim-hard-v0": dict(heaps=3, max_heap=7, strength=0.9, max_turns=40),
})
