"""Match-3: swap neighbouring gems to line up three or more of a kind; cleared gems score."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import ActionSet, GlyphTask, register_variants
from ...core.params import param

GEMS = "rgbypo"
GEM_NAMES = ("red", "green", "blue", "yellow", "purple", "orange")
_TRIES = 1000    # boards drawn per deal before the parameters are declared impossible


@dataclass(frozen=True)
class Match3Params:
    size: int = param(8, 4, 12)       # the board is size x size
    kinds: int = param(6, 3, len(GEMS))   # gem kinds in play
    target: int = param(80, 3, 10_000)    # gems to clear


def find_matches(board: list[list[str]]) -> set[tuple[int, int]]:
    """Every cell in a straight run of three or more equal gems."""
    n = len(board)
    found = set()
    for r in range(n):
        row = board[r]
        start = 0
        for c in range(1, n + 1):
            if c == n or row[c] != row[start]:
                if c - start >= 3:
                    found.update((r, k) for k in range(start, c))
                start = c
    for c in range(n):
        start = 0
        for r in range(1, n + 1):
            if r == n or board[r][c] != board[start][c]:
                if r - start >= 3:
                    found.update((k, c) for k in range(start, r))
                start = r
    return found


def makes_run(board: list[list[str]], r: int, c: int) -> bool:
    """Whether the gem at (r, c) lies in a run of three or more across or down."""
    n, g, row = len(board), board[r][c], board[r]
    a = c
    while a > 0 and row[a - 1] == g:
        a -= 1
    b = c
    while b < n - 1 and row[b + 1] == g:
        b += 1
    if b - a >= 2:
        return True
    a = r
    while a > 0 and board[a - 1][c] == g:
        a -= 1
    b = r
    while b < n - 1 and board[b + 1][c] == g:
        b += 1
    return b - a >= 2


def swap_matches(board: list[list[str]], r: int, c: int, r2: int, c2: int) -> bool:
    """Whether swapping (r, c) with (r2, c2) lines up a run (the board is left unchanged)."""
    if board[r][c] == board[r2][c2]:
        return False
    board[r][c], board[r2][c2] = board[r2][c2], board[r][c]
    ok = makes_run(board, r, c) or makes_run(board, r2, c2)
    board[r][c], board[r2][c2] = board[r2][c2], board[r][c]
    return ok


def swaps(size: int) -> list[tuple[int, int, int, int]]:
    """Every adjacent pair, in action order: each cell with its right neighbour, then with the one below."""
    right = [(r, c, r, c + 1) for r in range(size) for c in range(size - 1)]
    down = [(r, c, r + 1, c) for r in range(size - 1) for c in range(size)]
    return right + down


class Match3(GlyphTask):
    title = "Match-3"
    rules = ("The {size}x{size} board holds gems of {kinds} kinds. Swap a gem with its right or lower "
             "neighbour; a swap counts only if it lines up three or more equal gems across or down, "
             "otherwise the gems swap back and the turn is wasted. Lined-up gems are cleared, the gems "
             "above fall down, new random gems drop in from the top, and new lines clear too. If no "
             "swap can line up gems the board is reshuffled. Clear {target} gems.")
    rewards = "each cleared gem gives 1/{target}, up to {target} gems (a total of 1)."
    ends = "when {target} gems are cleared"
    Params = Match3Params
    axes = True
    default_max_turns = 40

    def _init(self) -> None:
        p = self.params
        self.kinds = GEMS[:p.kinds]
        self.pairs = swaps(p.size)
        self._vocab = {g: f"{name} gem" for g, name in zip(self.kinds, GEM_NAMES)}

    def vocab(self):
        return self._vocab

    def _make_actions(self) -> ActionSet:
        names = [f"{chr(65 + c)}{r + 1}{'R' if r2 == r else 'D'}" for r, c, r2, _ in swaps(self.params.size)]
        half = self.params.size * (self.params.size - 1)
        return ActionSet(groups=[("swap that cell's gem with the one to its right", names[:half]),
                                 ("swap that cell's gem with the one below it", names[half:])])

    def _setup(self, rng: np.random.Generator) -> None:
        self.rng = rng
        self.cleared = 0
        self.board = self._deal()

    def _deal(self) -> list[list[str]]:
        """A board with no line already made and at least one swap that makes one."""
        n = self.params.size
        for _ in range(_TRIES):
            board = [[""] * n for _ in range(n)]
            for r in range(n):
                for c in range(n):
                    banned = set()
                    if c >= 2 and board[r][c - 1] == board[r][c - 2]:
                        banned.add(board[r][c - 1])
                    if r >= 2 and board[r - 1][c] == board[r - 2][c]:
                        banned.add(board[r - 1][c])
                    allowed = [g for g in self.kinds if g not in banned]
                    board[r][c] = allowed[int(self.rng.integers(len(allowed)))]
            if self.has_move(board):
                return board
        raise RuntimeError(f"{self.task_id}: no playable board in {_TRIES} deals; "
                           "use more kinds or a larger board")

    def has_move(self, board: list[list[str]]) -> bool:
        return any(swap_matches(board, *pair) for pair in self.pairs)

    def _act(self, action: int) -> None:
        r, c, r2, c2 = self.pairs[action]
        board = self.board
        if not swap_matches(board, r, c, r2, c2):
            self.say("No line: the gems swap back.")
            return
        board[r][c], board[r2][c2] = board[r2][c2], board[r][c]
        total, waves = 0, 0
        matched = find_matches(board)
        while matched:
            total += len(matched)
            waves += 1
            self._collapse(matched)
            matched = find_matches(board)
        gain = min(total, self.params.target - self.cleared)
        self.cleared += gain
        self.reward(gain / self.params.target)
        self.say(f"Cleared {total} gems" + (f" in {waves} waves." if waves > 1 else "."))
        if self.cleared >= self.params.target:
            self.finish(won=True)
        elif not self.has_move(board):
            self.board = self._deal()
            self.say("No swap can line up gems: the board was reshuffled.")

    def _collapse(self, matched: set[tuple[int, int]]) -> None:
        """Remove ``matched`` gems, let the rest fall, and drop new random gems in from the top."""
        n, board, kinds = self.params.size, self.board, self.kinds
        for c in sorted({c for _, c in matched}):
            kept = [board[r][c] for r in range(n) if (r, c) not in matched]
            fresh = [kinds[int(k)] for k in self.rng.integers(len(kinds), size=n - len(kept))]
            for r, g in enumerate(fresh + kept):
                board[r][c] = g

    def _grid(self) -> list[str]:
        return ["".join(row) for row in self.board]

    def _hud(self) -> str:
        return f"Cleared {self.cleared}/{self.params.target}"


register_variants(Match3, "Classics", {
    "glyphbench/classics-match3-v0": dict(size=8, kinds=6, target=80, max_turns=40),
})
