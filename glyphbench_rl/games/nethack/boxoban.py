"""Boxoban levels for MiniHack's Boxoban tasks, generated here instead of downloaded.

MiniHack's Boxoban tasks read DeepMind's Boxoban level files (10x10 rooms, four boxes), which are
a separate download. We make levels of the same form the way DeepMind's generator did: carve a
room by a random walk of floor inside the walls, put four targets and the player on the floor,
then play backwards from the solved room, pulling boxes off their targets. Our reverse play is
exhaustive: a breadth-first search over pulls (``common.pushing.pull_layers``) reaches every
state the solved room can be pulled to, layer k holding the states that need exactly k pushes,
so a start state taken from layer k is solvable by construction with k pushes at best. Each
level is then checked by the push-optimal solver (``solve``) and kept only if it solves it.

Difficulty. DeepMind's "medium" and "hard" sets were the levels a trained agent failed. With no
agent, we split by the optimal number of pushes (``PUSHES``): "unfiltered" takes the room's
farthest start state whatever its push count (median 15 pushes, a quarter of them 18 or more),
"medium" a start state needing 14 to 17 pushes, "hard" one needing 18 or more. A start state has
no box on a target and the player off the targets: Boxoban's text form (and MiniHack's reading of
it) has no glyph for either.

NetHack's rules agree with Sokoban's here: the tasks allow only the four cardinal moves, and
walking into a boulder pushes it one cell unless the cell beyond is wall, iron bars (the walls
here) or another boulder; fountains (the targets) and the start's up stairs do not stop it.
NetHack's one extra rule, squeezing past a boulder that will not move, needs a failed push, which
no solution makes.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..common.grid import DELTAS
from ..common.pushing import PushRoom, bits, pull_layers, search

SIZE, BOXES = 10, 4
WALL, FLOOR, BOX, TARGET, PLAYER = "#", " ", "$", ".", "@"
DIFFICULTIES = ("unfiltered", "medium", "hard")
# Optimal push counts each difficulty accepts, (fewest, most); None: no upper bound.
PUSHES: dict[str, tuple[int, int | None]] = {"unfiltered": (BOXES, None), "medium": (14, 17),
                                             "hard": (18, None)}
MOVES = ("N", "S", "W", "E")       # compass names of common.grid's UP, DOWN, LEFT, RIGHT
_COMPASS = dict(zip(("UP", "DOWN", "LEFT", "RIGHT"), MOVES))
Cell = tuple[int, int]

_FLOOR = (20, 28)         # floor cells of a room, fewest and most
_WALK_STEPS = 120         # the walker's steps at most (rooms that stay small are carved again)
_TURN = 0.35              # chance that the walker turns before a step
# Cells a walker step opens around itself: a cell, a pair either way, a 2x2 block, a row or
# column of three.
_BRUSHES = (((0, 0),), ((0, 0), (0, 1)), ((0, 0), (1, 0)), ((0, 0), (0, 1), (1, 0), (1, 1)),
            ((0, -1), (0, 0), (0, 1)), ((-1, 0), (0, 0), (1, 0)))
_PULL_LIMIT = 5000        # reverse-play states per room
_SOLVE_LIMIT = 10000      # states the checking solver may close
_MAX_ROOMS = 200          # rooms tried per level before generation gives up


@dataclass(frozen=True)
class Level:
    """A level in Boxoban's text form: SIZE rows of SIZE characters, the outer ring wall."""

    rows: tuple[str, ...]

    def __post_init__(self) -> None:
        rows = self.rows
        if len(rows) != SIZE or any(len(row) != SIZE for row in rows):
            raise ValueError(f"a level is {SIZE} rows of {SIZE} characters")
        if set("".join(rows)) - {WALL, FLOOR, BOX, TARGET, PLAYER}:
            raise ValueError(f"level characters are {WALL!r}, {FLOOR!r}, {BOX!r}, {TARGET!r}, {PLAYER!r}")
        if set(rows[0] + rows[-1] + "".join(row[0] + row[-1] for row in rows)) != {WALL}:
            raise ValueError("the outer ring of a level is wall")
        if len(self.cells(PLAYER)) != 1 or len(self.cells(BOX)) != len(self.cells(TARGET)):
            raise ValueError("a level has one player and as many boxes as targets")

    @classmethod
    def from_text(cls, text: str) -> Level:
        return cls(tuple(text.strip("\n").split("\n")))

    @property
    def text(self) -> str:
        return "\n".join(self.rows)

    def cells(self, char: str) -> list[Cell]:
        """(row, col) of every cell showing ``char``, in reading order."""
        return [(r, c) for r, row in enumerate(self.rows) for c, ch in enumerate(row) if ch == char]

    @property
    def player(self) -> Cell:
        return self.cells(PLAYER)[0]


