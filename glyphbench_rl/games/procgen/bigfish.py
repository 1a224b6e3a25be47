"""Procgen Bigfish: eat fish no bigger than you to grow; a bigger fish eats you.

Fish (drawn as the digit of their size, 1 to 6) swim across the water from one side to the
other, one or two cells a turn, and leave; new ones keep coming from both sides, their sizes
drawn around yours. You start at size 1 and grow one size per ``per_size`` fish eaten; the fish
that makes you full grown wins (as upstream, where outgrowing the other fish ends the level).
Upstream eats only smaller fish; here equal sizes are eaten too. Built on the shooting engine
(bodies, swept collisions, spawners): a fish that crosses your path in a turn meets you even if
you never share a cell at a turn's end."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.params import param
from .engine import ACTIONS, OPEN, PLAYER_GLYPHS
from .shooting import FOE, GONE, PLAYER, Body, ShooterTask, Spawner, pair

MAX_SIZE = 6
DEATH = -1.0


@dataclass(frozen=True)
class BigfishParams:
    width: int = param(20, 10, 40)
    height: int = param(12, 6, 20)
    per_size: int = param(2, 1, 5)         # fish eaten per size grown
    min_fish: int = param(6, 1, 12)        # fewer fish in the water than this: one more comes
    fast_share: float = param(0.3, 0, 1)   # share of fish swimming two cells a turn


class ProcgenBigfish(ShooterTask):
    title = "Procgen Bigfish"
    rules = ("You are a fish in {width}x{height} water. Other fish, drawn as the digit of their "
             "size (1 to {max_size}), swim straight across, one or two cells a turn, and leave at "
             "the far side; new ones keep coming from both sides. Touching a fish of your size or "
             "smaller eats it; touching a bigger one gets you eaten. You start at size 1 and grow "
             "by one size per {per_size} fish eaten; reaching size {max_size} wins.")
    rewards = "+{fish_reward} per fish eaten; {death} for being eaten."
    ends = "when you reach size {max_size} or are eaten"
    ACTIONS = ACTIONS
    Params = BigfishParams
    player_hits = FOE
    glyphs = {OPEN: "water", **{str(n): f"fish of size {n}" for n in range(1, MAX_SIZE + 1)},
              **PLAYER_GLYPHS}

    def prompt_fields(self) -> dict:
        goal = (MAX_SIZE - 1) * self.params.per_size
        return {**super().prompt_fields(), "fish_reward": round(1 / goal, 4), "max_size": MAX_SIZE,
                "death": DEATH}

    def _setup(self, rng: np.random.Generator) -> None:
        p = self.params
        self.start([OPEN * p.width] * p.height, (p.height // 2, p.width // 2))
        self.size, self.eaten = 1, 0
        self.goal = (MAX_SIZE - 1) * p.per_size
        self.spawner = Spawner(self.stream("fish"), int(rng.integers(2, 5)), 1)
        for _ in range(p.min_fish + int(rng.integers(0, 3))):   # the opening school, from the seed
            r = int(rng.integers(p.height))
            if r == self.player.r:
                continue
            self._fish(rng, r, int(rng.integers(p.width)))

    def _fish(self, rng: np.random.Generator, r: int, c: int, heading: int = 0) -> None:
        """A fish in row ``r`` at column ``c`` (a side's outer column when spawning), its size
        drawn from your size - 2 .. your size + 1 (within 1..6)."""
        p = self.params
        size = int(rng.integers(max(1, self.size - 2), min(MAX_SIZE, self.size + 1) + 1))
        heading = heading or (1 if rng.random() < 0.5 else -1)
        speed = 2 if rng.random() < p.fast_share else 1
        self.world.add(Body(str(size), r, c, 0, heading * speed, side=FOE, hp=size, edge=GONE))

    def _think(self) -> None:
        p, rng = self.params, self.spawner.rng
        if self.spawner.due(self.turn) or len(self.world.bodies) - 1 < p.min_fish:   # fish + you
            r, heading = int(rng.integers(p.height)), (1 if rng.random() < 0.5 else -1)
            edge = -1 if heading == 1 else p.width
            near = abs(self.player.c - edge) <= 6
            if not (r == self.player.r and near):        # never out of nowhere onto you
                self._fish(rng, r, edge, heading)

    def _hit(self, a: Body, b: Body | None) -> None:
        met = pair(a, b, PLAYER)
        if met is None:
            return
        fish = met[1]
        if fish.hp > self.size:
            self.reward(DEATH)
            self.say(f"A size {fish.hp} fish ate you.")
            self.finish(won=False)
            return
        fish.alive = False
        self.eaten += 1
        self.reward(1 / self.goal)
        grown = min(MAX_SIZE, 1 + self.eaten // self.params.per_size)
        if grown > self.size:
            self.size = grown
            self.say(f"You ate a size {fish.hp} fish and grew to size {grown}.")
        else:
            self.say(f"You ate a size {fish.hp} fish.")
        if self.eaten >= self.goal:
            self.say("You are full grown.")
            self.finish(won=True)

    def _extras(self) -> str:
        return f"Size {self.size} | Eaten {self.eaten}/{self.goal}"


register_variants(ProcgenBigfish, "Procgen", {"glyphbench/procgen-bigfish-v0": dict(max_turns=500)})
