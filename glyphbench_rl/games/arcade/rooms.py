"""Worlds of many rooms or screens, seen one at a time: which rooms exist, which were visited,
where the player is, and the small map of them the HUD carries so an agent can plan across
rooms.

``RoomMap(layout)`` takes the world's layout as rows of text, ``#`` a room and anything else no
room (a pyramid of rooms, a hallway with rooms off it, a line of jungle screens). ``enter(r, c)``
moves the player there (True on a first visit); ``hud()`` is ``Map`` and the map row by row,
rows split by ``/``: ``@`` the player's room, ``+`` visited, ``?`` not yet visited, ``-`` no
room. A long world (a line of 255 screens) shows ``span`` columns either side of the player.
The text is made once per room change. ``LEGEND`` says all that for a prompt.
"""

from __future__ import annotations

from typing import Sequence

LEGEND = ("The HUD's Map shows the rooms row by row, rows split by /: @ your room, + visited, "
          "? not yet visited, - no room")


class RoomMap:
    __slots__ = ("rooms", "height", "width", "visited", "here", "span", "_text")

    def __init__(self, layout: Sequence[str], span: int = 0) -> None:
        self.height, self.width = len(layout), max(len(row) for row in layout)
        self.rooms = frozenset((r, c) for r, row in enumerate(layout)
                               for c, ch in enumerate(row) if ch == "#")
        if not self.rooms:
            raise ValueError("a room layout needs at least one room ('#')")
        self.span = span                  # columns shown either side of the player (0: all)
        self.visited: set[tuple[int, int]] = set()
        self.here: tuple[int, int] | None = None
        self._text: str | None = None

    def __contains__(self, room: tuple[int, int]) -> bool:
        return room in self.rooms

    def enter(self, r: int, c: int) -> bool:
        """Move to room (r, c); True when it had not been visited."""
        if (r, c) not in self.rooms:
            raise ValueError(f"no room at row {r}, column {c}")
        self.here = (r, c)
        self._text = None
        if (r, c) in self.visited:
            return False
        self.visited.add((r, c))
        return True

    def hud(self) -> str:
        if self._text is None:
            lo, hi = 0, self.width
            if self.span and self.here is not None:
                lo, hi = max(0, self.here[1] - self.span), min(self.width, self.here[1] + self.span + 1)
            rows = []
            for r in range(self.height):
                cells = []
                for c in range(lo, hi):
                    room = (r, c)
                    cells.append("@" if room == self.here else "+" if room in self.visited
                                 else "?" if room in self.rooms else "-")
                rows.append("".join(cells))
            self._text = "Map " + "/".join(rows)
        return self._text
