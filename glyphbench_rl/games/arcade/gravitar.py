"""Gravitar: a ship that keeps its momentum, in a solar system of four planets around a sun that
pulls it in. Flying into a planet lands you above its surface, where gravity pulls you down onto
jagged terrain that destroys the ship on contact, and bunkers fire up at you; shoot every bunker
and the planet is destroyed. Fuel runs down every turn and faster with the engine on; fuel tanks
on the surface are drawn up by the tractor beam when you hover just above them. Kept from the
original: rotate and thrust flight under gravity, the sun, the four planets entered from the
system map, bunkers, fuel tanks and the tractor beam, six ships, and the game ending when the fuel
is gone. Not kept: the reactor planet and the shield."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.params import param
from .arena import EMPTY, SHELL, SHOT, WALL, ArenaParams
from .bodies import Body
from .engine import register_atari
from .sectors import SCALE, FlightTask, Sectors, ship_glyphs

SUN, HOME, BUNKER, TANK, RUIN = "O", "H", "B", "F", "x"
PLANETS = "1234"
POWER = 2          # quarter cells a turn a THRUST adds


@dataclass(frozen=True)
class GravitarParams(ArenaParams):
    width: int = param(20, 16, 40)
    height: int = param(20, 14, 30)
    lives: int = param(6, 1, 9)
    goal: int = param(12, 1, 40)
    unit: float = param(250.0, 0, 10000)
    death: float = param(0.0, 0, 0)
    reach: int = param(8, 2, 20)
    volley: int = param(8, 0, 100)       # ticks between bunker shells
    air: int = param(3000, 100, 20000)   # fuel at the start
    tank: int = param(1000, 0, 10000)    # fuel a tank gives
    fall: int = param(4, 1, 20)          # ticks per quarter cell a turn of falling speed gained
    sun: int = param(8, 1, 50)           # ticks per quarter cell a turn the sun pulls you in
    bunkers: int = param(3, 2, 6)        # bunkers on each planet


class Gravitar(FlightTask):
    title = "Gravitar"
    rules = ("You fly a ship ({lives_text}) that keeps its speed: LEFT and RIGHT turn it by 45 "
             "degrees, THRUST adds {power} quarter cells a turn to its speed the way it points (on "
             "each axis of a diagonal), up to a cell a turn; the HUD shows where it points (Head) "
             "and its velocity (Vel rows,cols in quarter cells a turn, + meaning down or right). "
             "The {width}x{height} solar system has a sun (O) at its centre that pulls you in (a "
             "quarter cell a turn more on each axis every {sun} turns) and destroys you, your "
             "home base (H), and four planets (1-4). Fly into a planet to go to its surface: "
             "there gravity pulls you down (a quarter cell a turn more every {fall} turns), the ground (#) destroys you on "
             "contact, and {bunkers} bunkers (B) fire shells (!) at you every {volley} turns "
             "when you are in their row or column. FIRE sends a shot (*) {reach} cells the way "
             "you point. Shoot every bunker on a planet and it is destroyed (x) and you are back "
             "in space; flying off the top of a surface also takes you back, and its sides wrap "
             "around. Fuel ({air} at the start) burns a unit a turn and {burn} more for each "
             "THRUST; hover one or two cells straight above a fuel tank (F) and your tractor beam "
             "takes it for {tank} fuel. Losing a ship puts you back at the home base (or where you "
             "came down on the surface you are on). {map_text}.")
    rewards = "+{unit} for each bunker destroyed."
    ends = "when every bunker is destroyed ({goal}), the fuel runs out, or your last ship is lost"
    Params = GravitarParams
    pattern = "A"
    FOE, foe_name = BUNKER, "bunker"
    SOLID = frozenset((WALL, SUN))
    glyphs = {EMPTY: "space", WALL: "ground", SUN: "the sun", HOME: "home base",
              **{g: f"planet {g}" for g in PLANETS}, RUIN: "destroyed planet", BUNKER: "bunker",
              TANK: "fuel tank", SHOT: "your shot", SHELL: "bunker shell", **ship_glyphs()}

    def prompt_fields(self) -> dict:
        return {**super().prompt_fields(), "burn": self.burn,
                "power": POWER,
                "map_text": "The HUD's Map shows the system then planets 1-4: @ where you are, + "
                            "visited, ? not yet visited"}

    def _still(self) -> list[str]:
        p = self.params
        w, h = p.width, p.height
        rows = [[EMPTY] * w for _ in range(h)]
        for r, c in self._sun():
            rows[r][c] = SUN
        for k, (r, c) in enumerate(self._planets()):
            for a in (0, 1):
                for b in (0, 1):
                    rows[r + a][c + b] = PLANETS[k]
        rows[h - 2][w // 2] = HOME
        return ["".join(row) for row in rows]

    def _sun(self):
        h, w = self.params.height, self.params.width
        return [(h // 2 - 1 + a, w // 2 - 1 + b) for a in (0, 1) for b in (0, 1)]

    def _planets(self):
        h, w = self.params.height, self.params.width
        return [(2, 3), (2, w - 5), (h - 6, 3), (h - 6, w - 5)]

    def _surface(self, k: int):
        """Planet ``k``'s rows (ground from a random walk), its bunkers and its ground heights."""
        p, d = self.params, self.draws
        w, h = p.width, p.height
        top, g = h - 9, h - 5 - d.below(3)
        ground = []
        for _ in range(w):
            g = max(top, min(h - 3, g + d.below(3) - 1 - (d.random() < 0.08) * 2))
            ground.append(g)
        rows = [[WALL if r >= ground[c] else EMPTY for c in range(w)] for r in range(h)]
        n = p.bunkers + 2
        spots = [(i * w) // n + d.below(max(1, w // n - 1)) for i in range(n)]
        foes = []
        for i, c in enumerate(spots):             # the second and the second-last slots: tanks
            if i in (1, n - 2):
                rows[ground[c] - 1][c] = TANK
            else:
                foes.append((ground[c] - 1, c))
        return ["".join(row) for row in rows], foes, ground

    def _setup(self, rng) -> None:
        p = self.params
        self.start_flight(rng, p.height - 2, p.width // 2, power=POWER)
        self.system = self.still
        self.sectors = Sectors(["#####"])
        self.sectors.go((0, 0))
        self.ground, self.entry = {}, {}
        for k in range(4):
            rows, spots, ground = self._surface(k)
            foes = [Body(r, c, 0, 0, BUNKER, p.hp) for r, c in spots]
            self.sectors.held[(0, k + 1)] = (rows, foes)
            self.ground[k] = ground
            # you come down (and back after a loss) at the column farthest from the bunkers
            w = p.width
            self.entry[k] = max(range(w), key=lambda c: (min(min(abs(c - b), w - abs(c - b)) for _, b in spots),
                                                         -abs(c - w // 2)))
        self.planet = None

    def _go(self, planet: int | None, r: int, c: int) -> None:
        """Fly to planet ``planet``'s surface (None: the system) at (r, c), at rest."""
        self.planet = planet
        if planet is None:
            self.still, self.foes = self.system, []
        else:
            self.still, self.foes = self.sectors.held[(0, planet + 1)]
        self.still_version += 1
        self.sectors.go((0, 0 if planet is None else planet + 1))
        self.home = (r, c) if planet is not None else (self.params.height - 2, self.params.width // 2)
        self.r, self.c = r, c
        self.ship.place(r, c)
        self.gun.shots, self.shells.shots = [], []

    def _gravity(self):
        p, t = self.params, self.tick
        if self.planet is not None:
            return (1, 0) if t % p.fall == 0 else None
        if t % p.sun:
            return None
        h, w = p.height // 2, p.width // 2
        return (self.r < h - 1) - (self.r > h), (self.c < w - 1) - (self.c > w)

    def _arrive(self, r: int, c: int) -> bool:
        ch = self.still[r][c]
        if self.planet is None and ch in PLANETS:
            self.say(f"You descend to planet {ch}.")
            self._go(int(ch) - 1, 1, self.entry[int(ch) - 1])
            return True
        return False

    def _edge(self, r: int, c: int) -> bool:
        if self.planet is None:
            return super()._edge(r, c)
        if r < 0:
            self.say("You leave the planet.")
            self._leave(self.planet)
            return True
        ship, w = self.ship, self.params.width               # the sides of a surface wrap
        c %= w
        if self.still[r][c] in self.SOLID or self.foe_at(r, c) is not None:
            self.r, self.c = r, c
            return self._crash(r, c)
        ship.y, ship.x = ship.y + ship.vy, (ship.x + ship.vx) % (w * SCALE)
        self.r, self.c = r, c
        return False

    def _leave(self, k: int) -> None:
        """Back to the system, just off planet ``k`` on the sun's side."""
        pr, pc = self._planets()[k]
        self._go(None, pr + 2 if pr < self.params.height // 2 else pr - 1, pc)

    def _crash(self, r: int, c: int) -> bool:
        what = "the sun" if self.still[r][c] == SUN else "a bunker" if self.foe_at(r, c) else "the ground"
        return self._killed(f"You crashed into {what}.")

    def _hit(self, foe) -> None:
        super()._hit(foe)
        if not self.done and not self.foes:
            k = self.planet
            self.say(f"Planet {k + 1} destroyed!")
            self._leave(k)
            pr, pc = self._planets()[k]
            for a in (0, 1):
                for b in (0, 1):
                    self.set_still(pr + a, pc + b, RUIN)

    def _turn(self) -> None:
        if self.planet is None:
            return
        c = self.c
        g = self.ground[self.planet][c]
        if g - 3 <= self.r <= g - 2 and self.still[g - 1][c] == TANK:
            self.set_still(g - 1, c, EMPTY)
            self.air.left = min(self.air.left + self.params.tank, 99999)
            self.say(f"Tractor beam: fuel tank taken (+{self.params.tank} fuel).")

    def _place_hud(self) -> str:
        return " | " + self.sectors.map.hud()


register_atari(Gravitar, "gravitar", max_turns=10000)
