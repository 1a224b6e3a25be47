"""Fixed-bottom shooters: a cannon on a row near the bottom (or on fixed lanes, or fixed
turrets), shots straight up with a cooldown, enemies that descend in packs and waves, and
bombs that fall on the cannon.

A game derives its Params from ``ShooterParams`` and its task from ``Shooter``::

    class Demons(Shooter):
        def _setup(self, rng):
            self.arm(rng)                          # start(), the cannon, its gun, the bombs
            self.pack = Pack()                     # the enemies: Bodies with a glyph
        def _play(self, action):
            self.steer(action)                     # LEFT/RIGHT (lane to lane), FIRE
            for body, cell in self.volley(self.pack.at):   # shots that hit an enemy
                self.pack.kill(body); self.score.gain()
            if self.rain():                        # bombs fall; True when one hit the cannon
                self.lose_life("A bomb hit you.")

``_sprites`` draws the pack, your shots, the bombs and the cannon. Action ids are fixed:
0 NOOP, 1 LEFT, 2 RIGHT, 3 FIRE (games may append more after them).
"""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param
from .bodies import Body, Gun, sweep
from .engine import ArcadeParams, ArcadeTask

NOOP, LEFT, RIGHT, FIRE = 0, 1, 2, 3
CANNON, SHOT, BOMB = "A", "|", "!"
BASE_ACTIONS = [("NOOP", "hold still"), ("LEFT", "move one cell left"),
                ("RIGHT", "move one cell right"), ("FIRE", "shoot straight up")]


def shooter_actions(*extra: tuple[str, str], left: str = "move one cell left",
                    right: str = "move one cell right") -> ActionSet:
    """NOOP, LEFT, RIGHT, FIRE (ids 0-3) and the game's own actions after them."""
    base = [BASE_ACTIONS[0], ("LEFT", left), ("RIGHT", right), BASE_ACTIONS[3]]
    return ActionSet(base + list(extra), noop="NOOP")


@dataclass(frozen=True)
class ShooterParams(ArcadeParams):
    cooldown: int = param(1, 1, 20)       # turns between your shots
    shot_speed: int = param(2, 1, 4)      # cells a shot climbs a turn
    shots: int = param(1, 1, 4)           # your shots in flight at once at most
    bomb_chance: float = param(0.0, 0, 1)  # chance a turn that an enemy drops a bomb
    bombs: int = param(2, 1, 10)          # bombs falling at once at most


class Pack:
    """The enemies on the field: a few Bodies (glyph, data free for the game). Few enough that
    a scan beats an index."""
    __slots__ = ("bodies",)

    def __init__(self) -> None:
        self.bodies: list[Body] = []

    def add(self, r: int, c: int, glyph: str, dr: int = 0, dc: int = 0, data=None) -> Body:
        b = Body(r, c, dr, dc, glyph, data)
        self.bodies.append(b)
        return b

    def at(self, r: int, c: int) -> Body | None:
        for b in self.bodies:
            if b.c == c and b.r == r:   # (columns first: a formation shares its rows)
                return b
        return None

    def kill(self, body: Body) -> None:
        body.alive = False
        self.bodies.remove(body)

    def lowest(self) -> int:
        bodies = self.bodies
        if not bodies:
            return -1
        low = bodies[0].r
        for b in bodies:   # (a loop: a generator costs more than the few bodies)
            if b.r > low:
                low = b.r
        return low

    def __len__(self) -> int:
        return len(self.bodies)


def per(n: int, what: str) -> str:
    """'a cell a turn' style counts: ``per(1, "cell")`` is "a cell", ``per(3, "cell")`` "3 cells"."""
    return f"a {what}" if n == 1 else f"{n} {what}s"


def march(bodies: list[Body], dx: int, lo: int, hi: int, down: bool) -> int:
    """Move a formation (``bodies``) ``dx`` sideways together; at an edge (``lo``/``hi``) it
    turns and steps down instead, as it also does when ``down``. The new ``dx`` comes back."""
    if not bodies:
        return dx
    cs = [b.c for b in bodies]
    if min(cs) + dx < lo or max(cs) + dx > hi:
        dx, down = -dx, True
    else:
        for b in bodies:
            b.c += dx
    if down:
        for b in bodies:
            b.r += 1
    return dx


