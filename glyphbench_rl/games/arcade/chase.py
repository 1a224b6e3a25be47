"""Maze chase and collect: corridor grids, tiles to collect or paint, and ghosts that chase.

``MazeTask`` is an ``ArcadeTask`` whose still rows are a maze (``WALL`` cells block), with the
player at ``(self.r, self.c)`` moved by the compass actions and ghosts (``Body`` objects with a
``mode``) that step every ``pace`` ticks. A game builds its maze in ``_still()`` (``lattice``
gives corridors around ``block``-sized blocks), places things in ``_setup`` after
``self.start(rng)`` and ``self.enter(...)``, and reacts in ``_visit(r, c)`` (the player entered a
cell: collect or paint there). Ghost modes::

    CHASE    head for the player at every junction (with chance ``chance``, else a random turn)
    SCATTER  head for the corner nearest its start (the first ``scatter`` ticks of every ``cycle``)
    SCARED   random turns for ``scared`` ticks after ``frighten``; touching one eats it (``_eat``)
    PATROL   walk a fixed loop of cells (the ``path`` given to ``ghost``)
    WANDER   random turns at junctions, never reversing (Amidar's warriors)

A ghost never reverses unless it is at a dead end. Touching a ghost that is not scared costs a
life (``lose_life``); ``_respawn`` puts the player and every ghost back on their starts.
"""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param
from .bodies import Body
from .engine import EMPTY, ArcadeParams, ArcadeTask

WALL = "="
CHASE, SCATTER, SCARED, PATROL, WANDER = range(5)
COMPASS = [("NOOP", "stay where you are"), ("LEFT", "move one cell left"),
           ("RIGHT", "move one cell right"), ("UP", "move one cell up"), ("DOWN", "move one cell down")]
ACTIONS = ActionSet(COMPASS, noop="NOOP")
STEPS = ((0, 0), (0, -1), (0, 1), (-1, 0), (1, 0))
DIRS = STEPS[1:]
_MAZES: dict[tuple[str, ...], tuple[dict, dict]] = {}   # wall layout -> (exits, ghost ways)


@dataclass(frozen=True)
class ChaseParams(ArcadeParams):
    ghosts: int = param(2, 0, 8)
    pace: int = param(2, 1, 8)          # a ghost steps once every this many ticks
    chance: float = param(1.0, 0, 1)    # a chasing ghost heads for you at a junction this often
    release: int = param(0, 0, 500)     # ticks before the ghosts start to move
    block: int = param(1, 1, 6)         # side of the blocks between corridors (lattice mazes)
    scatter: int = param(0, 0, 100)     # ticks of scatter at the start of every cycle
    cycle: int = param(40, 1, 1000)
    scared: int = param(0, 0, 200)      # ticks the ghosts stay scared after ``frighten``


def lattice(width: int, height: int, block: int, floor: str = EMPTY) -> list[str]:
    """A walled maze of corridors one cell wide around square blocks of side ``block``."""
    span = block + 1
    rows = [WALL * width]
    for r in range(1, height - 1):
        if (r - 1) % span == 0:
            rows.append(WALL + floor * (width - 2) + WALL)
        else:
            rows.append(WALL + "".join(floor if (c - 1) % span == 0 else WALL
                                       for c in range(1, width - 1)) + WALL)
    rows.append(WALL * width)
    return rows


def ghost(r: int, c: int, glyph: str, kind: int = CHASE, path=None, dr: int = 0, dc: int = 0) -> Body:
    """A ghost at (r, c): ``kind`` CHASE (scatters and scares by the game's clock), PATROL along
    ``path`` (a loop of cells) or WANDER."""
    return Body(r, c, dr, dc, glyph, (kind, path, (r, c, dr, dc)))


def loop(top: int, left: int, rows: int, cols: int) -> list[tuple[int, int]]:
    """The cells of a rectangle's outline, clockwise from its top-left corner."""
    cells = [(top, left + k) for k in range(cols)]
    cells += [(top + k, left + cols - 1) for k in range(1, rows)]
    cells += [(top + rows - 1, left + cols - 1 - k) for k in range(1, cols)]
    cells += [(top + rows - 1 - k, left) for k in range(1, rows - 1)]
    return cells


