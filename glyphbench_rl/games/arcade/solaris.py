"""Solaris: a galactic chart of sectors, some holding federation planets, some Zylon fleets that
move across the chart toward the planets. WARP jumps to the next sector on the chart that holds
a fleet or a planet; inside a sector you fly a free-roaming ship in a wrap-around field of space
and shoot the fleet's fighters, which close in and fire back. A fleet that reaches a planet
destroys it and costs you a ship; fuel burns every turn and a warp costs more, and flying onto a
friendly planet refuels you. Kept from the original: the chart with moving Zylon fleets, warping
between sectors, dogfights with fighters that shoot, fuel and refuelling at federation planets,
planets lost to fleets, three ships. Not kept: the first-person view, the Zylon planets, the
corridors and the search for Solaris itself."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param
from .arena import EMPTY, FOUR, MOVES4, SHELL, SHOT, ArenaParams, ArenaTask, you_glyphs
from .bodies import chase
from .engine import register_atari
from .sectors import Sectors

ZYLON, PLANET, LOST = "Z", "P", "x"
WARP = 6
ACTIONS = ActionSet(FOUR + [("WARP", "jump to the next sector on the chart holding a fleet or a planet")],
                    noop="NOOP")


@dataclass(frozen=True)
class SolarisParams(ArenaParams):
    width: int = param(20, 12, 40)
    height: int = param(20, 10, 40)
    lives: int = param(3, 1, 9)
    goal: int = param(16, 1, 100)
    unit: float = param(100.0, 0, 10000)
    foes: int = param(3, 1, 9)           # fighters of a fleet in the field at once
    every: int = param(4, 1, 50)
    reach: int = param(6, 1, 30)
    volley: int = param(10, 0, 100)
    wrap: int = param(1, 0, 1)
    air: int = param(1500, 100, 10000)   # fuel
    chart: int = param(4, 3, 6)          # the chart's side, in sectors
    fleets: int = param(4, 1, 12)
    fleet: int = param(4, 1, 9)          # fighters in a fleet
    planets: int = param(3, 1, 6)
    advance: int = param(150, 10, 2000)  # ticks per chart step of a fleet
    jump: int = param(50, 0, 1000)       # fuel a warp costs


class Solaris(ArenaTask):
    title = "Solaris"
    rules = ("You fly a starship ({lives_text}) across a {chart}x{chart} galactic chart of "
             "sectors. The HUD's Chart shows every sector row by row (rows split by /): @ yours, "
             "a digit a Zylon fleet and how many fighters it has, P a federation planet, x a "
             "planet lost, . empty space. Every {advance} turns each fleet you are not fighting "
             "moves a sector toward the nearest planet; a fleet that reaches a planet destroys it "
             "and you lose a ship. WARP jumps to the next sector in reading order (wrapping) that "
             "holds a fleet or a planet, for {jump} fuel. A sector is a {width}x{height} field of "
             "space{edge_text} where up to {foes} of its fleet's fighters (Z) are out at once; "
             "each steps a cell toward you every {every} turns and one that reaches you destroys "
             "you. FIRE sends a shot (*) {reach} cells the way you face.{volley_text} Fuel "
             "({air}) burns a unit a turn; fly onto a planet (P) to refuel; running dry costs a "
             "ship.{turn_text}")
    rewards = "+{unit} for each Zylon fighter destroyed; {death} when the game is lost."
    ends = "when you have destroyed {goal} fighters or the game is lost"
    Params = SolarisParams
    pattern = "D"
    ACTIONS = ACTIONS
    MOVES = MOVES4 + (None,)
    FOE, foe_name, caught_text, air_name, air_out = ZYLON, "Zylon fighter", "A Zylon fighter rammed you.", "Fuel", "Your fuel ran out."
    glyphs = {EMPTY: "space", PLANET: "federation planet", ZYLON: "Zylon fighter",
              SHOT: "your shot", SHELL: "Zylon shot", **you_glyphs()}

    def prompt_fields(self) -> dict:
        return {**super().prompt_fields(),
                "edge_text": " that wraps around at its edges," if self.params.wrap else "",
                "turn_text": " A move into a fighter only turns you to face it."}

    def _setup(self, rng) -> None:
        p = self.params
        self.start_arena(rng, p.height // 2 + 2, p.width // 2)
        self.sectors = Sectors(["#" * p.chart] * p.chart)
        places = list(self.sectors.order)
        for i in range(len(places) - 1, 0, -1):           # a shuffle by the episode's draws
            j = self.draws.below(i + 1)
            places[i], places[j] = places[j], places[i]
        n = min(p.planets, len(places) - 1)
        self.planets = {q: True for q in places[:n]}       # place -> still there
        for q in places[n:n + p.fleets]:
            self.sectors.held[q] = p.fleet
        self.fled = 0
        self._enter_sector(places[0])

    def _enter_sector(self, place) -> None:
        p = self.params
        self.place = place
        self.sectors.go(place)
        self.foes, self.gun.shots, self.shells.shots = [], [], []
        self.still = self._still()
        if self.planets.get(place):
            self.set_still(p.height // 2, p.width // 2, PLANET)
        self.still_version += 1
        self.r, self.c = self.home
        self._muster()

    def _muster(self) -> None:
        """Bring this sector's fleet's fighters out, up to ``foes`` at once."""
        left = self.sectors.held[self.place] or 0
        while len(self.foes) < min(self.params.foes, left):
            self.add_foe(*self.spot(6))

    def _mark(self, place) -> str:
        n = self.sectors.held[place]
        if n:
            return str(min(n, 9))
        return {True: PLANET, False: LOST}.get(self.planets.get(place), EMPTY)

    def _play(self, action: int) -> None:
        if action != WARP:
            return super()._play(action)
        to = self.sectors.after(self.place, lambda q: self.sectors.held[q] or self.planets.get(q))
        if to is None or to == self.place:
            self.say("Nowhere to warp to.")
        elif self.air.tick(self.params.jump):
            self.lose_life(self.air_out)
        else:
            self.say(f"Warp to sector {to[0] + 1},{to[1] + 1}.")
            self._enter_sector(to)

    def _enter(self, r: int, c: int) -> bool:
        if self.still[r][c] == PLANET and self.air.left < self.air.full:
            self.air.refill()
            self.say("Refuelled at the federation planet.")
        return False

    def _hit(self, foe) -> None:
        super()._hit(foe)
        if foe in self.foes:                              # hit, not destroyed
            return
        held = self.sectors.held
        held[self.place] -= 1
        self.sectors.changed()
        if not held[self.place]:
            held[self.place] = None
            self.say("Zylon fleet destroyed!")
        elif not self.done:
            self._muster()

    def _turn(self) -> None:
        if self.tick % self.params.advance == 0:
            self._fleets_move()

    def _fleets_move(self) -> None:
        held, alive = self.sectors.held, [q for q, up in self.planets.items() if up]
        moving = [(q, n) for q, n in held.items() if n and q != self.place]
        for q, _ in moving:
            held[q] = None
        for (r, c), n in moving:
            if alive:
                tr, tc = min(alive, key=lambda t: (abs(t[0] - r) + abs(t[1] - c), t))
                dr, dc = chase(r, c, tr, tc)
                r, c = r + dr, c + dc
            held[(r, c)] = (held[(r, c)] or 0) + n
            if (r, c) == self.place:
                self.say("A Zylon fleet warps into your sector!")
                self._muster()
            elif self.planets.get((r, c)):
                self.planets[(r, c)] = False
                if self.lose_life("A Zylon fleet destroyed a federation planet."):
                    return
        self.sectors.changed()

    def _respawn(self) -> None:
        super()._respawn()
        self.sectors.changed()

    def _extra_hud(self) -> str:
        return f"Fuel {self.air.left} | {self.sectors.chart(self._mark)}"


register_atari(Solaris, "solaris", max_turns=10000)
