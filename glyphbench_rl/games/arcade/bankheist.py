"""Bank Heist: drive a getaway car through a grid of streets to rob banks while police cars
chase you. One bank ($) stands at a time; robbing it scores and a new one opens elsewhere. FIRE
drops a stick of dynamite that blows up a few turns later, sending every police car beside it
back to the station (and costing you a life if you are beside it). On the Atari preset the car
burns a unit of gas a turn and a robbery fills the tank; an empty tank costs a life (pattern D)."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param
from .bodies import Countdown
from .chase import COMPASS, WALL, ChaseParams, MazeTask, ghost, lattice
from .engine import EMPTY, register_arcade

BANK, COP, CAR, DYNAMITE = "$", "P", "A", "x"
ACTIONS = ActionSet(COMPASS + [("FIRE", "drop a stick of dynamite where you are")], noop="NOOP")
FIRE = 5


@dataclass(frozen=True)
class BankHeistParams(ChaseParams):
    width: int = param(12, 6, 60)
    height: int = param(9, 6, 40)
    goal: int = param(3, 1, 1000)
    unit: float = param(1 / 3, 0, 10)
    pace: int = param(3, 1, 8)
    chance: float = param(0.8, 0, 1)
    block: int = param(2, 1, 6)
    fuse: int = param(3, 1, 20)          # turns from dropping the dynamite to the blast
    gas: int = param(0, 0, 1000)         # a full tank, in turns (0: no gas to watch)
    near: int = param(4, 1, 40)          # a new bank opens at least this many cells from you


class BankHeist(MazeTask):
    title = "Bank Heist"
    rules = ("A {width}x{height} town of streets between blocks (=). You drive the getaway car "
             "(A) one cell a turn; drive into the bank ($) to rob it, and a new bank opens at least "
             "{near} cells away. {ghosts} police cars (P) step once every {pace} turns, heading for "
             "you at each junction with chance {chance}. FIRE drops dynamite (x) that blows up "
             "{fuse} turns later, sending police cars within one cell of it back to their start and "
             "costing you a life if you are within one cell.{gas_text} A police car that touches "
             "you costs a life; you have {lives_text}.")
    rewards = "+{unit} for each bank robbed; -1 when your last life is lost."
    ends = "when you have robbed {goal} banks, or you lose your last life"
    ACTIONS = ACTIONS
    Params = BankHeistParams
    player_glyph = CAR
    caught = "The police caught you!"
    glyphs = {EMPTY: "street", WALL: "block", BANK: "bank", CAR: "you (getaway car)",
              COP: "police car", DYNAMITE: "dynamite"}

    def prompt_fields(self) -> dict:
        g = self.params.gas
        text = (f" You burn one unit of gas a turn from a full tank of {g}; each robbery fills it, "
                "and an empty tank costs a life." if g else "")
        return {**super().prompt_fields(), "gas_text": text}

    def _still(self) -> list[str]:
        p = self.params
        return lattice(p.width, p.height, p.block)

    def _setup(self, rng) -> None:
        self.start(rng)
        p = self.params
        self.streets = self.floor_cells()
        corners = [(1, p.width - 2), (p.height - 2, 1), (p.height - 2, p.width - 2), (1, 1)]
        cops = [ghost(*corners[k % 4], COP) for k in range(p.ghosts)]
        safe = [rc for rc in self.streets if min((abs(rc[0] - g.r) + abs(rc[1] - g.c) for g in cops),
                                                 default=99) >= p.near]
        self.enter(safe[int(rng.integers(len(safe)))], cops)
        self.tank = Countdown(p.gas)
        self._extra = bool(p.gas)   # (no gas: nothing to add to the HUD)
        self.bomb = None                   # (row, col, tick of the blast)
        self._open_bank()

    def _open_bank(self) -> None:
        p = self.params
        while True:
            r, c = self.streets[self.draws.below(len(self.streets))]
            if abs(r - self.r) + abs(c - self.c) >= p.near:
                self.bank = (r, c)
                return

    def _play(self, action: int) -> None:
        if action == FIRE and self.bomb is None:
            self.bomb = (self.r, self.c, self.tick + self.params.fuse)
        super()._play(0 if action == FIRE else action)

    def _visit(self, r: int, c: int) -> None:
        if (r, c) == self.bank:
            self.say("Bank robbed!")
            self.tank.refill()
            self._open_bank()
            self.score.gain()

    def _tick_world(self) -> None:
        if self.bomb is not None and self.tick >= self.bomb[2]:
            br, bc, _ = self.bomb
            self.bomb = None
            for g in self.ghosts:
                if abs(g.r - br) <= 1 and abs(g.c - bc) <= 1:
                    self._eat(g)
                    self.say("Boom! A police car is blown back to the station.")
            if abs(self.r - br) <= 1 and abs(self.c - bc) <= 1 and self.lose_life("Caught in the blast!"):
                return
        if self.params.gas and self.tank.tick():
            self.lose_life("Out of gas!")

    def _respawn(self) -> None:
        super()._respawn()
        self.tank.refill()
        self.bomb = None
        if self.bank == (self.r, self.c):
            self._open_bank()

    def _below(self):
        if self.bomb is None:
            return ((self.bank[0], self.bank[1], BANK),)
        return ((self.bank[0], self.bank[1], BANK), (self.bomb[0], self.bomb[1], DYNAMITE))

    def _extra_hud(self) -> str:
        return f"Gas {self.tank.left}" if self.params.gas else ""


register_arcade(BankHeist, "bankheist",
                mini=dict(ghosts=2, max_turns=400),
                atari=dict(width=24, height=18, goal=30, unit=1.0, lives=3, ghosts=3, pace=2,
                           chance=0.75, gas=120, near=8, max_turns=10000))
