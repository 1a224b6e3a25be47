"""Side-view physics for the Procgen platformers (coinrun, jumper, ninja, climber).

Integer physics over ``games.common.physics``: each turn the player first moves one column
sideways (LEFT/RIGHT, in the air too: air control), then jumps if asked and able, then moves
``vy`` rows cell by cell (``move_vertical``: nothing tunnels), then gravity updates ``vy``
(``fall``). A jump sets ``vy = -JUMP_SPEED``; gravity adds ``GRAVITY`` a turn up to
``MAX_FALL``, so over flat ground a jump moves 2 up, 1 up, hang, 1 down, 2 down: three rows
high, five turns in the air. Only standing on something may you jump, unless a game grants air
jumps (jumper's double jump). Falling out of the bottom of the world kills; hazard cells
(spikes, saws) kill on touch; patrolling enemies walk a stretch back and forth, a pure function
of the turn, and kill on touch.

``advance(lines, state, action)`` is the player's step, pure: the game plays it and ``search``
(breadth-first over states ``(row, col, vy, air jumps left)`` and the turn modulo the patrol
period) uses it, so a path the search finds wins in the real game. Generators call
``PlatformTask._setup``'s loop: build, search, rebuild (seeded, bounded); tests replay
``task.solution()``.
"""

from __future__ import annotations

from collections import deque
from math import lcm
from typing import ClassVar, Iterable, Sequence

import numpy as np

from ...core.actions import ActionSet
from ..common.physics import fall, move_vertical
from .engine import ARROWS, MAX_MOVERS, OPEN, ProcgenTask, velocity_text

GROUND, PLATFORM, BREAKABLE, ENEMY, SHURIKEN = "#", "=", "B", "E", "-"
SOLID = frozenset(GROUND + PLATFORM + BREAKABLE)
JUMP_SPEED, GRAVITY, MAX_FALL = 2, 1, 2        # rows per turn, positive = down
TRIES = 40                                     # level draws before the game's easy level
SHURIKEN_SPEED = 2                             # columns per turn
VIEWS_KEPT = 4096                              # views (and HUD texts) kept per level, at most

VEL = {(vy, vx): "Vel " + velocity_text(vy, vx) for vy in range(-JUMP_SPEED, MAX_FALL + 1)
       for vx in (-1, 0, 1)}
STEP = {d: velocity_text(0, d) for d in range(-SHURIKEN_SPEED, SHURIKEN_SPEED + 1)}
_MOVER_TEXT: dict = {}            # (glyph, rows, columns, step) -> "E@+2,-3←1"
State = tuple[int, int, int, int]              # row, column, vy, air jumps left
Patrol = tuple[int, int, int, int]             # row, first column, last column, phase

_MOVES = [("NOOP", "stay (gravity still acts)"), ("LEFT", "move one column left"),
          ("RIGHT", "move one column right"), ("JUMP", "jump straight up"),
          ("JUMP_LEFT", "jump and move one column left"),
          ("JUMP_RIGHT", "jump and move one column right")]
ACTIONS = ActionSet(_MOVES, noop="NOOP")
THROW_ACTIONS = ActionSet(_MOVES + [("THROW", "throw a shuriken the way you last moved sideways")],
                          noop="NOOP")
THROW = 6
DX = (0, -1, 1, 0, -1, 1, 0)
JUMPS = (False, False, False, True, True, True, False)
FACING = (0, 1, 2, 3, 1, 2, 0)                 # the engine's arrow for each action (0: keep)


