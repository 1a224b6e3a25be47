"""Wave Defense: a Space Invaders-style defender shoots down marching waves of invaders."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import ActionSet, GlyphTask, register_variants
from ...core.params import param
from ..common.palette import FLOOR
from ..common.waves import Enemy, Rolls, hit, march

DEFENDER, INVADER, ARMORED, SHOT, BOMB = "▲", "M", "W", "|", "!"
LEFT, RIGHT, SHOOT = 0, 1, 2      # action indices


@dataclass(frozen=True)
class WaveDefenseParams:
    width: int = param(9, 5, 26)
    height: int = param(10, 6, 20)
    target: int = param(15, 1, 99)           # invaders destroyed to win
    rows: int = param(2, 1, lambda p: min(4, p.height - 3))   # formation rows per wave, 3 rows left below it
    # formation columns per wave (every other column, with room to march)
    cols: int = param(4, 1, lambda p: (p.width - 1) // 2)
    fill: float = param(0.85, 0, 1, open_lo=True)   # chance that a formation slot holds an invader
    # wave w: an invader is armored (2 hits) with chance armor_step x (w-1)
    armor_step: float = param(0.25, 0, 1)
    march_period: int = param(2, 1, 9)       # the formation steps once every this many turns
    shot_speed: int = param(3, 1, 9)         # cells your shot climbs per turn
    fire_chance: float = param(0.2, 0, 1)    # chance per turn that an invader drops a bomb
    death_penalty: float = param(0.5, 0, 1)


class WaveDefense(GlyphTask):
    title = "Wave Defense"
    rules = ("You are the defender on the bottom row of a {width}x{height} field. Invaders march "
             "sideways one cell every {march_period} turns; when the formation would leave the "
             "field it steps one row down instead and turns around. SHOOT fires a shot straight up "
             "from your cell (one shot at a time); it climbs {shot_speed} cells per turn and stops "
             "at the first invader it hits. An invader takes one hit, an armored one two. Invaders "
             "drop bombs that fall one cell per turn. A new wave comes when one is destroyed. Each "
             "turn you act, your shot climbs, bombs fall, then invaders march and drop bombs.")
    rewards = ("+{kill_reward:.4g} per invader destroyed, {target} wins; being bombed or letting an "
               "invader reach the bottom row costs {death_penalty:g}.")
    ends = "when you destroy {target} invaders, a bomb hits you or an invader reaches the bottom row"
    Params = WaveDefenseParams
    ACTIONS = ActionSet([("LEFT", "move one cell left"), ("RIGHT", "move one cell right"),
                         ("SHOOT", "fire a shot up from your cell"), ("WAIT", "stay put")])
    glyphs = {FLOOR: "empty", DEFENDER: "you", INVADER: "invader", ARMORED: "armored invader",
              SHOT: "your shot", BOMB: "bomb"}
    default_max_turns = 300

    def prompt_fields(self) -> dict:
        return super().prompt_fields() | {"kill_reward": 1 / self.params.target}

    def _setup(self, rng: np.random.Generator) -> None:
        self.rng = rng
        self.rolls = Rolls(rng)
        self.x = self.params.width // 2
        self.shot: tuple[int, int] | None = None
        self.bombs: list[tuple[int, int]] = []
        self.kills = 0
        self.wave = 0
        self._spawn_wave()

    def _spawn_wave(self) -> None:
        p, rng = self.params, self.rng
        self.wave += 1
        armor = min(1.0, p.armor_step * (self.wave - 1))
        slots = p.rows * p.cols
        filled = rng.random(slots) < p.fill
        filled[int(rng.integers(slots))] = True   # never an empty wave
        tough = (rng.random(slots) < armor).tolist()
        left = int(rng.integers(2))               # formation starts in column 0 or 1
        self.enemies = [Enemy(1 + i // p.cols, left + 2 * (i % p.cols), hp=2 if tough[i] else 1)
                        for i in range(slots) if filled[i]]
        self.direction = 1
        self.clock = 0                            # turns since the formation last stepped

    # -- play --------------------------------------------------------------------------------------
    def _lose(self, text: str) -> None:
        self.reward(-self.params.death_penalty)
        self.say(text)
        self.finish(won=False)

    def _hit_at(self, r: int, c: int) -> bool:
        """Resolve the shot reaching (r, c): True when an invader there takes the hit."""
        for e in self.enemies:
            if e.r == r and e.c == c:
                self.shot = None
                if hit(e):
                    self.enemies.remove(e)
                    self.kills += 1
                    self.reward(1 / self.params.target)
                    self.say("Invader destroyed.")
                    if self.kills >= self.params.target:
                        self.say("Target reached.")
                        self.finish(won=True)
                else:
                    self.say("Armor hit.")
                return True
        return False

    def _act(self, action: int) -> None:
        p = self.params
        bottom = p.height - 1
        if action == LEFT or action == RIGHT:
            x = self.x + (1 if action == RIGHT else -1)
            if 0 <= x < p.width:
                self.x = x
        elif action == SHOOT:
            if self.shot is None:
                self.shot = (bottom, self.x)
            else:
                self.say("Your shot is still flying.")
        if self.shot is not None:                  # the shot climbs cell by cell
            r, c = self.shot
            for _ in range(p.shot_speed):
                r -= 1
                if r < 0:
                    self.shot = None
                    break
                if self._hit_at(r, c):
                    break
                self.shot = (r, c)
            if self.done:
                return
        falling = []
        for r, c in self.bombs:                    # bombs fall one cell
            if r + 1 < bottom:
                falling.append((r + 1, c))
            elif c == self.x:
                self.bombs = []
                return self._lose("A bomb hit you.")
        self.bombs = falling
        self.clock += 1
        if self.clock >= p.march_period and self.enemies:
            self.clock = 0
            self.direction, _ = march(self.enemies, p.width, self.direction)
            if self.shot is not None and self._hit_at(*self.shot) and self.done:
                return
            if any(e.r >= bottom for e in self.enemies):
                return self._lose("An invader reached the bottom row.")
        if not self.enemies:
            self.say(f"Wave {self.wave} destroyed.")
            self._spawn_wave()
        elif self.rolls.next() < p.fire_chance:
            lowest: dict[int, Enemy] = {}
            for e in self.enemies:
                if e.c not in lowest or e.r > lowest[e.c].r:
                    lowest[e.c] = e
            shooters = sorted(lowest)
            e = lowest[shooters[self.rolls.pick(len(shooters))]]
            self.bombs.append((e.r + 1, e.c))

    def _grid(self) -> list[str]:
        p = self.params
        out = [FLOOR * p.width] * p.height
        cover = [(r, c, BOMB) for r, c in self.bombs]
        if self.shot is not None:
            cover.append((*self.shot, SHOT))
        cover.extend((e.r, e.c, ARMORED if e.hp > 1 else INVADER) for e in self.enemies)
        cover.append((p.height - 1, self.x, DEFENDER))
        for r, c, ch in cover:
            out[r] = out[r][:c] + ch + out[r][c + 1:]
        return out

    def _hud(self) -> str:
        side = "right" if self.direction > 0 else "left"
        return (f"Kills {self.kills}/{self.params.target} | Wave {self.wave} | "
                f"March {side} in {self.params.march_period - self.clock}")


register_variants(WaveDefense, "Classics", {
    "glyphbench/classics-wavedefense-v0": dict(max_turns=300),
})
