"""MiniGrid's world objects: each carries its own behaviour and its glyph.

As in Farama Minigrid (``minigrid/core/world_object.py``) an object answers whether the agent
may walk onto it (``overlap``), pick it up (``pickup``) and see past it (``see_behind``), and
``toggle`` is how it reacts when the agent activates it; the movement rules live once, in the
engine. The flags are plain attributes rather than methods because the view code reads them
for 49 cells every step; a door updates its own when its state changes.

Glyphs: one character per cell; the letter of an object names its colour (r red, g green,
b blue, p purple, y yellow, e grey) and its form names the kind::

    key  r   (small letter)       closed door  R   (capital)      open door  _
    ball ⓡ   (circled letter)     locked door  Ⓡ   (circled capital: the key r opens it)
    box  ⒭   (letter in brackets: a container)
"""

from __future__ import annotations

from functools import lru_cache
from typing import TYPE_CHECKING, ClassVar

from ..common.palette import FLOOR, GOAL, LAVA, UNSEEN, WALL

if TYPE_CHECKING:
    from .engine import MiniGridTask

# MiniGrid's colour names; COLOR_NAMES is its sorted list, which its generators sample from.
COLORS = ("red", "green", "blue", "purple", "yellow", "grey")
COLOR_NAMES = tuple(sorted(COLORS))
_INITIAL = dict(zip(COLORS, "rgbpye"))

OPEN_DOOR = "_"
AGENT = "▶▼◀▲"                       # indexed by direction: 0 east, 1 south, 2 west, 3 north
DIR_NAMES = ("east", "south", "west", "north")
DIR_VEC = ((1, 0), (0, 1), (-1, 0), (0, -1))

_CIRCLED_SMALL = {c: chr(0x24D0 + ord(ch) - 97) for c, ch in _INITIAL.items()}    # ⓐ..ⓩ
_CIRCLED_CAPITAL = {c: chr(0x24B6 + ord(ch) - 97) for c, ch in _INITIAL.items()}  # Ⓐ..Ⓩ
_BRACKETED = {c: chr(0x249C + ord(ch) - 97) for c, ch in _INITIAL.items()}        # ⒜..⒵


class WorldObj:
    """Anything that occupies a cell. Subclasses set the flags and may override ``toggle``."""

    kind: ClassVar[str] = ""
    overlap: bool = False        # the agent may stand on it
    pickup: bool = False         # the agent may carry it
    see_behind: bool = True      # sight passes through it
    __slots__ = ("color", "glyph", "pos")

    def __init__(self, color: str) -> None:
        if color not in COLORS:
            raise ValueError(f"unknown colour {color!r}; colours: {', '.join(COLORS)}")
        self.color = color
        self.glyph = self._glyph()
        self.pos: tuple[int, int] | None = None   # where it lies; None while carried

    def _glyph(self) -> str:
        raise NotImplementedError

    @property
    def name(self) -> str:
        """How the legend, HUD and messages call it: 'red key'."""
        return f"{self.color} {self.kind}"

    def toggle(self, task: "MiniGridTask", pos: tuple[int, int]) -> bool:
        """React to TOGGLE from the agent facing ``pos``; True if something happened."""
        return False

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.color!r})"


class Wall(WorldObj):
    kind = "wall"
    see_behind = False
    __slots__ = ()

    def __init__(self, color: str = "grey") -> None:
        super().__init__(color)

    def _glyph(self) -> str:
        return WALL

    @property
    def name(self) -> str:
        return "wall"


class Goal(WorldObj):
    kind = "goal"
    overlap = True
    __slots__ = ()

    def __init__(self, color: str = "green") -> None:
        super().__init__(color)

    def _glyph(self) -> str:
        return GOAL


class Lava(WorldObj):
    kind = "lava"
    overlap = True
    __slots__ = ()

    def __init__(self, color: str = "red") -> None:
        super().__init__(color)

    def _glyph(self) -> str:
        return LAVA

    @property
    def name(self) -> str:
        return "lava"


class Key(WorldObj):
    kind = "key"
    pickup = True
    __slots__ = ()

    def __init__(self, color: str = "blue") -> None:
        super().__init__(color)

    def _glyph(self) -> str:
        return _INITIAL[self.color]


class Ball(WorldObj):
    kind = "ball"
    pickup = True
    __slots__ = ()

    def __init__(self, color: str = "blue") -> None:
        super().__init__(color)

    def _glyph(self) -> str:
        return _CIRCLED_SMALL[self.color]