def _carve(rng: np.random.Generator) -> list[Cell]:
    """The floor of a room: a walker starts on a random inner cell and, step by step, may turn,
    opens the cells of a random brush around itself and moves on (staying inside the walls),
    until the floor has at least a size drawn from ``_FLOOR``. Every brush holds the walker's own cell,
    so the floor is one connected room."""
    size = int(rng.integers(_FLOOR[0], _FLOOR[1] + 1))
    turns = rng.random(_WALK_STEPS) < _TURN
    headings = rng.integers(4, size=_WALK_STEPS)
    brushes = rng.integers(len(_BRUSHES), size=_WALK_STEPS)
    r, c = (int(x) for x in rng.integers(1, SIZE - 1, size=2))
    heading = int(rng.integers(4))
    floor: set[Cell] = set()
    for turn, new_heading, brush in zip(turns, headings, brushes):
        if turn:
            heading = int(new_heading)
        floor.update((r + dr, c + dc) for dr, dc in _BRUSHES[brush]
                     if 0 < r + dr < SIZE - 1 and 0 < c + dc < SIZE - 1)
        if len(floor) >= size:
            break
        dr, dc = DELTAS[heading]
        r, c = min(max(r + dr, 1), SIZE - 2), min(max(c + dc, 1), SIZE - 2)
    return sorted(floor)


def generate(rng: np.random.Generator, difficulty: str = "unfiltered") -> Level:
    """A solvable level whose optimal push count lies in ``PUSHES[difficulty]``; everything
    random is drawn from ``rng``."""
    if difficulty not in PUSHES:
        raise ValueError(f"difficulty is one of {DIFFICULTIES}, got {difficulty!r}")
    fewest, most = PUSHES[difficulty]
    for _ in range(_MAX_ROOMS):
        floor = _carve(rng)
        if len(floor) < _FLOOR[0]:
            continue
        targets = [floor[int(i)] for i in rng.choice(len(floor), size=BOXES, replace=False)]
        walls = {(r, c) for r in range(SIZE) for c in range(SIZE)}.difference(floor)
        room = PushRoom(walls, SIZE, SIZE, targets)
        layers, goals = pull_layers(room, _PULL_LIMIT), room.goals
        # The deepest layer in the band holding a start state: no box on a target, and room
        # for the player off the targets.
        deepest = len(layers) - 1 if most is None else min(len(layers) - 1, most)
        for pushes in range(deepest, fewest - 1, -1):
            starts = [(boxes, reach) for boxes, reach in layers[pushes]
                      if not boxes & goals and reach & ~goals]
            if starts:
                break
        else:
            continue
        boxes, reach = starts[int(rng.integers(len(starts)))]
        spots = bits(reach & ~goals)
        player = spots[int(rng.integers(len(spots)))]
        if search(room, boxes, player, limit=_SOLVE_LIMIT) is None:
            continue
        grid = [[WALL] * SIZE for _ in range(SIZE)]
        for cells, char in ((floor, FLOOR), (room.cells(goals), TARGET), (room.cells(boxes), BOX),
                            ([room.cell(player)], PLAYER)):
            for r, c in cells:
                grid[r][c] = char
        return Level(tuple("".join(row) for row in grid))
    raise RuntimeError(f"no {difficulty} Boxoban level in {_MAX_ROOMS} rooms; the generator's "
                       f"parameters cannot meet PUSHES[{difficulty!r}]")


def solve(level: Level, limit: int | None = 200_000) -> list[str] | None:
    """Compass moves ("N", "S", "E", "W", pushes included) of a solution with the fewest pushes,
    or None if the level has none or the search closes more than ``limit`` states."""
    walls = level.cells(WALL)
    room = PushRoom(walls, SIZE, SIZE, level.cells(TARGET))
    boxes = sum(1 << room.index(*cell) for cell in level.cells(BOX))
    found = search(room, boxes, room.index(*level.player), limit=limit)
    return None if found is None else [_COMPASS[name] for name in found[0]]


def to_des(level: Level) -> str:
    """The MiniHack des-file text of ``level``, built exactly as MiniHack's BoxoHack builds it
    from a Boxoban level: floor and targets become floor ('.'), walls iron bars ('F'), boxes
    boulders, targets fountains, and the player's cell the start position; lit, premapped,
    no teleporting, solid stone around the map. Coordinates there are (x, y) = (col, row)."""
    from minihack import LevelGenerator   # heavy (NetHack): only when a des file is wanted

    table = str.maketrans({FLOOR: ".", TARGET: ".", BOX: ".", PLAYER: ".", WALL: "F"})
    gen = LevelGenerator(map="\n".join(row.translate(table) for row in level.rows), lit=True,
                         flags=["noteleport", "premapped"], solidfill=" ")
    for r, c in level.cells(BOX):
        gen.add_boulder((c, r))
    for r, c in level.cells(TARGET):
        gen.add_fountain((c, r))
    r, c = level.player
    gen.set_start_pos((c, r))
    return gen.get_des()