def advance(lines: Sequence[str], state: State, action: int, air_jumps: int = 0
            ) -> tuple[State, list[tuple[int, int]]]:
    """One turn of the player's physics; returns the new state and the cells entered in order.
    Columns outside the world and rows above it are solid; a row at or below ``len(lines)``
    means the player fell out of the world."""
    r, c, vy, air = state
    height = len(lines)
    passed = []
    grounded = vy >= 0 and r + 1 < height and lines[r + 1][c] in SOLID
    dx = DX[action]
    if dx and 0 <= c + dx < len(lines[0]) and lines[r][c + dx] not in SOLID:
        c += dx
        passed.append((r, c))
    if JUMPS[action]:
        if grounded:
            vy = -JUMP_SPEED
        elif air:
            vy, air = -JUMP_SPEED, air - 1
    if vy:
        r0, step, col = r, (1 if vy > 0 else -1), c
        r, stopped = move_vertical(r, vy, lambda y: y < 0 or (y < height and lines[y][col] in SOLID))
        passed += [(y, c) for y in range(r0 + step, r + step, step)]
        if stopped:
            vy = 0
    if r >= height:
        return (r, c, vy, air), passed
    if vy >= 0 and r + 1 < height and lines[r + 1][c] in SOLID:
        vy, air = 0, air_jumps
    else:
        vy = fall(vy, GRAVITY, MAX_FALL)
    return (r, c, vy, air), passed


def jump_arc() -> list[int]:
    """Rows moved each turn by a jump over flat ground (negative is up), from the constants."""
    lines = [OPEN] * 8 + [GROUND]
    state, arc = (7, 0, 0, 0), []
    for action in (3, *[0] * 10):
        nxt, _ = advance(lines, state, action)
        arc.append(nxt[0] - state[0])
        state = nxt
        if state[0] == 7:
            return arc
    raise AssertionError("a jump over flat ground never lands")


def patrol_col(patrol: Patrol, turn: int) -> int:
    """Column of a patroller after ``turn`` turns: it walks its stretch back and forth."""
    _, lo, hi, phase = patrol
    span = hi - lo
    if not span:
        return lo
    k = (turn + phase) % (2 * span)
    return lo + (k if k <= span else 2 * span - k)


def period_of(patrols: Iterable[Patrol]) -> int:
    return lcm(1, *(2 * (hi - lo) for _, lo, hi, _ in patrols if hi > lo))


def caught(start: tuple[int, int], end: tuple[int, int], passed: list, before: tuple[int, int],
           after: tuple[int, int]) -> bool:
    """Does an enemy moving ``before`` -> ``after`` touch a player moving ``start`` -> ``end``
    through ``passed`` (on ``after``, met on the way, or the two swapping cells)?"""
    return after == end or after in passed or (after == start and before in passed)


def search(lines: Sequence[str], start: State, goals: frozenset, *, air_jumps: int = 0,
           hazards: str = "", patrols: Sequence[Patrol] = (), turn: int = 0,
           n_actions: int = 6, limit: int = 400_000, memo: dict | None = None):
    """Breadth-first search over the player's states (and the turn modulo the patrol period):
    the shortest action list from ``start`` at ``turn`` that touches a cell of ``goals`` without
    falling, touching a hazard or being caught. Returns (actions or None, visited keys).

    The player's moves do not depend on the turn, so each state's distinct safe moves are
    worked out once (``advance`` per action) and reused at every turn of the period. ``memo``
    (``(state, action) -> advance(...)``, for this level) is read and filled."""
    height = len(lines)
    period = period_of(patrols)
    danger = []                      # per turn t: cells enemies enter at t + 1, and where from
    for t in range(period):
        came: dict = {}
        for p in patrols:
            came.setdefault((p[0], patrol_col(p, t + 1)), []).append((p[0], patrol_col(p, t)))
        danger.append((frozenset(came), came))
    moves: dict = {}
    memo = {} if memo is None else memo
    bad = frozenset((r, c) for r, line in enumerate(lines) for c, ch in enumerate(line)
                    if ch in hazards) if hazards else frozenset()
    key0 = (start, turn % period)
    parent: dict = {key0: None}
    queue = deque([key0])
    while queue and len(parent) < limit:
        key = queue.popleft()
        state, t = key
        options = moves.get(state)
        if options is None:
            options, kept = [], set()
            r, c, vy, air = state
            can_jump = air or vy >= 0 and r + 1 < height and lines[r + 1][c] in SOLID
            for action in range(n_actions if can_jump else 3):   # else a jump is a step
                got = memo.get((state, action))
                if got is None:
                    got = memo[state, action] = advance(lines, state, action, air_jumps)
                nxt, passed = got
                if nxt[0] >= height or (nxt, *passed) in kept:
                    continue
                kept.add((nxt, *passed))
                if bad and not bad.isdisjoint(passed):
                    continue
                won = not goals.isdisjoint(passed)
                options.append((action, nxt, passed, won))
            moves[state] = options
        t1 = t + 1
        p0 = state[:2]
        for action, nxt, passed, won in options:
            nkey = (nxt, t1 % period)
            if nkey in parent:
                continue
            if patrols:
                after, came = danger[t]
                end = nxt[:2]
                if (end in after or any(cell in after for cell in passed)
                        or (p0 in after and any(b in passed for b in came[p0]))):
                    continue
            parent[nkey] = (key, action)
            if won:
                path = []
                while parent[nkey] is not None:
                    nkey, action = parent[nkey]
                    path.append(action)
                return path[::-1], parent
            queue.append(nkey)
    return None, parent


