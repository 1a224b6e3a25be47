"""Procgen CaveFlyer: fly a ship through a winding cave to the exit near its far end. Touching the
cave wall, a patrolling enemy or a target rock destroys the ship; shooting enemies and targets
pays a little.

Differences from Procgen, for a grid: the ship moves one cell a turn in four directions (no
rotation or momentum) and shoots the way it last moved. Every cave is a random walk of varying
width with a few rocks inside, regenerated until a search finds a way from start to exit."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from ..common.grid import bfs_distances
from .engine import OPEN, PLAYER_GLYPHS
from .shooting import FOE, SHOT, STOP, Body, Gun, ShooterTask, pair, with_fire

ROCK, EXIT, ENEMY, TARGET, BOLT = "#", ">", "E", "o", "*"
MARK = 64    # the targets' side


@dataclass(frozen=True)
class CaveFlyerParams:
    width: int = param(48, 24, 80)
    height: int = param(12, 9, 16)
    enemies: int = param(4, 0, 8)
    targets: int = param(3, 0, 8)
    shot_range: int = param(6, 2, 12)
    paid: int = param(4, 0, 10)          # kills (enemies or targets) that pay


class ProcgenCaveFlyer(ShooterTask):
    title = "Procgen CaveFlyer"
    rules = ("Fly your ship through a cave {width} columns long, seen through a window that "
             "follows you, to the exit (>) near its right end; you move one cell a turn. FIRE "
             "shoots a bolt (*) the way you last moved (right before any move), 2 cells a turn "
             "for {shot_range} cells; after a shot the gun needs 2 turns. Enemies (E) patrol up "
             "and down, a cell every other turn, turning at the walls; target rocks (o) stand "
             "still. Flying into the cave wall (#), an enemy or a target rock destroys your ship; "
             "bolts destroy enemies and targets. The status line gives the exit's place relative "
             "to you (Exit@rows,columns).")
    rewards = ("+0.1 for each of the first {paid} enemies or targets destroyed, +{exit_pay:.3g} for "
               "reaching the exit, -1 for losing your ship.")
    ends = "when you reach the exit or lose your ship"
    Params = CaveFlyerParams
    solid = ROCK
    start_dir = (0, 1)
    player_hits = FOE | MARK
    ACTIONS = with_fire("shoot a bolt the way you last moved")
    glyphs = {OPEN: "open", ROCK: "cave wall", EXIT: "exit", ENEMY: "enemy", TARGET: "target rock",
              BOLT: "your bolt", **PLAYER_GLYPHS}

    def prompt_fields(self) -> dict:
        return {**super().prompt_fields(), "exit_pay": 1 - 0.1 * self.params.paid}

    def _setup(self, rng: np.random.Generator) -> None:
        while True:
            rows, middle = self._cave(rng)
            start, self.exit = (middle[2], 2), (middle[-3], self.params.width - 3)
            rows[self.exit[0]][self.exit[1]] = EXIT
            things = self._things(rng, rows, middle)
            if things is not None:
                break
        self.start(["".join(row) for row in rows], start, Gun(BOLT, 2, self.params.shot_range, 2,
                                                              hits=FOE | MARK))
        for glyph, r, c, vr in things:
            side = FOE if glyph == ENEMY else MARK
            self.world.add(Body(glyph, r, c, vr, 0, side=side, period=2, edge=STOP))
        self.killed = 0

    def _cave(self, rng: np.random.Generator) -> tuple[list[list[str]], list[int]]:
        """A random-walk corridor: its centre row drifts a row at most per column, its half-width
        between 1 and 3, so neighbouring columns always share the centre row; then a few rocks."""
        h, w = self.params.height, self.params.width
        rows = [[ROCK] * w for _ in range(h)]
        y, half = int(rng.integers(3, h - 3)), 1
        middle, halves = [y], [half]
        for c in range(1, w - 1):
            if rng.random() < 0.3:
                half = min(max(half + (1 if rng.random() < 0.5 else -1), 1), 3)
            y = min(max(y + int(rng.integers(-1, 2)), 1 + half), h - 2 - half)
            middle.append(y)
            halves.append(half)
            for r in range(y - half, y + half + 1):
                rows[r][c] = OPEN
        middle.append(y)
        for _ in range(w // 6):                        # loose rocks inside the wide parts
            c = int(rng.integers(6, w - 4))
            if halves[c] >= 2:
                rows[middle[c] + int(rng.integers(-halves[c], halves[c] + 1))][c] = ROCK
        return rows, middle

    def _things(self, rng, rows, middle) -> list[tuple[str, int, int, int]] | None:
        """Enemies and targets on open cells, or None when the exit cannot be reached around
        the rocks and targets."""
        p = self.params
        cols = rng.choice(np.arange(8, p.width - 4), p.enemies + p.targets, replace=False).tolist()
        things = []
        for i, c in enumerate(cols):
            r = middle[c]
            if i < p.enemies:
                things.append((ENEMY, r, c, 1 if rng.random() < 0.5 else -1))
            else:
                r += int(rng.integers(-1, 2))
                if rows[r][c] == OPEN:
                    things.append((TARGET, r, c, 0))
        blocked = {(r, c) for g, r, c, _ in things if g == TARGET}
        reach = bfs_distances((middle[2], 2), lambda r, c: rows[r][c] != ROCK and (r, c) not in blocked)
        return things if (middle[-3], p.width - 3) in reach else None

    def _hit(self, a: Body, b: Body | None) -> None:
        if b is None:
            if a is self.player:
                self._lose("You crashed into the cave wall.")
            elif a.side == FOE:
                a.vr = -a.vr                  # an enemy turns at the wall
            else:
                a.alive = False               # a bolt on the wall
            return
        shot = pair(a, b, SHOT)
        if shot:
            bolt, thing = shot
            bolt.alive = thing.alive = False
            self.killed += 1
            if self.killed <= self.params.paid:
                self.reward(0.1)
            self.say("Enemy destroyed." if thing.glyph == ENEMY else "Target destroyed.")
        elif a is self.player or b is self.player:
            self._lose("An enemy got you." if ENEMY in (a.glyph, b.glyph) else "You hit a target rock.")

    def _lose(self, why: str) -> None:
        self.reward(-1)
        self.say(why)
        self.finish(won=False)

    def _after(self) -> None:
        if self.pos == self.exit:
            self.reward(1 - 0.1 * self.params.paid)
            self.say("You reached the exit.")
            self.finish(won=True)

    def _extras(self) -> str:
        return f"Exit@{self.exit[0] - self.pos[0]:+d},{self.exit[1] - self.pos[1]:+d} | {super()._extras()}"


register_variants(ProcgenCaveFlyer, "Procgen", {"glyphbench/procgen-caveflyer-v0": dict(max_turns=500)})
