"""Guard Evasion: sneak across a room to the exit while guards patrol and watch.

Guards walk back and forth along straight lines and sentries stand still turning clockwise;
each sees a cone ahead of it that walls cut short. Everything the guards do repeats with a
period, so a breadth-first search over (cell, time mod period) decides at generation that the
exit can be reached unseen, and gives the fewest turns that takes.
"""

from __future__ import annotations

from dataclasses import dataclass
from math import lcm

import numpy as np

from ...core import ActionSet, GlyphTask, register_variants
from ...core.params import param
from ..common.grid import DELTAS, MOVES, bfs_distances, bfs_search, interior_cells, random_room
from ..common.palette import FLOOR, GOAL, PLAYER, WALL
from ..common.sight import view_cone
from ..common.view import stamped

ARROWS = "▲▼◀▶"     # a guard facing up, down, left, right (DELTAS order)
SENTRIES = "△▽◁▷"   # a sentry, likewise
WATCHED = "░"
CLOCKWISE_NEXT = {0: 3, 3: 1, 1: 2, 2: 0}   # up -> right -> down -> left -> up
_TRIES = 300

Cell = tuple[int, int]


@dataclass(frozen=True)
class GuardEvasionParams:
    size: int = param(8, 5, 20)              # the room's interior is size x size
    pillars: int = param(8, 0, lambda p: p.size * p.size // 4)   # wall blocks to hide behind
    guards: int = param(2, 0, 8)             # guards patrolling straight lines
    sentries: int = param(0, 0, 4)           # guards standing still, turning clockwise
    sentry_turn: int = param(2, 1, 4)        # a sentry turns every this many turns
    patrol: int = param(5, 2, 6)             # longest patrol line, in cells
    reach: int = param(3, 1, 8)              # how far a guard sees
    min_moves: int = param(10, 1, 100)       # generated levels need at least this many turns
    caught_penalty: float = param(0.5, 0, 1)
    time_weight: float = param(0.5, 0, 1, open_hi=True)   # share of the win reward lost by using every turn


def patrol_steps(line: list[Cell], phase: int, period: int) -> list[tuple[Cell, int]]:
    """(cell, facing) of a guard walking ``line`` back and forth, for times 0..period-1 (period
    a multiple of the line's own period). It faces the way its next step goes."""
    own = 2 * (len(line) - 1)
    cells = [line[i if i < len(line) else own - i] for i in ((t + phase) % own for t in range(period + 1))]
    out = []
    for here, nxt in zip(cells, cells[1:]):
        out.append((here, DELTAS.index((nxt[0] - here[0], nxt[1] - here[1]))))
    return out


def sentry_steps(cell: Cell, facing: int, every: int, phase: int, period: int) -> list[tuple[Cell, int]]:
    """(cell, facing) of a sentry turning clockwise every ``every`` turns, for times 0..period-1."""
    out = []
    for t in range(period):
        f = facing
        for _ in range((t + phase) // every % 4):
            f = CLOCKWISE_NEXT[f]
        out.append((cell, f))
    return out


class GuardEvasion(GlyphTask):
    title = "Guard Evasion"
    rules = ("Sneak through a walled {size}x{size} room to the exit. Guards (arrows, pointing "
             "where they face) walk back and forth along straight lines, turning at the ends"
             "{sentry_rule}. Each guard or sentry sees up to {reach} cells ahead in a cone that widens by a "
             "cell to each side every two cells; walls block sight. Shaded cells are watched now. "
             "Each turn you move or wait, then the guards move; you are caught if you end your "
             "move in a watched cell or are watched after the guards move.")
    rewards = ("reaching the exit gives 1 minus {time_weight:g} x (turns used / {max_turns}); "
               "being caught costs {caught_penalty:g}.")
    ends = "when you reach the exit or are caught"
    Params = GuardEvasionParams
    ACTIONS = ActionSet([*[(n, f"step one cell {n.lower()}") for n in MOVES], ("WAIT", "stay where you are")])
    glyphs = {WALL: "wall", FLOOR: "floor", WATCHED: "watched floor", PLAYER: "you", GOAL: "exit",
              **{a: f"guard facing {d}" for a, d in zip(ARROWS, ("up", "down", "left", "right"))},
              **{a: f"sentry facing {d}" for a, d in zip(SENTRIES, ("up", "down", "left", "right"))}}
    default_max_turns = 60

    def prompt_fields(self) -> dict:
        p = self.params
        sentry = (f"; sentries (hollow arrows) stand still and turn clockwise every {p.sentry_turn} turns"
                  if p.sentries else "")
        return super().prompt_fields() | {"sentry_rule": sentry}

    # -- generation -------------------------------------------------------------------------------
    def _layout(self, rng: np.random.Generator):
        p = self.params
        n = p.size
        board, _ = random_room(n, p.pillars, 0, rng, WALL, FLOOR)
        floor = [cell for cell in interior_cells(n) if board[cell] == FLOOR]
        start = floor[int(rng.integers(len(floor)))]
        walk = bfs_distances(start, lambda r, c: board.rows[r][c] != WALL)
        far = sorted(cell for cell, d in walk.items() if d >= n)
        if not far:
            return None
        exit_ = far[int(rng.integers(len(far)))]
        taken = {start, exit_} | {(start[0] + dr, start[1] + dc) for dr, dc in DELTAS}
        routes, posts = [], []
        for _ in range(p.guards):
            for _ in range(20):     # a free cell with room to walk along a random axis
                cell = floor[int(rng.integers(len(floor)))]
                dr, dc = DELTAS[int(rng.integers(4))]
                line = [cell]
                while len(line) < p.patrol:
                    r, c = line[-1][0] + dr, line[-1][1] + dc
                    if board.rows[r][c] == WALL or (r, c) in taken:
                        break
                    line.append((r, c))
                if len(line) >= 2 and cell not in taken:
                    break
            else:
                return None
            taken.update(line)
            routes.append(line)
        for _ in range(p.sentries):
            free = [cell for cell in floor if cell not in taken]
            if not free:
                return None
            cell = free[int(rng.integers(len(free)))]
            taken.add(cell)
            posts.append((cell, int(rng.integers(4))))
        period = lcm(*(2 * (len(line) - 1) for line in routes), *([4 * p.sentry_turn] * bool(posts)), 1)
        steps = [patrol_steps(line, int(rng.integers(2 * len(line) - 2)), period) for line in routes]
        steps += [sentry_steps(cell, f, p.sentry_turn, int(rng.integers(4 * p.sentry_turn)), period)
                  for cell, f in posts]
        return board, start, exit_, period, steps

    def _setup(self, rng: np.random.Generator) -> None:
        p = self.params
        for _ in range(_TRIES):
            layout = self._layout(rng)
            if layout is None:
                continue
            board, start, exit_, period, steps = layout
            opaque = lambda r, c: not board.inside(r, c) or board.rows[r][c] == WALL  # noqa: E731
            cones: dict = {}
            watched = []
            for t in range(period):
                seen: set[Cell] = set()
                for cell, facing in (guard[t] for guard in steps):
                    if (cell, facing) not in cones:
                        cones[cell, facing] = view_cone(cell, facing, p.reach, opaque)
                    seen |= cones[cell, facing]
                watched.append(frozenset(seen))
            self.board, self.exit, self.period, self.steps, self.watched = board, exit_, period, steps, watched
            if start in watched[0]:
                continue
            plan = self.solve(start, 0)
            if plan is not None and len(plan) >= p.min_moves:
                self.pos, self.phase = start, 0
                self._scenes = [self._scene(t) for t in range(period)]
                self.optimal = len(plan)   # fewest turns, for tests and baselines
                return
        raise RuntimeError(f"{self.task_id}: no level needing {p.min_moves} turns found in {_TRIES} "
                           "layouts; lower min_moves or use fewer guards")

    # -- rules ------------------------------------------------------------------------------------
    def _move(self, cell: Cell, action: int) -> Cell:
        if action == 4:
            return cell
        dr, dc = DELTAS[action]
        nxt = (cell[0] + dr, cell[1] + dc)
        return cell if self.board.rows[nxt[0]][nxt[1]] == WALL else nxt

    def _caught(self, cell: Cell, phase: int) -> bool:
        """Seen by the guards as they stand (phase) or after they move (phase + 1)."""
        return cell in self.watched[phase] or cell in self.watched[(phase + 1) % self.period]

    def solve(self, cell: Cell, phase: int) -> list[int] | None:
        """Action indices of a fastest unseen way to the exit from ``cell`` at ``phase``."""
        exit_, period, watched = self.exit, self.period, self.watched
        succ = {}   # each cell's five successors, worked out once per search

        def neighbours(state):
            here, t = state
            if here == exit_:
                return
            nt = (t + 1) % period
            now, then = watched[t], watched[nt]
            if here not in succ:
                succ[here] = [self._move(here, a) for a in range(5)]
            for a, nxt in enumerate(succ[here]):
                if nxt == exit_ or (nxt not in now and nxt not in then):
                    yield a, (nxt, nt)
        return bfs_search((cell, phase), neighbours, lambda s: s[0] == exit_)

    def _act(self, action: int) -> None:
        nxt = self._move(self.pos, action)
        if nxt == self.pos and action != 4:
            self.say("Bumped into a wall.")
        self.pos = nxt
        if nxt == self.exit:
            self.reward(self.time_bonus(self.params.time_weight))
            self.say("You slipped out through the exit.")
            self.finish(won=True)
            return
        caught = self._caught(nxt, self.phase)
        self.phase = (self.phase + 1) % self.period
        if caught:
            self.reward(-self.params.caught_penalty)
            self.say("A guard saw you.")
            self.finish(won=False)

    def _scene(self, phase: int) -> list[str]:
        """The room at ``phase`` without you: it repeats with the guards, so it is drawn once per
        phase at reset."""
        rows = [row.copy() for row in self.board.rows]
        for r, c in self.watched[phase]:
            rows[r][c] = WATCHED
        rows[self.exit[0]][self.exit[1]] = GOAL
        for i, guard in enumerate(self.steps):
            (r, c), facing = guard[phase]
            rows[r][c] = (ARROWS if i < self.params.guards else SENTRIES)[facing]
        return ["".join(row) for row in rows]

    def _grid(self) -> list[str]:
        return stamped(self._scenes[self.phase], *self.pos, PLAYER)


register_variants(GuardEvasion, "Classics", {
    "glyphbench/classics-guardevasion-easy-v0": dict(size=8, pillars=8, guards=2, reach=3, min_moves=10,
                                                     max_turns=60),
    "glyphbench/classics-guardevasion-medium-v0": dict(size=10, pillars=14, guards=3, sentries=1, reach=4,
                                                       min_moves=14, max_turns=100),
    "glyphbench/classics-guardevasion-hard-v0": dict(size=12, pillars=20, guards=4, sentries=2, reach=5,
                                                     min_moves=18, max_turns=150),
})