def bounce(body: Body, lo: int, hi: int) -> None:
    """Move ``body`` one step sideways, turning back at ``lo``/``hi``."""
    c = body.c + body.dc
    if c < lo or c > hi:
        body.dc = -body.dc
        c = body.c + body.dc
    body.c = c


class Shooter(ArcadeTask):
    Params = ShooterParams
    ACTIONS = shooter_actions()
    lanes: tuple[int, ...] | None = None   # the columns the cannon may stand on (None: all)
    cannon = CANNON

    def prompt_fields(self) -> dict:
        p = self.params
        many = "one shot at a time" if p.shots == 1 else f"at most {p.shots} shots in flight"
        wait = f", one every {p.cooldown} turns" if p.cooldown > 1 else ""
        death = self.pattern == "D" and p.death
        return {**super().prompt_fields(), "death_text": f"; {p.death:g} when the game is lost" if death else "",
                "gun_text": f"FIRE sends a shot (|) up {per(p.shot_speed, 'cell')} a turn, {many}{wait}."}

    def arm(self, rng, row: int | None = None) -> None:
        """Call first in ``_setup``: ``start``, the cannon (middle of the row), gun and bombs."""
        self.start(rng)
        p = self.params
        self.row = p.height - 1 if row is None else row
        self.lane_list = self._lanes()
        self.col = self.lane_list[len(self.lane_list) // 2] if self.lane_list else p.width // 2
        self.gun = Gun(cooldown=p.cooldown, speed=p.shot_speed, reach=p.height, limit=p.shots)
        self.bombs = Gun(cooldown=0, speed=1, reach=p.height, limit=p.bombs)
        self.pack = Pack()
        # _blocks, or None where the game keeps the default (nothing blocks: no call per cell)
        self._blocking = None if type(self)._blocks is Shooter._blocks else self._blocks

    def _lanes(self) -> list[int] | None:
        return list(self.lanes) if self.lanes else None

    def steer(self, action: int) -> None:
        """LEFT/RIGHT move a cell (or hop to the next lane); FIRE shoots up from the cannon."""
        if action == LEFT or action == RIGHT:
            step = -1 if action == LEFT else 1
            lanes = self.lane_list
            if lanes:
                i = lanes.index(self.col) + step
                if 0 <= i < len(lanes):
                    self.col = lanes[i]
            else:
                self.col = min(self.params.width - 1, max(0, self.col + step))
        elif action == FIRE:
            self.gun.fire(self.tick, self.row, self.col, -1, 0, SHOT)

    def volley(self, at=None) -> list[tuple[Body, tuple[int, int]]]:
        """Move your shots; (enemy, cell) for each that hit one of ``at(r, c)`` (the pack's by
        default; a shot leaving the field or hitting ``_blocks`` is gone)."""
        gun = self.gun
        if not gun.shots:
            return []
        blocks = self._blocking
        speed = gun.speed
        hits, kept = [], []
        foe = None
        if at is None:   # the pack holds still while shots fly: index it by cell once
            lanes: set[int] | None = set()   # the columns straight shots fly up (None: any)
            for shot in gun.shots:
                if shot.dc:
                    lanes = None
                    break
                lanes.add(shot.c)
            cells: dict[tuple[int, int], Body] = {}
            for b in reversed(self.pack.bodies):   # (reversed: the first body on a cell wins, as in at)
                if lanes is None or b.c in lanes:
                    cells[b.r, b.c] = b
            find = cells.get
            # nothing but enemies stops a straight shot: they are found without a call a cell
            direct = find if blocks is None and lanes is not None else None

            def stops(r: int, c: int) -> bool:   # remembers the enemy it found for the hit below
                nonlocal foe
                if r < 0:
                    return True
                foe = find((r, c))
                return foe is not None or (blocks is not None and blocks(r, c))
        else:
            direct = None

            def stops(r: int, c: int) -> bool:   # as above, asking ``at``
                nonlocal foe
                if r < 0:
                    return True
                foe = at(r, c)
                return foe is not None or (blocks is not None and blocks(r, c))

        # Gun.advance's loop, inlined with sweep's for the usual shot (straight up): each shot
        # moves and its hit is dealt with before the next one moves, as there
        for shot in gun.shots:
            if shot.dr == -1 and not shot.dc:
                cell, r, c = None, shot.r, shot.c
                if direct is not None:
                    for _ in range(speed):
                        r -= 1
                        if r < 0 or (foe := direct((r, c))) is not None:
                            cell = r, c
                            break
                        shot.r = r
                else:
                    for _ in range(speed):
                        r -= 1
                        if stops(r, c):
                            cell = r, c
                            break
                        shot.r = r
            else:
                cell = sweep(shot, stops, speed) if (shot.dr or shot.dc) else None
            shot.data -= speed
            if cell is not None:
                shot.alive = False
                if cell[0] >= 0:
                    if foe is not None:
                        hits.append((foe, cell))
                    else:
                        self._struck(*cell)
            elif shot.data <= 0:
                shot.alive = False
            else:
                kept.append(shot)
        gun.shots = kept
        return hits

    def shoot_down(self, say: str, at=None) -> list | None:
        """``volley``, then kill, announce and score (a unit each) every enemy hit; the (enemy,
        cell) hits come back, or None when one of them won the game."""
        hits = self.volley(at)
        for foe, _ in hits:
            self.pack.kill(foe)
            self.say(say)
            self.score.gain()
            if self.done:
                return None
        return hits

    def _blocks(self, r: int, c: int) -> bool:
        """A still cell that stops shots and bombs (shields, mushrooms); none by default."""
        return False

    def _struck(self, r: int, c: int) -> None:
        """A shot or a bomb stopped on a blocking cell (``_blocks``)."""

    def drop(self, r: int, c: int) -> None:
        """An enemy at (r, c) drops a bomb, if fewer than ``bombs`` are falling."""
        self.bombs.fire(self.tick, r, c, 1, 0, BOMB)

    def maybe_drop(self) -> None:
        """With chance ``bomb_chance``, a random enemy drops a bomb."""
        p = self.params
        if self.pack.bodies and p.bomb_chance and self.draws.random() < p.bomb_chance:
            b = self.pack.bodies[self.draws.below(len(self.pack.bodies))]
            self.drop(b.r, b.c)

    def rain(self) -> bool:
        """Bombs fall a cell; True when one reached the cannon (the bomb is gone)."""
        bombs = self.bombs
        if not bombs.shots:
            return False
        hit = False
        row, col, h = self.row, self.col, self.params.height
        blocks = self._blocking

        def stops(r: int, c: int) -> bool:   # past the bottom, on you or on a blocking cell
            return r >= h or (r == row and c == col) or (blocks is not None and blocks(r, c))

        # Gun.advance's loop, inlined with sweep's for the usual bomb (a cell down a turn): each
        # bomb's stop is dealt with before the next one falls, as there
        speed, kept = bombs.speed, []
        for bomb in bombs.shots:
            if speed == 1 and bomb.dr == 1 and not bomb.dc:
                r, c = bomb.r + 1, bomb.c
                if r >= h or (r == row and c == col) or (blocks is not None and blocks(r, c)):   # stops
                    cell = r, c
                else:
                    bomb.r, cell = r, None
            else:
                cell = sweep(bomb, stops, speed) if (bomb.dr or bomb.dc) else None
            bomb.data -= speed
            if cell is not None:
                bomb.alive = False
                if cell[0] < h:
                    if cell[0] == row and cell[1] == col:
                        hit = True
                    else:
                        self._struck(*cell)
            elif bomb.data <= 0:
                bomb.alive = False
            else:
                kept.append(bomb)
        bombs.shots = kept
        return hit

    def touches(self) -> bool:
        """An enemy on the cannon's cell."""
        return self.pack.at(self.row, self.col) is not None

    def _respawn(self) -> None:
        self.bombs.shots = []

    def _sprites(self):
        out = [(b.r, b.c, b.glyph) for b in self.pack.bodies]
        out += [(s.r, s.c, SHOT) for s in self.gun.shots]
        out += [(b.r, b.c, BOMB) for b in self.bombs.shots]
        out.append((self.row, self.col, self.cannon))
        return out

    def _grid(self) -> list[str]:
        """``_sprites`` drawn straight from the bodies (no list of tuples), in the same order;
        a game that draws other sprites goes through ``ArcadeTask._grid``."""
        if type(self)._sprites is not Shooter._sprites:
            return super()._grid()
        rows = self._rows() if self._slides else self.still[:]
        self._grids += 1
        paint = self._paint
        paint(rows, self.pack.bodies)
        if self.gun.shots:
            paint(rows, self.gun.shots, SHOT)
        if self.bombs.shots:
            paint(rows, self.bombs.shots, BOMB)
        self._put(rows, self.row, self.col, self.cannon)
        return rows
