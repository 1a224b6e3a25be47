"""Stargunner: a side-scrolling shooter. Your ship keeps to the left columns while enemies stream
in from the right edge, weaving as they come; shoot them before one gets past your column. On
the Atari preset a star field scrolls by and enemies fire back (pattern D; the MiniAtari preset
pays no death penalty)."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param, require
from .bodies import Body, Gun
from .engine import EMPTY, ArcadeParams, ArcadeTask, register_arcade
from .scroller import Pacer, Strip, stamp

SHIP, ENEMY, SHOT, BOLT, STAR = ">", "E", "-", "~", "*"
ACTIONS = ActionSet([("NOOP", "hold position"), ("UP", "move one row up"), ("DOWN", "move one row down"),
                     ("LEFT", "move one column back"), ("RIGHT", "move one column forward"),
                     ("FIRE", "shoot right")], noop="NOOP")
MOVES = ((0, 0), (-1, 0), (1, 0), (0, -1), (0, 1), (0, 0))
FIRE = 5


@dataclass(frozen=True)
class GunnerParams(ArcadeParams):
    width: int = param(14, 8, 60)
    height: int = param(8, 5, 30)
    goal: int = param(5, 1, 500)
    unit: float = param(0.2, 0, 100)
    death: float = param(0.0, -1, 0)
    zone: int = param(3, 1, 30)           # the last column you may fly to
    spawn: int = param(4, 1, 30)          # turns between enemies
    pace: int = param(2, 1, 6)            # turns per column an enemy flies
    weave: float = param(0.3, 0, 1)       # chance an enemy shifts a row as it flies
    fire: float = param(0.0, 0, 1)        # chance an enemy fires as it flies
    stars: float = param(0.0, 0, 0.5)     # star density of the scrolling backdrop

    def check(self) -> None:
        require(self.zone + 4 < self.width, "zone", "leave room for the enemies", self.zone)


class Stargunner(ArcadeTask):
    title = "Stargunner"
    rules = ("You fly the ship (>) on a {width}x{height} view, with {lives_text}; you may move "
             "anywhere in columns 0 to {zone}. Enemies (E) enter at the right edge every {spawn} "
             "turns and fly one column left every {pace} turns, sometimes shifting a row.{fire_text} "
             "FIRE sends your shot (-) right two cells a turn. An enemy that reaches your column "
             "or touches you costs a life.{star_text}")
    rewards = "+{unit} for each enemy shot down{death_text}."
    ends = "when you have shot down {goal} enemies or the game is lost"
    ACTIONS = ACTIONS
    Params = GunnerParams
    pattern = "D"
    glyphs = {EMPTY: "space", STAR: "star (scenery)", ENEMY: "enemy", SHOT: "your shot",
              BOLT: "enemy shot", SHIP: "you (the ship)"}

    def prompt_fields(self) -> dict:
        p = self.params
        return {**super().prompt_fields(),
                "fire_text": " Enemies fire shots (~) left, one cell a turn." if p.fire else "",
                "star_text": " Stars (*) are scenery." if p.stars else "",
                "death_text": f"; {p.death} when the game is lost" if p.death else ""}

    def _setup(self, rng) -> None:
        self.start(rng)
        p = self.params
        self.strip = Strip([EMPTY * p.width] * p.height, "left")
        self.r, self.col = p.height // 2, 1
        self.enemies: list[Body] = []
        self.gun = Gun(cooldown=1, speed=2, reach=p.width, limit=2)
        self.bolts: list[Body] = []
        self.spawner, self.star_cols = Pacer(p.spawn), []
        self.moves, self.layer_at, self.layer = 0, -1, []    # moves: stars or enemies changed
        if p.stars:
            for _ in range(p.width):
                self.strip.push(self._stars())

    def _stars(self) -> str:
        """The next backdrop column: one of a few made at the start (cheap per turn)."""
        if not self.star_cols:
            p = self.params
            self.star_cols = ["".join(STAR if self.draws.random() < p.stars else EMPTY
                                      for _ in range(p.height)) for _ in range(8)]
        return self.star_cols[self.draws.below(8)]

    def _play(self, action: int) -> None:
        p = self.params
        dr, dc = MOVES[action]
        r, c = self.r + dr, self.col + dc
        self.r = 0 if r < 0 else r if r < p.height else p.height - 1
        self.col = 0 if c < 0 else c if c < p.zone else p.zone
        if action == FIRE:
            self.gun.fire(self.tick, self.r, self.col + 1, 0, 1, SHOT)
        if self._struck():
            return
        if p.stars and self.tick % 2 == 0:
            self.strip.push(self._stars())
            self.moves += 1
        if self.tick % p.pace == 0:
            self.moves += 1
            rand, weave, fire, low = self.draws.random, p.weave, p.fire, p.height - 1
            for e in self.enemies:
                e.c -= 1
                if weave and rand() < weave:
                    r = e.r + (1 if rand() < 0.5 else -1)
                    e.r = 0 if r < 0 else r if r < low else low
                if fire and rand() < fire:
                    self.bolts.append(Body(e.r, e.c - 1, glyph=BOLT))
        if self.bolts:
            kept = []
            for b in self.bolts:
                b.c -= 1
                if b.c >= 0:
                    kept.append(b)
            self.bolts = kept
        if self.spawner.due(self.tick):
            self.enemies.append(Body(self.draws.below(p.height), p.width - 1, glyph=ENEMY))
            self.moves += 1
        if self._struck():
            return
        col = self.col
        for e in self.enemies:
            if e.c <= col:
                self.lose_life("An enemy got past you!")
                return

    def _struck(self) -> bool:
        """Shots against enemies (they move first), then anything touching the ship."""
        if self.gun.shots and self._fly():
            return True
        r, c = self.r, self.col
        for e in self.enemies:
            if e.c == c and e.r == r:
                break
        else:
            for b in self.bolts:
                if b.c == c and b.r == r:
                    break
            else:
                return False
        self.lose_life("You were hit!")
        return True

    def _fly(self) -> bool:
        """Your shots fly right two cells, cell by cell (``fly_shots`` with the hit test
        written into the loop); True when one won the game (the shots are left as they are)."""
        width, kept = self.params.width, []
        spots = {(e.r, e.c) for e in self.enemies}     # where a shot stops
        for shot in self.gun.shots:
            r, c = shot.r, shot.c
            stop = 0                                    # (shots fly right of column 0)
            for at in (c + 1, c + 2):
                if at >= width or (r, at) in spots:
                    stop = at
                    break
                shot.c = at
            shot.data -= 2
            if stop:
                shot.alive = False
                if stop < width:
                    self.enemies = [e for e in self.enemies if e.r != r or e.c != stop]
                    self.moves += 1
                    spots.discard((r, stop))
                    self.score.gain()
                    self.say("Enemy down!")
                    if self.done:
                        return True
            elif shot.data <= 0:
                shot.alive = False
            else:
                kept.append(shot)
        self.gun.shots = kept
        return False

    def _respawn(self) -> None:
        self.enemies = [e for e in self.enemies if e.c > self.params.width // 2]
        self.moves += 1
        self.bolts, self.gun.shots = [], []

    def _grid(self) -> list[str]:
        if self.layer_at != self.moves:       # stars and enemies: redrawn only when they moved
            self.layer = self.strip.rows[:]
            stamp(self.layer, self.enemies, ENEMY)
            self.layer_at = self.moves
        rows = self.layer[:]
        if self.bolts:
            stamp(rows, self.bolts, BOLT)
        if self.gun.shots:
            stamp(rows, self.gun.shots, SHOT)
        self._grids += 1
        drawn = self._drawn   # (the ship's row remembered: see ``_draw``)
        r = self.r
        key = (rows[r], self.col, SHIP)
        rows[r] = drawn.get(key) or self._draw(key)
        return rows


register_arcade(Stargunner, "stargunner",
                mini=dict(max_turns=200),
                atari=dict(width=30, height=16, lives=3, goal=30, unit=1.0, death=-1.0, zone=14,
                           spawn=3, pace=2, weave=0.3, fire=0.04, stars=0.05, max_turns=10000))
