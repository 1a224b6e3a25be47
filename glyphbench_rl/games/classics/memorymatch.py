"""Memory Match (Concentration): turn cards over two at a time; matching pairs stay face up."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import GlyphTask, register_variants
from ...core.params import param, require
from ..common.boards import cell_actions

DOWN = "■"
FACES = "abcdefghijklmnopqrstuvwxyz"


@dataclass(frozen=True)
class MemoryMatchParams:
    rows: int = param(4, 2, 8)
    cols: int = param(5, 2, 8)
    pair_share: float = param(0.5, 0, 1)   # the return shared by the pairs; clearing the board adds the rest

    def check(self) -> None:
        cards = self.rows * self.cols
        require(cards % 2 == 0 and cards <= 2 * len(FACES), "rows x cols",
                f"even (cards come in pairs) and at most {2 * len(FACES)}", cards)


class MemoryMatch(GlyphTask):
    title = "Memory Match"
    rules = ("{cards} cards lie face down on a {rows}x{cols} board: {pairs} pairs of letters. "
             "Each action turns one card over. After every second card: if the two letters "
             "match, both stay face up; if not, both stay visible until your next action and "
             "then turn face down. Find every pair.")
    rewards = "+{pair_reward:.4g} per pair found; finding all {pairs} adds {clear_reward:g}."
    ends = "when every pair is found"
    Params = MemoryMatchParams
    axes = True
    default_max_turns = 60

    def _init(self) -> None:
        p = self.params
        self.pairs = p.rows * p.cols // 2
        self._vocab = {DOWN: "face down"} | {FACES[k]: "card" for k in range(self.pairs)}
        self._cells = [divmod(i, p.cols) for i in range(p.rows * p.cols)]   # card -> (row, column)

    def vocab(self):
        return self._vocab

    def prompt_fields(self) -> dict:
        p = self.params
        return super().prompt_fields() | {"cards": 2 * self.pairs, "pairs": self.pairs,
                                          "pair_reward": p.pair_share / self.pairs,
                                          "clear_reward": 1 - p.pair_share}

    def _make_actions(self):
        return cell_actions(self.params.rows, self.params.cols, [("", "turn over that card")])

    def _setup(self, rng: np.random.Generator) -> None:
        self.faces = rng.permutation(np.repeat(np.arange(self.pairs), 2)).tolist()
        self.up = [False] * len(self.faces)     # face up: found pairs and the cards on show
        self.showing: list[int] = []            # face-up cards not yet matched (0, 1 or 2)
        self.found = 0
        self._hud_text = f"Pairs 0/{self.pairs}"
        self._face_up = [FACES[f] for f in self.faces]   # each card's glyph face up
        # the board: each row's glyphs, and each row joined (again when one of its cards turns)
        self._glyphs = [[DOWN] * self.params.cols for _ in range(self.params.rows)]
        self._lines = ["".join(row) for row in self._glyphs]

    def _act(self, action: int) -> None:
        up, showing = self.up, self.showing
        if len(showing) == 2:             # a failed pair turns back first
            for i in showing:
                up[i] = False
                self._draw(i, DOWN)
            showing = self.showing = []
        if up[action]:
            self.say("That card is already face up.")
            return
        up[action] = True
        self._draw(action, self._face_up[action])
        showing.append(action)
        if len(showing) == 2:
            a, b = showing
            if self.faces[a] == self.faces[b]:
                self.showing = []
                self.found += 1
                self._hud_text = f"Pairs {self.found}/{self.pairs}"
                self.reward(self.params.pair_share / self.pairs)
                self.say("A pair.")
                if self.found == self.pairs:
                    self.reward(1 - self.params.pair_share)
                    self.say("Every pair is found.")
                    self.finish(won=True)
            else:
                self.say("No match.")

    def _draw(self, card: int, glyph: str) -> None:
        """Show ``glyph`` for ``card`` and join its row again."""
        r, c = self._cells[card]
        row = self._glyphs[r]
        row[c] = glyph
        self._lines[r] = "".join(row)

    def _grid(self) -> list[str]:
        return self._lines

    def _hud(self) -> str:
        return self._hud_text


register_variants(MemoryMatch, "Classics", {
    "glyphbench/classics-memorymatch-easy-v0": dict(rows=4, cols=5, max_turns=60),
    "glyphbench/classics-memorymatch-hard-v0": dict(rows=6, cols=6, max_turns=120),
})
