"""Name This Game (Atari 2600, 1982; Octopus in Europe): a diver on the sea floor guards a
treasure. Kept from the original: the octopus at the top whose tentacles reach down toward the
treasure (a shot to a tentacle's tip drives it back), the shark that swims back and forth lower
and lower, kills paid by the depth reached, the diver's air running out, the boat on the
surface that now and then lowers a line to refill it, both foes speeding up as you score, and
the treasure lost (a life) to a tentacle or the shark reaching it. Pattern D: every kill (a
tentacle's tip or a shark) is a unit toward ``goal``, paid in native points."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.params import param, require
from .bodies import Body, Countdown
from .engine import EMPTY, register_atari
from .shooter import SHOT, Shooter, ShooterParams, bounce

SURFACE, BOAT, LINE, OCTOPUS, ARM, TREASURE, DIVER = "~", "B", ":", "M", "&", "$", "D"
SHARKS = {1: ">", -1: "<"}
AIR_TEXT: dict[int, str] = {}


@dataclass(frozen=True)
class OctopusParams(ShooterParams):
    width: int = param(20, 10, 40)
    height: int = param(20, 10, 40)
    lives: int = param(3, 1, 9)
    goal: int = param(30, 1, 1000)
    unit: float = param(10.0, 0, 1000)
    arms: int = param(6, 1, 12)           # tentacles
    grow: int = param(4, 1, 50)           # turns between tentacle growths (one tentacle a cell)
    reach: int = param(3, 0, 20)          # each tentacle's length at the start and after a loss
    swim: int = param(2, 1, 20)           # turns per shark move
    level: int = param(10, 1, 1000)       # kills that speed both foes up a turn
    air: int = param(200, 10, 2000)       # turns of air
    line_every: int = param(100, 10, 2000)  # turns between the boat's lines
    line_stay: int = param(25, 1, 500)    # turns a lowered line stays down

    def check(self) -> None:
        require(2 * self.arms + 1 <= self.width, "arms", "fit the octopus two cells apart", self.arms)
        require(self.reach + 5 <= self.height, "reach", "stay well above the treasure", self.reach)


class NameThisGame(Shooter):
    title = "Name This Game"
    rules = ("You are a diver (D) on the second-to-last row of a {width}x{height} sea, guarding the "
             "treasure ($) on the bottom row ({lives_text}). At the top the octopus (M) reaches "
             "{arms} tentacles (&) down toward the treasure: one of them grows a cell every "
             "{grow} turns. A shot that meets a tentacle's tip drives it all the way back. A shark (< or >, "
             "facing its way) swims across a cell every {swim} turns, dropping a row at each wall; "
             "shot, another comes from the top. {gun_text} A tentacle or the shark reaching your "
             "row takes the treasure: a life, and the octopus and the shark start over. Both speed "
             "up a turn every {level} kills. Your air lasts {air} turns (the HUD's Air); every "
             "{line_every} turns the boat (B) on the surface (~) stops and lowers a line (:) for "
             "{line_stay} turns: stand under it once it is down to refill your air. Out of air "
             "costs a life.")
    rewards = ("For each kill (a tentacle's tip or the shark shot), {unit} times the rows below the "
               "octopus it had reached (deeper pays more); {death} when the game is lost.")
    ends = "after {goal} kills or when the last life is lost"
    Params = OctopusParams
    pattern = "D"
    cannon = DIVER
    glyphs = {SURFACE: "surface", BOAT: "boat", LINE: "air line", OCTOPUS: "octopus", ARM: "tentacle",
              ">": "shark swimming right", "<": "shark swimming left", EMPTY: "water", SHOT: "your shot",
              DIVER: "you (the diver)", TREASURE: "treasure"}

    def _still(self) -> list[str]:
        p = self.params
        w, left, right = p.width, self._arm_col(0) - 1, self._arm_col(p.arms - 1) + 1
        octopus = EMPTY * left + OCTOPUS * (right - left + 1) + EMPTY * (w - right - 1)
        return [SURFACE * w, octopus] + [EMPTY * w] * (p.height - 3) + [TREASURE * w]

    def _arm_col(self, i: int) -> int:
        p = self.params
        return (p.width - 2 * p.arms + 1) // 2 + 2 * i

    def _setup(self, rng) -> None:
        p = self.params
        self.arm(rng, row=p.height - 2)
        self.air = Countdown(p.air)
        self.boat = Body(0, self.draws.below(p.width), dc=1, glyph=BOAT)
        self.line = 0                                 # rows of line lowered (0: none)
        self.layer, self._layer_at = 0, -1            # bumped when tentacles or the line change
        self.line_left = 0                            # turns the lowered line stays
        self.shark = None
        if "_water" not in self.__dict__:             # _draw_layer's rows under the octopus (kept)
            self._water: dict[tuple[int, int], str] = {}
        self._start_over()

    def _start_over(self) -> None:
        """After a loss (and at the start): tentacles back to ``reach``, a new shark, full air."""
        p = self.params
        self.gun.shots = []
        self.pack.bodies.clear()
        self.tips = [self.pack.add(1 + p.reach, self._arm_col(i), ARM, data=i) for i in range(p.arms)]
        self.air.refill()
        self.layer += 1
        self._new_shark()

    def _respawn(self) -> None:
        super()._respawn()
        self._start_over()

    def _new_shark(self) -> None:
        if self.shark is not None and self.shark in self.pack.bodies:
            self.pack.kill(self.shark)
        dc = 1 if self.draws.random() < 0.5 else -1
        self.shark = self.pack.add(2, 0 if dc > 0 else self.params.width - 1, SHARKS[dc], dc=dc)

    def _pace(self, turns: int) -> int:
        return max(1, turns - self.score.done // self.params.level)

    def _play(self, action: int) -> None:
        p = self.params
        if action:
            self.steer(action)
        for foe, _ in self.volley():
            if foe.r > 1:                             # (a tip at the octopus is no target)
                self.score.award(foe.r - 1)
                if foe is self.shark:
                    self.say("You shot the shark!")
                    self._new_shark()
                else:
                    foe.r = 1
                    self.layer += 1
                    self.say("The tentacle pulls back.")
            if self.done:
                return
        if self.tick % self._pace(p.grow) == 0:
            tip = self.tips[self.draws.below(p.arms)]
            tip.r += 1
            self.layer += 1
            if tip.r >= self.row:
                self.lose_life("A tentacle took the treasure.")
                return
        if self.tick % self._pace(p.swim) == 0 and self._swim():
            return
        if self.air.tick():
            self.lose_life("You ran out of air.")
            return
        self._sail()

    def _swim(self) -> bool:
        """The shark's move; True when it reached your row (a life lost)."""
        s, w = self.shark, self.params.width
        if not 0 <= s.c + s.dc < w:
            s.r += 1
        bounce(s, 0, w - 1)
        s.glyph = SHARKS[s.dc]
        return s.r >= self.row and self.lose_life("The shark took the treasure.") is not None

    def _sail(self) -> None:
        """The boat sails to and fro, stopping to lower its line every ``line_every`` turns."""
        p, boat = self.params, self.boat
        if self.tick % p.line_every == 0 and not self.line:
            self.line, self.line_left = 1, p.line_stay
            self.layer += 1
        if not self.line:
            if self.tick % 2 == 0:
                bounce(boat, 0, p.width - 1)
            return
        if self.line < self.row - 1:
            self.line += 1
            self.layer += 1
            return
        if self.col == boat.c and self.air.left < p.air:
            self.air.refill()
            self.say("You breathe from the line: air refilled.")
        self.line_left -= 1
        if self.line_left <= 0:
            self.line = 0
            self.layer += 1

    def _rows(self) -> list[str]:
        if self._layer_at != self.layer:
            self._layer, self._layer_at = self._draw_layer(), self.layer
        return self._layer[:]

    def _draw_layer(self) -> list[str]:
        """The tentacles and the line over the still rows: a row under the octopus is water
        with the tentacles that reach it and the line if it is down that far, made once per
        (tentacles, line column) and looked up after."""
        rows, memo = self.still[:], self._water
        line, c = self.line, self.boat.c
        ends: dict[int, int] = {}
        mask = 0
        for i, t in enumerate(self.tips):
            if t.r >= 2:
                mask |= 1 << i
                ends[t.r] = ends.get(t.r, 0) | 1 << i
        if line:
            rows[1] = rows[1][:c] + LINE + rows[1][c + 1:]
        for r in range(2, max(line, *ends) + 1 if ends else line + 1):
            key = (mask, c if r <= line else -1)
            row = memo.get(key)
            if row is None:
                cells = list(self.still[2])
                for i, t in enumerate(self.tips):
                    if mask >> i & 1:
                        cells[t.c] = ARM
                if key[1] >= 0:
                    cells[c] = LINE
                row = memo[key] = "".join(cells)
            rows[r] = row
            mask &= ~ends.get(r, 0)
        return rows

    def _sprites(self):
        s, b = self.shark, self.boat
        out = [(b.r, b.c, BOAT), (s.r, s.c, s.glyph)]
        out += [(x.r, x.c, SHOT) for x in self.gun.shots]
        out.append((self.row, self.col, DIVER))
        return out

    def _extra_hud(self) -> str:
        left = self.air.left
        text = AIR_TEXT.get(left)
        if text is None:
            text = AIR_TEXT[left] = f"Air {left}"
        return text


register_atari(NameThisGame, "namethisgame", max_turns=10000)
