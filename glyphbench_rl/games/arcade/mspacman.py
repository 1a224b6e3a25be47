"""Ms. Pac-Man: eat the dots of a corridor maze while ghosts hunt you. The ghosts wait in the
middle for a few ticks, then step every ``pace`` ticks, heading for you at each junction (for the
first ticks of every cycle they scatter to their corners instead). A power pellet scares them for
a while: a scared ghost wanders, and touching it sends it back to the middle (pattern D)."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.params import param, require
from .chase import WALL, ChaseParams, MazeTask, ghost, lattice
from .engine import register_arcade

DOT, POWER, EATEN, GHOST = ".", "o", "-", "G"


@dataclass(frozen=True)
class MsPacmanParams(ChaseParams):
    width: int = param(13, 7, 41)
    height: int = param(9, 7, 31)
    goal: int = param(61, 1, 1000)
    unit: float = param(1 / 61, 0, 10)
    powers: int = param(2, 0, 4)        # power pellets, in the maze's corners

    def check(self) -> None:
        floor = sum(row.count(DOT) for row in lattice(self.width, self.height, self.block, DOT))
        require(self.goal <= floor - 1, "goal", f"at most the {floor - 1} dots of the maze", self.goal)


class MsPacman(MazeTask):
    title = "Ms. Pac-Man"
    rules = ("A {width}x{height} maze of corridors between walls (=), with a dot (.) on every "
             "corridor cell and {powers} power pellets (o) in the corners. You (C) move one cell a "
             "turn. {ghosts} ghosts (G) start in the middle, wait {release} turns, then step once "
             "every {pace} turns, heading for you at each junction{scatter_text}. Eating a power "
             "pellet scares them for {scared} turns: scared ghosts (g) wander, and touching one "
             "sends it back to the middle. Touching any other ghost costs a life; you have {lives_text}.")
    rewards = "+{unit} for each dot or pellet eaten; -1 when your last life is lost."
    ends = "when you have eaten {goal} dots, or a ghost catches you with no lives left"
    Params = MsPacmanParams
    glyphs = {DOT: "dot", POWER: "power pellet", EATEN: "empty corridor", WALL: "wall",
              "C": "you", GHOST: "ghost", "g": "scared ghost"}

    def prompt_fields(self) -> dict:
        p = self.params
        scatter = (f" (except the first {p.scatter} of every {p.cycle} turns, when they scatter "
                   "to their corners)" if p.scatter else "")
        return {**super().prompt_fields(), "scatter_text": scatter}

    def _still(self) -> list[str]:
        p = self.params
        rows = lattice(p.width, p.height, p.block, DOT)
        corners = [(1, 1), (p.height - 2, p.width - 2), (1, p.width - 2), (p.height - 2, 1)]
        for r, c in corners[:p.powers]:
            rows[r] = rows[r][:c] + POWER + rows[r][c + 1:]
        return rows

    def _setup(self, rng) -> None:
        self.start(rng)
        p = self.params
        floor = self.floor_cells()
        mid = min(floor, key=lambda rc: abs(rc[0] - p.height // 2) + abs(rc[1] - p.width // 2))
        low = [(p.height - 2, c) for c, ch in enumerate(self.still[p.height - 2]) if ch == DOT]
        start = low[int(rng.integers(len(low)))]
        self.set_still(*start, EATEN)
        self.enter(start, [ghost(*mid, GHOST, dc=1 if k % 2 else -1) for k in range(p.ghosts)])

    def _visit(self, r: int, c: int) -> None:
        ch = self.still[r][c]
        if ch in (DOT, POWER):
            self.set_still(r, c, EATEN)
            if ch == POWER:
                self.frighten()
                self.say("Power pellet! The ghosts are scared.")
            self.score.gain()

    def _eat(self, g) -> None:
        super()._eat(g)
        self.say("You ate a ghost.")


register_arcade(MsPacman, "mspacman",
                mini=dict(ghosts=2, pace=2, release=10, chance=0.8, scatter=6, cycle=30, scared=12,
                          max_turns=400),
                atari=dict(width=27, height=24, block=2, goal=325, unit=1.0, lives=3, ghosts=4,
                           pace=2, release=6, chance=0.9, powers=4, scatter=7, cycle=40, scared=20,
                           max_turns=1000))
