"""ProcgenTask: what the Procgen games share.

Five actions (NOOP, LEFT, RIGHT, UP, DOWN), an agent-centred view window clamped to the world
(a world smaller than the window is shown whole), the player drawn as an arrow of its last move
(``@`` before any), a HUD with the score (the return so far) plus each game's extras, and a
horizon of 500 turns. A game keeps its world as row strings or row lists (``_rows``), lists the
things drawn on top (``_sprites``), and moves by ``target(action)``.

Motion in the HUD: a game whose things move reports the player's velocity (``_velocity``) and its
moving things (``_movers``); the HUD then carries ``Vel →1↑2`` and ``Moving: E@+2,-3←1 ...``
(each visible mover's place relative to you, rows then columns, and its velocity per turn), and
the rules gain one sentence saying so. Open cells are ``.``: SmolLM2 reads a run of ``.`` as a
few tokens where a run of the shared palette's ``·`` costs one token a cell.
"""

from __future__ import annotations

from functools import lru_cache
from typing import ClassVar, Iterable, Sequence

from ...core import GlyphTask
from ...core.actions import ActionSet
from ..common.view import window

Cell = tuple[int, int]
OPEN = "."          # an open cell in every Procgen game
MAX_MOVERS = 6      # the HUD lists at most this many moving things, nearest first
MOTION_RULE = (" The status line lists moving things in view, nearest first: E@+2,-3←1 is an E "
               "2 rows below and 3 columns left of you moving 1 column left a turn (↑2: 2 rows up "
               "a turn); Vel is your own velocity.")

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

    shows_motion: ClassVar[bool] = False   # the HUD reports Vel and Moving (and the rules say so)

    pos: Cell
    facing: int
    _origin_key: tuple | None = None    # what the view origin below was worked out for
    _origin_at: Cell = (0, 0)
    _score: tuple = (None, "")          # the return last shown and its HUD text

    def __init_subclass__(cls, **kwargs) -> None:
        super().__init_subclass__(**kwargs)
        if cls.__dict__.get("shows_motion") and MOTION_RULE not in cls.rules:
            cls.rules = cls.rules + MOTION_RULE.replace("{", "{{").replace("}", "}}")
            cls.extra_chars = "".join(dict.fromkeys(cls.extra_chars + "←→↑↓"))

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

    def _velocity(self) -> Cell | None:
        """The player's velocity (rows, columns per turn; rows grow downward), or None for a
        game where the player has none beyond the last move (the HUD then leaves Vel out)."""
        return None

    def _movers(self) -> Iterable[tuple[str, int, int, int, int]]:
        """Moving things as (glyph, row, column, row velocity, column velocity), world cells."""
        return ()

    def _origin(self) -> Cell:
        """The view's top-left world cell: centred on the player, clamped to the world."""
        rows = self._rows()
        key = (self.pos, len(rows), len(rows[0]), self.view_h, self.view_w)
        if key != self._origin_key:       # (asked twice a turn, by _grid and _motion)
            r, c = self.pos
            self._origin_key, self._origin_at = key, (
                min(max(r - self.view_h // 2, 0), max(len(rows) - self.view_h, 0)),
                min(max(c - self.view_w // 2, 0), max(len(rows[0]) - self.view_w, 0)))
        return self._origin_at

    def _motion(self) -> str:
        """``Vel ... | Moving: ...`` for the things inside the current view."""
        r, c = self.pos
        top, left = self._origin()
        bottom, right = top + self.view_h, left + self.view_w
        seen = [(abs(mr - r) + abs(mc - c), mr - r, mc - c, ch, vr, vc)
                for ch, mr, mc, vr, vc in self._movers()
                if (vr or vc) and top <= mr < bottom and left <= mc < right]
        seen.sort()                        # (a list sorted in place: quicker than sorted(gen))
        vel = self._velocity()
        text = "" if vel is None else "Vel " + velocity_text(*vel)
        if seen:
            words = _MOVER_WORDS
            out = []
            for entry in seen[:MAX_MOVERS]:
                word = words.get(entry)
                if word is None:
                    _, dr, dc, ch, vr, vc = entry
                    word = words[entry] = f"{ch}@{dr:+d},{dc:+d}{velocity_text(vr, vc)}"
                out.append(word)
            text += (" | Moving: " if text else "Moving: ") + " ".join(out)
        return text

    def _grid(self) -> list[str]:
        top, left = self._origin()
        view = window(self._rows(), top, left, self.view_h, self.view_w)
        h, w = len(view), len(view[0]) if view else 0
        r, c = self.pos
        for sr, sc, ch in (*self._sprites(), (r, c, ARROWS[self.facing])):
            sr -= top           # (view.overlay, inlined: a few calls a turn in every game)
            sc -= left
            if 0 <= sr < h and 0 <= sc < w:
                row = view[sr]
                view[sr] = row[:sc] + ch + row[sc + 1:]
        return view

    def _hud(self) -> str:
        score = self.episode_return
        if score is not self._score[0]:   # (the same float object: the same text)
            self._score = score, f"Score {score:.2f}"
        text = self._score[1]
        extras = self._extras()
        if extras:
            text += " | " + extras
        if self.shows_motion:
            motion = self._motion()
            if motion:
                text += " | " + motion
        return text


@lru_cache(maxsize=None)
def velocity_text(dr: int, dc: int) -> str:
    """``→1↑2``-style velocity; ``0`` when still."""
    text = (f"←{-dc}" if dc < 0 else f"→{dc}" if dc > 0 else "") + \
        (f"↑{-dr}" if dr < 0 else f"↓{dr}" if dr > 0 else "")
    return text or "0"


# HUD words of movers, by (distance, rows, columns, glyph, row velocity, column velocity):
# a bounded set (positions within a view, a few glyphs and speeds), shared by all games
_MOVER_WORDS: dict[tuple, str] = {}
