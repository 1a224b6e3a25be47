"""Venture: Winky the archer in a dungeon level of four rooms off a hallway.

Kept from the original: the level map (the hallway with the four rooms as boxes, doors in their
walls, and invincible hallmonsters roaming it, back at their posts whenever you come out of a
room); a room entered through a door fills the screen and holds a treasure guarded by its own
monsters (serpents, skeletons, goblins, trolls...); take the treasure and leave by a door. Your
arrow flies the way you face, one at a time, and only in rooms. A slain monster leaves a corpse
that is deadly to touch for a while, and slaying pays only once the room's treasure is taken.
Linger in a room and a hallmonster comes in through the walls after you. Four treasures clear a
level; the next has four new rooms (new walls, new monsters, doors on the other sides).
"""

from __future__ import annotations

from dataclasses import dataclass

from ...core.params import param
from .arena import EMPTY, SHOT, WALL, you_glyphs
from .dungeon import CORPSE, HUNTER, SIDES, DungeonParams, DungeonTask, free_near, side_cell
from .engine import register_atari

HALL, DOOR, GOLD, INSIDE, HALLER = (1, 1), "D", "$", ":", HUNTER
BACK = {"top": "bottom", "bottom": "top", "left": "right", "right": "left"}
LAYOUT = ("#.#", ".#.", "#.#")            # the four rooms at the corners, the hallway between
ROOMS = (("serpent", "S"), ("skeleton", "K"), ("goblin", "G"), ("spider", "X"),
         ("troll", "T"), ("dragon", "R"), ("bat", "B"), ("zombie", "Z"))


@dataclass(frozen=True)
class VentureParams(DungeonParams):
    foes: int = param(3, 0, 8)           # monsters in each room
    hallers: int = param(3, 0, 6)        # hallmonsters in the hallway
    kill: int = param(100, 0, 10000)     # points per monster slain once its room's treasure is taken


