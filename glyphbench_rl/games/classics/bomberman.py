"""Bomberman: bomb your way through crates; kill the wandering enemies or find the hidden exit."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import ActionSet, GlyphTask, register_variants
from ...core.actions import directions
from ...core.params import param
from ..common.grid import DELTAS
from ..common.palette import FLOOR, GOAL, PLAYER, WALL
from ..common.waves import Enemy, Rolls, spawn_cells, wander

CRATE, BLAST, ENEMY = "▒", "*", "E"
START = (1, 1)
SAFE = {(1, 1), (1, 2), (2, 1)}   # never crates: from here one bomb always leaves a way out
BOMB, WAIT = 4, 5                 # action indices after the four moves


@dataclass(frozen=True)
class BombermanParams:
    size: int = param(11, 7, 15, odd=True)            # the arena with its outer wall is size x size
    crate_density: float = param(0.4, 0, 0.8, open_lo=True)   # chance that an open cell holds a crate
    min_enemies: int = param(1, 1, lambda p: p.max_enemies)   # the enemy count is drawn in min..max
    max_enemies: int = param(3, 1, 5)
    fuse: int = param(3, 2, 9)                        # your actions between placing a bomb and its explosion
    blast_range: int = param(2, 1, lambda p: p.fuse)  # cells the blast reaches in each direction
    enemy_speed: float = param(0.5, 0, 1, open_lo=True)   # chance that an enemy moves on a turn
    death_penalty: float = param(0.5, 0, 1)


class Bomberman(GlyphTask):
    title = "Bomberman"
    rules = ("The {size}x{size} arena has walls and crates. BOMB places a bomb on your cell (one "
             "at a time); it explodes after {fuse} more of your actions, its digit counting them "
             "down. The blast reaches {blast_range} cells up, down, left and right of the "
             "bomb; walls stop it, and it destroys the first crate on each side. It kills enemies "
             "and you. Nobody walks through walls, crates or bombs. {enemy_count} enemies wander at "
             "random, each moving on a turn with probability {enemy_speed:g}; touching one kills "
             "you. The exit is hidden under one crate. Each turn you act, then the bomb counts "
             "down or explodes, then enemies move.")
    rewards = ("killing enemies earns {kill_total:g} in all, split equally among them; killing the "
               "last one earns {win_reward:g} more, and so does reaching the exit; dying costs "
               "{death_penalty:g}.")
    ends = "when you kill every enemy, reach the exit or die"
    Params = BombermanParams
    ACTIONS = ActionSet(directions() + [("BOMB", "place a bomb on your cell"), ("WAIT", "stay put")])
    glyphs = {WALL: "wall", CRATE: "crate", FLOOR: "floor", GOAL: "exit", PLAYER: "you",
              ENEMY: "enemy", BLAST: "blast"}
    default_max_turns = 200
    KILL_TOTAL = 0.5
    WIN_REWARD = 0.5

    def _init(self) -> None:
        self._vocab = dict(self.glyphs) | {str(k): f"bomb going off in {k}" for k in range(1, self.params.fuse + 1)}

    def vocab(self):
        return self._vocab

    def prompt_fields(self) -> dict:
        p = self.params
        count = f"{p.min_enemies}" if p.min_enemies == p.max_enemies else f"{p.min_enemies} to {p.max_enemies}"
        return super().prompt_fields() | {"enemy_count": count, "kill_total": self.KILL_TOTAL,
                                          "win_reward": self.WIN_REWARD}

    # -- level ------------------------------------------------------------------------------------
    def _setup(self, rng: np.random.Generator) -> None:
        p, n = self.params, self.params.size
        self.rolls = Rolls(rng)
        self.tiles = [[WALL if r in (0, n - 1) or c in (0, n - 1) or (r % 2 == 0 and c % 2 == 0)
                       else FLOOR for c in range(n)] for r in range(n)]
        open_cells = [(r, c) for r in range(n) for c in range(n)
                      if self.tiles[r][c] == FLOOR and (r, c) not in SAFE]
        crates = [x for x, u in zip(open_cells, rng.random(len(open_cells)).tolist()) if u < p.crate_density]
        crate_set = set(crates)
        free = [x for x in open_cells if x not in crate_set]
        count = int(rng.integers(p.min_enemies, p.max_enemies + 1))
        self.enemies = [Enemy(r, c, heading=int(rng.integers(4)))
                        for r, c in spawn_cells(rng, free, count, START, n // 2 + 2)]
        if not crates:   # the exit needs a crate to hide under
            taken = {e.cell for e in self.enemies}
            crates = [x for x in free if x not in taken][-1:]
        for r, c in crates:
            self.tiles[r][c] = CRATE
        self._text = ["".join(row) for row in self.tiles]
        self.exit = spawn_cells(rng, crates, 1, START, n // 2 + 1)[0]
        self.exit_seen = False
        self.start_enemies = count
        self.player = START
        self.bomb: tuple[int, int] | None = None
        self.timer = 0
        self.blast: list[tuple[int, int]] = []

    def set_tile(self, r: int, c: int, tile: str) -> None:
        """Change a wall, crate or floor tile (explosions; tests build situations with it)."""
        self.tiles[r][c] = tile
        self._text[r] = "".join(self.tiles[r])

    def blast_cells(self, center: tuple[int, int]) -> list[tuple[int, int]]:
        """The cells a bomb at ``center`` reaches: the cross, cut by walls, ending at a crate."""
        cells = [center]
        for dr, dc in DELTAS:
            r, c = center
            for _ in range(self.params.blast_range):
                r, c = r + dr, c + dc
                tile = self.tiles[r][c]
                if tile == WALL:
                    break
                cells.append((r, c))
                if tile == CRATE:
                    break
        return cells

    def walkable(self, r: int, c: int) -> bool:
        """Open for walking: no wall, crate or bomb (the outer wall keeps indices in range)."""
        return self.tiles[r][c] == FLOOR and (r, c) != self.bomb

    # -- play --------------------------------------------------------------------------------------
    def _die(self, text: str) -> None:
        self.reward(-self.params.death_penalty)
        self.say(text)
        self.finish(won=False)

    def _act(self, action: int) -> None:
        self.blast = []
        if action == BOMB:
            if self.bomb is None:
                self.bomb, self.timer = self.player, self.params.fuse + 1   # ticks below this turn
            else:
                self.say("Your bomb is already lit.")
        elif action != WAIT:
            dr, dc = DELTAS[action]
            r, c = self.player[0] + dr, self.player[1] + dc
            if not self.walkable(r, c):
                self.say("Blocked.")
            elif any(e.r == r and e.c == c for e in self.enemies):
                self.player = (r, c)
                return self._die("You ran into an enemy.")
            else:
                self.player = (r, c)
                if self.exit_seen and self.player == self.exit:
                    self.reward(self.WIN_REWARD)
                    self.say("You reached the exit.")
                    return self.finish(won=True)
        if self.bomb is not None:
            self.timer -= 1
            if self.timer == 0:
                self._explode()
                if self.done:
                    return
        self._move_enemies()

    def _explode(self) -> None:
        self.blast = cells = self.blast_cells(self.bomb)
        self.bomb = None
        hit = set(cells)
        for r, c in cells:
            if self.tiles[r][c] == CRATE:
                self.set_tile(r, c, FLOOR)
                if (r, c) == self.exit:
                    self.exit_seen = True
                    self.say("The exit is revealed.")
        killed = [e for e in self.enemies if e.cell in hit]
        if killed:
            self.enemies = [e for e in self.enemies if e.cell not in hit]
            self.reward(self.KILL_TOTAL * len(killed) / self.start_enemies)
            self.say(f"Killed {len(killed)} enemy." if len(killed) == 1 else f"Killed {len(killed)} enemies.")
        if self.player in hit:
            return self._die("You were caught in the blast.")
        if not self.enemies:
            self.reward(self.WIN_REWARD)
            self.say("Every enemy is dead.")
            self.finish(won=True)

    def _move_enemies(self) -> None:
        tiles, bomb, rolls = self.tiles, self.bomb, self.rolls
        taken = {(e.r, e.c) for e in self.enemies}

        def open_(r: int, c: int) -> bool:
            return tiles[r][c] == FLOOR and (r, c) not in taken and (r, c) != bomb

        speed, player = self.params.enemy_speed, self.player
        for e in self.enemies:
            if rolls.next() >= speed:
                continue
            taken.discard((e.r, e.c))
            wander(e, open_, rolls.next(), rolls.next())
            taken.add((e.r, e.c))
            if e.r == player[0] and e.c == player[1]:
                return self._die("An enemy caught you.")

    def _grid(self) -> list[str]:
        out = self._text.copy()     # the tiles' rows, redrawn only where something covers them
        over = []                   # (row, col, glyph), later entries on top
        if self.exit_seen:
            over.append((*self.exit, GOAL))
        if self.bomb is not None:
            over.append((*self.bomb, str(self.timer)))
        over.extend((r, c, BLAST) for r, c in self.blast)
        over.extend((e.r, e.c, ENEMY) for e in self.enemies)
        over.append((*self.player, PLAYER))
        for r, c, ch in over:
            row = out[r]
            out[r] = row[:c] + ch + row[c + 1:]
        return out

    def _hud(self) -> str:
        bomb = "ready" if self.bomb is None else f"in {self.timer}"
        return f"Enemies {len(self.enemies)} | Bomb {bomb}"


register_variants(Bomberman, "Classics", {
    "glyphbench/classics-bomberman-v0": dict(size=11, max_turns=200),
})
