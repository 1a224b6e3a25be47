"""Spawners for real-time games (one tick per turn), driven by the task's rng.

- ``Bag``: shuffled-bag draws (Tetris's 7-bag).
- ``Lane``: a cyclic row that slides one cell every ``period`` ticks (Frogger's cars and logs).
  Its content is a pure function of the tick, so a whole lane renders as one precomputed string
  and a planner can read any future tick.
- ``runs``: a random pattern of objects and gaps, the way rows of cars, logs and trees spawn.
- ``Draws``: uniform draws from a numpy stream taken in blocks, for the few draws a turn that
  chasers and wanderers make (one numpy call per draw costs more than their whole turn).
"""

from __future__ import annotations

from itertools import chain
from operator import length_hint
from typing import Iterator, Sequence, TypeVar

import numpy as np

T = TypeVar("T")


class Bag:
    """Draws every item once per shuffled bag, then refills: no long droughts, no floods."""

    __slots__ = ("items", "rng", "queue")

    def __init__(self, items: Sequence[T], rng: np.random.Generator) -> None:
        self.items, self.rng = tuple(items), rng
        self.queue: list[T] = []

    def _fill(self) -> None:
        self.queue.extend(self.items[int(i)] for i in self.rng.permutation(len(self.items)))

    def draw(self) -> T:
        if not self.queue:
            self._fill()
        return self.queue.pop(0)

    def peek(self) -> T:
        if not self.queue:
            self._fill()
        return self.queue[0]


class Lane:
    """A cyclic row of cells that slides ``direction`` (+1 right, -1 left) one cell every
    ``period`` ticks; ``phase`` staggers lanes of equal speed."""

    __slots__ = ("pattern", "direction", "period", "phase", "_rotations")

    def __init__(self, pattern: str, direction: int, period: int, phase: int = 0) -> None:
        if direction not in (-1, 1) or period < 1:
            raise ValueError("a lane needs direction +1 or -1 and period >= 1")
        self.pattern, self.direction, self.period, self.phase = pattern, direction, period, phase
        n = len(pattern)
        # rotation k: the pattern shifted k cells to the right (wrapping)
        self._rotations = tuple(pattern[n - k:] + pattern[:n - k] for k in range(n))

    def shift(self, tick: int) -> int:
        """Cells moved (signed) by the end of ``tick``; moves happen at ticks 1, 2, ..."""
        moves = (tick + self.phase) // self.period - self.phase // self.period
        return self.direction * moves

    def moves_at(self, tick: int) -> int:
        """Cells moved (signed) during ``tick`` itself: 0 or the direction."""
        return self.direction if tick >= 1 and (tick + self.phase) % self.period == 0 else 0

    def row(self, tick: int) -> str:
        """The lane's cells at the end of ``tick``."""
        return self._rotations[self.shift(tick) % len(self.pattern)]


def runs(rng: np.random.Generator, width: int, item: str, empty: str,
         lengths: tuple[int, int], gaps: tuple[int, int]) -> str:
    """``width`` cells of alternating gaps and runs of ``item`` whose lengths are drawn uniformly
    from the inclusive ranges ``gaps`` and ``lengths`` (cut off at ``width``)."""
    cells: list[str] = []
    while len(cells) < width:
        cells.extend(empty * int(rng.integers(gaps[0], gaps[1] + 1)))
        cells.extend(item * int(rng.integers(lengths[0], lengths[1] + 1)))
    return "".join(cells[:width])


class Draws:
    """Uniform floats in [0, 1) from a numpy stream, drawn ``block`` at a time; the sequence is
    the stream's own, so it is as reproducible as the stream. A copy (``copy.deepcopy`` of a
    task, a pickle) goes on with the same floats as the original, independently."""

    __slots__ = ("stream", "_blocks", "random")

    def __init__(self, stream: np.random.Generator, block: int = 256, first: list[float] | None = None) -> None:
        self.stream = stream
        self._blocks = _Blocks(stream, block, first)
        # random(): the next float of the blocks chained (a C call: half the cost of a method
        # indexing a block)
        self.random = chain.from_iterable(self._blocks).__next__

    def below(self, n: int) -> int:
        """A uniform int in [0, n)."""
        return int(self.random() * n)

    def __reduce__(self):
        blocks = self._blocks
        left = length_hint(blocks.left)   # (the floats of the block in hand not yet drawn)
        return Draws, (self.stream, blocks.size, blocks.block[len(blocks.block) - left:])


class _Blocks:
    """The blocks ``Draws`` chains, each drawn from the stream when the last has run out (the
    first may be given: the rest of a copied block), and the one in hand, to copy from."""
    __slots__ = ("stream", "size", "block", "left")

    def __init__(self, stream: np.random.Generator, size: int, first: list[float] | None) -> None:
        self.stream, self.size, self.block = stream, size, first or []
        self.left = iter(self.block)

    def __iter__(self) -> "_Blocks":
        return self

    def __next__(self) -> Iterator[float]:
        if length_hint(self.left):   # (the given first block, not yet handed out)
            return self.left
        self.block = self.stream.random(self.size).tolist()
        self.left = iter(self.block)
        return self.left
