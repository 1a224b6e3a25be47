"""Crazy Climber: climb the facade of a skyscraper, hand over hand, to the helicopter on its roof.
Kept from the original: the building taller than the screen, scrolling as you climb; climbing by
alternate hands (the first UP puts a hand on the window frame above, the second pulls you up
when both hands are on it); windows that open and shut, a shut one barring the way and one
shutting on your raised hand knocking you down; objects dropped from above, to be dodged; the
helicopter on the roof that takes you to the next, taller building; points for every new height
and a bonus a building. Dropped: the condor, King Kong, the bald residents and the girders."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param, require
from .climbing import ClimbTask, Fallers, Tower
from .engine import ArcadeParams, register_atari

OPEN, SHUT, CLOSING, EDGE, ROOF, COPTER, YOU, REACH, POT = ".", "=", "-", "|", "_", "H", "Y", "y", "o"
ACTIONS = ActionSet([("NOOP", "hold on"), ("UP", "reach up a hand; with a hand already up, pull up a row"),
                     ("DOWN", "climb down a row"), ("LEFT", "move a window left"),
                     ("RIGHT", "move a window right")], noop="NOOP")
UP, DOWN, LEFT, RIGHT = 1, 2, 3, 4


@dataclass(frozen=True)
class CrazyClimberParams(ArcadeParams):
    width: int = param(12, 6, 30)
    height: int = param(24, 10, 40)     # the rows in view
    lives: int = param(4, 1, 9)
    goal: int = param(5, 1, 100)        # buildings
    unit: float = param(1000.0, 0, 10000)
    tall: int = param(32, 10, 400)      # rows of the first building, roof included
    taller: int = param(6, 0, 100)      # rows added each building
    cycle: int = param(12, 4, 60)       # turns of a window's open-and-shut cycle
    shut: int = param(4, 1, 50)         # turns of the cycle a window stays shut
    shutters: float = param(0.3, 0, 0.9)  # share of windows that open and shut, first building
    more: float = param(0.05, 0, 0.5)   # more of them each building
    drop: int = param(6, 1, 50)         # a pot falls every this many turns, first building
    aim: float = param(0.5, 0, 1)       # chance a pot falls in your column
    knock: int = param(2, 1, 10)        # rows a window shutting on your hand knocks you down
    below: int = param(6, 0, 30)        # rows kept in view below you
    row_points: int = param(10, 0, 1000)

    def check(self) -> None:
        require(self.shut < self.cycle - 1, "shut", "less than cycle - 1", self.shut)
        require(self.below < self.height, "below", "less than height", self.below)


class CrazyClimber(ClimbTask):
    title = "Crazy Climber"
    rules = ("You (Y) climb the facade of a skyscraper, {width} cells wide with its edges (|), to the "
             "helicopter (H) on the roof (_). The field shows {height} rows of it and scrolls as you "
             "climb; the first building is {tall} rows tall and each is {taller} taller. Every cell "
             "is a window. You climb hand over hand: UP puts a hand on the window above (you show "
             "as y), a second UP pulls you up a row; both need that window open (.). LEFT, RIGHT and "
             "DOWN move a window and lower your hand; none enters a shut window (=). Some windows "
             "shut for {shut} turns in every {cycle}; a closing one (-) is shut on the next turn, and "
             "a window shutting on your raised hand knocks you {knock} rows down. Residents drop pots "
             "(o) from above you, a row a turn; one that hits you costs a life. On the roof walk to the "
             "helicopter to finish the building. You have {lives_text}.")
    rewards = ("+{row_points} for each row higher than you have been on a building, +{unit:g} a "
               "building finished; -1 when your last life is lost.")
    ends = "when you have finished {goal} buildings, or you lose your last life"
    ACTIONS = ACTIONS
    Params = CrazyClimberParams
    pattern = "D"
    glyphs = {OPEN: "open window", SHUT: "shut window", CLOSING: "window shutting next turn",
              EDGE: "building edge", ROOF: "roof", COPTER: "helicopter", YOU: "you",
              REACH: "you, a hand up", POT: "falling pot"}

    def _setup(self, rng) -> None:
        self.start(rng)
        self.building = 0
        self._build()

    def _build(self) -> None:
        """A new building: each window always open or, with the building's chance, shut for
        ``shut`` turns of every ``cycle`` from its own phase; its rows at every turn of the
        cycle made once (``frames``)."""
        p, d = self.params, self.draws
        tall, w = p.tall + self.building * p.taller, p.width
        share = min(0.9, p.shutters + self.building * p.more)
        phases = [[d.below(p.cycle) if d.random() < share else -1 for _ in range(w - 2)]
                  for _ in range(tall)]
        self.copter = 1 + d.below(w - 2)
        roof = EDGE + ROOF * (w - 2) + EDGE
        roof = roof[:self.copter] + COPTER + roof[self.copter + 1:]
        cycle = p.cycle   # a window's cells over the cycle, one string per phase (-1: always open)
        runs = {-1: OPEN * cycle}
        runs.update((f, "".join(SHUT if (t + f) % cycle < p.shut else CLOSING if (t + f) % cycle == cycle - 1
                                else OPEN for t in range(cycle))) for f in range(cycle))
        self.frames = [[roof] for _ in range(cycle)]
        for r in range(1, tall):
            for frame, cells in zip(self.frames, zip(*[runs[f] for f in phases[r]])):
                frame.append(EDGE + "".join(cells) + EDGE)
        self.tower = Tower(self.frames[0], p.height)
        self.r, self.c, self.hand, self.best = tall - 1, w // 2, False, tall - 1
        self.pots = Fallers()
        self.every = max(1, p.drop - self.building)
        self.tower.follow(self.r, p.below)

    def _respawn(self) -> None:
        self.pots, self.hand = Fallers(), False

    def _world_rows(self, top: int) -> list[str]:
        return self.frames[self.tick % self.params.cycle][top:top + self.params.height]

    def _move(self, action: int, seen: list[str]) -> None:
        """Your move, against the windows as you saw them."""
        r, c = self.r, self.c
        if action == UP and r > 0:
            if seen[r - 1][c] == SHUT:
                self.say("A shut window bars your hand.")
            elif self.hand:
                self.r, self.hand = r - 1, False
                if self.r < self.best:
                    self.best = self.r
                    self.score.bonus(self.params.row_points)
            else:
                self.hand = True
        elif action == DOWN and r + 1 < len(seen) and seen[r + 1][c] != SHUT:
            self.r, self.hand = r + 1, False
        elif action in (LEFT, RIGHT):
            x = c + (1 if action == RIGHT else -1)
            if seen[r][x] not in (SHUT, EDGE):
                self.c, self.hand = x, False

    def _play(self, action: int) -> None:
        p = self.params
        cycle = p.cycle
        self._move(action, self.frames[(self.tick - 1) % cycle])
        if (self.r, self.c) == (0, self.copter):
            self.say("The helicopter takes you to the next building!")
            self.score.gain()
            if not self.done:
                self.building += 1
                self._build()
            return
        if self.pots.hits(self.r, self.c) and self.lose_life("A pot hit you."):
            return
        now = self.frames[self.tick % cycle]
        if self.hand and now[self.r - 1][self.c] == SHUT:
            self.say("A window shut on your hand!")
            self.r, self.hand = min(len(now) - 1, self.r + p.knock), False
        tower = self.tower
        tower.follow(self.r, p.below)
        self.pots.advance(tower.top + p.height - 1)
        if self.pots.hits(self.r, self.c) and self.lose_life("A pot hit you."):
            return
        if self.tick % self.every == 0 and self.r - tower.top > 3:
            d = self.draws
            self.pots.drop(tower.top, self.c if d.random() < p.aim else 1 + d.below(p.width - 2))

    def _movers(self):
        out = [(r, c, POT) for r, c in self.pots.cells]
        out.append((self.r, self.c, REACH if self.hand else YOU))
        return out

    def _extra_hud(self) -> str:
        return f"Building {self.building + 1} | Floor {len(self.frames[0]) - 1 - self.r}"


register_atari(CrazyClimber, "crazyclimber", max_turns=1000)
