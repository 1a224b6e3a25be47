"""Wave and enemy mechanics for action games (Bomberman, Tower Defense, Wave Defense): enemies
with hit points, spawn schedules and spawn cells drawn from the task's rng, walking along a
fixed path, wandering a maze, and marching in a formation.

Every random choice takes the task's generator as an argument; nothing here keeps state of its
own, so a game's episode stays reproducible from its seed.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Iterable, Sequence

import numpy as np

from .grid import DELTAS

Cell = tuple[int, int]


@dataclass(slots=True)
class Enemy:
    """One enemy: its cell, hit points, heading (for wanderers and marchers) and path index."""

    r: int
    c: int
    hp: int = 1
    heading: int = 0      # index into grid.DELTAS
    step: int = 0         # index along a path, for path walkers

    @property
    def cell(self) -> Cell:
        return (self.r, self.c)


class Rolls:
    """Uniform draws in [0, 1) from the task's generator, fetched a block at a time: one numpy
    call per block instead of one per draw, whose overhead would dominate a turn's cost. The
    sequence depends only on the generator, so episodes stay reproducible from their seed."""

    __slots__ = ("rng", "block", "_buf")

    def __init__(self, rng: np.random.Generator, block: int = 256) -> None:
        self.rng, self.block, self._buf = rng, block, []

    def next(self) -> float:
        if not self._buf:
            self._buf = self.rng.random(self.block).tolist()[::-1]   # popped from the end
        return self._buf.pop()

    def pick(self, n: int) -> int:
        """A uniform index in 0..n-1."""
        return int(self.next() * n)


def hit(enemy: Enemy, damage: int = 1) -> bool:
    """Take ``damage`` hit points off ``enemy``; True when that kills it."""
    enemy.hp -= damage
    return enemy.hp <= 0


# -- spawning ---------------------------------------------------------------------------------
def spawn_schedule(rng: np.random.Generator, count: int, min_gap: int, max_gap: int,
                   start: int = 0) -> list[int]:
    """Turns (from ``start``) at which ``count`` enemies enter, each gap drawn in min_gap..max_gap."""
    if not 1 <= min_gap <= max_gap:
        raise ValueError(f"need 1 <= min_gap <= max_gap, got {min_gap} and {max_gap}")
    turns, t = [], start
    for gap in rng.integers(min_gap, max_gap + 1, size=count).tolist():
        turns.append(t)
        t += gap
    return turns


def spawn_cells(rng: np.random.Generator, cells: Sequence[Cell], count: int,
                away_from: Cell, min_dist: int) -> list[Cell]:
    """``count`` distinct cells from ``cells`` at Manhattan distance >= ``min_dist`` from
    ``away_from`` (nearer ones only when too few are that far), in a random order."""
    def dist(x: Cell) -> int:
        return abs(x[0] - away_from[0]) + abs(x[1] - away_from[1])
    pool = [x for x in cells if dist(x) >= min_dist]
    if len(pool) < count:
        pool = sorted(cells, key=dist, reverse=True)[:count]
    if len(pool) < count:
        raise ValueError(f"only {len(pool)} cells to spawn {count} enemies")
    picks = rng.choice(len(pool), size=count, replace=False).tolist()
    return [pool[i] for i in picks]


# -- movement ---------------------------------------------------------------------------------
def walk_path(enemies: Iterable[Enemy], path: Sequence[Cell], cells: int = 1) -> list[Enemy]:
    """Move every path walker ``cells`` cells along ``path``; return those that walked off its end."""
    leaked = []
    for e in enemies:
        e.step += cells
        if e.step >= len(path):
            leaked.append(e)
        else:
            e.r, e.c = path[e.step]
    return leaked


def wander(enemy: Enemy, open_: Callable[[int, int], bool], turn_roll: float, pick_roll: float,
           turn_chance: float = 0.3) -> bool:
    """Move a maze wanderer one cell: it keeps its heading while that cell is open, except that
    at a junction it turns when ``turn_roll`` < ``turn_chance``; when blocked, or turning, it
    takes the open direction that ``pick_roll`` selects. The rolls are uniform draws in [0, 1)
    from the task's rng (drawn in bulk by the caller: one generator call per turn is cheaper).
    Returns False when every neighbour is blocked (the enemy stays)."""
    r, c = enemy.r, enemy.c
    options = [d for d, (dr, dc) in enumerate(DELTAS) if open_(r + dr, c + dc)]
    if not options:
        return False
    if enemy.heading not in options or (len(options) > 2 and turn_roll < turn_chance):
        enemy.heading = options[int(pick_roll * len(options))]
    dr, dc = DELTAS[enemy.heading]
    enemy.r, enemy.c = r + dr, c + dc
    return True


def march(enemies: Sequence[Enemy], width: int, direction: int) -> tuple[int, bool]:
    """Move a formation one column in ``direction`` (+1 right, -1 left); a formation that would
    leave the field steps one row down instead and turns around. Returns (direction, descended)."""
    cols = [e.c for e in enemies]
    if not cols:
        return direction, False
    if (direction > 0 and max(cols) + 1 >= width) or (direction < 0 and min(cols) - 1 < 0):
        for e in enemies:
            e.r += 1
        return -direction, True
    for e in enemies:
        e.c += direction
    return direction, False


# -- targeting --------------------------------------------------------------------------------
def covered_steps(path: Sequence[Cell], cell: Cell, reach: int) -> tuple[int, ...]:
    """Indices of the path cells within ``reach`` of ``cell`` (the square), farthest along first:
    what a turret there can shoot at, computed once when it is built."""
    return tuple(i for i in range(len(path) - 1, -1, -1)
                 if abs(path[i][0] - cell[0]) <= reach and abs(path[i][1] - cell[1]) <= reach)


def volley(walkers: Iterable[Enemy], watch: Sequence[Sequence[tuple[object, int, bool]]]) -> int:
    """Fire every turret once; return the kills. ``walkers`` come farthest along the path first
    (the order they entered in, when they share one speed); ``watch[i]`` lists the turrets that
    reach path cell i as (key, damage, splash). A splash turret hits every walker it reaches, any
    other only the farthest one still alive."""
    fired = set()
    kills = 0
    for e in walkers:
        if e.hp <= 0:
            continue
        for key, damage, splash in watch[e.step]:
            if not splash:
                if key in fired:
                    continue
                fired.add(key)
            if hit(e, damage):
                kills += 1
                break
    return kills
