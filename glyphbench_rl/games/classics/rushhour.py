"""Rush Hour: slide cars and trucks along their lanes on a 6x6 lot until the red car can leave.

Levels: the red car is parked near the left end of the exit row and vertical vehicles across
the row ahead of it, the rest anywhere (each letter has a fixed orientation, so the action names
never change between levels). A quick check drops parkings that can never clear the exit row; a
breadth-first search then gives the fewest one-cell moves to the exit, and the parking is kept
when that is at least ``min_moves``. Random parkings rarely need many moves, so the search is the
cost of a reset: a state is one int holding the vehicle offsets and the occupied cells, and a move
is a table lookup, a mask test and an addition.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import ActionSet, GlyphTask, register_variants
from ...core.params import param
from ..common.grid import bfs_search
from ..common.palette import FLOOR, GOAL, WALL

N = 6                   # the lot is N x N
EXIT_ROW = 2            # the exit is in the right wall of this row
RED = "X"
_OCC = 36               # state bits from here on hold the lot's occupancy, one bit per cell
_OUT = 1 << (_OCC + N * N)   # a state bit that is always set: the cells past the lot's edge
_SEARCH_LIMIT = 5000    # positions the solver may see per parking before it is given up
_TRIES = 2000           # parkings tried per reset before the parameters are declared impossible


@dataclass(frozen=True)
class RushHourParams:
    horizontal: int = param(1, 0, 4)         # vehicles besides the red car that move left-right
    vertical: int = param(3, 0, 6)           # vehicles that move up-down
    truck_chance: float = param(0.3, 0, 1)   # a vehicle is a 3-cell truck with this probability, else a car
    min_moves: int = param(8, 1, 40)         # generated levels need at least this many one-cell moves
    time_weight: float = param(0.5, 0, 1, open_hi=True)   # share of the win reward lost by using every turn


class Lot:
    """Vehicles fixed to lanes: vehicle v covers ``lengths[v]`` cells of its row (horizontal) or
    column (vertical) from its offset on. A state is one int: 3 bits of offset per vehicle, and
    from bit ``_OCC`` on the cells they cover, so a move is one table lookup, one mask test and
    one addition (this search is what makes a reset fast or slow)."""

    def __init__(self, horizontal: list[bool], lanes: list[int], lengths: list[int]) -> None:
        self.count, self.horizontal, self.lanes, self.lengths = len(lanes), horizontal, lanes, lengths
        self.cover: list[list[int]] = []
        self.steps = []   # per vehicle: shift, then per offset the blocking mask and the delta
        for v, (h, lane, length) in enumerate(zip(horizontal, lanes, lengths)):
            def bit(i: int, lane=lane, h=h) -> int:
                return 1 << (_OCC + (lane * N + i if h else i * N + lane))
            cover = [sum(bit(o + i) for i in range(length)) for o in range(N - length + 1)]
            last, one = len(cover) - 1, 1 << 3 * v
            self.cover.append(cover)
            self.steps.append((3 * v,
                               [_OUT if o == 0 else bit(o - 1) for o in range(last + 1)],
                               [0 if o == 0 else cover[o - 1] - cover[o] - one for o in range(last + 1)],
                               [_OUT if o == last else bit(o + length) for o in range(last + 1)],
                               [0 if o == last else cover[o + 1] - cover[o] + one for o in range(last + 1)]))

    def state(self, offsets: list[int]) -> int:
        return sum(o << 3 * v | self.cover[v][o] for v, o in enumerate(offsets)) | _OUT

    def offset(self, state: int, v: int) -> int:
        return state >> 3 * v & 7

    def moves(self, state: int):
        """(action index, next state) for every legal one-cell move: action 2v backs vehicle v
        off (left or up), 2v + 1 moves it on (right or down)."""
        for v, (shift, back_mask, back, ahead_mask, ahead) in enumerate(self.steps):
            o = state >> shift & 7
            if not state & back_mask[o]:
                yield 2 * v, state + back[o]
            if not state & ahead_mask[o]:
                yield 2 * v + 1, state + ahead[o]

    def solved(self, state: int) -> bool:
        return state & 7 == N - self.lengths[0]   # the red car (vehicle 0) touches the exit

    def distance(self, start: int, limit: int) -> int | None:
        """Fewest moves from ``start`` to the exit, or None when unsolvable or when the search
        sees more than ``limit`` positions. The same search as ``solve`` without paths, inlined:
        generation runs it on dozens of parkings per reset."""
        goal = N - self.lengths[0]
        if start & 7 == goal:
            return 0
        seen, frontier, d = {start}, [start], 0
        while frontier:
            d += 1
            new = []
            for s in frontier:
                for shift, back_mask, back, ahead_mask, ahead in self.steps:
                    o = s >> shift & 7
                    if not s & back_mask[o]:
                        t = s + back[o]
                        if t not in seen:
                            seen.add(t)
                            new.append(t)
                    if not s & ahead_mask[o]:
                        t = s + ahead[o]
                        if t & 7 == goal and t not in seen:
                            return d     # only the red car's moves change its offset
                        if t not in seen:
                            seen.add(t)
                            new.append(t)
            if len(seen) > limit:
                return None
            frontier = new
        return None

    def may_clear(self, state: int) -> bool:
        """A quick necessary condition for a solution: no horizontal vehicle sits in the exit row
        ahead of the red car, and the vertical vehicles sharing a column ahead of it can stack
        above and below the exit row (they cannot pass each other)."""
        front = self.offset(state, 0) + self.lengths[0]
        columns: dict[int, list[tuple[int, int]]] = {}
        for v in range(1, self.count):
            if self.horizontal[v]:
                if self.lanes[v] == EXIT_ROW and self.offset(state, v) >= front:
                    return False
            elif self.lanes[v] >= front:
                columns.setdefault(self.lanes[v], []).append((self.offset(state, v), self.lengths[v]))
        for stack in columns.values():
            lengths = [length for _, length in sorted(stack)]
            if not any(sum(lengths[:k]) <= EXIT_ROW and sum(lengths[k:]) < N - EXIT_ROW
                       for k in range(len(lengths) + 1)):
                return False
        return True


def solve(lot: Lot, state: int, limit: int | None = None) -> list[int] | None:
    """Action indices of a shortest solution from ``state``, or None when there is none (or the
    search saw more than ``limit`` positions)."""
    path = bfs_search(state, lot.moves, lot.solved, limit)
    return None if path is None else list(path)


class RushHour(GlyphTask):
    title = "Rush Hour"
    rules = ("Cars (2 cells) and trucks (3 cells) are parked on a {size}x{size} lot. Each vehicle "
             "moves only along its length, one cell per action, and only into an empty cell. "
             "Vehicles {horizontal_names} move left and right; vehicles {vertical_names} move up "
             "and down. Clear the way and drive the red car X to the exit in the right wall of "
             "its row.")
    rewards = "getting the red car to the exit gives 1 minus {time_weight:g} x (turns used / {max_turns})."
    ends = "when the red car reaches the exit"
    Params = RushHourParams
    default_max_turns = 60

    def _init(self) -> None:
        p = self.params
        self.names = [RED] + [chr(65 + i) for i in range(p.horizontal + p.vertical)]
        self.horiz = [True] * (1 + p.horizontal) + [False] * p.vertical
        ways = ["left-right" if h else "up-down" for h in self.horiz]
        self._vocab = {FLOOR: "empty", WALL: "wall", GOAL: "exit", RED: f"red car {ways[0]}",
                       **{name: f"vehicle {way}" for name, way in zip(self.names[1:], ways[1:])}}

    def _make_actions(self) -> ActionSet:
        names = [f"{name}_{d}" for name, h in zip(self.names, self.horiz)
                 for d in (("LEFT", "RIGHT") if h else ("UP", "DOWN"))]
        return ActionSet(groups=[("move that vehicle one cell that way", names)])

    def vocab(self) -> dict[str, str]:
        return self._vocab

    def prompt_fields(self) -> dict:
        def listed(names):
            return ", ".join(names) if names else "(none)"
        p = self.params
        return super().prompt_fields() | {"size": N, "horizontal_names": listed(self.names[1:1 + p.horizontal]),
                                          "vertical_names": listed(self.names[1 + p.horizontal:])}

    # -- generation -------------------------------------------------------------------------------
    def _park(self, rng: np.random.Generator) -> tuple[Lot, int] | None:
        """The red car near the left of the exit row; vertical vehicles across the exit row ahead
        of it while there are free columns (they are the obstacles), the rest anywhere, never
        overlapping; None when a vehicle finds no room."""
        p = self.params
        x = int(rng.integers(2))
        lanes, lengths, offsets = [EXIT_ROW], [2], [x]
        used = sum(1 << (EXIT_ROW * N + x + i) for i in range(2))
        ahead = [c for c in range(x + 2, N)]
        for h in self.horiz[1:]:
            length = 3 if rng.random() < p.truck_chance else 2
            for attempt in range(20):
                if h:
                    lane = int(rng.integers(N - 1))
                    lane += lane >= EXIT_ROW        # any row but the exit row
                    o = int(rng.integers(N - length + 1))
                elif ahead and attempt < 10:        # across the exit row, ahead of the red car
                    lane = ahead[int(rng.integers(len(ahead)))]
                    o = int(rng.integers(max(0, EXIT_ROW - length + 1), EXIT_ROW + 1))
                else:
                    lane, o = int(rng.integers(N)), int(rng.integers(N - length + 1))
                cells = sum(1 << (lane * N + o + i if h else (o + i) * N + lane) for i in range(length))
                if not cells & used:
                    break
            else:
                return None
            if not h and lane in ahead:
                ahead.remove(lane)
            used |= cells
            lanes.append(lane)
            lengths.append(length)
            offsets.append(o)
        lot = Lot(self.horiz, lanes, lengths)
        return lot, lot.state(offsets)

    def _setup(self, rng: np.random.Generator) -> None:
        p = self.params
        for _ in range(_TRIES):
            parked = self._park(rng)
            if parked is None or not parked[0].may_clear(parked[1]):
                continue
            lot, state = parked
            moves = lot.distance(state, _SEARCH_LIMIT)
            if moves is not None and moves >= p.min_moves:
                self.lot, self.state = lot, state
                self.optimal = moves   # fewest moves, for tests and baselines
                return
        raise RuntimeError(f"{self.task_id}: no level needing {p.min_moves} moves found in {_TRIES} "
                           "parkings; lower min_moves or change the vehicle counts")

    # -- play ---------------------------------------------------------------------------------------
    def _act(self, action: int) -> None:
        v, on = divmod(action, 2)
        shift, back_mask, back, ahead_mask, ahead = self.lot.steps[v]
        o = self.state >> shift & 7
        mask, delta = (ahead_mask[o], ahead[o]) if on else (back_mask[o], back[o])
        if self.state & mask:
            self.say(f"{self.actions[action].name} is blocked.")
            return
        self.state += delta
        if self.lot.solved(self.state):
            self.reward(self.time_bonus(self.params.time_weight))
            self.say("The red car drove out.")
            self.finish(won=True)

    def _grid(self) -> list[str]:
        rows = [[FLOOR] * N + [WALL] for _ in range(N)]
        rows[EXIT_ROW][N] = GOAL
        lot = self.lot
        for v, name in enumerate(self.names):
            o, lane = lot.offset(self.state, v), lot.lanes[v]
            for i in range(o, o + lot.lengths[v]):
                if lot.horizontal[v]:
                    rows[lane][i] = name
                else:
                    rows[i][lane] = name
        return ["".join(row) for row in rows]


register_variants(RushHour, "Classics", {
    "glyphbench/classics-rushhour-easy-v0": dict(horizontal=1, vertical=3, min_moves=8, max_turns=60),
    "glyphbench/classics-rushhour-hard-v0": dict(horizontal=3, vertical=5, truck_chance=0.7, min_moves=12,
                                                 max_turns=120),
})
