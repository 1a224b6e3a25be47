"""Platformer: run and jump along a side-view level, over pits, collecting coins, to the flag."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import ActionSet, GlyphTask, register_variants
from ...core.params import param
from ..common.palette import FLOOR, PLAYER, WALL
from ..common.physics import fall, move_vertical
from ..common.view import overlay, signed, window

COIN, FLAG = "o", "⚑"
JUMP_SPEED, GRAVITY, MAX_FALL = 2, 1, 2   # rows per turn, positive = down
START_RUN, END_RUN = 4, 6                 # flat columns at each end of a level


@dataclass(frozen=True)
class PlatformerParams:
    length: int = param(48, 16, 200)         # columns in the level
    height: int = param(8, 7, 16)            # rows; the bottom two are ground
    view: int = param(14, 8, lambda p: p.length)   # columns shown
    coin_share: float = param(0.3, 0, 1, open_hi=True)   # of the return, split evenly over the level's coins
    fall_penalty: float = param(0.5, 0, 1)


class Platformer(GlyphTask):
    title = "Platformer"
    rules = ("A side view of a level {length} columns long; the view follows you. Walk with LEFT "
             "and RIGHT, one column per turn, in the air too. JUMP, only while standing on "
             "something, sets Vy to -{jump} (Vy in the status line is your vertical speed in rows "
             "per turn, positive = down); in the air gravity adds {gravity} to Vy each turn, up to "
             "+{max_fall}. You move sideways first, then by Vy; solid cells stop you. Falling into a "
             "pit is fatal. Pick up coins by touching them; reach the flag's column to finish.")
    rewards = ("+{flag_reward:g} for reaching the flag; coins share +{coin_share:g} evenly; falling "
               "costs {fall_penalty:g}.")
    ends = "when you reach the flag or fall into a pit"
    Params = PlatformerParams
    ACTIONS = ActionSet([("LEFT", "move one column left"), ("RIGHT", "move one column right"),
                         ("JUMP", "jump (while standing)"), ("WAIT", "do nothing")], noop="WAIT")
    glyphs = {FLOOR: "air", WALL: "solid ground", COIN: "coin", FLAG: "flag", PLAYER: "you"}
    default_max_turns = 150

    def prompt_fields(self) -> dict:
        return super().prompt_fields() | {"jump": JUMP_SPEED, "gravity": GRAVITY, "max_fall": MAX_FALL,
                                          "flag_reward": 1 - self.params.coin_share}

    # -- level -------------------------------------------------------------------------------------
    def _setup(self, rng: np.random.Generator) -> None:
        p = self.params
        h = p.height
        stand = h - 3                                     # the row you stand in on the ground
        flat = [FLOOR] * (h - 2) + [WALL, WALL]
        cols = [flat[:] for _ in range(START_RUN)]
        while len(cols) == START_RUN or len(cols) < p.length - END_RUN - 6:   # a segment <= 6 columns
            kind = int(rng.integers(4))
            if kind == 0:                                 # a pit 2 or 3 wide, a coin above it
                pit = [[FLOOR] * h for _ in range(int(rng.integers(2, 4)))]
                pit[0][stand - 3] = COIN
                cols.extend(pit)
            elif kind == 1:                               # a step 1 or 2 high, a coin on top
                top = stand - int(rng.integers(0, 2))
                for i in range(int(rng.integers(2, 4))):
                    col = [FLOOR] * top + [WALL] * (h - top)
                    if i == 0:
                        col[top - 2] = COIN
                    cols.append(col)
            elif kind == 2:                               # a floating platform, a coin on it
                for i in range(3):
                    col = flat[:]
                    col[stand - 2] = WALL
                    if i == 1:
                        col[stand - 3] = COIN
                    cols.append(col)
            else:                                         # open ground, a coin to jump for
                for i in range(int(rng.integers(2, 4))):
                    col = flat[:]
                    if i == 1:
                        col[stand - 2] = COIN
                    cols.append(col)
            cols.extend(flat[:] for _ in range(int(rng.integers(2, 4))))   # landing room
        cols.extend(flat[:] for _ in range(p.length - len(cols)))
        self.flag_col = p.length - 3
        cols[self.flag_col][stand] = FLAG
        self.level = ["".join(col[r] for col in cols) for r in range(h)]
        self.coins = sum(row.count(COIN) for row in self.level)   # at least one: length >= 16
        self.got = 0
        self.x, self.y, self.vy = 1, stand, 0

    def solid(self, r: int, c: int) -> bool:
        if r < 0:
            return True                                   # the top edge is a ceiling
        return r < self.params.height and self.level[r][c] == WALL

    # -- a turn --------------------------------------------------------------------------------------
    def advance(self, x: int, y: int, vy: int, action: int) -> tuple[int, int, int]:
        """(x, y, vy) after one turn; y >= height means fallen. Pure, for planners."""
        grounded = self.solid(y + 1, x)
        if action == 2 and grounded:
            vy = -JUMP_SPEED
        elif action < 2:
            nx = x + (1 if action == 1 else -1)
            if 0 <= nx < self.params.length and not self.solid(y, nx):
                x = nx
            vy = 0 if self.solid(y + 1, x) else fall(vy, GRAVITY, MAX_FALL)
        else:
            vy = 0 if grounded else fall(vy, GRAVITY, MAX_FALL)
        if vy:
            y, stopped = move_vertical(y, vy, lambda r: self.solid(r, x))
            if stopped or (vy > 0 and self.solid(y + 1, x)):   # bumped or landed
                vy = 0
        return x, y, vy

    def _act(self, action: int) -> None:
        p = self.params
        x, y, vy = self.advance(self.x, self.y, self.vy, action)
        lo, hi = sorted((self.y, min(y, p.height - 1)))
        for r in range(lo, hi + 1):      # every cell passed: the sideways step, then the column
            row = self.level[r]
            if row[x] == COIN:
                self.level[r] = row[:x] + FLOOR + row[x + 1:]
                self.got += 1
                self.reward(p.coin_share / self.coins)
                self.say("Coin!")
        self.x, self.y, self.vy = x, y, vy
        if y >= p.height:
            self.reward(-p.fall_penalty)
            self.say("You fell into a pit.")
            self.finish(won=False)
        elif x >= self.flag_col:
            self.reward(1 - p.coin_share)
            self.say("You reached the flag!")
            self.finish(won=True)

    def camera(self) -> int:
        p = self.params
        return min(max(0, self.x - p.view // 3), p.length - p.view)

    def _grid(self) -> list[str]:
        p = self.params
        left = self.camera()
        rows = window(self.level, 0, left, p.height, p.view)
        overlay(rows, self.y, self.x - left, PLAYER)
        return rows

    def _hud(self) -> str:
        hud = f"Coins {self.got}/{self.coins} | Vy {signed(self.vy)}"
        if self.flag_col >= self.camera() + self.params.view:
            hud += f" | Flag {self.flag_col - self.x} right"
        return hud


register_variants(Platformer, "Classics", {
    "glyphbench/classics-platformer-v0": dict(max_turns=150),
})
