"""Assault: a turret on the bottom row under a formation of attackers (a leader A flanked by
wingmen a) that drifts side to side and steps down on a clock. Shots go straight up; on the
Atari preset the attackers shoot back and the turret overheats when fired too fast."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.params import param, require
from .engine import EMPTY, register_arcade
from .shooter import BOMB, FIRE, SHOT, Shooter, ShooterParams, march

TURRET, LEADER, WING = "^", "A", "a"
HEAT = 3                                  # heat a shot adds; a turn takes 1 off
HEAT_TEXT: dict[tuple[int, int], str] = {}   # the HUD's heat note, made once per value


@dataclass(frozen=True)
class AssaultParams(ShooterParams):
    width: int = param(14, 8, 60)
    height: int = param(12, 8, 40)
    goal: int = param(5, 1, 300)
    unit: float = param(0.2, 0, 100)
    ships: int = param(5, 1, 15)          # attackers per formation
    drift: int = param(2, 1, 20)          # turns per sideways step
    descend: int = param(4, 1, 100)       # turns per step down
    heat: int = param(0, 0, 50)           # overheat limit (0: no heat); see HEAT

    def check(self) -> None:
        require(2 * self.ships < self.width - 1, "ships", "fit the field two cells apart", self.ships)


class Assault(Shooter):
    title = "Assault"
    rules = ("You are the turret (^) on the bottom row of a {width}x{height} field, with "
             "{lives_text}. A formation of {ships} attackers (a leader A and wingmen a) drifts a "
             "cell sideways every {drift} turns, turning and stepping down at the edges, and also "
             "steps down every {descend} turns. {gun_text} A cleared formation is replaced by a new one.{bomb_text}"
             "{heat_text} An attacker reaching your row ends the game.")
    rewards = "+{unit} for each attacker shot."
    ends = "when you have shot {goal} attackers or the game is lost"
    Params = AssaultParams
    pattern = "A"
    cannon = TURRET
    glyphs = {EMPTY: "empty", LEADER: "leader", WING: "wingman", SHOT: "your shot",
              BOMB: "enemy shot", TURRET: "you (the turret)"}

    def prompt_fields(self) -> dict:
        p = self.params
        return {**super().prompt_fields(),
                "bomb_text": (f" Each turn an attacker fires down (!) with chance {p.bomb_chance:g}; "
                              "a hit costs a life.") if p.bomb_chance else "",
                "heat_text": (f" Each shot heats the turret by {HEAT} and each turn cools it by 1; "
                              f"heat {p.heat} blows it up (a life).") if p.heat else ""}

    def _setup(self, rng) -> None:
        self.arm(rng)
        self.hot = 0
        self._wave()

    def _wave(self) -> None:
        p = self.params
        left = (p.width - 2 * p.ships + 1) // 2
        mid = p.ships // 2
        for k in range(p.ships):
            self.pack.add(1, left + 2 * k, LEADER if k == mid else WING)
        self.dx = 1

    def _play(self, action: int) -> None:
        p = self.params
        if action == FIRE and p.heat and self.gun.ready_at(self.tick):
            self.hot += HEAT
            if self.hot >= p.heat:
                self.hot = 0
                if self.lose_life("Your turret overheated."):
                    return
        if action:
            self.steer(action)
        if self.hot:
            self.hot -= 1
        drift, down = self.tick % p.drift == 0, self.tick % p.descend == 0
        if drift or down:
            dx = march(self.pack.bodies, self.dx if drift else 0, 0, p.width - 1, down)
            self.dx = dx if drift else self.dx
        if self.gun.shots and self.shoot_down("Attacker down!") is None:
            return
        if not self.pack.bodies:
            self._wave()
        if self.pack.lowest() >= self.row:
            self.lives = 1
            self.lose_life("An attacker reached your row.")
            return
        if p.bomb_chance:
            self.maybe_drop()
        if self.bombs.shots and self.rain():
            self.lose_life("An enemy shot hit you.")

    def _extra_hud(self) -> str:
        heat = self.params.heat
        if not heat:
            return ""
        key = (self.hot, heat)
        text = HEAT_TEXT.get(key)
        if text is None:
            text = HEAT_TEXT[key] = f"Heat {self.hot}/{heat}"
        return text


register_arcade(Assault, "assault",
                mini=dict(max_turns=200),
                atari=dict(width=20, height=20, lives=3, goal=30, unit=10.0, ships=7, drift=2,
                           descend=8, shots=3, shot_speed=3, bomb_chance=0.15, bombs=2, heat=12, max_turns=10000))
