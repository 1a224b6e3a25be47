"""The MiniGrid world grid and the agent's partial view.

Cells are kept in one flat list with a ring of wall ``VIEW_PAD`` cells wide around the world:
MiniGrid's ``Grid.slice`` treats everything beyond the edge as wall, and the ring lets the view
read its 49 cells by index offsets without bounds checks. Coordinates are MiniGrid's ``(x, y)``:
x grows east (columns), y grows south (rows).

The view is MiniGrid's ``gen_obs_grid``: the ``size`` x ``size`` square ahead of the agent, the
agent at the middle of its back edge, with ``process_vis`` (sight spreads from the agent row by
row and stops at walls and closed doors) deciding which cells are seen. It is drawn in world
orientation (north at the top). Visibility depends only on where the agent stands, where it faces
and on what blocks sight, so it is cached per (cell, direction) until something that blocks sight
changes; the drawn view is cached the same way until any cell changes. Whatever changes how an
object looks or whether it blocks sight while it lies on the grid must go through ``set`` or
``refresh``.
"""

from __future__ import annotations

from functools import lru_cache
from typing import Callable, Sequence

from .world import FLOOR, UNSEEN, Wall, WorldObj

VIEW_PAD = 6   # agent_view_size - 1: the farthest the 7x7 view reaches past the agent's cell