class MazeTask(ArcadeTask):
    Params = ChaseParams
    ACTIONS = ACTIONS
    pattern = "D"
    scared_glyph, player_glyph = "g", "C"
    _own_things = False        # set per game class: it draws things of its own (``_below``)

    def open(self, r: int, c: int) -> bool:
        return 0 <= r < len(self.still) and 0 <= c < len(self.still[r]) and self.still[r][c] != WALL

    def floor_cells(self) -> list[tuple[int, int]]:
        return [(r, c) for r, row in enumerate(self.still) for c, ch in enumerate(row) if ch != WALL]

    def enter(self, start: tuple[int, int], ghosts: list[Body]) -> None:
        """Place the player and the ghosts (made by ``ghost``)."""
        self.home, self.ghosts, self.scared_until = start, ghosts, 0
        self.r, self.c = start
        # the walls never move: a cell's exits, and the ways a ghost may take from a cell on a
        # heading (found as needed), hold for every episode on the same walls
        floor = str.maketrans({g: "." for g in self.vocab() if len(g) == 1 and g != WALL})
        walls = tuple(row.translate(floor) for row in self.still)
        maze = _MAZES.get(walls)
        if maze is None:
            if len(_MAZES) >= 64:
                _MAZES.clear()
            maze = _MAZES[walls] = ({(r, c): tuple(d for d in DIRS if self.open(r + d[0], c + d[1]))
                                     for r, c in self.floor_cells()}, {})
        self.exits, self._ways = maze

    def _respawn(self) -> None:
        self.r, self.c = self.home
        self.scared_until = 0
        for g in self.ghosts:
            g.r, g.c, g.dr, g.dc = g.data[2]

    def frighten(self) -> None:
        self.scared_until = self.tick + self.params.scared + 1
        for g in self.ghosts:
            g.dr, g.dc = -g.dr, -g.dc

    def _visit(self, r: int, c: int) -> None:
        """The player entered (r, c): collect or paint there."""

    def _eat(self, ghost: Body) -> None:
        """A scared ghost was touched: back to its start."""
        ghost.r, ghost.c, ghost.dr, ghost.dc = ghost.data[2]

    def _play(self, action: int) -> None:
        step = STEPS[action]
        if action and step in self.exits[self.r, self.c]:
            self.r += step[0]
            self.c += step[1]
            self._visit(self.r, self.c)
            if self.done or self._touch():
                return
        self._tick_world()
        if self.done:
            return
        p = self.params
        if self.tick > p.release and self.tick % p.pace == 0:
            self._steer()
            self._touch()

    def _tick_world(self) -> None:
        """Per-tick work of the game besides the ghosts (timers, spawns)."""

    def _touch(self) -> bool:
        for g in self.ghosts:
            if g.r == self.r and g.c == self.c:
                if self.tick < self.scared_until and g.data[0] == CHASE:
                    self._eat(g)
                    continue
                self.lose_life(self.caught)
                return True
        return False

    caught = "Caught!"

    def mode(self, ghost: Body) -> int:
        if ghost.data[0] != CHASE:
            return ghost.data[0]
        if self.tick < self.scared_until:
            return SCARED
        return SCATTER if self.tick % self.params.cycle < self.params.scatter else CHASE

    def _steer(self) -> None:
        """Every ghost takes a step, in order, by its ``mode``."""
        p, tick, memo, exits, draws = self.params, self.tick, self._ways, self.exits, self.draws
        clock = SCARED if tick < self.scared_until else SCATTER if tick % p.cycle < p.scatter else CHASE
        for g in self.ghosts:
            mode = g.data[0]
            if mode == CHASE:
                mode = clock
            elif mode == PATROL:
                path = g.data[1]
                i = (path.index((g.r, g.c)) + 1) % len(path) if (g.r, g.c) in path else 0
                g.r, g.c = path[i]
                continue
            key = (g.r, g.c, g.dr, g.dc)
            ways = memo.get(key)
            if ways is None:   # every exit but the way back (that only at a dead end), remembered
                back = (-g.dr, -g.dc)
                ways = memo[key] = tuple(d for d in exits[g.r, g.c] if d != back) or (back,)
            if len(ways) == 1:
                pick = ways[0]
            elif mode == SCARED or mode == WANDER or (mode == CHASE and draws.random() >= p.chance):
                pick = ways[draws.below(len(ways))]
            else:
                if mode == CHASE:
                    tr, tc = self.r, self.c
                else:
                    r0, c0 = g.data[2][:2]
                    tr = 0 if r0 < len(self.still) // 2 else len(self.still)
                    tc = 0 if c0 < len(self.still[0]) // 2 else len(self.still[0])
                pick, near = None, 0
                for d in ways:          # the first way nearest the target
                    dr, dc = g.r + d[0] - tr, g.c + d[1] - tc
                    if pick is None or dr * dr + dc * dc < near:
                        pick, near = d, dr * dr + dc * dc
            g.dr, g.dc = pick
            g.r += pick[0]
            g.c += pick[1]

    def __init_subclass__(cls, **kwargs) -> None:
        super().__init_subclass__(**kwargs)
        cls._own_things = cls._below is not MazeTask._below   # else ``_grid`` skips asking

    def _below(self):
        """Things of the game's own drawn under the ghosts: (row, col, glyph) each."""
        return ()

    def _sprites(self):
        scared = self.tick < self.scared_until
        out = [*self._below(), *((g.r, g.c, self.scared_glyph if scared and g.data[0] == CHASE else g.glyph)
                                 for g in self.ghosts)]
        out.append((self.r, self.c, self.player_glyph))
        return out

    def _grid(self) -> list[str]:
        """``_sprites()`` drawn on ``_rows()`` straight from the bodies (no tuple per mover, no
        bounds test: everything walks the maze), each row remembered (``_draw``)."""
        rows = self._rows() if self._slides else self.still[:]
        self._grids += 1
        drawn = self._drawn
        if self._own_things:
            for r, c, g in self._below():
                key = (rows[r], c, g)
                rows[r] = drawn.get(key) or self._draw(key)
        scared = self.tick < self.scared_until
        for g in self.ghosts:
            r = g.r
            key = (rows[r], g.c, self.scared_glyph if scared and g.data[0] == CHASE else g.glyph)
            rows[r] = drawn.get(key) or self._draw(key)
        r = self.r
        key = (rows[r], self.c, self.player_glyph)
        rows[r] = drawn.get(key) or self._draw(key)
        return rows
