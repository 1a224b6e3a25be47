"""ProcgenTask: what the Procgen games share.

Five actions (NOOP, LEFT, RIGHT, UP, DOWN), an agent-centred view window clamped to the world
(a world smaller than the window is shown whole), the player drawn as an arrow of its last move
(``@`` before any), a HUD with the score (the return so far) plus each game's extras, and a
horizon of 500 turns. A game keeps its world as row strings or row lists (``_rows``), lists the
things drawn on top (``_sprites``), and moves by ``target(action)``.
"""

from __future__ import annotations

from typing import ClassVar, Iterable, Sequence

from ...core import GlyphTask
from ...core.actions import ActionSet
from ..common.view import overlay, window

Cell = tuple[int, int]

ACTIONS = ActionSet([("NOOP", "wait a turn"), ("LEFT", "move one cell left"),
                     ("RIGHT", "move one cell right"), ("UP", "move one cell up"),
                     ("DOWN", "move one cell down")], noop="NOOP")
DELTAS: tuple[Cell, ...] = ((0, 0), (0, -1), (0, 1), (-1, 0), (1, 0))   # in action order
ARROWS = "@◀▶▲▼"                                                          # in action order
PLAYER_GLYPHS = {"@": "you (not moved yet)", "◀": "you (last moved left)",
                 "▶": "you (last moved right)", "▲": "you (last moved up)",
                 "▼": "you (last moved down)"}


class ProcgenTask(GlyphTask):
    ACTIONS = ACTIONS
    default_max_turns = 500
    view_h: ClassVar[int] = 12
    view_w: ClassVar[int] = 20
    extra_chars = "".join(PLAYER_GLYPHS)

    pos: Cell
    facing: int

    def place_player(self, cell: Cell) -> None:
        self.pos = cell
        self.facing = 0

    def target(self, action: int) -> Cell:
        """The cell ``action`` moves towards (the player's own for NOOP); turns the player."""
        if action:
            self.facing = action
        dr, dc = DELTAS[action]
        return self.pos[0] + dr, self.pos[1] + dc

    # -- drawing -----------------------------------------------------------------------------------
    def _rows(self) -> Sequence[str]:
        """The world as equal-length row strings (without the player and ``_sprites``)."""
        raise NotImplementedError

    def _sprites(self) -> Iterable[tuple[int, int, str]]:
        return ()

    def _extras(self) -> str:
        return ""

    def _grid(self) -> list[str]:
        rows = self._rows()
        height, width = len(rows), len(rows[0])
        r, c = self.pos
        top = min(max(r - self.view_h // 2, 0), max(height - self.view_h, 0))
        left = min(max(c - self.view_w // 2, 0), max(width - self.view_w, 0))
        view = window(rows, top, left, self.view_h, self.view_w)
        for sr, sc, ch in (*self._sprites(), (r, c, ARROWS[self.facing])):
            overlay(view, sr - top, sc - left, ch)
        return view

    def _hud(self) -> str:
        extras = self._extras()
        score = f"Score {self.episode_return:.2f}"
        return f"{score} | {extras}" if extras else score
