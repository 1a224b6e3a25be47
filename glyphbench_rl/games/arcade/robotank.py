"""Robotank: a tank commander against a squadron of robot tanks that close in fast. Enemy
tanks take hits before they burst. On the Atari preset they fire back, and each hit you take
knocks out one of your four systems (video, cannon, radar, treads) with its own handicap; the
fourth ends the game."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.params import param
from .arena import EMPTY, SHELL, SHOT, ArenaParams, ArenaTask, you_glyphs
from .engine import ArcadeTask, register_arcade

ROBOT = "R"
SYSTEMS = ("video", "cannon", "radar", "treads")


@dataclass(frozen=True)
class RobotankParams(ArenaParams):
    width: int = param(12, 8, 40)
    height: int = param(12, 8, 40)
    goal: int = param(4, 1, 500)
    unit: float = param(0.25, 0, 10000)
    death: float = param(0.0, -1000, 0)
    foes: int = param(2, 1, 8)
    every: int = param(2, 1, 50)
    reach: int = param(5, 2, 40)
    lives: int = param(1, 1, 4)


class Robotank(ArenaTask):
    title = "Robotank"
    rules = ("You command a tank ({lives_text}) on a {width}x{height} plain. Robot tanks (R), "
             "{foes} at a time, roll one cell toward you every {every} turns; one that rams you "
             "{ram_text}. FIRE sends a shell (*) {reach} cells the way you face; {hp_text}.{turn_text}"
             "{volley_text}{systems_text}")
    rewards = "+{unit} for each robot tank destroyed{death_text}."
    ends = "when you have destroyed {goal} robot tanks or the game is lost"
    Params = RobotankParams
    pattern = "D"
    FOE, foe_name, caught_text = ROBOT, "robot tank", "A robot tank rammed you."
    glyphs = {EMPTY: "open plain", ROBOT: "robot tank", SHOT: "your shell", SHELL: "enemy shell",
              **you_glyphs()}

    def prompt_fields(self) -> dict:
        p = self.params
        return {**super().prompt_fields(),
                "ram_text": "destroys you" if p.lives == 1 else "knocks out one of your systems",
                "hp_text": "one hit destroys a robot tank" if p.hp == 1 else f"{p.hp} hits destroy a robot tank",
                "death_text": f"; {p.death} when the game is lost" if p.death else "",
                "systems_text": (f" Your {p.lives} systems ({', '.join(SYSTEMS[:p.lives])}) are lost "
                                 "one per hit in that order: without video you see no shells, "
                                 "without the cannon your shells fly half as far, without radar "
                                 "robots far away are hidden, without treads you move every other "
                                 "turn. Losing the last ends the game.") if p.lives > 1 else ""}

    def _setup(self, rng) -> None:
        p = self.params
        self.start_arena(rng, p.height // 2, p.width // 2)
        self._systems = (-1, "")
        self.stock()

    def broken(self, system: str) -> bool:
        return self.params.lives > 1 and self.params.lives - self.lives > SYSTEMS.index(system)

    def _play(self, action: int) -> None:
        if self.lives < self.params.lives and self.broken("treads") and self.tick % 2 and self.MOVES[action] is not None:
            action = 0
        super()._play(action)

    def _hit(self, foe) -> None:
        super()._hit(foe)
        if not self.done:
            self.stock()

    def _respawn(self) -> None:
        self.say(f"Your {SYSTEMS[self.params.lives - self.lives - 1]} is out.")
        if self.broken("cannon"):
            self.gun.reach = max(1, self.params.reach // 2)
        self.shells.shots = []
        for foe in self.foes:
            if abs(foe.r - self.r) + abs(foe.c - self.c) < 4:
                foe.r, foe.c = self.spot(5)

    def _sprites(self):
        out = super()._sprites()
        if self.broken("video"):
            out = [s for s in out if s[2] != SHELL]
        if self.broken("radar"):
            out = [s for s in out if s[2] != ROBOT or abs(s[0] - self.r) + abs(s[1] - self.c) <= 6]
        return out

    def _grid(self) -> list[str]:
        if self.broken("video"):            # (any hit taken) some movers are hidden: draw the list
            return ArcadeTask._grid(self)
        return super()._grid()

    def _extra_hud(self) -> str:
        if self.params.lives == 1:
            return ""
        if self._systems[0] != self.lives:  # (the text changes with the lives only)
            self._systems = (self.lives, "Systems " + ",".join(
                s for s in SYSTEMS[:self.params.lives] if not self.broken(s)))
        return self._systems[1]


register_arcade(Robotank, "robotank",
                mini=dict(max_turns=200),
                atari=dict(width=20, height=20, goal=12, unit=1000.0, death=-1.0, lives=4, foes=3,
                           every=2, hp=2, volley=8, reach=6, max_turns=10000))