class PlatformTask(ProcgenTask):
    """A side-view game: a still level (``rows`` as lists, ``_lines`` as strings), the player's
    physics state, patrollers and (ninja) shuriken. A game supplies ``_build(rng, easy)``
    (setting ``rows``, ``start``, ``goals``, ``patrols``), ``_touch(cell, ch)`` for its pickups,
    its HUD extras and its death penalty."""

    ACTIONS = ACTIONS
    air_jumps: ClassVar[int] = 0
    hazards: ClassVar[str] = ""
    death_penalty: ClassVar[float] = 0.0
    shows_motion = True

    rows: list[list[str]]
    start: tuple[int, int]
    goals: frozenset
    patrols: list[Patrol]
    proven = False

    def prompt_fields(self) -> dict:
        arc = jump_arc()
        words = ", ".join("hang" if d == 0 else f"{abs(d)} {'up' if d < 0 else 'down'}" for d in arc)
        n = self.air_jumps
        air = (", or once more in mid-air (restored on landing)" if n == 1 else
               f", or {n} more times in mid-air (restored on landing)" if n else "")
        rise = -sum(d for d in arc if d < 0)
        physics = (f"LEFT/RIGHT move you one column a turn, in the air too. You may jump only "
                   f"standing on something{air}; over flat ground a jump moves you {words} "
                   f"({rise} rows up and {len(arc)} turns in the air; vertical speed changes by "
                   f"{GRAVITY} a turn up to {MAX_FALL} down; Vel gives the rows you move next turn "
                   f"unless stopped, and your last sideways step). Solid cells stop you.")
        return {**super().prompt_fields(), "physics": physics}

    # -- level ------------------------------------------------------------------------------------
    def _build(self, rng: np.random.Generator, easy: bool) -> None:
        """Draw a level; set ``proven`` when the draw itself searched its way to the goal."""
        raise NotImplementedError

    def _setup(self, rng: np.random.Generator) -> None:
        for attempt in range(TRIES + 1):
            self._build(rng, easy=attempt == TRIES)
            self._lines = ["".join(row) for row in self.rows]
            self.height, self.width = len(self._lines), len(self._lines[0])
            self.state: State = (*self.start, 0, self.air_jumps)
            self.alive, self.clock = [True] * len(self.patrols), 0
            self._memo: dict = {}            # (state, action) -> advance(...) on this level
            self._still: tuple = (None, [])  # (view origin, the still rows there)
            self._at: tuple = (None, (0, 0))  # (player's cell, view origin)
            self._forget()
            if self.goals and (self.proven or self.solution() is not None):
                break
        else:
            raise AssertionError(f"{self.task_id}: the easy level is not winnable")
        self.place_player(self.start)
        self.clock = 0
        self.heading, self.vx, self.kills = 1, 0, 0
        self.stars: list[list[int]] = []      # shuriken in flight: [row, col, direction]
        self._tracks: list[tuple] | None = None   # per patrol: its entries over its period
        self._place_enemies()

    def _place_enemies(self) -> None:
        """The live enemies at the clock, once a turn: (index, row, column, column a turn ago,
        next step). Each patrol's entries over its period are worked out once."""
        if self._tracks is None or len(self._tracks) != len(self.patrols):   # (tests add some)
            self._tracks = []
            self._forget()
            for i, p in enumerate(self.patrols):
                n = max(1, 2 * (p[2] - p[1]))
                cols = [patrol_col(p, t) for t in range(n)]
                self._tracks.append(tuple((i, p[0], cols[k], cols[k - 1], cols[(k + 1) % n] - cols[k])
                                          for k in range(n)))
            self._period = lcm(1, *(len(track) for track in self._tracks))
        phase = self.clock % self._period
        enemies = self._enemies_at.get(phase)
        if enemies is None:
            t, alive = self.clock, self.alive
            enemies = self._enemies_at[phase] = [track[t % len(track)] for track in self._tracks
                                                 if alive[track[0][0]]]
        self.enemies = enemies           # (shared with the cache: never changed in place)
        self._phase = phase

    def _forget(self) -> None:
        """Drop what is worked out per turn of the patrols' period: the enemies, the views with
        them drawn, the HUD's movers. The enemies are a pure function of the clock modulo the
        period (while none dies), so each is worked out once per phase (and view or place)."""
        self._enemies_at: dict = {}          # phase -> live enemies
        self._views: dict = {}               # (top, left, phase) -> view rows with enemies
        self._moving: dict = {}              # (player's cell, phase) -> " | Moving: ..." or ""

    def solution(self) -> list[int] | None:
        """Actions that win from here (enemies included), by ``search``; None if none found."""
        patrols = [p for p, a in zip(self.patrols, self.alive) if a]
        path, _ = search(self._lines, self.state, self.goals, air_jumps=self.air_jumps,
                         hazards=self.hazards, patrols=patrols, turn=self.clock, memo=self._memo)
        return path

    def set_tile(self, r: int, c: int, ch: str) -> None:
        if ch in SOLID or self.rows[r][c] in SOLID:
            self._memo.clear()               # the physics changed
        self.rows[r][c] = ch
        self._lines[r] = "".join(self.rows[r])
        self._still = (None, [])
        self._views.clear()

    # -- turn -------------------------------------------------------------------------------------
    def _act(self, action: int) -> None:
        self.clock += 1                 # the patrols' clock (a forfeited turn moves nothing)
        if self.patrols:
            self._place_enemies()
        if action == THROW:
            self.stars.append([self.pos[0], self.pos[1], self.heading])
        start = self.pos
        got = self._memo.get((self.state, action))
        if got is None:
            got = self._memo[self.state, action] = advance(self._lines, self.state, action,
                                                           self.air_jumps)
        self.state, passed = got
        r, c = self.state[0], self.state[1]
        self.vx = c - start[1]
        if self.vx:
            self.heading = self.vx
        if FACING[action]:
            self.facing = FACING[action]
        if r >= self.height:
            self.pos = (self.height - 1, c)
            return self._die("You fell out of the world.")
        self.pos = (r, c)
        lines = self._lines
        for pr, pc in passed:
            ch = lines[pr][pc]
            if ch in self.hazards:
                return self._die("You touched a hazard.")
            if ch != OPEN:
                self._touch((pr, pc), ch)
                if self.done:
                    return
        if self.stars:
            self._fly()
        if self.enemies:                # (rows the player was on: only enemies there can touch)
            rows = {start[0], r, *[cell[0] for cell in passed]}
            for _, row, col, before, _ in self.enemies:
                if row in rows and caught(start, self.pos, passed, (row, before), (row, col)):
                    return self._die("An enemy got you.")

    def _touch(self, cell: tuple[int, int], ch: str) -> None:
        """The player entered a cell holding ``ch`` (a pickup or the goal)."""

    def _die(self, message: str) -> None:
        if self.death_penalty:
            self.reward(-self.death_penalty)
        self.say(message)
        self.finish(won=False)

    def _fly(self) -> None:
        """Shuriken fly ``SHURIKEN_SPEED`` columns a turn: a breakable wall breaks, an enemy
        dies, anything else solid or the world's edge stops them."""
        flying = []
        for star in self.stars:
            r, c, d = star
            for _ in range(SHURIKEN_SPEED):
                c += d
                if not 0 <= c < self.width:
                    break
                ch = self._lines[r][c]
                if ch == BREAKABLE:
                    for rr in range(self.height):
                        if self.rows[rr][c] == BREAKABLE:
                            self.set_tile(rr, c, OPEN)
                    self.say("Your shuriken broke a wall.")
                    break
                if ch in SOLID:
                    break
                hit = next((e for e in self.enemies if e[1] == r and c in (e[2], e[3])), None)
                if hit is not None:
                    self.alive[hit[0]] = False
                    self.enemies = [e for e in self.enemies if e is not hit]
                    self._forget()               # the patrols' cycle changed
                    self.kills += 1
                    self._kill()
                    break
            else:
                star[1] = c
                flying.append(star)
        self.stars = flying

    def _kill(self) -> None:
        """A shuriken killed an enemy (ninja pays for it)."""

    # -- drawing ----------------------------------------------------------------------------------
    def _rows(self) -> list[str]:
        return self._lines

    def _sprites(self):
        out = [(r, c, ENEMY) for _, r, c, _, _ in self.enemies]
        if self.stars:
            out += [(r, c, SHURIKEN) for r, c, _ in self.stars]
        return out

    def _velocity(self) -> tuple[int, int]:
        return self.state[2], self.vx

    def _origin(self) -> tuple[int, int]:
        """The view's top-left world cell (the engine's window, clamped to the world), worked
        out once per place of the player."""
        at, origin = self._at
        if at != self.pos:
            r, c = self.pos
            origin = (min(max(r - self.view_h // 2, 0), max(self.height - self.view_h, 0)),
                      min(max(c - self.view_w // 2, 0), max(self.width - self.view_w, 0)))
            self._at = self.pos, origin
        return origin

    def _grid(self) -> list[str]:
        """The engine's view, drawing only the sprites inside it (a test holds it to the
        engine's)."""
        top, left = self._origin()
        key = (top, left, self._phase)
        view = self._views.get(key)       # the enemies drawn: once per place and phase
        if view is None:
            view = self._draw(top, left, [(r, c, ENEMY) for _, r, c, _, _ in self.enemies])
            if len(self._views) >= VIEWS_KEPT:
                self._views.clear()
            self._views[key] = view
        if self.stars:                    # then shuriken, then the player, as _sprites orders
            view = self._draw_on(view, top, left, [(r, c, SHURIKEN) for r, c, _ in self.stars])
        else:
            view = list(view)
        r, k = self.pos[0] - top, self.pos[1] - left   # (the player is always in view)
        row = view[r]
        view[r] = row[:k] + ARROWS[self.facing] + row[k + 1:]
        return view

    def _draw(self, top: int, left: int, sprites) -> list[str]:
        """The still rows in view with ``sprites`` drawn on them (those inside it)."""
        bottom, right = top + self.view_h, left + self.view_w
        if self._still[0] != (top, left):         # the still rows in view, cut once per place
            self._still = (top, left), [row[left:right] for row in self._lines[top:bottom]]
        return self._draw_on(self._still[1], top, left, sprites)

    def _draw_on(self, view: list[str], top: int, left: int, sprites) -> list[str]:
        """A copy of ``view`` (whose top-left world cell is top, left) with ``sprites`` drawn."""
        bottom, right = top + self.view_h, left + self.view_w
        view = list(view)
        for r, c, ch in sprites:
            if top <= r < bottom and left <= c < right:
                row, k = view[r - top], c - left
                view[r - top] = row[:k] + ch + row[k + 1:]
        return view

    def _motion(self) -> str:
        """The engine's ``Vel ... | Moving: ...`` text, made quicker for things that move along
        rows only (a test holds it to the engine's)."""
        text = VEL[self.state[2], self.vx]
        if self.stars:
            return text + self._moving_text()
        key = (self.pos, self._phase)             # without shuriken: once per place and phase
        moving = self._moving.get(key)
        if moving is None:
            if len(self._moving) >= VIEWS_KEPT:
                self._moving.clear()
            moving = self._moving[key] = self._moving_text()
        return text + moving

    def _moving_text(self) -> str:
        """`` | Moving: ...`` for the movers in view, or ""."""
        r, c = self.pos
        top, left = self._origin()
        bottom, right = top + self.view_h, left + self.view_w
        seen = [(abs(mr - r) + abs(mc - c), mr - r, mc - c, ENEMY, vc)
                for _, mr, mc, _, vc in self.enemies
                if vc and top <= mr < bottom and left <= mc < right]
        if self.stars:
            seen += [(abs(mr - r) + abs(mc - c), mr - r, mc - c, SHURIKEN, d * SHURIKEN_SPEED)
                     for mr, mc, d in self.stars if top <= mr < bottom and left <= mc < right]
        seen.sort()
        if not seen:
            return ""
        names = _MOVER_TEXT
        out = []
        for _, dr, dc, ch, vc in seen[:MAX_MOVERS]:
            key = (ch, dr, dc, vc)
            name = names.get(key)
            if name is None:
                name = names[key] = f"{ch}@{dr:+d},{dc:+d}{STEP[vc]}"
            out.append(name)
        return " | Moving: " + " ".join(out)

    def _movers(self):
        out = [(ENEMY, r, c, 0, d) for _, r, c, _, d in self.enemies]
        if self.stars:
            out += [(SHURIKEN, r, c, 0, d * SHURIKEN_SPEED) for r, c, d in self.stars]
        return out


def ground_level(rng: np.random.Generator, width: int, height: int, *, lo: int, hi: int,
                 pits: int, pit_width: tuple[int, int], step: int, flat_start: int = 5,
                 flat_end: int = 6) -> tuple[list[list[str]], list[int | None]]:
    """A side-scroller's ground: the top row of ground per column (None over a pit), changing by
    up to ``step`` rows between stretches, between rows ``lo`` and ``hi``; flat at both ends."""
    tops: list[int | None] = []
    top = hi
    pit_cols = set()
    body = list(range(flat_start + 2, width - flat_end - 4))
    for c0 in sorted(rng.choice(body, size=min(pits, len(body) // 6), replace=False).tolist()):
        if not pit_cols & set(range(c0 - 4, c0 + 5)):
            pit_cols.update(range(c0, c0 + int(rng.integers(pit_width[0], pit_width[1] + 1))))
    run = 0
    for c in range(width):
        if c in pit_cols:
            tops.append(None)
            continue
        if flat_start <= c < width - flat_end and run <= 0:
            top = int(np.clip(top + rng.integers(-step, step + 1), lo, hi))
            run = int(rng.integers(3, 7))
        run -= 1
        tops.append(top)
    rows = [[OPEN] * width for _ in range(height)]
    for c, t in enumerate(tops):
        if t is not None:
            for r in range(t, height):
                rows[r][c] = GROUND
    return rows, tops


def flats(tops: Sequence[int | None], length: int, lo: int, hi: int) -> list[tuple[int, int]]:
    """Stretches (first column, top) of ``length`` equal ground tops within columns lo..hi."""
    out = []
    for c in range(lo, hi - length + 1):
        t = tops[c]
        if t is not None and all(tops[c + i] == t for i in range(length)):
            out.append((c, t))
    return out


def ground_patrols(rng: np.random.Generator, rows: Sequence[Sequence[str]],
                   tops: Sequence[int | None], count: int | None, lo: int, hi: int) -> list[Patrol]:
    """Enemies patrolling open stretches of flat ground between columns ``lo`` and ``hi``: one
    span (2 or 3 columns) for the level, up to ``count`` stretches drawn, each kept only if it
    is clear of the ones before; ``count`` None draws none (a game's easy level)."""
    span = int(rng.integers(2, 4))
    stretches = [(c, t) for c, t in flats(tops, span + 1, lo, hi)
                 if all(rows[t - 1][c + i] == OPEN for i in range(span + 1))]
    patrols: list[Patrol] = []
    if count is None:
        return patrols
    for i in rng.choice(len(stretches), min(count, len(stretches)), replace=False).tolist():
        c, t = stretches[i]
        if all(abs(c - q[1]) > span + 1 for q in patrols):
            patrols.append((t - 1, c, c + span, int(rng.integers(2 * span))))
    return patrols
