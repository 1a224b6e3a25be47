"""Tutankham: an explorer in King Tut's tomb, zone after zone of chambers.

Kept from the original: each zone is a row of maze chambers seen one at a time (the tomb
scrolls a screen when you pass through a passage; the HUD map shows the chambers); treasures to
pick up, a key somewhere in the zone that opens the locked exit door in its last chamber (only
one key carried at a time); snakes, mummies and bats that come out of nests in the walls and hunt
you; a gun that fires only left or right; one flash bomb per life that slays every creature on
the screen; and a clock per zone, after which the gun no longer fires. Creatures score as the
original (snake 20, mummy 40, bat 60), the key 500.
"""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param
from ..common.lanes import Draws
from .arena import EMPTY, MOVES4, SHOT, WALL
from .dungeon import DungeonParams, DungeonTask, distinct
from .engine import register_atari

PASS, DOOR, KEY, GOLD, NEST = "+", "D", "k", "$", "O"
CREATURES = (("snake", "S", 20), ("mummy", "M", 40), ("bat", "B", 60))
WORTH = {g: points for _, g, points in CREATURES}
FLASH = 6
ACTIONS = ActionSet([("NOOP", "wait a turn"), ("UP", "move up a cell"), ("DOWN", "move down a cell"),
                     ("LEFT", "move left a cell (and aim left)"),
                     ("RIGHT", "move right a cell (and aim right)"),
                     ("FIRE", "shoot the way you aim: left or right only"),
                     ("FLASH", "set off your flash bomb: every creature on the screen dies (once a life)")],
                    noop="NOOP")


@dataclass(frozen=True)
class TutankhamParams(DungeonParams):
    chambers: int = param(4, 2, 12)      # chambers in a zone
    treasures: int = param(3, 0, 20)     # treasures in a zone
    foes: int = param(3, 0, 10)          # creatures in a chamber at once (at most)
    spawn: int = param(10, 1, 200)       # turns between creatures from a nest
    key: int = param(500, 0, 10000)      # points for picking up the key


