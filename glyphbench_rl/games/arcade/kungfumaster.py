"""Kung-Fu Master: a fighter in a temple corridor. Grippers walk in from both ends; strike them on
the side you face (a punch reaches one cell, a kick two) before one reaches you. On the Atari
preset the corridor is longer than the view (it follows you): walk it to its far end to climb
to the next floor, and knife throwers stop short to throw knives at head height (DUCK under
them) (pattern D)."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param, require
from .bodies import Body
from .engine import EMPTY, ArcadeParams, ArcadeTask, register_arcade
from .scroller import Camera

FIGHTER, HEAD, GRIPPER, THROWER, KNIFE, FLOOR = "P", "o", "G", "K", "-", "="
ACTIONS = ActionSet([("NOOP", "stand"), ("LEFT", "step left (face left)"), ("RIGHT", "step right (face right)"),
                     ("FACE_LEFT", "turn to face left"), ("FACE_RIGHT", "turn to face right"),
                     ("PUNCH", "punch the cell you face"), ("KICK", "kick up to two cells ahead"),
                     ("DUCK", "duck under knives this turn and the next")], noop="NOOP")
LEFT, RIGHT, FACE_LEFT, FACE_RIGHT, PUNCH, KICK, DUCK = range(1, 8)


@dataclass(frozen=True)
class KungFuParams(ArcadeParams):
    width: int = param(16, 8, 60)
    height: int = param(4, 3, 20)
    goal: int = param(8, 1, 500)
    unit: float = param(0.125, 0, 100)
    world: int = param(16, 8, 400)         # the corridor's length (longer than the view: it scrolls)
    spawn: int = param(4, 1, 30)           # turns between enemies (from alternating ends)
    walk: int = param(2, 1, 10)            # turns per cell an enemy walks
    throwers: float = param(0.0, 0, 1)     # share of enemies that throw knives
    throw: int = param(5, 2, 30)           # turns between a thrower's knives

    def check(self) -> None:
        require(self.world >= self.width, "world", "be at least the view's width", self.world)


class KungFuMaster(ArcadeTask):
    title = "Kung-Fu Master"
    rules = ("You are the fighter (P, head o) in a temple corridor {world} cells long{scroll_text}, "
             "with {lives_text}. Grippers (G) enter from the two ends of the view in turn, one "
             "every {spawn} turns, and walk at you a cell every {walk} turns. You strike only the "
             "way you face: PUNCH hits the next cell, KICK the nearest enemy within two cells. An "
             "enemy reaching your cell costs a life.{thrower_text}{floor_text}")
    rewards = "+{unit} for each enemy knocked out; {death} when the game is lost."
    ends = "when you have knocked out {goal} enemies or the game is lost"
    ACTIONS = ACTIONS
    Params = KungFuParams
    pattern = "D"
    glyphs = {EMPTY: "corridor", FLOOR: "floor", GRIPPER: "gripper", THROWER: "knife thrower",
              KNIFE: "knife (head height)", FIGHTER: "you", HEAD: "your head"}

    def prompt_fields(self) -> dict:
        p = self.params
        return {**super().prompt_fields(),
                "scroll_text": f" (the view, {p.width} cells, follows you)" if p.world > p.width else "",
                "thrower_text": (f" Knife throwers (K) stop three cells away and throw a knife (-) at "
                                 f"head height every {p.throw} turns; DUCK under it." if p.throwers else ""),
                "floor_text": (" Reach the corridor's left end to climb to the next floor."
                               if p.world > p.width else "")}

    def _still(self) -> list[str]:
        p = self.params
        return [EMPTY * p.width] * (p.height - 1) + [FLOOR * p.width]

    def _setup(self, rng) -> None:
        self.start(rng)
        p = self.params
        self.row = p.height - 2
        self.x = p.world - 3 if p.world > p.width else p.world // 2
        self.face, self.floor, self.ducked, self.side = -1, 1, 0, -1
        self.camera = Camera(p.world, p.width, wrap=False)
        self.enemies: list[Body] = []
        self.knives: list[Body] = []
        self._floor_texts()

    def _play(self, action: int) -> None:
        p = self.params
        if action in (LEFT, RIGHT, FACE_LEFT, FACE_RIGHT):
            self.face = -1 if action in (LEFT, FACE_LEFT) else 1
        if action in (LEFT, RIGHT) and not self._blocked(self.x + self.face):
            self.x = min(p.world - 1, max(0, self.x + self.face))
            if self.x == 0 and p.world > p.width:
                self.floor += 1
                self.x, self.enemies, self.knives = p.world - 3, [], []
                self.say(f"Floor {self.floor}!")
                self._floor_texts()
        elif action in (PUNCH, KICK):
            self._strike(1 if action == PUNCH else 2)
            if self.done:
                return
        elif action == DUCK:
            self.ducked = self.tick + 1
        if (self.knives and self._knives()) or self._walk():
            return
        if self.tick % p.spawn == 0:
            self.side = -self.side
            c = min(p.world - 1, max(0, self.x + self.side * (p.width // 2)))
            if c != self.x:
                kind = THROWER if p.throwers and self.draws.random() < p.throwers else GRIPPER
                self.enemies.append(Body(self.row, c, glyph=kind, data=0))

    def _blocked(self, c: int) -> bool:
        for e in self.enemies:
            if e.c == c:
                return True
        return False

    def _strike(self, reach: int) -> None:
        for d in range(1, reach + 1):
            for e in self.enemies:
                if e.c == self.x + self.face * d:
                    self.enemies.remove(e)
                    self.score.gain()
                    self.say("Knocked out!")
                    return

    def _knives(self) -> bool:
        kept = []
        for k in self.knives:
            k.c += k.dc
            if k.c == self.x and self.tick > self.ducked:
                self.knives = []
                return self.lose_life("A knife hit you!") or True
            if 0 <= k.c < self.params.world and k.c != self.x:
                kept.append(k)
        self.knives = kept
        return False

    def _walk(self) -> bool:
        p = self.params
        if self.tick % p.walk:
            return False
        x = self.x
        for e in self.enemies:
            gap = x - e.c
            if -3 <= gap <= 3 and e.glyph == THROWER:
                if self.tick - e.data >= p.throw:
                    e.data = self.tick
                    self.knives.append(Body(self.row - 1, e.c, dc=1 if gap > 0 else -1))
                continue
            e.c += 1 if gap > 0 else -1
            if e.c == x:
                self.enemies.remove(e)
                return self.lose_life("An enemy grabbed you!") or True
        return False

    def _respawn(self) -> None:
        self.enemies = [e for e in self.enemies if abs(e.c - self.x) > 3]
        self.knives = []

    def _grid(self) -> list[str]:
        cam = self.camera
        cam.follow(self.x)
        left, w, rows = cam.left, self.params.world, self.still[:]
        view = len(rows[0])
        for e in self.enemies:                 # (enemies walk your row, knives fly above it)
            c = (e.c - left) % w
            if c < view:
                line = rows[e.r]
                rows[e.r] = line[:c] + e.glyph + line[c + 1:]
        for k in self.knives:
            c = (k.c - left) % w
            if c < view:
                line = rows[k.r]
                rows[k.r] = line[:c] + KNIFE + line[c + 1:]
        c, r = (self.x - left) % w, self.row     # you are always in view
        if self.tick > self.ducked:
            rows[r - 1] = rows[r - 1][:c] + HEAD + rows[r - 1][c + 1:]
        rows[r] = rows[r][:c] + FIGHTER + rows[r][c + 1:]
        return rows

    def _floor_texts(self) -> None:
        """The HUD's note for each way you may face, made when the floor changes."""
        floor = f" | Floor {self.floor}" if self.params.world > self.params.width else ""
        self.hud_notes = {-1: "facing left" + floor, 1: "facing right" + floor}

    def _extra_hud(self) -> str:
        return self.hud_notes[self.face]


register_arcade(KungFuMaster, "kungfumaster",
                mini=dict(max_turns=300),
                atari=dict(width=30, height=6, world=120, lives=3, goal=40, unit=1.0, spawn=3,
                           walk=2, throwers=0.3, throw=6, max_turns=10000))
