"""Procgen Dodgeball: a walled arena with inner walls and wandering enemies who throw balls at
you. THROW your own ball the way you face; hit every enemy and the exit opens; walk out.

As upstream, clearing the arena opens the exit (no endless waves). Enemies step every second
turn and throw only along a clear row or column, so a ball can be seen coming and side-stepped.
Built on the shooting engine (bodies, swept collisions, guns). A level is kept only if every
open cell (the exit's inner neighbour included) is connected."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import register_variants
from ...core.actions import ActionSet
from ...core.params import param
from ..common.grid import bfs_distances
from ..common.lanes import Draws
from ..common.palette import GOAL, WALL
from .engine import ACTIONS, DELTAS, OPEN, PLAYER_GLYPHS
from .shooting import FOE, FOE_SHOT, PLAYER, SHOT, Body, Gun, ShooterTask, pair

ENEMY, BALL, THEIR_BALL, CLOSED = "E", "*", "o", "X"
DEATH = -1.0
SIDESTEP = 3        # enemies throw from this far or farther
BALL_SPEED = 2      # your ball's cells a turn (an enemy's ball flies one)
THROW_ACTIONS = ActionSet([(a.name, a.description) for a in ACTIONS]
                          + [("THROW", "throw a ball the way you face")], noop="NOOP")


@dataclass(frozen=True)
class DodgeballParams:
    width: int = param(20, 10, 30)
    height: int = param(12, 8, 20)
    enemies: int = param(4, 1, 8)
    walls: int = param(4, 0, 10)            # inner wall segments
    reach: int = param(8, 2, 20)            # cells a ball flies (yours and theirs)
    cooldown: int = param(3, 1, 10)         # turns between your throws
    throw_chance: float = param(0.2, 0, 1)  # an enemy in line with you throws with this chance
    enemy_cooldown: int = param(6, 1, 20)
    hit_share: float = param(0.6, 0, 1)     # shared over the enemies; the exit pays the rest


class ProcgenDodgeball(ShooterTask):
    title = "Procgen Dodgeball"
    rules = ("A {width}x{height} walled arena holds {enemies} enemies (E) who wander, one step "
             "every second turn, and throw balls (o), one cell a turn, at you along a clear row or "
             "column from {sidestep} or more cells away. THROW sends your ball (*) the way you "
             "last moved (up before you move), {speed} cells a turn for {reach} cells, once every "
             "{cooldown} turns; a ball stops at a wall. Hit every enemy and the exit (X) opens; "
             "walk into it. An enemy or an enemy's ball touching you ends the game.")
    rewards = ("+{hit_reward} for each enemy hit, +{exit_reward} for leaving by the open exit, "
               "{death} for being hit or caught.")
    ends = "when you leave by the exit or are hit or caught"
    ACTIONS = THROW_ACTIONS
    Params = DodgeballParams
    solid = WALL + CLOSED
    player_hits = FOE | FOE_SHOT
    glyphs = {OPEN: "floor", WALL: "wall", CLOSED: "exit (closed until every enemy is hit)",
              GOAL: "exit (open)", ENEMY: "enemy", BALL: "your ball", THEIR_BALL: "enemy ball",
              **PLAYER_GLYPHS}

    def prompt_fields(self) -> dict:
        p = self.params
        return {**super().prompt_fields(), "hit_reward": round(p.hit_share / p.enemies, 4),
                "exit_reward": round(1 - p.hit_share, 4), "death": DEATH,
                "sidestep": SIDESTEP, "speed": BALL_SPEED}

    def _setup(self, rng: np.random.Generator) -> None:
        p = self.params
        while True:
            rows, exit_, start, spots = self._arena(rng)
            if spots is not None:
                break
        self.start(["".join(row) for row in rows], start,
                   Gun(BALL, BALL_SPEED, p.reach, p.cooldown, side=SHOT, hits=FOE))
        self.exit = exit_
        picks = rng.choice(len(spots), p.enemies, replace=False).tolist()
        self.enemies = [self.world.add(Body(ENEMY, *spots[i], side=FOE, data=0))   # data: the
                        for i in picks]                                          # turn it may throw
        rows = self.world.rows
        self.exits = {(r, c): [(dr, dc) for dr, dc in DELTAS[1:] if rows[r + dr][c + dc] == OPEN]
                      for r in range(1, p.height - 1) for c in range(1, p.width - 1)}
        # the enemies' per-turn draws: a Python generator seeded from the episode's stream
        self.left = p.enemies
        self.rng = Draws(self.stream("enemies"))

    def _arena(self, rng: np.random.Generator):
        """Border walls, inner wall segments, an exit in the border, the player's start, and
        the enemy spots (open cells at least 5 steps from the start), or None spots when the
        open cells are not all connected."""
        p, h, w = self.params, self.params.height, self.params.width
        rows = [[WALL] * w for _ in range(h)]
        for r in range(1, h - 1):
            rows[r][1:w - 1] = [OPEN] * (w - 2)
        for _ in range(p.walls):
            length = int(rng.integers(2, 5))
            if rng.random() < 0.5:
                r, c = int(rng.integers(2, h - 2)), int(rng.integers(2, w - 1 - length))
                for k in range(length):
                    rows[r][c + k] = WALL
            else:
                r, c = int(rng.integers(2, h - 1 - length)), int(rng.integers(2, w - 2))
                for k in range(length):
                    rows[r + k][c] = WALL
        side = int(rng.integers(4))
        if side < 2:
            c = int(rng.integers(1, w - 1))
            exit_, inner = ((0, c), (1, c)) if side == 0 else ((h - 1, c), (h - 2, c))
        else:
            r = int(rng.integers(1, h - 1))
            exit_, inner = ((r, 0), (r, 1)) if side == 2 else ((r, w - 1), (r, w - 2))
        rows[inner[0]][inner[1]] = OPEN
        rows[exit_[0]][exit_[1]] = CLOSED
        open_cells = [(r, c) for r in range(h) for c in range(w) if rows[r][c] == OPEN]
        start = open_cells[int(rng.integers(len(open_cells)))]
        dist = bfs_distances(start, lambda r, c: rows[r][c] == OPEN)
        if len(dist) != len(open_cells):
            return rows, exit_, start, None
        spots = [cell for cell, d in dist.items() if d >= 5]
        return rows, exit_, start, (spots if len(spots) >= p.enemies else None)

    # -- the turn ----------------------------------------------------------------------------------
    def _think(self) -> None:
        p, rng, world, me, turn = self.params, self.rng, self.world, self.player, self.turn
        enemies = self.enemies = [e for e in self.enemies if e.alive]
        taken = {(e.r, e.c) for e in enemies}
        for e in enemies:
            e.vr = e.vc = 0
            line = (e.r == me.r or e.c == me.c) and turn >= e.data and self._line(e, me)
            if line and rng.random() < p.throw_chance:
                e.data = turn + p.enemy_cooldown
                world.add(Body(THEIR_BALL, e.r, e.c, *line, side=FOE_SHOT, hits=PLAYER,
                               reach=p.reach))
            elif turn % 2 == 0:
                options = [(dr, dc) for dr, dc in self.exits[e.r, e.c]
                           if (e.r + dr, e.c + dc) not in taken]
                if options:
                    e.vr, e.vc = options[rng.below(len(options))]
                    taken.add((e.r + e.vr, e.c + e.vc))

    def _line(self, e: Body, me: Body) -> tuple[int, int] | None:
        """The unit step from ``e`` towards ``me`` along a clear row or column, at least
        ``SIDESTEP`` cells away (time to step aside) and within reach."""
        if e.r != me.r and e.c != me.c:
            return None
        dr, dc = (me.r > e.r) - (me.r < e.r), (me.c > e.c) - (me.c < e.c)
        far = abs(me.r - e.r) + abs(me.c - e.c)
        if not SIDESTEP <= far <= self.params.reach:
            return None
        rows = self.world.rows
        if any(rows[e.r + dr * k][e.c + dc * k] != OPEN for k in range(1, far)):
            return None
        return dr, dc

    def _hit(self, a: Body, b: Body | None) -> None:
        if b is None:                           # a ball at a wall stops there
            if a.glyph in (BALL, THEIR_BALL):
                a.alive = False
            return
        met = pair(a, b, PLAYER)
        if met is not None:
            self.reward(DEATH)
            self.say("An enemy caught you." if met[1].glyph == ENEMY else "A ball hit you.")
            self.finish(won=False)
            return
        met = pair(a, b, SHOT)
        if met is not None:
            ball, enemy = met
            ball.alive = enemy.alive = False
            self.left -= 1
            self.reward(self.params.hit_share / self.params.enemies)
            if self.left:
                self.say("You hit an enemy.")
            else:
                self.world.put(*self.exit, GOAL)
                self.say("You hit the last enemy: the exit is open.")

    def _after(self) -> None:
        if self.pos == self.exit:
            self.reward(1 - self.params.hit_share)
            self.say("You left the arena.")
            self.finish(won=True)

    def _extras(self) -> str:
        wait = self.gun.ready - self.turn - 1
        return f"Enemies {self.left} | Ball {'ready' if wait <= 0 else f'in {wait}'}"


register_variants(ProcgenDodgeball, "Procgen",
                  {"glyphbench/procgen-dodgeball-v0": dict(max_turns=500)})
