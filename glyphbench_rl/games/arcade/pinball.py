"""Pinball machinery (video pinball): each scoring event is a unit of the goal worth its own
native points (``Tally.award``).

The table is still rows whose glyphs say what a cell does (``Table``): walls and posts reflect
the ball, rails in the top corners turn it back down into the table, bumpers kick it away,
drop targets fall when struck (a whole bank pays a bonus and stands again), spinners and
rollovers score as the ball passes over them, and the bottom row's drains take it. Under it
all a ``PinBall`` moves a cell a turn with a ``lift``: rising, it loses a row of lift a turn
and falls once it is spent (gravity on a grid). ``Flipper``s on the flipper row swing a ball
resting on them up at an angle by the part struck; an idle flipper lets the ball roll down it
to its tip and off into the drain between them. ``Tilt`` counts nudges in a window::

    class Pinball(PinballTask):
        values = {BUMPER: 1, TARGET: 1, SPINNER: 1, ROLL: 1, "bank": 10}   # units per event
        def _still(self): ...                    # the table's rows, from the parameters
        def _flippers(self): ...                 # [left, right]
        def _setup(self, rng): self.open_table(rng)
        def _play(self, action):
            self.flip(left=action == 1, right=action == 2)
            if action == 3: self.nudge()
            self.roll(action != 0)               # one ball step: plunger, scores, drains, lives
"""

from __future__ import annotations

from .duel import Ball, deflect, velocity_text
from .engine import EMPTY, ArcadeTask

WALL, TOP, POST = "|", "-", "#"
RAIL_L, RAIL_R = "(", ")"        # top corners: send the ball down and inward
BUMPER, TARGET, SPINNER = "O", "T", "S"
ROLL, LIT = "R", "r"             # a rollover before and after the ball passed over it
DRAIN = "v"
FLIP_L, FLIP_R, FLIP_UP = "\\", "/", "="
PASSING = {SPINNER: "spinner", ROLL: "rollover", LIT: "rollover"}
RAILS = {RAIL_L: (1, 1), RAIL_R: (1, -1)}
HUDS: dict[tuple, str] = {}       # the extra HUD text per (state, nudges), made once


class PinBall(Ball):
    """A ball with ``lift``: the rows it still rises before gravity turns it down."""
    __slots__ = ("lift",)

    def __init__(self, r: int, c: int) -> None:
        super().__init__(r, c)
        self.lift = 0


class Flipper:
    """A flipper on ``row`` over columns ``lo..hi``; ``side`` -1 (left: its tip at ``hi``) or
    +1 (right: its tip at ``lo``). ``up`` while pressed this turn."""
    __slots__ = ("row", "lo", "hi", "side", "up")

    def __init__(self, row: int, lo: int, hi: int, side: int) -> None:
        self.row, self.lo, self.hi, self.side, self.up = row, lo, hi, side, False

    def covers(self, c: int) -> bool:
        return self.lo <= c <= self.hi

    def strike(self, c: int) -> int:
        """The ball's sideways velocity off the flipper struck in column ``c``: toward its own
        side off the base, straight up off the middle, across the table off the tip."""
        size = self.hi - self.lo + 1
        if self.side < 0:
            return deflect(c - self.lo, size)
        return -deflect(self.hi - c, size)

    @property
    def roll(self) -> int:
        """The way a ball rolls down the idle flipper (toward its tip)."""
        return -self.side


class Tilt:
    """More than ``limit`` nudges within ``window`` turns tilt the table until ``clear()``."""
    __slots__ = ("limit", "window", "times", "tilted")

    def __init__(self, limit: int, window: int) -> None:
        self.limit, self.window, self.times, self.tilted = limit, window, [], False

    def nudge(self, tick: int) -> bool:
        self.times = [t for t in self.times if tick - t < self.window] + [tick]
        if len(self.times) > self.limit:
            self.tilted = True
        return self.tilted

    def recent(self, tick: int) -> int:
        return sum(1 for t in self.times if tick - t < self.window)

    def clear(self) -> None:
        self.times, self.tilted = [], False


