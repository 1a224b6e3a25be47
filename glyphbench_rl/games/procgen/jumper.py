"""Procgen Jumper: a bunny with a double jump explores an open cave for a carrot.

As upstream, the world is a cave larger than the view, the bunny may jump once more in mid-air,
spikes kill, and a compass in the status line points at the carrot. The cave is a cellular
automaton's; the carrot goes on a ledge the search over the game's own physics reaches, far
from the start (in cells, and at least half as many turns away as the farthest ledge), so every
level is winnable by construction: that search is the check."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from .engine import OPEN, PLAYER_GLYPHS
from .platforms import GROUND, SOLID, PlatformTask, search

CARROT, SPIKES = "%", "^"


@dataclass(frozen=True)
class JumperParams:
    width: int = param(40, 20, 80)
    height: int = param(24, 12, 40)
    fill: float = param(0.42, 0.2, 0.5)      # share of rock before smoothing
    spikes: int = param(8, 0, 20)
    min_distance: int = param(16, 0, 60)     # rows + columns from the start to the carrot


class ProcgenJumper(PlatformTask):
    title = "Procgen Jumper"
    rules = ("You are a bunny in a cave {width} columns wide and {height} rows high, seen through a "
             "window that follows you. {physics} Spikes (^) kill on touch. Find the carrot (%): the "
             "status line's compass gives how far it is, columns then rows.")
    rewards = "+1 for the carrot; dying ends the episode with nothing."
    ends = "when you reach the carrot or die"
    Params = JumperParams
    air_jumps = 1
    hazards = SPIKES
    shows_motion = True
    glyphs = {GROUND: "rock", OPEN: "air", SPIKES: "spikes", CARROT: "carrot", **PLAYER_GLYPHS}

    def _build(self, rng: np.random.Generator, easy: bool) -> None:
        p = self.params
        h, w = p.height, p.width
        rock = rng.random((h, w)) < (0.0 if easy else p.fill)
        for _ in range(4):
            rock[0, :] = rock[-1, :] = rock[:, 0] = rock[:, -1] = True
            padded = np.pad(rock, 1, constant_values=True).astype(np.int8)
            count = sum(padded[1 + dr:1 + dr + h, 1 + dc:1 + dc + w]
                        for dr in (-1, 0, 1) for dc in (-1, 0, 1))
            rock = count >= 5
        rock[0, :] = rock[-1, :] = rock[:, 0] = rock[:, -1] = True
        rows = [[GROUND if x else OPEN for x in line] for line in rock.tolist()]
        ledges = [(r, c) for r in range(1, h - 1) for c in range(1, w - 1)
                  if rows[r][c] == OPEN and rows[r + 1][c] in SOLID]
        left = [cell for cell in ledges if cell[1] < w // 4] or ledges
        self.start = left[int(rng.integers(len(left)))]
        far = [cell for cell in ledges if abs(cell[0] - self.start[0]) + abs(cell[1] - self.start[1]) > 5]
        for i in (rng.choice(len(far), min(p.spikes, len(far)), replace=False) if not easy else ()):
            r, c = far[int(i)]
            rows[r][c] = SPIKES
        self.rows, self.patrols = rows, []
        lines = ["".join(row) for row in rows]
        _, seen = search(lines, (*self.start, 0, 1), frozenset(), air_jumps=1, hazards=SPIKES)
        turns: dict = {}                # standing cell -> fewest turns to reach it
        depth: dict = {}
        for key, link in seen.items():  # (the search's insertion order is breadth-first)
            depth[key] = d = 0 if link is None else depth[link[0]] + 1
            r, c, vy, _ = key[0]
            if vy == 0 and rows[r][c] == OPEN and rows[r + 1][c] in SOLID and (r, c) not in turns:
                turns[r, c] = d
        far = max(turns.values())
        cands = sorted(cell for cell, d in turns.items()
                       if (abs(cell[0] - self.start[0]) + abs(cell[1] - self.start[1]) >= p.min_distance
                           and 2 * d >= far) or easy and d == far)
        self.goals = frozenset()
        self.proven = bool(cands)       # the search above reached the carrot's ledge
        if cands:
            carrot = cands[int(rng.integers(len(cands)))]
            rows[carrot[0]][carrot[1]] = CARROT
            self.goals = frozenset([carrot])

    def _touch(self, cell, ch) -> None:
        if ch == CARROT:
            self.reward(1.0)
            self.say("You found the carrot.")
            self.finish(won=True)

    def _extras(self) -> str:
        (gr, gc), (r, c) = next(iter(self.goals)), self.pos
        return f"Carrot {abs(gc - c)}{'←' if gc < c else '→'} {abs(gr - r)}{'↑' if gr < r else '↓'}"


register_variants(ProcgenJumper, "Procgen", {"glyphbench/procgen-jumper-v0": dict(max_turns=500)})
