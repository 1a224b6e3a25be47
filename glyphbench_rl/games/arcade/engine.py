"""ArcadeTask: what every arcade game (MiniAtari and Atari presets) shares.

One game class, one Params dataclass (derived from ``ArcadeParams``), two presets::

    @dataclass(frozen=True)
    class PongParams(ArcadeParams):
        paddle: int = param(3, 1, 8)

    class Pong(ArcadeTask):
        Params, ACTIONS, glyphs = PongParams, ACTIONS, {...}
        pattern = "C"                      # "A", "B", "C" or "D": picks self.score's rule

        def _setup(self, rng):
            self.start(rng)                # lives, score rule, draws, still rows
            ...                            # place the movers
        def _sprites(self):                # (row, col, glyph) of every mover, drawn last wins
            yield self.ball.r, self.ball.c, "o"
        def _play(self, action):           # one tick; self.tick counts ticks (forfeits excluded)
            ... self.score.point(True)     # C: +unit, first to goal wins
            ... if self.lose_life(): return    # D/A: a life lost; True when none are left

    register_arcade(Pong, "pong", mini=dict(goal=3, unit=1/3, max_turns=200),
                    atari=dict(width=34, height=18, goal=21, unit=1.0, max_turns=5000))

``register_arcade`` registers ``glyphbench/miniatari-pong-v0`` (suite MiniAtari, standard tier)
and ``glyphbench/atari-pong-v0`` (suite Atari, extended tier) and refuses a mini preset whose
rule could leave [-1, 1] (so the base clamp never engages). The field is ``self.still`` (row
strings, the background, built by ``_still()`` and cached; change it with ``set_still``; a game
whose rows slide overrides ``_rows()``) with the ``_sprites()`` drawn on top. The HUD is the score
rule's text (``Score 2/5`` on mini presets, native points then ``k/N`` on Atari ones), then
``Lives n`` where more than one life was given, then ``_extra_hud()``.

Score rules (specs section 0), ``self.score`` after ``start``:
- ``Tally`` (A, and D with ``death``): +unit per credited unit, capped at ``goal`` (won there);
  ``award(value)`` credits a unit worth ``value`` units, ``bonus(points)`` pays native points
  that count toward no unit (Atari presets);
- ``Milestones`` (B): ``reach(key)`` pays ``unit x share`` once per key;
- ``Duel`` (C): ``point(mine)`` pays +unit or -unit; first side to ``goal`` ends the episode.
Lives: ``lose_life()`` takes one; the last one pays ``death`` (pattern D; 0 for A) and ends the
episode lost, else the game respawns (``_respawn()``). Per-turn randomness: ``self.draws`` (a
``Draws`` over the episode's "arcade" stream; never numpy per call).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar, Iterable

import numpy as np

from ...core import GlyphTask, register_variants
from ...core.params import param
from ..common.lanes import Draws

EMPTY = "."
EPS = 1e-9
DRAWN = 2048   # rows with a mover drawn in that a task remembers (see ArcadeTask._draw)
NONE_DRAWN: dict = {}   # a task's ``_drawn`` while it remembers no rows (see ``_keep``): never filled


@dataclass(frozen=True)
class ArcadeParams:
    width: int = param(14, 6, 80)
    height: int = param(10, 5, 40)
    lives: int = param(1, 1, 9)
    goal: int = param(4, 1, 1000)          # N: units (or points in a duel) that win
    unit: float = param(0.25, 0, 1000)     # reward per unit
    death: float = param(-1.0, -1000, 0)   # paid when the last life is lost (0: pattern A)


class Tally:
    """Patterns A and D: a monotone credited counter capped at ``goal``. ``shown`` is the HUD
    text the task last drew for it, None once the score changed (so it is formatted only then)."""
    __slots__ = ("task", "goal", "unit", "done", "points", "shown")

    def __init__(self, task: "ArcadeTask", goal: int, unit: float) -> None:
        self.task, self.goal, self.unit, self.done, self.points = task, goal, unit, 0, 0.0
        self.shown: str | None = None

    def gain(self, k: int = 1) -> None:
        k = min(k, self.goal - self.done)
        if k > 0:
            self.shown = None
            self.done += k
            self.points += k * self.unit
            self.task.reward(k * self.unit)
            if self.done >= self.goal:
                self.task.finish(won=True)

    def award(self, value: float = 1) -> None:
        """One unit worth ``value`` x ``unit`` (events of different native worth: a bumper, a
        bank of targets, a shark shot deeper)."""
        if self.done < self.goal:
            self.shown = None
            self.done += 1
            pay = value * self.unit
            self.points += pay
            self.task.reward(pay)
            if self.done >= self.goal:
                self.task.finish(won=True)

    def bonus(self, points: float) -> None:
        """Native points that count toward no unit (a critter shot, a key taken, the power left
        at a rescue): paid and shown in the score at once."""
        if points:
            self.shown = None
            self.points += points
            self.task.reward(points)

    def hud(self, native: bool) -> str:
        return f"Score {self.points:g} ({self.done}/{self.goal})" if native else f"Score {self.done}/{self.goal}"


class Milestones(Tally):
    """Pattern B: ``reach(key, share)`` pays ``share`` of ``goal x unit`` once per key; shares
    are the game's to keep summing to at most 1. ``done`` counts keys; the last ``goal``-th
    key wins."""
    __slots__ = ("keys",)

    def __init__(self, task: "ArcadeTask", goal: int, unit: float) -> None:
        super().__init__(task, goal, unit)
        self.keys: set = set()

    def reach(self, key, share: float) -> None:
        if key not in self.keys and self.done < self.goal:
            self.shown = None
            self.keys.add(key)
            pay = share * self.goal * self.unit
            self.points += pay
            self.task.reward(pay)
            self.done += 1
            if self.done >= self.goal:
                self.task.finish(won=True)


class Duel:
    """Pattern C: +unit per own point, -unit per opponent point; first to ``goal`` ends it."""
    __slots__ = ("task", "goal", "unit", "mine", "theirs", "shown")

    def __init__(self, task: "ArcadeTask", goal: int, unit: float) -> None:
        self.task, self.goal, self.unit, self.mine, self.theirs = task, goal, unit, 0, 0
        self.shown: str | None = None   # as Tally's

    def point(self, mine: bool) -> None:
        self.shown = None
        if mine:
            self.mine += 1
            self.task.reward(self.unit)
        else:
            self.theirs += 1
            self.task.reward(-self.unit)
        if self.mine >= self.goal or self.theirs >= self.goal:
            self.task.finish(won=self.mine >= self.goal)

    def hud(self, native: bool) -> str:
        return f"Score {self.mine}-{self.theirs}/{self.goal}"


RULES = {"A": Tally, "B": Milestones, "C": Duel, "D": Tally}


def bound(pattern: str, p: ArcadeParams) -> tuple[float, float]:
    """The lowest and highest return a preset's rule can pay."""
    top = p.goal * p.unit
    if pattern == "C":
        return -top, top
    return (p.death if pattern == "D" else 0.0), top


