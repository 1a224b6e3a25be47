"""Space Invaders: a cannon on the bottom row under a formation of invaders that slides side to
side, steps down at each edge (and on a timer) and drops bombs. FIRE sends one shot at a time
straight up; shields (Atari preset) soak up shots and bombs, a cell at a time. A cleared
formation is followed by a fresh one; invaders reaching the cannon's row end the game."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param, require
from .bodies import Formation, Gun
from .engine import EMPTY, ArcadeParams, ArcadeTask, register_arcade

CANNON, INVADER, SHOT, BOMB, SHIELD = "A", "M", "|", "!", "#"
ACTIONS = ActionSet([("NOOP", "hold still"), ("LEFT", "move one cell left"),
                     ("RIGHT", "move one cell right"), ("FIRE", "shoot straight up (one shot at a time)")],
                    noop="NOOP")
MOVES = (0, -1, 1, 0)
FIRE = 3


@dataclass(frozen=True)
class InvadersParams(ArcadeParams):
    width: int = param(14, 8, 60)
    height: int = param(12, 8, 40)
    goal: int = param(8, 1, 200)
    unit: float = param(0.125, 0, 100)
    rows: int = param(2, 1, 8)
    cols: int = param(4, 1, 16)
    sweep: int = param(5, 1, 20)          # turns per sideways step
    advance: int = param(24, 0, 200)      # turns per step down besides the edges (0: edges only)
    shot_speed: int = param(2, 1, 4)
    bomb_every: int = param(0, 0, 50)     # turns between bombs (0: no bombs)
    bombs: int = param(2, 1, 10)          # bombs falling at once at most
    shields: int = param(0, 0, 6)

    def check(self) -> None:
        require(2 * self.cols < self.width - 2, "cols", "fit the field two cells apart", self.cols)
        require(self.rows + 5 < self.height, "rows", "leave room to descend", self.rows)


class SpaceInvaders(ArcadeTask):
    title = "Space Invaders"
    rules = ("You are the cannon (A) on the bottom row of a {width}x{height} field, with "
             "{lives_text}. {rows}x{cols} invaders (M) slide one cell sideways every {sweep} turns "
             "and step down a row at each edge{advance_text}.{bomb_text}{shield_text} FIRE sends a "
             "shot (|) up {shot_speed} cells a turn, one shot at a time. A cleared formation is "
             "replaced by a new one. Invaders reaching your row end the game.")
    rewards = "+{unit} for each invader shot; {death} when the game is lost."
    ends = "when you have shot {goal} invaders or the game is lost"
    ACTIONS = ACTIONS
    Params = InvadersParams
    pattern = "D"
    glyphs = {EMPTY: "space", INVADER: "invader", SHIELD: "shield", SHOT: "your shot",
              BOMB: "bomb", CANNON: "you (the cannon)"}

    def prompt_fields(self) -> dict:
        p = self.params
        return {**super().prompt_fields(),
                "advance_text": f" and every {p.advance} turns" if p.advance else "",
                "bomb_text": (f" Every {p.bomb_every} turns the lowest invader of a random column "
                              f"drops a bomb (!) that falls a cell a turn; a bomb that hits you "
                              f"costs a life.") if p.bomb_every else "",
                "shield_text": (f" {p.shields} shields (#) above you absorb shots and bombs, "
                                "losing a cell to each.") if p.shields else ""}

    def _still(self) -> list[str]:
        p = self.params
        rows = [EMPTY * p.width] * p.height
        if p.shields:
            line = [EMPTY] * p.width
            span = p.width // p.shields
            for k in range(p.shields):
                mid = k * span + span // 2
                line[mid - 1:mid + 2] = SHIELD * 3
            rows[p.height - 3] = "".join(line)
        return rows

    def _setup(self, rng) -> None:
        self.start(rng)
        p = self.params
        self.col = p.width // 2
        self.gun = Gun(cooldown=1, speed=p.shot_speed, reach=p.height, limit=1)
        self.bombs = Gun(cooldown=max(1, p.bomb_every), speed=1, reach=p.height, limit=p.bombs)
        self.waves = 0
        self._wave()

    def _wave(self) -> None:
        p = self.params
        self.waves += 1
        self.wave = Formation(p.rows, p.cols, 1, 1, 2, p.width, p.sweep, p.advance)

    def _play(self, action: int) -> None:
        p = self.params
        if MOVES[action]:
            c = self.col + MOVES[action]
            self.col = 0 if c < 0 else c if c < p.width else p.width - 1
        elif action == FIRE:
            self.gun.fire(self.tick, p.height - 1, self.col, -1, 0, SHOT)
        self.wave.tick(self.tick)
        h = p.height
        if self.wave.bottom() >= h - 1:
            self.lives = 1
            self.lose_life("The invaders landed.")
            return
        wave, still = self.wave, self.still   # (shields change in place: still stays this list)

        gun = self.gun
        if gun.shots:   # (Gun.advance and sweep written out for shots flying straight up)
            speed, kept = gun.speed, []
            top, left, gap, alive = wave.top, wave.left, wave.gap, wave.alive
            for shot in gun.shots:
                r, c, cell = shot.r, shot.c, None
                for _ in range(speed):
                    r -= 1
                    if not 0 <= r < h or still[r][c] == SHIELD:   # off the field or a shield
                        cell = r, c
                        break
                    j, rem = divmod(c - left, gap)
                    if not rem and (r - top, j) in alive:        # an invader
                        cell = r, c
                        break
                    shot.r = r
                shot.data -= speed
                if cell is not None:
                    shot.alive = False
                    self._strike(cell)
                elif shot.data <= 0:
                    shot.alive = False
                else:
                    kept.append(shot)
            gun.shots = kept
        if p.bomb_every and self.wave.alive and self.bombs.ready_at(self.tick):
            front = self.wave.front()
            self.bombs.fire(self.tick, *front[self.draws.below(len(front))], 1, 0, BOMB)
        bombs = self.bombs
        if not bombs.shots:
            return
        # bombs.advance for bombs falling a cell a turn, inlined: a bomb stops on a shield, past
        # the field or on you (each seen to before the next one falls), else falls and, out of
        # reach, is gone; a last life lost leaves the bombs as they were, as there
        kept = []
        for bomb in bombs.shots:
            r, c = bomb.r + 1, bomb.c
            bomb.data -= 1
            if not r < h:
                bomb.alive = False
            elif still[r][c] == SHIELD:
                bomb.alive = False
                self.set_still(r, c, EMPTY)
            elif r == h - 1 and c == self.col:
                bomb.alive = False
                if self.lose_life("A bomb hit you."):
                    return
            else:
                bomb.r = r
                if bomb.data <= 0:
                    bomb.alive = False
                else:
                    kept.append(bomb)
        bombs.shots = kept

    def _strike(self, cell: tuple[int, int]) -> None:
        """Your shot stopped at ``cell``: an invader dies, or a shield loses the cell."""
        member = self.wave.member_at(*cell)
        if member is not None:
            self.wave.kill(member)
            self.say("Invader hit!")
            self.score.gain()
            if not self.wave.alive and not self.done:
                self._wave()
        elif 0 <= cell[0] < self.params.height and self.still[cell[0]][cell[1]] == SHIELD:
            self.set_still(*cell, EMPTY)

    def _respawn(self) -> None:
        self.bombs.shots = []
        self.col = self.params.width // 2

    def _rows(self) -> list[str]:
        return self.cached_rows((self.waves, self.wave.version), self._layer)

    def _layer(self) -> list[str]:
        rows = self.still[:]
        blank = EMPTY * self.params.width
        for r, line in self.wave.lines(INVADER, EMPTY).items():
            if 0 <= r < len(rows):
                rows[r] = line if rows[r] == blank else "".join(
                    a if a != EMPTY else b for a, b in zip(line, rows[r]))
        return rows

    def _grid(self) -> list[str]:
        """``_sprites`` drawn straight from the bodies, in the same order."""
        rows = self._rows()
        self._grids += 1
        if self.gun.shots:
            self._paint(rows, self.gun.shots, SHOT)
        if self.bombs.shots:
            self._paint(rows, self.bombs.shots, BOMB)
        r = self.params.height - 1   # (the cannon, always on the bottom row)
        key = (rows[r], self.col, CANNON)
        rows[r] = self._drawn.get(key) or self._draw(key)
        return rows

    def _sprites(self):
        out = [(s.r, s.c, SHOT) for s in self.gun.shots]
        out += [(b.r, b.c, BOMB) for b in self.bombs.shots]
        out.append((self.params.height - 1, self.col, CANNON))
        return out


register_arcade(SpaceInvaders, "spaceinvaders",
                mini=dict(max_turns=200),
                atari=dict(width=30, height=20, rows=5, cols=11, goal=55, unit=10.0, lives=3,
                           sweep=3, advance=0, bomb_every=4, bombs=3, shields=4, max_turns=10000))
