"""Berzerk: a room of electrified walls full of robots that close in on you. Shoot them the way
you face; touching a wall (or a robot) is death. A cleared room is followed by the next one; on
the Atari preset the robots shoot back and Evil Otto, who cannot be shot and passes through
walls, comes for you if you linger in a room."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.params import param
from .arena import EMPTY, SHELL, SHOT, WALL, ArenaParams, ArenaTask, you_glyphs
from .engine import register_arcade

ROBOT, OTTO = "R", "O"


@dataclass(frozen=True)
class BerzerkParams(ArenaParams):
    width: int = param(16, 10, 40)
    height: int = param(10, 8, 30)
    goal: int = param(5, 1, 500)
    unit: float = param(0.2, 0, 100)
    foes: int = param(5, 1, 12)
    reach: int = param(5, 1, 40)
    otto: int = param(0, 0, 500)         # ticks in a room before Evil Otto comes (0: never)


class Berzerk(ArenaTask):
    title = "Berzerk"
    rules = ("You ({lives_text}) are in a {width}x{height} room whose walls (#) are electrified: "
             "walking into one kills you. {foes} robots (R) each step one cell toward you every "
             "{every} turns; one that reaches you kills you. FIRE sends a shot (*) {reach} cells "
             "the way you face; it destroys the first robot it meets. A move into a robot only "
             "turns you to face it. Clear the room and you "
             "enter a new one.{volley_text}{otto_text}")
    rewards = "+{unit} for each robot destroyed; {death} when the game is lost."
    ends = "when you have destroyed {goal} robots or the game is lost"
    Params = BerzerkParams
    pattern = "D"
    FOE, foe_name, caught_text = ROBOT, "robot", "A robot got you."
    glyphs = {EMPTY: "floor", WALL: "electrified wall", ROBOT: "robot", OTTO: "Evil Otto",
              SHOT: "your shot", SHELL: "robot shot", **you_glyphs()}

    def prompt_fields(self) -> dict:
        p = self.params
        return {**super().prompt_fields(), "otto_text": (
            f" After {p.otto} turns in a room Evil Otto (O) appears at the door and moves a cell "
            "toward you every turn, through walls; he cannot be shot.") if p.otto else ""}

    def _still(self) -> list[str]:
        p = self.params
        w, h = p.width, p.height
        rows = [WALL * w] + ["#" + EMPTY * (w - 2) + "#" for _ in range(h - 2)] + [WALL * w]
        rooms = getattr(self, "rooms", 0)
        for k in range(1, 3):                 # two inner wall stubs, placed by the room number
            c = k * w // 3
            r0, r1 = (1, h // 2 - 1) if (k + rooms) % 2 else (h // 2 + 1, h - 1)
            for r in range(r0, r1):
                rows[r] = rows[r][:c] + WALL + rows[r][c + 1:]
        return rows

    def _setup(self, rng) -> None:
        p = self.params
        self.rooms = 0
        self.start_arena(rng, p.height // 2, 1)
        self.face = (0, 1)
        self.otto = None
        self._fill()

    def _fill(self) -> None:
        self.entered = self.tick
        for _ in range(min(self.params.foes, self.params.goal - self.kills)):
            self.add_foe(*self.spot(6))

    def _enter(self, r: int, c: int) -> bool:
        if self.still[r][c] == WALL:
            self._killed("You touched an electrified wall.")
            return True
        return False

    def _hit(self, foe) -> None:
        super()._hit(foe)
        if not self.done and not self.foes:
            self.say("Room cleared: on to the next one.")
            self.rooms += 1
            self.still = self._still()
            self.still_version += 1
            self.r, self.c = self.home
            self.face, self.otto = (0, 1), None
            self.gun.shots, self.shells.shots = [], []
            self._fill()

    def _turn(self) -> None:
        p = self.params
        if p.otto and self.otto is None and self.tick - self.entered >= p.otto:
            self.otto = [p.height // 2, 0]
            self.say("Evil Otto is coming!")
        if self.otto is not None:
            o = self.otto
            o[0] += (self.r > o[0]) - (self.r < o[0])
            o[1] += (self.c > o[1]) - (self.c < o[1])
            if o == [self.r, self.c]:
                self._killed("Evil Otto got you.")

    def _respawn(self) -> None:
        super()._respawn()
        self.otto, self.entered, self.face = None, self.tick, (0, 1)

    def _above(self):
        return () if self.otto is None else ((self.otto[0], self.otto[1], OTTO),)


register_arcade(Berzerk, "berzerk",
                mini=dict(every=4, max_turns=200),
                atari=dict(width=24, height=16, goal=30, unit=50.0, lives=3, foes=6, every=2,
                           volley=6, otto=60, max_turns=10000))
