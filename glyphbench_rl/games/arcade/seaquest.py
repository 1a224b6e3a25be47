"""Seaquest: a submarine under the sea rescues divers and must come back up for air. Sharks
swim back and forth across the lanes and sink the sub on contact (the torpedo stops them);
the oxygen runs down while the sub is under water and is refilled at the surface, where a full
load of divers is also delivered."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.params import param, require
from .arena import EMPTY, SHOT, ArenaParams, ArenaTask, you_glyphs
from .bodies import Body
from .engine import register_arcade

SHARK, DIVER, WAVES = "F", "D", "~"


@dataclass(frozen=True)
class SeaquestParams(ArenaParams):
    width: int = param(14, 8, 40)
    height: int = param(12, 6, 40)
    goal: int = param(4, 1, 1000)
    foes: int = param(2, 0, 12)
    every: int = param(2, 1, 50)
    air: int = param(80, 10, 1000)
    divers: int = param(3, 1, 6)          # divers that make a full load
    shark_pays: int = param(0, 0, 1)      # 1: a shark shot scores a unit

    def check(self) -> None:
        require(self.foes + self.divers <= self.height - 2, "foes", "leave a lane for each diver", self.foes)


HUD_TEXT: dict[tuple, str] = {}   # the HUD note by its values


class Seaquest(ArenaTask):
    title = "Seaquest"
    rules = ("You are a submarine ({lives_text}) in a {width}x{height} sea; the top row (~) is the "
             "surface. {divers} divers (D) swim in the lanes below; touch one to pick it up. "
             "{foes} sharks (F) swim across, a cell every {every} turns, and sink you on contact; "
             "FIRE sends a torpedo (*) {reach} cells the way you face. Under water your air "
             "lasts {air} turns; at the surface it is refilled, and a full load of {divers} "
             "divers is delivered. Running out of air sinks you.")
    rewards = "+{unit} for each diver picked up and for each full load delivered{shark_text}; {death} when the game is lost."
    ends = "when you have scored {goal} times or the game is lost"
    Params = SeaquestParams
    pattern = "D"
    drift = True
    FOE, foe_name, caught_text, air_name = SHARK, "shark", "A shark sank you.", "O2"
    air_out = "You ran out of air."
    glyphs = {WAVES: "surface", EMPTY: "water", SHARK: "shark", DIVER: "diver", SHOT: "your torpedo",
              **you_glyphs()}

    def prompt_fields(self) -> dict:
        return {**super().prompt_fields(),
                "shark_text": " and for each shark shot" if self.params.shark_pays else ""}

    def _still(self) -> list[str]:
        p = self.params
        return [WAVES * p.width] + [EMPTY * p.width] * (p.height - 1)

    def _setup(self, rng) -> None:
        p = self.params
        self.start_arena(rng, 0, p.width // 2)
        self.face, self.carried = (0, 1), 0
        lanes = list(range(2, p.height))
        order = [lanes.pop(self.draws.below(len(lanes))) for _ in range(p.foes + p.divers)]
        self.swimmers = [Body(r, self.draws.below(p.width), 0, 1 if k % 2 else -1, DIVER)
                         for k, r in enumerate(order[p.foes:])]
        for k, r in enumerate(order[:p.foes]):
            self.add_foe(r, self.draws.below(p.width), 0, -1 if k % 2 else 1)

    def _turn(self) -> None:
        p = self.params
        if self.r == 0:
            self.air.refill()
            if self.carried >= p.divers:
                self.carried = 0
                self.say("Divers delivered!")
                self.score.gain()
                if not self.done:
                    self._restock()
        if self.tick % p.every == 0:
            for d in self.swimmers:
                d.c += d.dc
                if not 0 <= d.c < p.width:
                    d.dc, d.c = -d.dc, d.c - 2 * d.dc
        r, c, picked = self.r, self.c, False
        for d in self.swimmers:
            if d.r == r and d.c == c:
                d.alive, picked = False, True
                self.carried += 1
                self.say("Diver rescued.")
                self.score.gain()
        if picked:
            self.swimmers = [d for d in self.swimmers if d.alive]

    def _restock(self) -> None:
        p = self.params
        taken = {f.r for f in self.foes}
        free = [r for r in range(2, p.height) if r not in taken]
        self.swimmers = [Body(free[self.draws.below(len(free))], self.draws.below(p.width), 0, 1, DIVER)
                         for _ in range(p.divers)]

    def _hit(self, foe) -> None:
        self.foes.remove(foe)
        self.say("Shark shot!")
        if self.params.shark_pays:
            self.score.gain()
        self.add_foe(foe.r, 0 if foe.dc > 0 else self.params.width - 1, 0, foe.dc)

    def _below(self):
        return [(d.r, d.c, DIVER) for d in self.swimmers]

    def _extra_hud(self) -> str:
        key = (self.air_name, self.air.left, self.carried, self.params.divers)
        text = HUD_TEXT.get(key)
        if text is None:   # (made once per value: the values recur from episode to episode)
            if len(HUD_TEXT) >= 4096:
                HUD_TEXT.clear()
            text = HUD_TEXT[key] = f"{self.air_name} {self.air.left} | Divers {self.carried}/{self.params.divers}"
        return text


register_arcade(Seaquest, "seaquest",
                mini=dict(max_turns=400),
                atari=dict(width=20, height=16, goal=100, unit=20.0, lives=3, foes=5, divers=6,
                           air=120, shark_pays=1, every=1, max_turns=10000))
