"""Tower Defense: build towers beside a fixed path to stop waves of enemies walking along it."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import ActionSet, GlyphTask, cell_names, register_variants
from ...core.params import param, require
from ..common.palette import FLOOR
from ..common.waves import Enemy, covered_steps, spawn_schedule, volley, walk_path

PATH = "░"
HEIGHT, WIDTH = 7, 10
# The path's corners, from the entrance at the left edge to the way out at the right edge.
WAYPOINTS = ((1, 0), (1, 8), (3, 8), (3, 1), (5, 1), (5, 9))


def trace(waypoints: tuple[tuple[int, int], ...]) -> list[tuple[int, int]]:
    """Every cell of a path of straight segments between consecutive waypoints."""
    cells = [waypoints[0]]
    for (r0, c0), (r1, c1) in zip(waypoints, waypoints[1:]):
        dr, dc = (r1 > r0) - (r1 < r0), (c1 > c0) - (c1 < c0)
        r, c = r0, c0
        while (r, c) != (r1, c1):
            r, c = r + dr, c + dc
            cells.append((r, c))
    return cells


@dataclass(frozen=True)
class Tower:
    glyph: str
    cost: int
    reach: int     # Chebyshev range: the square of cells within reach
    damage: int
    splash: bool   # hits every enemy in reach, else only the one farthest along the path


TOWERS = {"ARROW": Tower("A", cost=5, reach=2, damage=1, splash=False),
          "CANNON": Tower("C", cost=9, reach=1, damage=2, splash=True)}


@dataclass(frozen=True)
class TowerDefenseParams:
    waves: int = param(5, 1, 9)
    lives: int = param(3, 1, 20)             # each enemy that walks off the end of the path costs one
    start_gold: int = param(5, 0, 99)
    bounty: int = param(1, 0, 9)             # gold per kill
    build_turns: int = param(5, 1, 20)       # turns before a wave starts by itself
    base_count: int = param(3, 1, 12)        # wave w has base_count + w enemies
    hp_growth: float = param(1.5, 0, None)   # wave w draws hit points in low .. low + hp_spread,
    hp_spread: int = param(2, 0, 8)          # low = 1 + floor(hp_growth * (w - 1))
    speed: int = param(2, 1, 3)              # path cells an enemy walks per turn
    loss_penalty: float = param(0.5, 0, 1)

    def check(self) -> None:
        require(1 + int(self.hp_growth * (self.waves - 1)) + self.hp_spread <= 9, "hp_growth",
                f"small enough to keep hit points at most 9 in wave {self.waves}", self.hp_growth)


class TowerDefense(GlyphTask):
    title = "Tower Defense"
    rules = ("Enemies enter the path at its left end and walk {speed} cells along it per turn; "
             "each one that walks off its right end costs a life. Build towers on non-path cells: "
             "{tower_text}. Each turn you act, towers fire, enemies move, then new ones enter. "
             "Wave w of {waves} brings {base_count}+w enemies with L to L+{hp_spread} hit points "
             "each, L = 1 + floor({hp_growth:g} x (w-1)); an enemy is drawn as its hit points. A "
             "wave starts {build_turns} turns after the last one is cleared, or when you START "
             "it. Each kill pays {bounty} gold.")
    rewards = "+{wave_reward:.4g} per wave cleared; losing every life costs {loss_penalty:g}."
    ends = "when all {waves} waves are cleared or your lives run out"
    Params = TowerDefenseParams
    glyphs = {FLOOR: "buildable", PATH: "path"} | {t.glyph: f"{name.lower()} tower" for name, t in TOWERS.items()} \
        | {str(k): f"enemy with {k} hit point{'s' * (k > 1)}" for k in range(1, 10)}
    axes = True
    default_max_turns = 200

    def _init(self) -> None:
        self.path = trace(WAYPOINTS)
        on_path = set(self.path)
        names = cell_names(HEIGHT, WIDTH)
        self.sites = [(divmod(i, WIDTH), name) for i, name in enumerate(names)
                      if divmod(i, WIDTH) not in on_path]
        self._blank = ["".join(PATH if (r, c) in on_path else FLOOR for c in range(WIDTH))
                       for r in range(HEIGHT)]

    def _make_actions(self) -> ActionSet:
        groups = [(f"build {kind.lower()} tower there ({t.cost} gold)",
                   [f"{kind}_{name}" for _, name in self.sites]) for kind, t in TOWERS.items()]
        # what each action index builds where (START and WAIT come first and build nothing)
        self.builds = [None, None] + [(t, cell) for t in TOWERS.values() for cell, _ in self.sites]
        return ActionSet([("START", "start the next wave now"), ("WAIT", "do nothing")], groups=groups)

    def prompt_fields(self) -> dict:
        text = "; ".join(f"{kind.lower()} tower {t.glyph} costs {t.cost} gold and each turn hits "
                         + ("every enemy" if t.splash else "the enemy farthest along the path")
                         + f" within {t.reach} cell{'s' * (t.reach > 1)} (diagonals too) for {t.damage}"
                         for kind, t in TOWERS.items())
        return super().prompt_fields() | {"tower_text": text, "wave_reward": 1 / self.params.waves}

    # -- play --------------------------------------------------------------------------------------
    def _setup(self, rng: np.random.Generator) -> None:
        p = self.params
        self.rng = rng
        self.towers: dict[tuple[int, int], Tower] = {}
        self.watch: list[list[tuple]] = [[] for _ in self.path]   # towers reaching each path cell
        self._base = self._blank.copy()                              # the rows with the towers
        self.enemies: list[Enemy] = []
        self.incoming: list[tuple[int, int]] = []   # (turn of the wave, hit points), in order
        self.gold, self.lives = p.start_gold, p.lives
        self.wave = 0              # waves started so far
        self.countdown = p.build_turns
        self.wave_turn = 0

    def _start_wave(self) -> None:
        p, rng = self.params, self.rng
        self.wave += 1
        count = p.base_count + self.wave
        low = 1 + int(p.hp_growth * (self.wave - 1))
        hps = rng.integers(low, low + p.hp_spread + 1, size=count).tolist()
        self.incoming = list(zip(spawn_schedule(rng, count, 1, 2), hps))
        self.wave_turn = 0
        self.countdown = 0
        self.say(f"Wave {self.wave} begins.")

    def _act(self, action: int) -> None:
        build = self.builds[action]
        if build is not None:
            tower, cell = build
            if cell in self.towers:
                self.say("That cell already has a tower.")
            elif self.gold < tower.cost:
                self.say("Not enough gold.")
            else:
                self.gold -= tower.cost
                self.towers[cell] = tower
                for i in covered_steps(self.path, cell, tower.reach):
                    self.watch[i].append((cell, tower.damage, tower.splash))
                r, c = cell
                self._base[r] = self._base[r][:c] + tower.glyph + self._base[r][c + 1:]
        elif action == 0:   # START
            if self.countdown:
                self._start_wave()
            else:
                self.say("A wave is already under way.")
        if self.countdown:
            self.countdown -= 1
            if self.countdown:
                return
            self._start_wave()
        if self.towers and self.enemies:
            self._fire()
        leaked = walk_path(self.enemies, self.path, self.params.speed)
        if leaked:
            self.lives -= len(leaked)
            self.enemies = [e for e in self.enemies if e.step < len(self.path)]
            self.say(f"{len(leaked)} got through.")
        if self.lives <= 0:
            self.reward(-self.params.loss_penalty)
            self.say("No lives left.")
            return self.finish(won=False)
        while self.incoming and self.incoming[0][0] <= self.wave_turn:
            r, c = self.path[0]
            self.enemies.append(Enemy(r, c, hp=self.incoming.pop(0)[1]))
        self.wave_turn += 1
        if not self.incoming and not self.enemies:
            self.reward(1 / self.params.waves)
            if self.wave == self.params.waves:
                self.say("Every wave is cleared.")
                return self.finish(won=True)
            self.say(f"Wave {self.wave} cleared.")
            self.countdown = self.params.build_turns

    def _fire(self) -> None:
        killed = volley(self.enemies, self.watch)   # enemies stay in entry order: farthest first
        if killed:
            self.enemies = [e for e in self.enemies if e.hp > 0]
            self.gold += self.params.bounty * killed
            self.say(f"Killed {killed}.")

    def _grid(self) -> list[str]:
        out = self._base.copy()
        for e in self.enemies:
            out[e.r] = out[e.r][:e.c] + str(e.hp) + out[e.r][e.c + 1:]
        return out

    def _hud(self) -> str:
        p = self.params
        status = f"Next wave in {self.countdown}" if self.countdown else f"Incoming {len(self.incoming)}"
        return f"Wave {self.wave}/{p.waves} | Lives {self.lives} | Gold {self.gold} | {status}"


register_variants(TowerDefense, "Classics", {
    "glyphbench/classics-towerdefense-v0": dict(waves=5, lives=3, start_gold=5, speed=2, max_turns=200),
})
