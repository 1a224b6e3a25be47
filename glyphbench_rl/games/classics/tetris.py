"""Tetris: steer falling tetrominoes, clear full lines, don't top out."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import ActionSet, GlyphTask, register_variants
from ...core.params import param
from ..common.lanes import Bag
from ..common.palette import FLOOR
from ..common.physics import move_vertical

BLOCK, PIECE = "#", "@"

# Each tetromino in its spawn orientation inside an n x n box; the other three orientations are
# clockwise quarter turns of the box, (r, c) -> (c, n - 1 - r), as in the modern rotation system.
SHAPES: dict[str, tuple[int, tuple[tuple[int, int], ...]]] = {
    "I": (4, ((1, 0), (1, 1), (1, 2), (1, 3))),
    "O": (2, ((0, 0), (0, 1), (1, 0), (1, 1))),
    "T": (3, ((0, 1), (1, 0), (1, 1), (1, 2))),
    "S": (3, ((0, 1), (0, 2), (1, 0), (1, 1))),
    "Z": (3, ((0, 0), (0, 1), (1, 1), (1, 2))),
    "J": (3, ((0, 0), (1, 0), (1, 1), (1, 2))),
    "L": (3, ((0, 2), (1, 0), (1, 1), (1, 2))),
}


def _rotations(n: int, cells: tuple[tuple[int, int], ...]) -> tuple[tuple[tuple[int, int], ...], ...]:
    out = [tuple(sorted(cells))]
    for _ in range(3):
        out.append(tuple(sorted((c, n - 1 - r) for r, c in out[-1])))
    return tuple(out)


ROTATIONS = {name: _rotations(n, cells) for name, (n, cells) in SHAPES.items()}
KICKS = (0, -1, 1, -2, 2)   # column shifts tried, in order, when a rotation is blocked


@dataclass(frozen=True)
class TetrisParams:
    width: int = param(10, 4, 20)
    height: int = param(16, 6, 30)
    target: int = param(5, 1, 100)           # lines to clear
    fall_every: int = param(1, 1, 8)         # gravity drops the piece one row every this many turns
    topout_penalty: float = param(0.5, 0, 1)


class Tetris(GlyphTask):
    title = "Tetris"
    rules = ("The grid is a well {width} wide and {height} deep. Tetrominoes (I O T S Z J L, "
             "dealt in shuffled bags of seven) appear at the top; the status line names the next "
             "one. Gravity drops the falling piece one row {fall_text} after your "
             "action; when it cannot drop it locks in place. A rotation blocked by a wall or "
             "block tries nudging the piece sideways. A row filled completely is cleared and "
             "everything above falls one row. A new piece that does not fit tops out the well.")
    rewards = "+{line_reward:.4g} per cleared line; {target} lines win; topping out costs {topout_penalty:g}."
    ends = "when you clear {target} lines or the well tops out"
    Params = TetrisParams
    ACTIONS = ActionSet([
        ("LEFT", "move the piece one column left"),
        ("RIGHT", "move the piece one column right"),
        ("ROTATE", "turn the piece a quarter clockwise"),
        ("SOFT_DROP", "move the piece one extra row down"),
        ("HARD_DROP", "drop the piece to the bottom and lock it at once"),
        ("NOOP", "let it fall"),
    ], noop="NOOP")
    glyphs = {FLOOR: "empty", BLOCK: "block", PIECE: "falling piece"}
    default_max_turns = 300

    def prompt_fields(self) -> dict:
        n = self.params.fall_every
        return super().prompt_fields() | {"line_reward": 1 / self.params.target,
                                          "fall_text": "every turn" if n == 1 else f"every {n} turns"}

    def _setup(self, rng: np.random.Generator) -> None:
        p = self.params
        self.board = [[FLOOR] * p.width for _ in range(p.height)]
        self.lines_drawn = ["".join(row) for row in self.board]   # the board's text, redrawn on locks
        self.bag = Bag(tuple(SHAPES), rng)
        self.lines = 0
        self.tick = 0                 # gravity's clock (forfeited turns stop it)
        self._spawn()

    # -- pieces -------------------------------------------------------------------------------------
    def cells(self, name: str, rot: int, r: int, c: int) -> list[tuple[int, int]]:
        return [(r + dr, c + dc) for dr, dc in ROTATIONS[name][rot]]

    def fits(self, name: str, rot: int, r: int, c: int) -> bool:
        w, h, board = self.params.width, self.params.height, self.board
        for dr, dc in ROTATIONS[name][rot]:        # a plain loop: this is the hot path
            y, x = r + dr, c + dc
            if not (0 <= y < h and 0 <= x < w) or board[y][x] != FLOOR:
                return False
        return True

    def drop_row(self, name: str, rot: int, r: int, c: int) -> int:
        """The row where the piece comes to rest if dropped straight down."""
        return move_vertical(r, self.params.height, lambda y: not self.fits(name, rot, y, c))[0]

    def _spawn(self) -> bool:
        name = self.bag.draw()
        n, cells = SHAPES[name]
        self.piece = [name, 0, -min(r for r, _ in cells), (self.params.width - n) // 2]
        return self.fits(*self.piece)

    def _lock(self) -> None:
        p = self.params
        name, rot, r, c = self.piece
        for y, x in self.cells(name, rot, r, c):
            self.board[y][x] = BLOCK
        full = [y for y, row in enumerate(self.board) if FLOOR not in row]
        if full:
            self.board = [[FLOOR] * p.width for _ in full] + [row for row in self.board if FLOOR in row]
        self.lines_drawn = ["".join(row) for row in self.board]
        if full:                                   # only lines up to the target are paid
            counted = min(len(full), p.target - self.lines)
            self.lines += len(full)
            self.reward(counted / p.target)
            self.say(f"Cleared {len(full)} line{'s' * (len(full) > 1)}.")
            if self.lines >= p.target:
                self.piece = None
                self.finish(won=True)
                return
        if not self._spawn():
            self.piece = None
            self.reward(-p.topout_penalty)
            self.say("Topped out.")
            self.finish(won=False)

    # -- a turn ---------------------------------------------------------------------------------------
    def _act(self, action: int) -> None:
        self.tick += 1
        name, rot, r, c = self.piece
        if action in (0, 1):                       # LEFT, RIGHT
            dc = -1 if action == 0 else 1
            if self.fits(name, rot, r, c + dc):
                self.piece[3] = c + dc
        elif action == 2:                          # ROTATE
            new = (rot + 1) % 4
            for kick in KICKS:
                if self.fits(name, new, r, c + kick):
                    self.piece[1], self.piece[3] = new, c + kick
                    break
        elif action == 3 and self.fits(name, rot, r + 1, c):   # SOFT_DROP
            self.piece[2] = r + 1
        elif action == 4:                          # HARD_DROP
            self.piece[2] = self.drop_row(name, rot, r, c)
            self._lock()
            return
        if self.tick % self.params.fall_every == 0:
            name, rot, r, c = self.piece
            if self.fits(name, rot, r + 1, c):
                self.piece[2] = r + 1
            else:
                self._lock()

    def _grid(self) -> list[str]:
        lines = self.lines_drawn[:]
        if self.piece:
            for y, x in self.cells(*self.piece):
                lines[y] = lines[y][:x] + PIECE + lines[y][x + 1:]
        return lines

    def _hud(self) -> str:
        return f"Lines {self.lines}/{self.params.target} | Next {self.bag.peek()}"


register_variants(Tetris, "Classics", {
    "glyphbench/classics-tetris-v0": dict(width=10, height=16, target=5, max_turns=300),
})
