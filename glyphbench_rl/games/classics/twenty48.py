"""2048: slide numbered tiles; equal tiles merge; reach the target tile."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import GlyphTask, register_variants
from ...core.params import param, require
from ..common.grid import move_actions

from ..common.palette import FLOOR

# A tile 2**k is drawn as the k-th letter: "a" is 2, "b" is 4, ..., "j" is 1024. Letters, not
# digits: a digit drawn for another number ("1" for 2) misleads a reader of the grid.
TILE_GLYPHS = "abcdefghijklmnopq"


@dataclass(frozen=True)
class Twenty48Params:
    size: int = param(4, 2, 8)
    target: int = param(512, 8, 1 << len(TILE_GLYPHS))   # reaching this tile wins
    four_chance: float = param(0.1, 0, 1)    # a new tile is a 4 with this probability, else a 2
    loss_penalty: float = param(0.5, 0, 1)   # when no move is possible

    def check(self) -> None:
        require(self.target & (self.target - 1) == 0, "target", "a power of two", self.target)


def slide_row(row: list[int]) -> list[int]:
    """Slide one row of exponents (0 = empty) towards index 0, merging equal neighbours once."""
    tiles = [v for v in row if v]
    out = []
    i = 0
    while i < len(tiles):
        if i + 1 < len(tiles) and tiles[i] == tiles[i + 1]:
            out.append(tiles[i] + 1)
            i += 2
        else:
            out.append(tiles[i])
            i += 1
    return out + [0] * (len(row) - len(out))


def slide(board: list[list[int]], action: str) -> list[list[int]]:
    """The board after a move in direction ``action`` (a MOVES key), without spawning."""
    n = len(board)
    if action == "LEFT":
        return [slide_row(row) for row in board]
    if action == "RIGHT":
        return [slide_row(row[::-1])[::-1] for row in board]
    cols = [[board[r][c] for r in range(n)] for c in range(n)]
    if action == "DOWN":
        cols = [col[::-1] for col in cols]
    moved = [slide_row(col) for col in cols]
    if action == "DOWN":
        moved = [col[::-1] for col in moved]
    return [[moved[c][r] for c in range(n)] for r in range(n)]


class Twenty48(GlyphTask):
    title = "2048"
    rules = ("Tiles on a {size}x{size} board hold powers of two, drawn as letters: {letters} and "
             "so on, each letter double the one before (the legend gives the value of every tile "
             "on the board). A move slides every tile as far as it goes in that direction; two "
             "equal tiles that meet merge into their sum (once per move). After every move that "
             "changes the board a new tile appears on a random empty cell: {four} with probability "
             "{four_chance:g}, else {two}. A move that changes nothing wastes the turn.")
    rewards = ("whenever your largest tile grows from value x to value y you gain (y - max(x, 4)) "
               "/ {span}, so reaching {target} totals 1; having no possible move costs {loss_penalty:g}.")
    ends = "when you make the {target} tile or no move is possible"
    Params = Twenty48Params
    ACTIONS = move_actions("slide all tiles", unit="")
    default_max_turns = 512

    def _init(self) -> None:
        self.target_exp = self.params.target.bit_length() - 1
        self._vocab = {FLOOR: "empty"} | {TILE_GLYPHS[k - 1]: f"tile {1 << k}" for k in range(1, self.target_exp + 1)}

    def vocab(self):
        return self._vocab

    def prompt_fields(self) -> dict:
        letters = ", ".join(f"{g} is {1 << k}" for k, g in enumerate(TILE_GLYPHS[:3], 1))
        two, four = (f"{1 << k} ({TILE_GLYPHS[k - 1]})" for k in (1, 2))
        return super().prompt_fields() | {"span": self.params.target - 4, "letters": letters,
                                          "two": two, "four": four}

    def _setup(self, rng: np.random.Generator) -> None:
        n = self.params.size
        self.rng = rng
        self.board = [[0] * n for _ in range(n)]
        self._spawn()
        self._spawn()
        self.largest = max(max(row) for row in self.board)

    def _spawn(self) -> None:
        empty = [(r, c) for r, row in enumerate(self.board) for c, v in enumerate(row) if not v]
        r, c = empty[int(self.rng.integers(len(empty)))]
        self.board[r][c] = 2 if self.rng.random() < self.params.four_chance else 1

    def can_move(self) -> bool:
        """A move exists while a cell is empty or two neighbours are equal."""
        b, n = self.board, self.params.size
        return any(not b[r][c] or (c + 1 < n and b[r][c] == b[r][c + 1]) or
                   (r + 1 < n and b[r][c] == b[r + 1][c]) for r in range(n) for c in range(n))

    def _act(self, action: int) -> None:
        new = slide(self.board, self.actions[action].name)
        if new == self.board:
            self.say("Nothing moved.")
            return
        self.board = new
        top = max(max(row) for row in new)
        if top > self.largest:
            gained = (1 << top) - max(1 << self.largest, 4)
            if gained > 0:
                self.reward(gained / (self.params.target - 4))
            self.largest = top
            self.say(f"New largest tile {1 << top}.")
        if top >= self.target_exp:
            self.finish(won=True)
            return
        self._spawn()
        if not self.can_move():
            self.reward(-self.params.loss_penalty)
            self.say("No move is possible.")
            self.finish(won=False)

    def _grid(self) -> list[str]:
        return ["".join(TILE_GLYPHS[v - 1] if v else FLOOR for v in row) for row in self.board]

    def _hud(self) -> str:
        return f"Largest {1 << self.largest}/{self.params.target}"


register_variants(Twenty48, "Classics", {
    "glyphbench/classics-2048-v0": dict(size=4, target=512, max_turns=512),
})
