"""Time Pilot: a fighter in open sky with enemy planes swarming in from every edge. Shoot them
down the way you fly. On the Atari preset a mothership (the boss) arrives after every few kills;
downing it takes several hits and carries you to the next era, where the swarm is quicker."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.params import param
from .arena import EMPTY, SHOT, ArenaParams, ArenaTask, you_glyphs
from .engine import register_arcade

PLANE, BOSS = "x", "B"


@dataclass(frozen=True)
class PilotParams(ArenaParams):
    width: int = param(14, 8, 40)
    height: int = param(12, 8, 40)
    goal: int = param(5, 1, 500)
    unit: float = param(0.2, 0, 10000)
    death: float = param(0.0, -1000, 0)
    foes: int = param(3, 1, 10)
    every: int = param(2, 1, 50)
    boss: int = param(0, 0, 100)         # kills that bring the boss (0: no boss)
    boss_hp: int = param(3, 1, 9)


class TimePilot(ArenaTask):
    title = "Time Pilot"
    rules = ("You fly a fighter ({lives_text}) in a {width}x{height} stretch of sky. Enemy planes "
             "(x), {foes} at a time, enter at the edges and fly one cell toward you every {every} "
             "turns; one that collides with you {crash_text}. FIRE sends a shot (*) {reach} cells "
             "the way you fly; it downs the first plane it meets.{turn_text}{boss_text}")
    rewards = "+{unit} for each plane downed{death_text}."
    ends = "when you have downed {goal} planes or the game is lost"
    Params = PilotParams
    pattern = "D"
    FOE, foe_name, caught_text = PLANE, "plane", "An enemy plane collided with you."
    glyphs = {EMPTY: "sky", PLANE: "enemy plane", BOSS: "mothership (boss)", SHOT: "your shot",
              **you_glyphs()}

    def prompt_fields(self) -> dict:
        p = self.params
        return {**super().prompt_fields(),
                "crash_text": "ends the game" if p.lives == 1 else "costs a life",
                "death_text": f"; {p.death} when the game is lost" if p.death else "",
                "boss_text": (f" After every {p.boss} planes a mothership (B) joins; {p.boss_hp} "
                              "hits down it (it counts as a plane) and start the next era, where "
                              "the planes fly a turn quicker.") if p.boss else ""}

    def _setup(self, rng) -> None:
        p = self.params
        self.start_arena(rng, p.height // 2, p.width // 2)
        self.era, self.pace, self.since = 1, p.every, 0
        self.stock()

    def stock(self, far: int = 0, one: bool = False) -> None:
        p = self.params
        h, w = p.height, p.width
        while len(self.foes) < p.foes and self.kills + len(self.foes) < p.goal:
            side = self.draws.below(4)
            rows = range(h) if side < 2 else (range(1) if side == 2 else range(h - 1, h))
            cols = range(w) if side >= 2 else (range(1) if side == 0 else range(w - 1, w))
            self.add_foe(*self.spot(4, rows, cols))

    def _hit(self, foe) -> None:
        p = self.params
        boss = foe.glyph == BOSS
        super()._hit(foe)
        if self.done or foe in self.foes:
            return
        self.since += 1
        if boss:
            self.era += 1
            self.pace = max(1, self.pace - 1)
            self.say(f"Mothership down: on to era {self.era}.")
        elif p.boss and self.since >= p.boss and self.kills + len(self.foes) < p.goal:
            self.since = 0
            self.add_foe(0, p.width // 2, glyph=BOSS, data=p.boss_hp)
            self.say("A mothership approaches!")
        self.stock()

    def _turn(self) -> None:
        if self.pace < self.params.every and self.tick % self.pace == 0 and self.tick % self.params.every:
            self._march()

    def _extra_hud(self) -> str:
        return f"Era {self.era}" if self.params.boss else ""


register_arcade(TimePilot, "timepilot",
                mini=dict(reach=4, max_turns=200),
                atari=dict(width=20, height=20, goal=25, unit=100.0, death=-1.0, lives=3, foes=4,
                           every=3, reach=6, boss=8, boss_hp=3, max_turns=10000))
