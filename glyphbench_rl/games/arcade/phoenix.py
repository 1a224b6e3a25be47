"""Phoenix: a cannon on the bottom row under a flock of birds (V) that sweeps side to side and
steps down on a clock; at random a bird leaves the flock and dives (v) at the cannon (one that
misses climbs back to the top). On the Atari preset the birds also drop bombs, and SHIELD raises a short shield (the cannon cannot move under it) that destroys what touches it."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.params import param
from .engine import EMPTY, register_arcade
from .shooter import BOMB, CANNON, SHOT, Shooter, ShooterParams, march, shooter_actions

BIRD, DIVER, SHIELDED = "V", "v", "@"
SHIELD = 4
ON_TEXT = tuple(f"Shield {k}" for k in range(11))        # the HUD's shield notes, made once
WAIT_TEXT = tuple(f"Shield in {k}" for k in range(101))


@dataclass(frozen=True)
class PhoenixParams(ShooterParams):
    width: int = param(14, 8, 60)
    height: int = param(10, 8, 40)
    goal: int = param(6, 1, 300)
    unit: float = param(1 / 6, 0, 100)
    birds: int = param(6, 1, 14)          # birds in a flock
    drift: int = param(2, 1, 20)          # turns per sideways step of the flock
    descend: int = param(6, 1, 100)       # turns per step down of the flock
    dive: float = param(0.18, 0, 1)       # chance a turn that a bird starts a dive
    shield: int = param(2, 0, 10)         # turns a SHIELD lasts (0: none)
    recharge: int = param(15, 1, 100)     # turns from one SHIELD to the next


class Phoenix(Shooter):
    title = "Phoenix"
    rules = ("You are the cannon (A) on the bottom row of a {width}x{height} field, with "
             "{lives_text}. A flock of {birds} birds (V) moves a cell sideways every {drift} turns, "
             "turning and stepping down at the edges, and steps down every {descend} turns. Each "
             "turn a bird leaves the flock with chance {dive} and dives (v): a row down each turn, "
             "a column toward you every other turn; one that reaches your row hits you (a life) or "
             "else climbs back to the top. {gun_text} A cleared flock is replaced by a new one. "
             "The flock reaching your row ends the game.{bomb_text}{shield_text}")
    rewards = "+{unit} for each bird shot{death_text}."
    ends = "when you have shot {goal} birds or the game is lost"
    ACTIONS = shooter_actions(("SHIELD", "raise your shield (the cannon stands still under it)"))
    Params = PhoenixParams
    pattern = "D"
    glyphs = {EMPTY: "empty", BIRD: "bird", DIVER: "diving bird", SHOT: "your shot", BOMB: "bomb",
              CANNON: "you (the cannon)", SHIELDED: "you, shielded"}

    def prompt_fields(self) -> dict:
        p = self.params
        return {**super().prompt_fields(),
                "bomb_text": (f" Each turn a bird drops a bomb (!) with chance {p.bomb_chance:g}; a "
                              "hit costs a life.") if p.bomb_chance else "",
                "shield_text": (f" SHIELD guards you (@) for {p.shield} turns, once every "
                                f"{p.recharge} turns: birds and bombs touching it are destroyed.")
                if p.shield else " SHIELD does nothing here."}

    def _setup(self, rng) -> None:
        self.arm(rng)
        self.cannon, self.guard, self.next_guard = CANNON, 0, 0
        self._flock()

    def _flock(self) -> None:
        p = self.params
        per_row = min(p.birds, (p.width - 1) // 2)
        left = (p.width - 2 * per_row + 1) // 2
        for k in range(p.birds):
            self.pack.add(1 + k // per_row, left + 2 * (k % per_row), BIRD)
        self.dx = 1

    def _play(self, action: int) -> None:
        p, d, tick = self.params, self.draws, self.tick
        if action == SHIELD and p.shield and tick >= self.next_guard:
            self.guard, self.next_guard = p.shield, tick + p.recharge
        if self.guard:
            self.guard -= 1
            self.cannon = SHIELDED
            if action != 3:
                action = 0
        else:
            self.cannon = CANNON
        if action:
            self.steer(action)
        bodies = self.pack.bodies
        flock = [b for b in bodies if b.glyph == BIRD]
        drift, down = tick % p.drift == 0, tick % p.descend == 0
        if drift or down:
            dx = march(flock, self.dx if drift else 0, 0, p.width - 1, down)
            self.dx = dx if drift else self.dx
        divers = len(bodies) - len(flock)
        if flock and d.random() < p.dive:
            flock[d.below(len(flock))].glyph = DIVER
            divers += 1
        if divers:   # a row down, a column toward you every other row
            col = self.col
            for b in bodies:
                if b.glyph == DIVER:
                    b.r += 1
                    if b.r % 2 == 0:
                        b.c += (col > b.c) - (col < b.c)
        if self.gun.shots and self.shoot_down("Bird down!") is None:
            return
        if not bodies:
            self._flock()
        row, col, touching = self.row, self.col, None
        for b in bodies:
            if b.r >= row:
                if b.r == row and b.c == col:   # on you: the first such is the one that hits you
                    if touching is None:
                        touching = b
                elif b.glyph == BIRD:
                    self.lives = 1
                    self.lose_life("The flock reached your row.")
                    return
                else:                          # a diver that missed climbs back to the top
                    b.r, b.glyph = 1, BIRD
        if touching is not None:
            self.pack.kill(touching)
            if not self.guard and self.lose_life("A bird hit you."):
                return
        if p.bomb_chance:
            self.maybe_drop()
        if self.bombs.shots and self.rain() and not self.guard:
            self.lose_life("A bomb hit you.")

    def _extra_hud(self) -> str:
        if not self.params.shield:
            return ""
        if self.guard:
            return ON_TEXT[self.guard] if self.guard < len(ON_TEXT) else f"Shield {self.guard}"
        wait = self.next_guard - self.tick
        if wait <= 0:
            return "Shield ready"
        return WAIT_TEXT[wait] if wait < len(WAIT_TEXT) else f"Shield in {wait}"


register_arcade(Phoenix, "phoenix",
                mini=dict(max_turns=200),
                atari=dict(width=20, height=24, lives=5, goal=40, unit=10.0, birds=12, dive=0.1,
                           bomb_chance=0.15, bombs=3, shots=2, shield=3, recharge=12,
                           max_turns=10000))
