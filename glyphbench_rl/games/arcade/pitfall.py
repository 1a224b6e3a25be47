"""Pitfall!: Pitfall Harry runs a ring of jungle screens (255 in the original) against the clock,
collecting treasures. Kept from the original: each screen drawn from the seed (ladders down to
the underground tunnel with open holes beside them, tar pits and ponds with a vine to swing
across, quicksand that opens and closes, swamps with crocodiles whose jaws open and shut, fire
and snakes by the treasures), logs that roll along the ground and cost points on contact,
scorpions and brick walls in the tunnel, where a screen's walk moves you three screens, a
running jump, three lives, the clock, and the native points (2000 to 5000 a treasure, a log's
touch costs points). The screens seen are mapped in the HUD. Collecting ``goal`` treasures wins
(pattern D: losing the last life, or the clock running out, pays ``death``)."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param
from .engine import EMPTY, ArcadeParams, register_atari
from .platform import (DOWN, JUMP, JUMP_LEFT, JUMP_RIGHT, JUMP_TEXT, LADDER, LEFT, RIGHT, ROPE, STAY,
                       UP, Blink, Platformer, Swing, Walker, paint)
from .rooms import LEGEND, RoomMap

LEAVES, GROUND, EARTH, TAR, WATER, SAND, FIRE, GOLD, YOU = "%", "=", "#", ":", "~", ";", "^", "$", "@"
JAWS, SHUT = "C", "c"
KINDS = ("ladder", "ladder", "tar", "pond", "quicksand", "swamp", "logs")
VALUES = (2000, 3000, 4000, 5000)
SURFACE, TUNNEL, SPAN = 6, 10, 4
ACTIONS = ActionSet([("NOOP", "stand still (or hang on to a vine)"),
                     ("FIRE", "jump the way you last ran"),
                     ("UP", "climb up a ladder"), ("RIGHT", "run right"), ("LEFT", "run left"),
                     ("DOWN", "climb down a ladder, or let go of a vine")], noop="NOOP")
INTENTS = (STAY, JUMP, UP, RIGHT, LEFT, DOWN)


@dataclass(frozen=True)
class PitfallParams(ArcadeParams):
    width: int = param(40, 40, 60)
    height: int = param(12, 12, 12)
    lives: int = param(3, 1, 9)
    goal: int = param(32, 1, 64)         # treasures that win (at most one a screen)
    unit: float = param(0.0, 0, 1000)
    death: float = param(-1.0, -10000, 0)
    screens: int = param(255, 16, 255)
    clock: int = param(8000, 100, 100000)   # turns before time is up
    log: int = param(100, 0, 1000)       # points a rolling log's touch costs
    sand_open: int = param(12, 1, 100)   # quicksand: open this many ticks, then shut
    sand_shut: int = param(24, 14, 100)  # (long enough to run across)
    jaws_open: int = param(8, 1, 100)    # crocodiles: jaws open, then shut
    jaws_shut: int = param(12, 6, 100)


class Pitfall(Platformer):
    title = "Pitfall!"
    rules = ("Pitfall Harry (@) runs a ring of {screens} jungle screens, {width}x{height}, seen one at "
             "a time. " + LEGEND + " (it shows {span} screens either side of yours). Running off the side of a screen on the ground takes you to the "
             "next one; ladders (H) lead down to the tunnel below, where running off a side moves you "
             "three screens, and brick walls (#) block the way. " + JUMP_TEXT + ". Tar pits (:), "
             "ponds (~), quicksand (;, open {sand_open} ticks, then shut {sand_shut}), a crocodile "
             "with its jaws open (C, {jaws_open} ticks, then shut {jaws_shut}: c, a head you can "
             "stand on), fire (^), snakes (s) and scorpions (X) each cost a life; "
             "you have {lives_text}. A jump that comes within a column of a vine's tip (|) grabs it; it swings you over the pit, and DOWN lets go. "
             "Falling through an open hole beside a ladder drops you into the tunnel. Rolling logs "
             "(o) cost {log} points each time one hits you. {goal} treasures ($) lie on the screens.")
    rewards = ("+{low} to +{high} a treasure (money bag, silver bar, gold bar, ring){unit_text}, -{log} a log's "
               "hit; {death:g} when your last life is lost or the clock ({clock} turns) runs out.")
    ends = "when you have collected {goal} treasures, lose your last life, or the clock runs out"
    ACTIONS = ACTIONS
    Params = PitfallParams
    pattern = "D"
    glyphs = {EMPTY: "air", LEAVES: "jungle canopy", GROUND: "ground", EARTH: "earth or brick wall",
              LADDER: "ladder", ROPE: "vine", TAR: "tar pit", WATER: "pond", SAND: "quicksand",
              JAWS: "crocodile, jaws open", SHUT: "crocodile, jaws shut", FIRE: "fire", GOLD: "treasure",
              "o": "rolling log", "s": "snake", "X": "scorpion", YOU: "you"}
    SOLID = frozenset(GROUND + EARTH + SHUT)
    HAZARD = frozenset(TAR + WATER + SAND + JAWS + FIRE)
    safe_fall = 4

    def prompt_fields(self) -> dict:
        unit = self.params.unit
        return {**super().prompt_fields(), "low": min(VALUES), "high": max(VALUES), "span": SPAN,
                "unit_text": f" (and +{unit:g} more)" if unit else ""}

    def _setup(self, rng) -> None:
        p = self.params
        self.map = RoomMap(["#" * p.screens], span=SPAN)
        self.kinds = [KINDS[int(k)] for k in rng.integers(len(KINDS), size=p.screens)]
        picks = rng.choice(range(1, p.screens), size=min(p.goal, p.screens - 1), replace=False)
        self.gold = {int(s): VALUES[i % 4] for i, s in enumerate(picks)}
        for s in self.gold:
            self.kinds[s] = "treasure"
        self.guard = {s: ("fire", "snake", "logs")[int(rng.integers(3))] for s in self.gold}
        self.wall = rng.choice((-9, 9), size=p.screens).tolist()       # a tunnel's brick wall
        self.logs = rng.integers(0, 3, size=p.screens).tolist()        # logs on a ladder screen
        self.start(rng)
        self.swings = []
        self._enter(0, SURFACE, 2)

    def _build(self, s: int) -> list[str]:
        p = self.params
        w, mid, kind = p.width, p.width // 2, self.kinds[s]
        g = [[EMPTY] * w for _ in range(p.height)]
        paint(g, LEAVES, (0,), range(w))
        paint(g, GROUND, (7,), range(w))
        paint(g, EARTH, (8, 11), range(w))
        if kind == "ladder":
            paint(g, LADDER, range(7, TUNNEL + 1), (mid,))
            paint(g, EMPTY, (7, 8), (mid - 6, mid + 6))
            paint(g, EARTH, (9, TUNNEL), (mid + self.wall[s],))
        elif kind in ("tar", "pond", "quicksand", "swamp"):
            pit = {"tar": TAR, "pond": WATER, "quicksand": SAND, "swamp": WATER}[kind]
            paint(g, pit, (7,), range(mid - 6, mid + (5 if kind == "swamp" else 6)))
        elif kind == "treasure":
            g[SURFACE][w - 6] = GOLD
            if self.guard[s] == "fire":
                g[SURFACE][mid] = FIRE
        return ["".join(row) for row in g]

    def _enter(self, s: int, r: int, c: int) -> None:
        p = self.params
        self.screen = s
        self.map.enter(0, s)
        self.show(s)
        mid, kind = p.width // 2, self.kinds[s]
        self.swings = [Swing(1, mid, 4, 7)] if kind in ("tar", "pond") else []
        self.blinks = ([Blink([(7, c) for c in range(mid - 6, mid + 6)], SAND, GROUND, p.sand_open, p.sand_shut)]
                       if kind == "quicksand" else
                       [Blink([(7, mid - 3), (7, mid + 1)], JAWS, SHUT, p.jaws_open, p.jaws_shut)] if kind == "swamp" else [])
        self.blink(self.blinks)
        logs = (2 if kind == "logs" else 1 if kind == "treasure" and self.guard[s] == "logs"
                else self.logs[s] if kind == "ladder" else 0)
        self.foes = [Walker(SURFACE, c, 0, 0, 2, "o", d=-1, wrap=p.width) for c in (mid, mid + 12)[:logs]]
        if kind == "treasure" and self.guard[s] == "snake":
            self.foes.append(Walker(SURFACE, mid, mid, mid, 0, "s"))
        if kind != "ladder":
            self.foes.append(Walker(TUNNEL, mid, 1, p.width - 2, 2, "X", chase=True))
        self.place(r, c)
        self.entry = (r, c)

    def _respawn(self) -> None:
        self.place(SURFACE, 2)

    def _leave(self, dr: int, dc: int) -> None:
        p = self.params
        hop = dc * (3 if self.r > SURFACE + 1 else 1)
        self._enter((self.screen + hop) % p.screens, self.r, p.width - 1 if dc < 0 else 0)

    def _hazard_text(self) -> str:
        ch = self.still[self.r][self.c]
        return "A crocodile got you." if ch == JAWS else "The fire burned you." if ch == FIRE else "You sank."

    def _play(self, action: int) -> None:
        p = self.params
        if self.tick >= p.clock:
            self.say("Time is up.")
            self.reward(p.death)
            self.finish(won=False)
            return
        if self.blinks:
            self.blink(self.blinks)
        intent = INTENTS[action]
        if intent == JUMP:
            intent = JUMP_RIGHT if self.face > 0 else JUMP_LEFT
        if not self.walk(intent) or self.done:
            return
        if self.r == SURFACE and self.arc is None and self.held is None and self.still[7][self.c] == JAWS:
            self.lose_life("A crocodile got you.")
            return
        if self.still[self.r][self.c] == GOLD:
            self.set_still(self.r, self.c, EMPTY)
            self.say("Treasure!")
            self.score.bonus(self.gold[self.screen])
            self.score.gain()
            if self.done:
                return
        foe = self.meet(self.foes, self.c if self.r > SURFACE + 1 else None)
        if foe is not None:
            if foe.glyph != "o":
                self.lose_life("A snake bit you." if foe.glyph == "s" else "A scorpion stung you.")
                return
            if foe is not self.hit_by:
                self.say("A log hit you.")
                self.score.bonus(-p.log)
        self.hit_by = foe

    def place(self, r: int, c: int) -> None:
        super().place(r, c)
        self.hit_by = None

    def _sprites(self):
        out = [cell for s in self.swings for cell in s.cells(self.tick)]
        out += [(f.r, f.c, f.glyph) for f in self.foes]
        out.append((self.r, self.c, YOU))
        return out

    def _extra_hud(self) -> str:
        left = self.params.clock - self.tick
        if self._tail_of != (left, self.screen):
            self._tail_of = (left, self.screen)
            self._tail_text = f"Clock {left} | {self.map.hud()}"
        return self._tail_text

    _tail_of = None


register_atari(Pitfall, "pitfall", max_turns=10000)