class ArcadeTask(GlyphTask):
    Params: ClassVar[type] = ArcadeParams
    pattern: ClassVar[str] = "A"
    default_max_turns = 200
    _extra: ClassVar[bool] = False   # set per game class: it overrides _extra_hud (cleared on
    # the task in ``_setup`` where its preset never adds anything: no call a turn)

    _slides: ClassVar[bool] = False   # set per game class: it overrides _rows
    inside: ClassVar[bool] = False    # every sprite is always inside the rows (``_grid`` tests none)

    def __init_subclass__(cls, **kwargs) -> None:
        super().__init_subclass__(**kwargs)
        cls._extra = cls._extra_hud is not ArcadeTask._extra_hud
        cls._slides = cls._rows is not ArcadeTask._rows

    def prompt_fields(self) -> dict:
        p = self.params
        unit = round(p.unit, 4)
        return {**super().prompt_fields(), "unit": int(unit) if unit == int(unit) else unit, "lives_text":
                "one life" if p.lives == 1 else f"{p.lives} lives"}

    def start(self, rng: np.random.Generator) -> None:
        """Call first in ``_setup``: the score rule, lives, the per-turn draws, the still rows."""
        p = self.params
        self.native = self.tier != "standard"
        self.score = RULES[self.pattern](self, p.goal, p.unit)
        self.lives = p.lives
        self._head_lives = -1             # the lives the remembered HUD head shows
        self._tail = None                 # the _extra_hud text the remembered HUD ends with
        self.draws = Draws(self.stream("arcade"))
        self.tick = 0
        self.still_version = 0            # bumped by set_still, for games caching rows over it
        self._layers: dict = {}
        self._layers_of = 0               # the still_version the remembered layers were drawn on
        if "_drawn" not in self.__dict__:   # kept across episodes: the same rows come back
            self._drawn, self._grids, self._drawn_from = {}, 0, 0
        self.still = self._still()

    def _still(self) -> list[str]:
        """The background rows; empty cells by default."""
        return [EMPTY * self.params.width] * self.params.height

    def set_still(self, r: int, c: int, ch: str) -> None:
        row = self.still[r]
        self.still[r] = row[:c] + ch + row[c + 1:]
        self.still_version += 1

    def lose_life(self, why: str = "You lost a life.") -> bool:
        """Take a life; True (and the episode ends lost, paying ``death`` in pattern D) when it
        was the last, else ``_respawn()`` runs and False comes back."""
        self.lives -= 1
        if self.lives <= 0:
            if self.pattern == "D":
                self.reward(self.params.death)
            self.say(why)
            self.finish(won=False)
            return True
        self.say(f"{why} {self.lives} left.")
        self._respawn()
        return False

    def _act(self, action: int) -> None:
        self.tick += 1
        self._play(action)

    def _play(self, action: int) -> None:
        """One tick of the game; time it by ``self.tick`` (a forfeit turn is no tick)."""
        raise NotImplementedError

    def _respawn(self) -> None:
        """Put the player back after a life lost (games with lives override it)."""

    def _sprites(self) -> Iterable[tuple[int, int, str]]:
        """(row, col, glyph) of every mover, drawn in order (a list is fastest); keep it to the
        few things that move, and draw blocks (formations, lanes) as whole rows in ``_rows``."""
        return ()

    def _extra_hud(self) -> str:
        return ""

    def _rows(self) -> list[str]:
        """This turn's rows under the movers: the still rows (a copy), or rows that slide."""
        return self.still[:]

    def cached_rows(self, key, build) -> list[str]:
        """A copy of the rows ``build()`` made for ``key`` (the state of the slow movers drawn
        into whole rows: paddles, a formation), remembered (up to 256 keys) until the still
        rows change."""
        if self._layers_of != self.still_version or len(self._layers) >= 256:
            self._layers, self._layers_of = {}, self.still_version
        rows = self._layers.get(key)
        if rows is None:
            rows = self._layers[key] = build()
        return rows[:]

    def _grid(self) -> list[str]:
        rows = self._rows() if self._slides else self.still[:]
        self._grids += 1
        drawn = self._drawn
        if self.inside:
            for r, c, g in self._sprites():
                key = (rows[r], c, g)
                rows[r] = drawn.get(key) or self._draw(key)
            return rows
        h = len(rows)
        for r, c, g in self._sprites():   # a few movers: one cell each into its row
            if 0 <= r < h:
                line = rows[r]
                if 0 <= c < len(line):
                    if drawn is NONE_DRAWN:
                        rows[r] = line[:c] + g + line[c + 1:]
                    else:
                        key = (line, c, g)
                        rows[r] = drawn.get(key) or self._draw(key)
        return rows

    def _paint(self, rows: list[str], bodies, glyph: str | None = None) -> None:
        """Draw ``bodies`` (anything with ``r``, ``c`` and ``glyph``) on ``rows`` in order, each
        as ``glyph`` or its own, as ``_grid`` draws sprites, for games whose ``_grid`` draws
        their bodies straight (no tuple per mover; count the grid: ``_grids += 1``)."""
        inside = range(len(rows))
        drawn = self._drawn
        if drawn is NONE_DRAWN:   # (rows too varied to remember: drawn afresh)
            for b in bodies:
                r, c = b.r, b.c
                if r in inside:
                    line = rows[r]
                    if 0 <= c < len(line):
                        rows[r] = line[:c] + (glyph or b.glyph) + line[c + 1:]
            return
        get = drawn.get
        for b in bodies:
            r = b.r
            if r in inside:
                line = rows[r]
                key = (line, b.c, glyph or b.glyph)
                row = get(key)
                if row is None:
                    if not 0 <= key[1] < len(line):
                        continue
                    row = self._draw(key)
                rows[r] = row

    def _put(self, rows: list[str], r: int, c: int, g: str) -> None:
        """Draw one mover, glyph ``g`` at (r, c), on ``rows`` as ``_grid`` draws a sprite."""
        if 0 <= r < len(rows):
            line = rows[r]
            drawn = self._drawn
            if drawn is NONE_DRAWN:
                if 0 <= c < len(line):
                    rows[r] = line[:c] + g + line[c + 1:]
                return
            key = (line, c, g)
            row = drawn.get(key)
            if row is None:
                if not 0 <= c < len(line):
                    return
                row = self._draw(key)
            rows[r] = row

    def _draw(self, key: tuple[str, int, str]) -> str:
        """The row ``line`` with glyph ``g`` in column ``c`` (``key``), remembered: a mover over
        a still background makes the same few rows again and again, and finding one costs less
        than making it. A task that makes new rows at more than one a grid (a sliding or filling
        background) stops remembering them (``_drawn`` is then ``NONE_DRAWN``).

        A ``_grid`` that draws its movers straight (no tuple per mover, no bounds test: they
        stay inside the rows) counts the grid and puts glyph ``g`` in column ``c`` of row ``r``
        through the memo, a lookup costing half the slicing::

            self._grids += 1
            drawn = self._drawn
            key = (rows[r], c, g)
            rows[r] = drawn.get(key) or self._draw(key)
        """
        line, c, g = key
        return self._keep(key, line[:c] + g + line[c + 1:])

    def _keep(self, key: tuple, row: str) -> str:
        drawn = self._drawn
        if drawn is not NONE_DRAWN:
            if len(drawn) >= DRAWN:
                if self._grids - self._drawn_from < DRAWN:
                    self._drawn = NONE_DRAWN
                    return row
                drawn.clear()
                self._drawn_from = self._grids
            drawn[key] = row
        return row

    def _hud(self) -> str:
        score = self.score
        if score.shown is None or self.lives != self._head_lives:   # the head changes rarely
            score.shown = score.hud(self.native)
            self._head_lives = self.lives
            self._head = (f"{score.shown} | Lives {self.lives}" if self.params.lives > 1
                          else score.shown)
            self._tail = None
        if not self._extra:   # (the game adds nothing: no call)
            return self._head
        extra = self._extra_hud()
        if not extra:
            return self._head
        if extra != self._tail:   # (an equal text, remade or kept, costs a compare, not a join)
            self._tail, self._hud_text = extra, f"{self._head} | {extra}"
        return self._hud_text


def register_arcade(game: type, name: str, *, mini: dict, atari: dict) -> None:
    """Register ``glyphbench/miniatari-<name>-v0`` (MiniAtari, standard) and
    ``glyphbench/atari-<name>-v0`` (Atari, extended) from one game and two presets (each a dict
    of parameters plus ``max_turns``). The mini preset's rule must keep the return in [-1, 1]."""
    params = {k: v for k, v in mini.items() if k != "max_turns"}
    lo, hi = bound(game.pattern, game.Params(**params))
    if lo < -1 - EPS or hi > 1 + EPS:
        raise ValueError(f"miniatari-{name}: its rule pays within [{lo}, {hi}], not [-1, 1]")
    register_variants(game, "MiniAtari", {f"glyphbench/miniatari-{name}-v0": mini})
    register_atari(game, name, **atari)


def register_atari(game: type, name: str, **atari) -> None:
    """Register only ``glyphbench/atari-<name>-v0`` (Atari, extended tier): a game without a
    MiniAtari twin (``atari`` as ``register_arcade``'s)."""
    register_variants(game, "Atari", {f"glyphbench/atari-{name}-v0": atari}, tier="extended")