class PinballTask(ArcadeTask):
    """A pinball table: ``_still()`` gives the rows (walls, rails, bumpers, targets,
    spinners, rollovers, drains, the flipper row's cells empty); the game's ``values`` say
    what each scores (units of ``unit``: bumper, target, bank, spinner, rollover). Params the
    engine reads: ``kick`` (lift off a flipper or the plunger), ``bump`` (off a bumper),
    ``autolaunch``, ``nudges`` and ``window`` (tilt), ``balls`` (the most balls held)."""
    values: dict[str, int] = {}

    def open_table(self, rng) -> None:
        """Call first in ``_setup``: the score, the table, its flippers and a ball on the plunger."""
        self.start(rng)
        p = self.params
        self.frow = p.height - 2
        self.flippers = self._flippers()
        self.banks = self._banks()
        self.rolls = [(r, c) for r, row in enumerate(self.still) for c, ch in enumerate(row) if ch == ROLL]
        self.lane = p.width - 2
        self.tilt = Tilt(p.nudges, p.window)
        self.ball = PinBall(0, 0)
        self.rollovers = 0
        self._respawn()

    def _flippers(self) -> list[Flipper]:
        raise NotImplementedError

    def _banks(self) -> list[list[tuple[int, int]]]:
        """The drop-target banks: lists of (row, col) cells, each standing at the start."""
        return []

    def _respawn(self) -> None:
        b = self.ball
        b.r, b.c, b.dr, b.dc, b.lift = self.frow, self.lane, 0, 0, 0
        self.held, self.waited = True, 0
        self.tilt.clear()

    # -- the player's hands ----------------------------------------------------------------
    def flip(self, left: bool, right: bool) -> None:
        dead = self.tilt.tilted
        self.flippers[0].up = left and not dead
        self.flippers[1].up = right and not dead

    def nudge(self) -> None:
        """Shake the table: a ball in flight reverses its sideways motion (one falling straight
        is shoved toward the side it is on)."""
        if self.tilt.nudge(self.tick):
            self.say("TILT! The flippers are dead until the ball drains.")
        b = self.ball
        if self.held or b.dr == 0:
            return
        b.dc = -b.dc if b.dc else (-1 if 2 * b.c < self.lane else 1)

    def launch(self) -> None:
        b = self.ball
        self.held, b.dr, b.dc, b.lift = False, -1, 0, self.frow

    # -- the ball --------------------------------------------------------------------------
    def roll(self, pressed: bool) -> None:
        """One turn of the ball (``pressed``: any action but NOOP, which fires the plunger)."""
        if self.held:
            self.waited += 1
            if pressed or self.waited >= self.params.autolaunch:
                self.launch()
            return
        b = self.ball
        if b.r == self.frow - 1 and b.dr >= 0 and self._on_flipper(b):
            return
        if b.dr < 0:
            b.lift -= 1
            if b.lift <= 0:
                b.dr = 1
        r, c = b.r + b.dr, b.c + b.dc
        if r >= len(self.still) - 1:
            self.lose_life("The ball drained.")
            return
        ch = self.still[r][c]
        if ch == EMPTY:
            b.r, b.c = r, c
        elif ch in PASSING:
            b.r, b.c = r, c
            self._pass(ch, r, c)
        elif ch in RAILS:
            b.dr, b.dc = RAILS[ch]
        else:
            self._strike(ch, r, c)

    def _on_flipper(self, b: PinBall) -> bool:
        """A ball just above the flipper row: swung up by a raised flipper, else rolling down
        an idle one toward its tip (and off it to fall). False when no flipper is under it."""
        for f in self.flippers:
            if f.covers(b.c):
                if f.up:
                    b.dr, b.dc = -1, f.strike(b.c)
                    b.lift = self.params.kick - self.draws.below(4)   # a flip is never quite the same
                    b.r -= 1
                else:
                    b.dr, b.dc = 0, f.roll
                    b.c += f.roll
                    if not f.covers(b.c):
                        b.dr, b.dc = 1, 0
                return True
        if b.dr == 0:
            b.dr, b.dc = 1, 0
        return False

    def _solid(self, r: int, c: int) -> bool:
        ch = self.still[r][c]
        return ch != EMPTY and ch != DRAIN and ch not in PASSING

    def _strike(self, ch: str, r: int, c: int) -> None:
        """The ball meets a solid cell: it reflects off the blocked axes (a bumper kicks it
        away with fresh lift, a target drops), staying where it is this turn unless it glances
        off a wall beside it, when it slides on a row."""
        b = self.ball
        down = b.dr > 0
        vert, side = self._solid(r, b.c), b.dc and self._solid(b.r, c)
        if vert or not side:
            b.dr = -b.dr
        if side or not vert:
            b.dc = -b.dc
        if side and not vert:   # along a wall: slide on down (or up) beside it
            b.r += b.dr
            if b.r >= len(self.still) - 1:
                self.lose_life("The ball drained.")
                return
            ch2 = self.still[b.r][b.c]
            if ch2 in PASSING:
                self._pass(ch2, b.r, b.c)
        if down and b.dr < 0:   # off a floor: a small bounce
            b.lift = 2
            if not b.dc:   # roll off it rather than bounce in place
                b.dc = 1 if self.draws.random() < 0.5 else -1
        if ch == BUMPER:
            if not b.dc:
                b.dc = 1 if self.draws.random() < 0.5 else -1
            if b.dr < 0:
                b.lift = self.params.bump
            self._score(BUMPER, "Bumper!")
        elif ch == TARGET:
            self._drop(r, c)

    def _pass(self, ch: str, r: int, c: int) -> None:
        if ch == SPINNER:
            self._score(SPINNER, "The spinner spins.")
            return
        self._score(ROLL, "Rollover.")
        if ch == ROLL and not self.tilt.tilted:
            self.set_still(r, c, LIT)
            if all(self.still[i][j] == LIT for i, j in self.rolls):
                for i, j in self.rolls:
                    self.set_still(i, j, ROLL)
                if self.lives < self.params.balls:
                    self.lives += 1
                    self.say("All rollovers lit: an extra ball!")

    def _drop(self, r: int, c: int) -> None:
        self.set_still(r, c, EMPTY)
        self._score(TARGET, "A drop target falls.")
        for bank in self.banks:
            if (r, c) in bank and all(self.still[i][j] == EMPTY for i, j in bank):
                for i, j in bank:
                    self.set_still(i, j, TARGET)
                self._score("bank", "The bank is down: bonus! The targets stand again.")

    def _score(self, what: str, text: str) -> None:
        if not self.tilt.tilted and not self.done:
            self.score.award(self.values[what])
            self.say(text)

    # -- drawing ---------------------------------------------------------------------------
    def _rows(self) -> list[str]:
        left, right = self.flippers
        return self.cached_rows((left.up, right.up), self._flipper_rows)

    def _flipper_rows(self) -> list[str]:
        rows = self.still[:]
        line = list(rows[self.frow])
        for f in self.flippers:
            glyph = FLIP_UP if f.up else (FLIP_L if f.side < 0 else FLIP_R)
            for c in range(f.lo, f.hi + 1):
                line[c] = glyph
        rows[self.frow] = "".join(line)
        return rows

    def _extra_hud(self) -> str:
        tick, tilt, b = self.tick, self.tilt, self.ball
        state = "TILT" if tilt.tilted else "Plunger" if self.held else ""
        nudges = tilt.recent(tick) if tilt.times and tick - tilt.times[-1] < tilt.window else 0
        key = (state, nudges, tilt.limit, b.dr, b.dc)
        text = HUDS.get(key)
        if text is None:
            parts = [state] if state else []
            if not self.held:
                parts.append(velocity_text(b))
            if nudges:
                parts.append(f"Nudges {nudges}/{tilt.limit}")
            text = HUDS[key] = " | ".join(parts)
        return text