class Grid:
    __slots__ = ("width", "height", "stride", "cells", "glyphs", "_vis", "_views")

    def __init__(self, width: int, height: int) -> None:
        if width < 3 or height < 3:
            raise ValueError(f"a grid is at least 3x3, got {width}x{height}")
        self.width, self.height = width, height
        self.stride = width + 2 * VIEW_PAD
        outside = Wall()
        self.cells: list[WorldObj | None] = [outside] * (self.stride * (height + 2 * VIEW_PAD))
        self.glyphs: list[str] = [outside.glyph] * len(self.cells)   # what each cell draws as
        for y in range(height):
            start = self.index(0, y)
            self.cells[start:start + width] = [None] * width
            self.glyphs[start:start + width] = [FLOOR] * width
        # Keyed by (agent cell index * 4 + direction): the view's hidden cells, row by row (valid
        # until something that blocks sight changes), and the drawn view (until anything changes).
        self._vis: dict[int, list[list[int]]] = {}
        self._views: dict[int, list[str]] = {}

    # -- cells ------------------------------------------------------------------------------
    def index(self, x: int, y: int) -> int:
        return (y + VIEW_PAD) * self.stride + x + VIEW_PAD

    def inside(self, x: int, y: int) -> bool:
        return 0 <= x < self.width and 0 <= y < self.height

    def get(self, x: int, y: int) -> WorldObj | None:
        """The object at (x, y), None for empty floor; beyond the edge everything is wall."""
        return self.cells[(y + VIEW_PAD) * self.stride + x + VIEW_PAD]   # self.index, inlined

    def set(self, x: int, y: int, obj: WorldObj | None) -> None:
        if not (0 <= x < self.width and 0 <= y < self.height):
            raise IndexError(f"cell ({x}, {y}) is outside the {self.width}x{self.height} grid")
        i = (y + VIEW_PAD) * self.stride + x + VIEW_PAD
        old = self.cells[i]
        self.cells[i] = obj
        self.glyphs[i] = FLOOR if obj is None else obj.glyph
        if obj is not None:
            obj.pos = (x, y)
        self._views.clear()
        if (old is not None and not old.see_behind) or (obj is not None and not obj.see_behind):
            self._vis.clear()

    def refresh(self, x: int, y: int) -> None:
        """Call when the object at (x, y) changed its looks or whether it blocks sight (a door)."""
        obj = self.get(x, y)
        self.glyphs[self.index(x, y)] = FLOOR if obj is None else obj.glyph
        self._vis.clear()
        self._views.clear()

    def horz_wall(self, x: int, y: int, length: int | None = None,
                  obj_type: Callable[[], WorldObj] = Wall) -> None:
        for i in range(self.width - x if length is None else length):
            self.set(x + i, y, obj_type())

    def vert_wall(self, x: int, y: int, length: int | None = None,
                  obj_type: Callable[[], WorldObj] = Wall) -> None:
        for j in range(self.height - y if length is None else length):
            self.set(x, y + j, obj_type())

    def wall_rect(self, x: int, y: int, w: int, h: int) -> None:
        self.horz_wall(x, y, w)
        self.horz_wall(x, y + h - 1, w)
        self.vert_wall(x, y, h)
        self.vert_wall(x + w - 1, y, h)

    def objects(self) -> list[WorldObj]:
        """Every object inside the world, row by row."""
        return [o for y in range(self.height) for o in self.row(y) if o is not None]

    def row(self, y: int) -> list[WorldObj | None]:
        start = self.index(0, y)
        return self.cells[start:start + self.width]

    # -- drawing -----------------------------------------------------------------------------
    def render_full(self, agent: tuple[int, int], agent_glyph: str) -> list[str]:
        g, w = self.glyphs, self.width
        rows = []
        for y in range(self.height):
            start = self.index(0, y)
            row = g[start:start + w]
            if y == agent[1]:
                row[agent[0]] = agent_glyph
            rows.append("".join(row))
        return rows

    def render_view(self, agent: tuple[int, int], direction: int, agent_glyph: str,
                    size: int = 7, see_through: bool = False) -> list[str]:
        """The agent's view in world orientation, unseen cells drawn as UNSEEN."""
        base = self.index(*agent)
        key = base * 4 + direction
        view = self._views.get(key)
        if view is not None:
            return view
        layout = _view_layout(self.stride, size)
        if see_through:
            hidden = layout.no_rows
        else:
            hidden = self._vis.get(key)
            if hidden is None:
                cells = self.cells
                opaque = [(o := cells[base + d]) is not None and not o.see_behind
                          for d in layout.deltas[direction]]
                seen = process_vis(opaque, layout.rows[direction])
                hidden = self._vis[key] = [[c for c in range(size) if not seen[r * size + c]]
                                           for r in range(size)]
        g, stride = self.glyphs, self.stride
        top = base + layout.corner[direction]
        agent_row, agent_col = divmod(layout.agent_slot[direction], size)
        view = []
        for r in range(size):
            start = top + r * stride
            row = g[start:start + size]
            for c in hidden[r]:
                row[c] = UNSEEN
            if r == agent_row:
                row[agent_col] = agent_glyph
            view.append("".join(row))
        self._views[key] = view
        return view

    def view_mask(self, agent: tuple[int, int], direction: int, size: int = 7) -> list[list[bool]]:
        """MiniGrid's vis_mask in view coordinates: ``mask[vx][vy]`` (for tests and tools)."""
        layout = _view_layout(self.stride, size)
        base = self.index(*agent)
        deltas = layout.deltas[direction]
        opaque = [(o := self.cells[base + d]) is not None and not o.see_behind for d in deltas]
        seen = process_vis(opaque, layout.rows[direction])
        mask = [[False] * size for _ in range(size)]
        for k, (vx, vy) in enumerate(layout.view_xy[direction]):
            mask[vx][vy] = seen[k]
        return mask

    def view_cell(self, agent: tuple[int, int], direction: int, vx: int, vy: int,
                  size: int = 7) -> tuple[int, int]:
        """World (x, y) of the view cell (vx, vy) (MiniGrid's view coordinates)."""
        fx, fy = ((1, 0), (0, 1), (-1, 0), (0, -1))[direction]
        rx, ry = -fy, fx
        k = size - 1 - vy
        return agent[0] + fx * k + rx * (vx - size // 2), agent[1] + fy * k + ry * (vx - size // 2)


@lru_cache(maxsize=64)
def _view_layout(stride: int, size: int) -> "_ViewLayout":
    return _ViewLayout(stride, size)


class _ViewLayout:
    """For each direction, the view's slots in world order (row-major, north at the top):
    the index offset of each slot from the agent's cell and the slot's view coordinates."""

    def __init__(self, stride: int, size: int) -> None:
        half = size // 2
        self.no_rows: list[list[int]] = [[] for _ in range(size)]
        self.deltas: list[list[int]] = []
        self.view_xy: list[list[tuple[int, int]]] = []
        self.rows: list[list[list[int]]] = []  # [vy][vx] -> world-order slot of that view cell
        self.agent_slot: list[int] = []
        self.corner: list[int] = []            # offset of the window's north-west cell
        for d, (fx, fy) in enumerate(((1, 0), (0, 1), (-1, 0), (0, -1))):
            rx, ry = -fy, fx                   # MiniGrid's right_vec
            cells = []
            for vy in range(size):
                for vx in range(size):       # MiniGrid: world = agent + f*(size-1-vy) + r*(vx-half)
                    dx = fx * (size - 1 - vy) + rx * (vx - half)
                    dy = fy * (size - 1 - vy) + ry * (vx - half)
                    cells.append((dy, dx, vx, vy))
            cells.sort()                       # world order: by row, then by column
            self.deltas.append([dy * stride + dx for dy, dx, _, _ in cells])
            self.view_xy.append([(vx, vy) for _, _, vx, vy in cells])
            rows = [[0] * size for _ in range(size)]
            for k, (_, _, vx, vy) in enumerate(cells):
                rows[vy][vx] = k
            self.rows.append(rows)
            self.agent_slot.append(rows[size - 1][half])
            self.corner.append(self.deltas[-1][0])


def process_vis(opaque: Sequence[bool], rows: Sequence[Sequence[int]]) -> list[bool]:
    """MiniGrid's ``Grid.process_vis``, the agent at (size // 2, size - 1) in view coordinates.

    ``rows[vy][vx]`` is the slot of view cell (vx, vy); ``opaque`` and the result are indexed by
    slot.
    """
    size = len(rows)
    mask = [False] * (size * size)
    mask[rows[size - 1][size // 2]] = True
    for j in range(size - 1, -1, -1):
        row = rows[j]
        above = rows[j - 1] if j > 0 else None
        for i in range(size - 1):
            k = row[i]
            if not mask[k] or opaque[k]:
                continue
            mask[row[i + 1]] = True
            if above is not None:
                mask[above[i + 1]] = True
                mask[above[i]] = True
        for i in range(size - 1, 0, -1):
            k = row[i]
            if not mask[k] or opaque[k]:
                continue
            mask[row[i - 1]] = True
            if above is not None:
                mask[above[i - 1]] = True
                mask[above[i]] = True
    return mask
