"""Gopher: a farmer (F) walks the surface over a row of carrots (Y); underground a gopher (G)
runs along its tunnel on the bottom row and digs a shaft up through the soil (#) toward a
carrot, which it eats when it pops out. FILL packs soil into the top of the open shaft under
the farmer; filling the gopher's own cell bonks it back to the tunnel's end. Carrots are the
lives. The MiniAtari preset pays for the carrots still standing when the clock runs out; the
Atari one pays for each bonk."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param, require
from .bodies import Body
from .engine import EMPTY, register_arcade
from .shooter import LEFT, RIGHT, Shooter, ShooterParams

FARMER, GOPHER, CARROT, SOIL = "F", "G", "Y", "#"
FILL = 3
ACTIONS = ActionSet([("NOOP", "stand still"), ("LEFT", "walk one cell left"),
                     ("RIGHT", "walk one cell right"),
                     ("FILL", "pack soil into the top of the open shaft under you")], noop="NOOP")


@dataclass(frozen=True)
class GopherParams(ShooterParams):
    width: int = param(14, 8, 60)
    height: int = param(8, 5, 40)
    lives: int = param(3, 1, 5)           # carrots
    goal: int = param(3, 1, 300)
    unit: float = param(1 / 3, 0, 100)
    hold: int = param(60, 0, 5000)        # turns to hold; then each carrot left pays (0: bonks pay)

    def check(self) -> None:
        require(self.lives + 4 <= self.width, "lives", "leave room beside the carrots", self.lives)
        require(not self.hold or self.goal == self.lives, "goal", "equal the carrots when holding", self.goal)


class Gopher(Shooter):
    title = "Gopher"
    rules = ("You are the farmer (F) on the top row of a {width}x{height} field, guarding {lives} "
             "carrots (Y) in the middle of it. A gopher (G) runs along the tunnel on the bottom row, "
             "a cell a turn, to below a carrot and digs straight up through the soil (#), a cell a "
             "turn; out at the top, it eats the carrot and heads for another. FILL packs soil into "
             "the top open cell of the shaft under you; filling the gopher's cell bonks it back to "
             "an end of the tunnel.{hold_text}")
    rewards = "{reward_text}"
    ends = "{end_text}"
    ACTIONS = ACTIONS
    Params = GopherParams
    pattern = "D"
    cannon = FARMER
    glyphs = {EMPTY: "open ground or tunnel", SOIL: "soil", CARROT: "carrot", GOPHER: "gopher",
              FARMER: "you (the farmer)"}

    def prompt_fields(self) -> dict:
        p = self.params
        hold = p.hold
        return {**super().prompt_fields(),
                "hold_text": f" Hold out for {hold} turns." if hold else "",
                "reward_text": (f"+{p.unit:.4g} for each carrot left after {hold} turns" if hold else
                                f"+{p.unit:g} for each bonk") + (f"; {p.death:g} when the last carrot is eaten"
                                                                  if p.death else "") + ".",
                "end_text": (f"after {hold} turns or when the last carrot is eaten" if hold else
                             f"when you have bonked the gopher {p.goal} times or the last carrot is eaten")}

    def _carrots(self) -> list[int]:
        p = self.params
        left = (p.width - p.lives) // 2
        return list(range(left, left + p.lives))

    def _still(self) -> list[str]:
        p = self.params
        top = "".join(CARROT if c in self._carrots() else EMPTY for c in range(p.width))
        return [top] + [SOIL * p.width] * (p.height - 2) + [EMPTY * p.width]

    def _setup(self, rng) -> None:
        self.arm(rng, row=0)
        self._plain = self._carrots_hud = None
        self.gopher = Body(self.params.height - 1, 0)
        self._aim()

    def _aim(self) -> None:
        """The gopher picks a carrot still standing to go for."""
        live = [c for c in self._carrots() if self.still[0][c] == CARROT]
        self.target = live[self.draws.below(len(live))] if live else 0

    def _play(self, action: int) -> None:
        p = self.params
        if action == LEFT or action == RIGHT:
            self.steer(action)
        elif action == FILL:
            self._fill()
        g = self.gopher
        if g.r == p.height - 1 and g.c != self.target:
            g.c += 1 if self.target > g.c else -1
        elif g.r > 1:
            g.r -= 1
            if self.still[g.r][g.c] == SOIL:
                self.set_still(g.r, g.c, EMPTY)
        elif g.r == 1:
            self.set_still(0, g.c, EMPTY)
            g.r = p.height - 1
            self.say("The gopher ate a carrot!")
            if self.lose_life("The gopher ate a carrot."):
                return
            self._aim()
        if p.hold and self.tick >= p.hold:
            self.say(f"You held out with {self.lives} carrots.")
            self.score.gain(self.lives)
            self.finish(won=True)

    def _fill(self) -> None:
        col, g = self.col, self.gopher
        for r in range(1, self.params.height - 1):
            if self.still[r][col] != SOIL:
                self.set_still(r, col, SOIL)
                if (g.r, g.c) == (r, col):
                    self.say("Bonk!")
                    g.r, g.c = self.params.height - 1, (0 if self.draws.random() < 0.5 else self.params.width - 1)
                    self._aim()
                    if not self.params.hold:
                        self.score.gain()
                return

    def _respawn(self) -> None:
        pass

    def _hud(self) -> str:
        hud = super()._hud()
        if hud is not self._plain:   # (the engine hands back the same text while it holds)
            self._plain, self._carrots_hud = hud, hud.replace("Lives", "Carrots")
        return self._carrots_hud

    def _sprites(self):
        return [(self.gopher.r, self.gopher.c, GOPHER), (self.row, self.col, FARMER)]


register_arcade(Gopher, "gopher",
                mini=dict(max_turns=100),
                atari=dict(width=20, height=16, goal=8, unit=100.0, hold=0, max_turns=10000))