class Tutankham(DungeonTask):
    title = "Tutankham"
    rules = ("You are an explorer ({lives_text}) in King Tut's tomb. Each zone is a row of "
             "{chambers} maze chambers seen one at a time; a passage ({pass_}) at a chamber's side "
             "leads on to the next. Pick up treasures ({gold}) and the key ({key_}); the key opens "
             "the locked door ({door}) in the zone's last chamber, and going through it starts "
             "the next zone. Snakes, mummies and bats come out of nests ({nest}) in the walls, one "
             "every {spawn} turns while fewer than {foes} are in your chamber. {wander_text} FIRE "
             "shoots ({shot}) {reach} cells left or right only, the way you last moved sideways, and "
             "slays the first creature it meets. FLASH slays every creature in the chamber, once a "
             "life. Each zone has {clock} turns on the clock (Time in the HUD); after that your gun "
             "no longer fires.{turn_text}{map_text}")
    rewards = ("+{unit} for each treasure and each zone's door gone through; +{key} for the key; "
               "{kills}; {death} when the game is lost.")
    ends = "when treasures and doors gone through number {goal} together, or the game is lost"
    Params = TutankhamParams
    ACTIONS = ACTIONS
    MOVES = MOVES4 + (None,)
    pattern = "D"
    LINKS, SIDEWAYS = PASS + DOOR, True
    SOLID = frozenset((WALL, NEST))
    caught_text = "A creature got you."
    glyphs = {EMPTY: "floor", WALL: "wall", PASS: "passage to the next chamber", DOOR: "locked exit door",
              KEY: "key", GOLD: "treasure", NEST: "nest", **{g: name for name, g, _ in CREATURES},
              SHOT: "your shot", "<": "you (aiming left)", ">": "you (aiming right)"}

    def prompt_fields(self) -> dict:
        return {**super().prompt_fields(), "pass_": PASS, "gold": GOLD, "key_": KEY, "door": DOOR,
                "nest": NEST, "shot": SHOT, "kills": "; ".join(
                    f"+{points} for each {name} slain" for name, _, points in CREATURES)}

    def _setup(self, rng) -> None:
        self.zone, self.key, self.flashes = 1, False, 1
        self._zone()
        self.start_dungeon(rng, ("#" * self.params.chambers,), (0, 0), self.entry, 1)
        self.face = self.aim = (0, 1)

    def _zone(self) -> None:
        """Lay out the zone's chambers: corridors between barred rows, passages, nests, loot."""
        p = self.params
        h, w, n = p.height, p.width, p.chambers
        draws = Draws(self.stream("zone", self.zone), 512)
        bands = [r for r in range(1, h - 1) if r % 3]            # corridor rows
        links = [bands[draws.below(len(bands))] for _ in range(n + 1)]
        self.entry = links[0]
        self.plan, self.nests = [], []
        for k in range(n):
            grid = [[WALL] * w for _ in range(h)]
            for r in bands:
                grid[r][1:w - 1] = [EMPTY] * (w - 2)
            for r in range(3, h - 2, 3):                         # gaps in each bar between corridors
                for c in distinct(draws, w - 2, 2 + draws.below(2)):
                    grid[r][c + 1] = EMPTY
            for r in range(1, h - 2, 3):                         # pillars that make the corridors wind
                for c in distinct(draws, (w - 4) // 3, 2):
                    c = 3 + 3 * c
                    if grid[r - 1][c] == WALL and grid[r + 2][c] == WALL:
                        grid[r + draws.below(2)][c] = WALL
            if k:
                grid[links[k]][0] = PASS
            grid[links[k + 1]][w - 1] = PASS if k < n - 1 else DOOR
            walls = [(r, c) for r in range(3, h - 2, 3) for c in range(2, w - 2)
                     if grid[r][c] == WALL and grid[r][c - 1] == WALL and grid[r][c + 1] == WALL
                     and EMPTY in (grid[r - 1][c], grid[r + 1][c])]
            r, c = walls[draws.below(len(walls))]
            grid[r][c] = NEST
            self.nests.append((r, c, CREATURES[(k + self.zone) % 3][1]))
            self.plan.append(grid)
        floor = [(k, r, c) for k in range(n) for r in bands for c in range(2, w - 2)
                 if self.plan[k][r][c] == EMPTY and (k, r) != (0, self.entry)]
        for i, pick in enumerate(distinct(draws, len(floor), p.treasures + 1)):
            k, r, c = floor[pick]
            self.plan[k][r][c] = GOLD if i else KEY
        self.plan = [["".join(row) for row in grid] for grid in self.plan]

    def _room(self, room) -> list[str]:
        return self.plan[room[1]]

    def _populate(self, room) -> None:
        self.born = self.tick

    def _turn(self) -> None:
        p = self.params
        if self.tick - self.born >= p.spawn and len(self.foes) < p.foes:
            r, c, glyph = self.nests[self.room[1]]
            for dr in (1, -1):
                if self.free(r + dr, c) and abs(r + dr - self.r) + abs(c - self.c) > 2:
                    self.add_foe(r + dr, c, glyph=glyph)
                    self.born = self.tick
                    break

    def _play(self, action: int) -> None:
        if action == FLASH:
            action = 0
            if self.flashes:
                self.flashes -= 1
                self.say(f"Flash! {self.flash()} creatures slain.")
        super()._play(action)

    def _cross(self, r: int, c: int) -> None:
        p, k = self.params, self.room[1]
        if self.still[r][c] == PASS:
            k += 1 if c else -1
            self.go((0, k), r, 1 if c else p.width - 2)
            self.born = self.tick
            return
        if not self.key:
            self.say("The door is locked: find the key.")
            return
        self.key = False
        self.say("The door opens: on to the next zone!")
        self.score.gain()
        if not self.done:
            self.zone += 1
            self._zone()
            self.new_world(("#" * p.chambers,))
            self.go((0, 0), self.entry, 1)
            self.face = self.aim = (0, 1)
            if self.clock is not None:
                self.clock.refill()

    def _take(self, r: int, c: int, ch: str) -> None:
        if ch == GOLD:
            self.set_still(r, c, EMPTY)
            self.say("Treasure!")
            self.score.gain()
        elif ch == KEY and not self.key:
            self.set_still(r, c, EMPTY)
            self.key = True
            self.say("You have the key.")
            self.score.bonus(self.params.key)

    def _armed(self) -> bool:
        return self.clock is None or self.clock.left > 0

    def worth(self, foe) -> float:
        return WORTH.get(foe.glyph, 0)

    def _time_up(self) -> None:
        self.say("Time is up: your gun no longer fires.")

    def _respawn(self) -> None:
        super()._respawn()
        self.flashes, self.born = 1, self.tick

    def _extra_hud(self) -> str:
        left = self.clock.left if self.clock else 0
        state = (left, self.zone, self.room, self.key, self.flashes)
        if state != self._state:
            self._state = state
            self._text = (f"Zone {self.zone} | {self.map.hud()} | Time {left} | Key "
                          f"{'yes' if self.key else 'no'} | Flash {self.flashes}")
        return self._text

    _state = None


register_atari(Tutankham, "tutankham", width=20, height=16, lives=3, goal=8, unit=1000.0,
               chambers=4, treasures=3, foes=3, spawn=10, every=2, sense=8, reach=8, clock=400,
               key=500, max_turns=10000)