class Venture(DungeonTask):
    title = "Venture"
    rules = ("You are Winky ({lives_text}) in a dungeon. The hallway view shows {rooms} rooms as "
             "boxes of wall ({wall}) with doors ({door}); a box with {gold} inside still holds its "
             "treasure. Hallmonsters ({haller}) roam the hallway; they cannot be harmed. Step "
             "into a door to enter that room: it fills the screen, with its treasure ({gold}) guarded by monsters. Step "
             "on the treasure to take it and leave by a door. {wander_text} FIRE shoots an arrow "
             "({shot}) {reach} cells the way you face, one at a time, in rooms only; it slays the "
             "first monster it meets.{corpse_text}{turn_text}{linger_text}{level_text}{map_text} "
             "The hallway is the middle of the map, the rooms its corners.")
    rewards = ("+{unit} for each treasure; +{kill} times the level for each monster slain in a room "
               "whose treasure you hold; {death} when the game is lost.")
    ends = "when you have taken {goal} treasures or the game is lost"
    Params = VentureParams
    pattern = "D"
    LINKS, IMMUNE, FOE = DOOR, HALLER, HALLER
    SOLID = frozenset((WALL, INSIDE))
    caught_text, hunter_name = "A monster got you.", "hallmonster"
    glyphs = {EMPTY: "floor", WALL: "wall", INSIDE: "inside a room (enter by its door)",
              DOOR: "door", GOLD: "treasure", HALLER: "hallmonster", CORPSE: "corpse (deadly)",
              **{g: name for name, g in ROOMS}, SHOT: "your arrow", **you_glyphs()}

    def prompt_fields(self) -> dict:
        rooms = len(ROOMS) // 2
        return {**super().prompt_fields(), "gold": GOLD, "wall": WALL, "door": DOOR, "haller": HALLER,
                "shot": SHOT, "rooms": rooms, "level_text": (
                    f" When the {rooms} treasures of a level are taken, leaving the room starts the "
                    f"next level with {rooms} new rooms.") if self.params.goal > rooms else ""}

    def _setup(self, rng) -> None:
        self.level = 1
        self._level()
        self.start_dungeon(rng, LAYOUT, HALL, *self._start())

    def _start(self) -> tuple[int, int]:
        return self.params.height - 1, 0

    def _level(self) -> None:
        """The level's doors: (room, side) for each; the rooms still holding treasure."""
        p = self.params
        bh, bw = (p.height - 6) // 2, (p.width - 6) // 2
        self.boxes, self.doors, self.left = {}, {}, set()
        for room in ((0, 0), (0, 2), (2, 0), (2, 2)):
            top = 1 if room[0] == 0 else p.height - 1 - bh
            left = 1 if room[1] == 0 else p.width - 1 - bw
            box = self.boxes[room] = (top, left, top + bh - 1, left + bw - 1)
            inner = ("bottom" if room[0] == 0 else "top", "right" if room[1] == 0 else "left")
            for side in (inner if self.level % 2 else [BACK[s] for s in inner]):   # odd levels: inward
                self.doors[side_cell(box, side)] = (room, side)
            self.left.add(room)

    def _room(self, room) -> list[str]:
        p = self.params
        h, w = p.height, p.width
        if room == HALL:
            grid = [[EMPTY] * w for _ in range(h)]
            for key, (t, l, b, r) in self.boxes.items():
                for i in range(t, b + 1):
                    for j in range(l, r + 1):
                        edge = i in (t, b) or j in (l, r)
                        grid[i][j] = WALL if edge else INSIDE
                grid[(t + b) // 2][(l + r) // 2] = GOLD
            for cell in self.doors:
                grid[cell[0]][cell[1]] = DOOR
            return ["".join(row) for row in grid]
        grid = [[WALL] * w] + [[WALL] + [EMPTY] * (w - 2) + [WALL] for _ in range(h - 2)] + [[WALL] * w]
        for (i, j) in walls(self._kind(room), h, w):
            grid[i][j] = WALL
        for cell, (key, side) in self.doors.items():
            if key == room:
                i, j = side_cell((0, 0, h - 1, w - 1), side)
                grid[i][j] = DOOR
        i, j = free_near(grid, h // 2, w // 2)
        grid[i][j] = GOLD
        return ["".join(row) for row in grid]

    def _kind(self, room) -> int:
        return (room[0] + room[1] // 2) + 4 * ((self.level - 1) % 2)

    def _populate(self, room) -> None:
        p = self.params
        if room == HALL:
            h, w = p.height, p.width
            for r, c in ((h // 2 - 1, w // 2), (0, w // 2 + 1), (h // 2, w - 1),
                         (h // 2 + 1, 1), (h - 1, w // 2), (0, 2))[:p.hallers]:
                self.add_foe(r, c, glyph=HALLER)
            return
        glyph = ROOMS[self._kind(room)][1]
        gr, gc = next((i, j) for i, row in enumerate(self.still) for j, ch in enumerate(row) if ch == GOLD)
        rows = range(max(1, gr - 4), min(p.height - 1, gr + 5))
        cols = range(max(1, gc - 6), min(p.width - 1, gc + 7))
        for _ in range(p.foes):
            for _ in range(9):                        # guards stand beside the treasure, not on it
                r, c = self.spot(6, rows, cols)
                if self.still[r][c] == EMPTY:
                    break
            self.add_foe(r, c, glyph=glyph)

    def _cross(self, r: int, c: int) -> None:
        if self.room == HALL:
            room, side = self.doors[(r, c)]
            p = self.params
            i, j = side_cell((0, 0, p.height - 1, p.width - 1), side)
            dr, dc = SIDES[side]
            self.go(room, i - dr, j - dc)
            self.say(f"You enter the {ROOMS[self._kind(room)][0]} room.")
            return
        frame = (0, 0, self.params.height - 1, self.params.width - 1)
        cell, side = next((cell, side) for cell, (key, side) in self.doors.items()
                          if key == self.room and side_cell(frame, side) == (r, c))
        dr, dc = SIDES[side]
        self.held.pop(HALL, None)              # the hallmonsters are back at their posts
        if self.left:
            self.go(HALL, cell[0] + dr, cell[1] + dc)
            return
        self.level += 1
        self.new_world(LAYOUT)
        self._level()
        self.go(HALL, *self._start())
        self.say(f"Level {self.level}: four new rooms.")

    def _take(self, r: int, c: int, ch: str) -> None:
        if ch == GOLD and self.room != HALL:
            self.set_still(r, c, EMPTY)
            self.left.discard(self.room)
            t, l, b, rr = self.boxes[self.room]
            hall = self.rows_of(HALL)
            i, j = (t + b) // 2, (l + rr) // 2
            hall[i] = hall[i][:j] + INSIDE + hall[i][j + 1:]
            self.say("You took the treasure!")
            self.score.gain()

    def _armed(self) -> bool:
        return self.room != HALL

    def worth(self, foe) -> float:
        return 0.0 if self.room in self.left else self.params.kill * self.level

    def _haunted(self, room) -> bool:
        return room != HALL

    def _extra_hud(self) -> str:
        text = self.map.hud()                 # (the same text while you stay in a room)
        if text is not self._map_text:
            self._map_text, self._level_text = text, f"Level {self.level} | {text}"
        return self._level_text

    _map_text = None


def walls(kind: int, h: int, w: int) -> list[tuple[int, int]]:
    """The inner walls of a room of ``kind`` (0-7), never on a door's inner cell."""
    cells: list[tuple[int, int]] = []
    if kind in (0, 5):                                    # upright bars (from the top and bottom)
        for k, j in enumerate((w // 4, w // 2, w - 1 - w // 4)):
            lo, hi = ((1, h - 5) if k != 1 else (4, h - 4)) if kind == 5 else (3, h - 3)
            cells += [(i, j) for i in range(lo, hi)]
    elif kind in (1, 6):                                  # a vault around the treasure
        t, b, l, r = h // 2 - 2, h // 2 + 2, w // 2 - 3, w // 2 + 3
        cells += [(i, j) for i in range(t, b + 1) for j in range(l, r + 1)
                  if (i in (t, b) or j in (l, r)) and not (i == (t if kind == 1 else h // 2) and
                                                           j == (w // 2 if kind == 1 else l))]
    elif kind in (2, 7):                                  # long bars across
        for i in (h // 3, h - 1 - h // 3):
            cells += [(i, j) for j in range(3, w - 3) if kind == 2 or j % 4]
    else:                                                 # pillars
        for i in (3, h // 2, h - 4):
            cells += [(i, j) for j in range(3 + 2 * (kind == 4), w - 3, 4)]
    mr, mc = (h - 1) // 2, (w - 1) // 2                   # the doors' inner cells stay open
    return [(i, j) for i, j in cells if (i, j) not in ((mr, 1), (mr, w - 2), (1, mc), (h - 2, mc))]


register_atari(Venture, "venture", width=20, height=16, lives=4, goal=4, unit=200.0, foes=3,
               hallers=3, every=2, sense=6, reach=10, corpse=10, linger=60, kill=100,
               max_turns=10000)
