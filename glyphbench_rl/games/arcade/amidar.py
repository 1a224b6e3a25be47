"""Amidar: paint the tiles of a grid by walking over them while enemies patrol it. On the mini
preset the tiles are the outline of one random box, patrolled by a warrior that walks it round
and round; on the Atari preset they are every cell of a lattice of corridors, where the warriors
wander, turning at random at junctions and never doubling back (pattern D)."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.params import param, require
from .chase import PATROL, WALL, WANDER, ChaseParams, MazeTask, ghost, lattice, loop
from .engine import EMPTY, register_arcade

TILE, PAINTED, WARRIOR = "+", "#", "W"


@dataclass(frozen=True)
class AmidarParams(ChaseParams):
    width: int = param(12, 6, 60)
    height: int = param(10, 6, 40)
    goal: int = param(10, 1, 1000)
    unit: float = param(0.1, 0, 10)
    ghosts: int = param(1, 0, 12)
    pace: int = param(3, 1, 8)
    block: int = param(0, 0, 6)          # 0: an open floor (then the tiles are one box's outline)
    box_rows: int = param(3, 2, 20)
    box_cols: int = param(4, 2, 40)

    def check(self) -> None:
        if self.block == 0:
            require(self.box_rows <= self.height - 2 and self.box_cols <= self.width - 2, "box",
                    "inside the field", (self.box_rows, self.box_cols))
            require(self.goal <= 2 * (self.box_rows + self.box_cols) - 4, "goal",
                    "at most the box's outline", self.goal)


class Amidar(MazeTask):
    title = "Amidar"
    rules = ("A {width}x{height} field walled (=) round{layout}. Walk onto an unpainted tile (+) "
             "to paint it (#). You (C) move one cell a turn; the warriors (W), {ghosts} of them, {patrol}, one "
             "step every {pace} turns. Touching a warrior costs a life; you have {lives_text}.")
    rewards = "+{unit} for each tile you paint; -1 when your last life is lost."
    ends = "when you have painted {goal} tiles, or a warrior catches you with no lives left"
    Params = AmidarParams
    player_glyph = "C"
    glyphs = {EMPTY: "floor", WALL: "wall", TILE: "unpainted tile", PAINTED: "painted tile",
              "C": "you", WARRIOR: "warrior"}

    def prompt_fields(self) -> dict:
        p = self.params
        if p.block == 0:
            layout = f", with the outline of a {p.box_rows}x{p.box_cols} box of tiles on the floor"
            patrol = "walk round the box's outline"
        else:
            layout = f"; its corridors run between {p.block}x{p.block} blocks and every corridor cell is a tile"
            patrol = "wander the corridors, turning at random at junctions and never doubling back"
        return {**super().prompt_fields(), "layout": layout, "patrol": patrol}

    def _still(self) -> list[str]:
        p = self.params
        if p.block:
            return lattice(p.width, p.height, p.block, TILE)
        return [WALL * p.width] + [WALL + EMPTY * (p.width - 2) + WALL] * (p.height - 2) + [WALL * p.width]

    def _setup(self, rng) -> None:
        self.start(rng)
        p = self.params
        if p.block == 0:
            top = int(rng.integers(1, p.height - p.box_rows))
            left = int(rng.integers(1, p.width - p.box_cols))
            path = loop(top, left, p.box_rows, p.box_cols)
            for r, c in path:
                self.set_still(r, c, TILE)
            if rng.random() < 0.5:
                path.reverse()
            firsts = rng.choice(len(path), p.ghosts, replace=False).tolist()
            ghosts = [ghost(*path[i], WARRIOR, PATROL, path) for i in firsts]
            spots = [rc for rc in self.floor_cells() if self.still[rc[0]][rc[1]] == EMPTY
                     and min(abs(rc[0] - r) + abs(rc[1] - c) for r, c in path) >= 2]
        else:
            floor = self.floor_cells()
            ghosts = [ghost(*floor[int(rng.integers(len(floor)))], WARRIOR, WANDER) for _ in range(p.ghosts)]
            spots = [rc for rc in floor if min((abs(rc[0] - g.r) + abs(rc[1] - g.c) for g in ghosts),
                                               default=99) >= 6]
        self.enter(spots[int(rng.integers(len(spots)))], ghosts)

    def _visit(self, r: int, c: int) -> None:
        if self.still[r][c] == TILE:
            self.set_still(r, c, PAINTED)
            self.score.gain()


register_arcade(Amidar, "amidar",
                mini=dict(max_turns=300),
                atari=dict(width=21, height=18, block=2, goal=100, unit=1.0, lives=3, ghosts=5,
                           pace=2, max_turns=10000))
