"""Sokoban: push every box onto a goal.

Levels come from reverse play (the player walks backwards from a solved room, pulling boxes
off their goals) and are then proven solvable by a push-optimal search, which also gives the
optimal push count; both live in ``common.pushing``, shared with MiniHack's Boxoban levels.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import GlyphTask, register_variants
from ...core.params import param
from ..common.grid import DELTAS, move_actions
from ..common.palette import FLOOR, GOAL, PLAYER, WALL
from ..common.pushing import PushRoom, pull_back, search

BOX, BOX_ON_GOAL, PLAYER_ON_GOAL = "$", "*", "+"   # the classic Sokoban text notation
Cell = tuple[int, int]
_SEARCH_LIMIT = 4000      # states the generator lets the solver close before giving a level up
_PULL_RUNS = 8            # straight pulling runs per box in reverse play
_TRIES = 1000             # rooms tried per reset before the parameters are declared impossible


@dataclass(frozen=True)
class SokobanParams:
    size: int = param(6, 4, 12)              # the room's interior is size x size; the grid adds the outer wall
    boxes: int = param(1, 1, 4)              # boxes, and as many goals
    # wall cells tried inside the room (kept only if the room stays connected)
    inner_walls: int = param(2, 0, lambda p: p.size * p.size // 4)
    # generated levels need at least this many pushes to solve
    min_pushes: int = param(3, 1, lambda p: 6 * p.size)
    # ... and a push-optimal solution of at most this many moves
    max_moves: int = param(30, lambda p: p.min_pushes, 512)


class Sokoban(GlyphTask):
    title = "Sokoban"
    rules = ("You are in a walled {size}x{size} room with {box_count} and as many goals. "
             "Walking into a box pushes it one cell if the cell beyond it is floor or goal; a "
             "box against a wall or another box does not move, and boxes cannot be pulled, so "
             "a box pushed into a corner is stuck for good. Put every box on a goal.")
    rewards = ("+{box_reward:.4g} each time a box lands on a goal, -{box_reward:.4g} each time "
               "one is pushed off a goal, +{solve_reward:g} when every box is on a goal.")
    ends = "when every box is on a goal"
    Params = SokobanParams
    ACTIONS = move_actions("walk or push", " one cell")
    glyphs = {WALL: "wall", FLOOR: "floor", GOAL: "goal", BOX: "box", BOX_ON_GOAL: "box on goal",
              PLAYER: "you", PLAYER_ON_GOAL: "you on goal"}
    default_max_turns = 60
    SOLVE_REWARD = 0.5     # the other half of the return is shared by the boxes

    def prompt_fields(self) -> dict:
        n = self.params.boxes
        return super().prompt_fields() | {"box_count": f"{n} box" + "es" * (n > 1),
                                          "box_reward": self.box_reward, "solve_reward": self.SOLVE_REWARD}

    def _init(self) -> None:
        self.box_reward = (1 - self.SOLVE_REWARD) / self.params.boxes

    # -- generation -------------------------------------------------------------------------------
    def _setup(self, rng: np.random.Generator) -> None:
        for _ in range(_TRIES):   # each try is a fresh room; most succeed within a few
            level = self._generate(rng)
            if level is not None:
                break
        else:
            raise RuntimeError(f"{self.task_id}: no level found in {_TRIES} rooms for {self.params}; "
                               "lower min_pushes or raise max_moves")
        walls, boxes, goals, player, self.solution, self.optimal_pushes = level
        self._install(walls, boxes, goals, player)

    def _install(self, walls: set[Cell], boxes: set[Cell], goals: frozenset[Cell], player: Cell) -> None:
        """Set up play on a level; tests also use it to load hand-made levels."""
        self.walls, self.goals, self.boxes, self.player = set(walls), frozenset(goals), set(boxes), player
        self.on_goal, self.pushes = len(self.boxes & self.goals), 0
        height, width = max(r for r, _ in walls) + 1, max(c for _, c in walls) + 1
        self.rows = [[WALL] * width for _ in range(height)]
        for r in range(height):
            for c in range(width):
                self._paint((r, c))

    def _make_room(self, rng: np.random.Generator) -> tuple[set[Cell], list[Cell]]:
        """The walls (outer ring plus a few inside, never cutting the room apart) and the floor."""
        n = self.params.size
        walls = {(r, c) for r in range(n + 2) for c in range(n + 2) if r in (0, n + 1) or c in (0, n + 1)}
        floor = [(r, c) for r in range(1, n + 1) for c in range(1, n + 1)]
        for _ in range(self.params.inner_walls):
            cell = floor[int(rng.integers(len(floor)))]
            rest = [x for x in floor if x != cell]
            room = PushRoom(walls | {cell}, n + 2, n + 2, ())
            if bin(room.flood(room.index(*rest[0]), 0)).count("1") == len(rest):  # still connected
                walls.add(cell)
                floor = rest
        return walls, floor

    def _generate(self, rng: np.random.Generator):
        p = self.params
        walls, floor = self._make_room(rng)
        picks = rng.choice(len(floor), size=p.boxes + 1, replace=False)
        room = PushRoom(walls, p.size + 2, p.size + 2, [floor[int(i)] for i in picks[:-1]])
        best = pull_back(room, room.index(*floor[int(picks[-1])]), rng, _PULL_RUNS * p.boxes, p.min_pushes)
        if best is None:
            return None
        found = search(room, *best, limit=_SEARCH_LIMIT)
        if found is None or found[1] < p.min_pushes or len(found[0]) > p.max_moves:
            return None
        return walls, room.cells(best[0]), room.cells(room.goals), room.cell(best[1]), *found

    # -- play --------------------------------------------------------------------------------------
    def _paint(self, rc: Cell) -> None:
        on_goal = rc in self.goals
        if rc == self.player:
            ch = PLAYER_ON_GOAL if on_goal else PLAYER
        elif rc in self.boxes:
            ch = BOX_ON_GOAL if on_goal else BOX
        elif rc in self.walls:
            ch = WALL
        else:
            ch = GOAL if on_goal else FLOOR
        self.rows[rc[0]][rc[1]] = ch

    def _act(self, action: int) -> None:
        dr, dc = DELTAS[action]
        here = self.player
        nxt = (here[0] + dr, here[1] + dc)
        if nxt in self.walls:
            self.say("You bumped into a wall.")
            return
        if nxt in self.boxes:
            dest = (nxt[0] + dr, nxt[1] + dc)
            if dest in self.walls or dest in self.boxes:
                self.say("The box is blocked and did not move.")
                return
            self.boxes.remove(nxt)
            self.boxes.add(dest)
            self.pushes += 1
            if nxt in self.goals:
                self.on_goal -= 1
                self.reward(-self.box_reward)
                self.say("A box left its goal.")
            if dest in self.goals:
                self.on_goal += 1
                self.reward(self.box_reward)
                self.say("A box is on a goal.")
            self._paint(dest)
        self.player = nxt
        self._paint(here)
        self._paint(nxt)
        if self.on_goal == self.params.boxes:
            self.reward(self.SOLVE_REWARD)
            self.say("Every box is on a goal: solved.")
            self.finish(won=True)

    def _grid(self) -> list[str]:
        return ["".join(row) for row in self.rows]

    def _hud(self) -> str:
        return f"Boxes on goals {self.on_goal}/{self.params.boxes}"


register_variants(Sokoban, "Classics", {
    "glyphbench/classics-sokoban-easy-v0": dict(size=6, boxes=1, inner_walls=2, min_pushes=4, max_moves=30,
                                                max_turns=60),
    "glyphbench/classics-sokoban-medium-v0": dict(size=7, boxes=2, inner_walls=4, min_pushes=7, max_moves=60,
                                                  max_turns=120),
    "glyphbench/classics-sokoban-hard-v0": dict(size=8, boxes=3, inner_walls=6, min_pushes=10, max_moves=100,
                                                max_turns=200),
})