class Box(WorldObj):
    """A box can be carried; toggling it replaces it by what it holds (or by nothing)."""

    kind = "box"
    pickup = True
    __slots__ = ("contains",)

    def __init__(self, color: str, contains: WorldObj | None = None) -> None:
        super().__init__(color)
        self.contains = contains

    def _glyph(self) -> str:
        return _BRACKETED[self.color]

    def toggle(self, task: "MiniGridTask", pos: tuple[int, int]) -> bool:
        task.grid.set(*pos, self.contains)
        task.say(f"The {self.name} held {'a ' + self.contains.name if self.contains else 'nothing'}.")
        return True


class Door(WorldObj):
    """Open doors can be walked and seen through; a locked door opens only for the agent
    carrying the key of its colour, and then stays unlocked."""

    kind = "door"
    __slots__ = ("is_open", "is_locked", "overlap", "see_behind")

    def __init__(self, color: str, is_open: bool = False, is_locked: bool = False) -> None:
        self.is_open, self.is_locked = is_open, is_locked and not is_open
        super().__init__(color)
        self._update()

    def _update(self) -> None:
        self.overlap = self.see_behind = self.is_open
        self.glyph = self._glyph()

    def _glyph(self) -> str:
        if self.is_open:
            return OPEN_DOOR
        return _CIRCLED_CAPITAL[self.color] if self.is_locked else _INITIAL[self.color].upper()

    @property
    def name(self) -> str:
        state = "open" if self.is_open else "locked" if self.is_locked else "closed"
        return f"{state} {self.color} door"

    def toggle(self, task: "MiniGridTask", pos: tuple[int, int]) -> bool:
        if self.is_locked:
            carried = task.carrying
            if not (isinstance(carried, Key) and carried.color == self.color):
                task.say(f"The {self.color} door is locked.")
                return False
            self.is_locked = False
            self.is_open = True
            task.say(f"You unlocked the {self.color} door.")
        else:
            self.is_open = not self.is_open
            task.say(f"You {'opened' if self.is_open else 'closed'} the {self.color} door.")
        self._update()
        task.grid.refresh(*pos)
        return True


KINDS = ("goal", "lava", "door", "key", "ball", "box")
PORTABLE = {"key": Key, "ball": Ball, "box": Box}    # what the agent can carry, in MiniGrid's draw order


def from_glyph(glyph: str) -> WorldObj | None:
    """A new object drawn as ``glyph`` (floor gives None; an open door is a yellow one)."""
    if glyph == FLOOR:
        return None
    if glyph == OPEN_DOOR:
        return Door("yellow", is_open=True)
    maker = _MAKERS.get(glyph)
    if maker is None:
        raise ValueError(f"no object is drawn as {glyph!r}")
    return maker()


_MAKERS = {WALL: Wall, GOAL: Goal, LAVA: Lava}
for _color in COLORS:
    _MAKERS[_INITIAL[_color].upper()] = lambda c=_color: Door(c)
    _MAKERS[_CIRCLED_CAPITAL[_color]] = lambda c=_color: Door(c, is_locked=True)
    _MAKERS[_INITIAL[_color]] = lambda c=_color: Key(c)
    _MAKERS[_CIRCLED_SMALL[_color]] = lambda c=_color: Ball(c)
    _MAKERS[_BRACKETED[_color]] = lambda c=_color: Box(c)


@lru_cache(maxsize=None)
def vocabulary(kinds: tuple[str, ...] = KINDS, unseen: bool = True) -> dict[str, str]:
    """Glyph -> legend meaning, in legend order, for a level holding objects of ``kinds``."""
    vocab = {WALL: "wall", FLOOR: "floor"}
    if unseen:
        vocab[UNSEEN] = "unseen"
    if "goal" in kinds:
        vocab[GOAL] = "goal"
    if "lava" in kinds:
        vocab[LAVA] = "lava"
    vocab.update({AGENT[d]: f"you facing {DIR_NAMES[d]}" for d in (3, 0, 1, 2)})
    if "door" in kinds:
        vocab[OPEN_DOOR] = "open door"
        for color in COLORS:
            vocab[Door(color)._glyph()] = f"{color} door"
            vocab[Door(color, is_locked=True)._glyph()] = f"locked {color} door"
    for cls in (Key, Ball, Box):
        if cls.kind in kinds:
            vocab.update({cls(color).glyph: f"{color} {cls.kind}" for color in COLORS})
    return vocab
