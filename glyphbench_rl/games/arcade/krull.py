"""Krull: Prince Colwyn's quest in three stages, each its own screen. At the wedding, Slayers
storm the field; some come for you, some for Princess Lyssa, and a Slayer that reaches her
carries her off. Fight them off with the glaive, which FIRE throws the way you face and which
flies back to your hand, cutting down Slayers on the way out and back. Then the Fire Mares carry
you across the Iron Desert's swamps in leaps of two cells to the Black Fortress's door; landing
in a swamp drowns you. In the fortress the Beast hunts you through the halls; the glaive only
stuns it; reach Lyssa, its prisoner. Kept from the original: the three stages in order, the
Slayers and the kidnap of Lyssa, the returning glaive, the Fire Mares' leaps, the fortress and
the Beast, three lives. Not kept: the day and night cycle, the Widow of the Web and the Emerald
Seer."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.params import param
from ..common.grid import DELTAS, bfs_search
from .arena import EMPTY, SHOT, WALL, ArenaParams, ArenaTask, you_glyphs
from .bodies import Body, Gun, chase
from .engine import register_atari
from .rooms import RoomMap

SLAYER, LYSSA, SWAMP, DOOR, BEAST = "S", "L", "~", "D", "B"
FIRE = 5
STAGES = ("the wedding", "the Iron Desert", "the Black Fortress")


class Glaive(Gun):
    """The gun of one glaive: ``thrown`` is the last throw, for the task to follow it back."""
    __slots__ = ("thrown",)

    def fire(self, *args, **kw):
        self.thrown = super().fire(*args, **kw)
        return self.thrown


@dataclass(frozen=True)
class KrullParams(ArenaParams):
    width: int = param(20, 12, 40)
    height: int = param(16, 10, 30)
    lives: int = param(3, 1, 9)
    goal: int = param(3, 3, 3)
    unit: float = param(1000.0, 0, 10000)
    foes: int = param(3, 1, 9)           # Slayers on the field at once
    every: int = param(3, 1, 50)
    reach: int = param(5, 1, 20)         # cells the glaive flies out
    slayers: int = param(6, 1, 40)       # Slayers to cut down at the wedding
    swamp: float = param(0.4, 0.0, 0.7)  # share of the desert that is swamp
    stun: int = param(8, 1, 100)         # ticks the glaive stuns the Beast


class Krull(ArenaTask):
    title = "Krull"
    rules = ("You are Prince Colwyn ({lives_text}) and go through three stages, each its own "
             "{width}x{height} screen. 1) The wedding: Slayers (S) step a cell every {every} "
             "turns, some toward you and some toward Princess Lyssa (L); a Slayer that reaches "
             "you kills you, one that reaches Lyssa carries her off and costs you a life. FIRE "
             "throws your glaive (*) up to {reach} cells the way you face, cutting down the first "
             "Slayer it meets; then it flies back to you through anything, 2 cells a turn, cutting "
             "down every Slayer on its way; you cannot throw it again until it is back. Cut down {slayers} Slayers. 2) The Iron Desert: the Fire Mares carry you "
             "in leaps of two cells a move (over anything; one cell at the screen's edge); "
             "landing in swamp (~) drowns you; you cannot throw the glaive while you ride. Reach the Black Fortress's door (D). 3) The "
             "Black Fortress: walls (#) block you; the Beast (B) steps toward you every {every} "
             "turns and kills you if it reaches you; the glaive stuns it for {stun} turns. Reach "
             "Lyssa (L). A life lost puts you back at the start of the stage (Slayers cut down "
             "stay down). {map_text}.")
    rewards = "+{unit} for each stage done; {death} when the game is lost."
    ends = "when Lyssa is saved or the game is lost"
    Params = KrullParams
    pattern = "D"
    FOE, foe_name, caught_text = SLAYER, "Slayer", "A Slayer cut you down."
    SOLID = frozenset((WALL, LYSSA))
    glyphs = {EMPTY: "ground", WALL: "wall", SWAMP: "swamp", DOOR: "door of the Black Fortress",
              LYSSA: "Princess Lyssa", SLAYER: "Slayer", BEAST: "the Beast", SHOT: "your glaive",
              **you_glyphs()}

    def prompt_fields(self) -> dict:
        return {**super().prompt_fields(), "map_text": "The HUD's Map shows the three stages: @ "
                "the one you are in, + done, ? still to come"}

    def _setup(self, rng) -> None:
        p = self.params
        self.start_arena(rng, p.height - 2, p.width // 2)
        self.stages = RoomMap(["###"])
        self.gun = Glaive(cooldown=1, speed=p.shot_speed, reach=p.reach, limit=1)
        self.gun.thrown = None
        self.back: Body | None = None              # the glaive on its way back
        self.out: Body | None = None               # the glaive flying out
        self.desert = self._desert()
        self._stage(0)

    # -- the three screens ---------------------------------------------------------------------------
    def _stage(self, k: int) -> None:
        p = self.params
        h, w = p.height, p.width
        self.stage, self.stunned = k, 0
        self.stages.enter(0, k)
        if k == 0:
            self.still = [EMPTY * w] * h
            self.home, self.lyssa = (h - 2, w // 2), (h // 2, w // 2)
            self.still[h // 2] = EMPTY * (w // 2) + LYSSA + EMPTY * (w - w // 2 - 1)
        elif k == 1:
            self.still, self.home = self.desert
            self.lyssa = None
        else:
            rows = [WALL * w] + ["#" + EMPTY * (w - 2) + "#" for _ in range(h - 2)] + [WALL * w]
            for i, r in enumerate(range(3, h - 2, 3)):    # halls: walls with a gap at alternate ends
                gap = (1, 2) if i % 2 else (w - 3, w - 2)
                rows[r] = "".join(WALL if 0 < c < w - 1 and c not in gap else rows[r][c] for c in range(w))
            rows[1] = rows[1][:w - 2] + LYSSA + WALL
            self.still, self.home, self.lyssa = rows, (h - 2, 1), (1, w - 2)
        self.still_version += 1
        self._reset_stage()

    def _reset_stage(self) -> None:
        p = self.params
        self.r, self.c = self.home
        self.face = (-1, 0) if self.stage != 1 else (0, 1)
        self.gun.shots, self.gun.thrown, self.back, self.out, self.foes = [], None, None, None, []
        if self.stage == 0:
            self._muster()
        elif self.stage == 2:
            self.add_foe(p.height // 2, p.width // 2, glyph=BEAST)

    def _muster(self) -> None:
        p = self.params
        h = p.height
        while len(self.foes) < min(p.foes, p.slayers - self.kills):
            self.add_foe(*self.spot(6, rows=range(0, h // 2 - 1)))

    def _desert(self):
        """The Iron Desert's rows and start: swamp by ``swamp``, redrawn until the door can be
        reached in leaps."""
        p, d = self.params, self.draws
        h, w = p.height, p.width
        start = (h // 2 - (h // 2) % 2, 0)
        for _ in range(50):
            door = (2 * d.below(h // 2), w - 1)
            rows = ["".join(SWAMP if d.random() < p.swamp else EMPTY for _ in range(w)) for _ in range(h)]
            rows = [row[:0] + EMPTY + row[1:] if r == start[0] else row for r, row in enumerate(rows)]
            rows[door[0]] = rows[door[0]][:w - 1] + DOOR
            if self._leaps(rows, start, door):
                return rows, start
        rows = [EMPTY * (w - 1) + (DOOR if r == door[0] else EMPTY) for r in range(h)]
        return rows, start

    def _leaps(self, rows, start, door) -> bool:
        def leaps(at):
            for d in DELTAS:
                q = self._landing(at, d)
                if rows[q[0]][q[1]] != SWAMP:
                    yield d, q
        return bfs_search(start, leaps, lambda q: q == door, limit=4000) is not None

    def _landing(self, at, d):
        p = self.params
        for k in (2, 1, 0):
            r, c = at[0] + k * d[0], at[1] + k * d[1]
            if 0 <= r < p.height and 0 <= c < p.width:
                return r, c

    # -- one tick ------------------------------------------------------------------------------------
    def _play(self, action: int) -> None:
        if action == FIRE and (self.back is not None or self.stage == 1):
            action = 0                               # the glaive is still out (or you ride)
        super()._play(action)
        if not self.done and self.stage != 1:
            self._glaive()

    def _enter(self, r: int, c: int) -> bool:
        if self.stage == 1:
            self.r, self.c = self._landing((self.r, self.c), self.face)
            ch = self.still[self.r][self.c]
            if ch == SWAMP:
                self._killed("Your Fire Mare landed in the swamp: you drowned.")
            elif ch == DOOR:
                self._done("You reach the door of the Black Fortress!")
            return True
        if (r, c) == self.lyssa and self.stage == 2:
            self._done("You rescue Lyssa from the Black Fortress!")
            return True
        return False

    def _march(self) -> bool:
        for i, f in enumerate(self.foes):
            if f.glyph == BEAST and self.tick < self.stunned:
                continue
            goal = self.lyssa if i % 2 and self.stage == 0 else (self.r, self.c)
            dr, dc = chase(f.r, f.c, *goal)
            r, c = f.r + dr, f.c + dc
            if (r, c) == (self.r, self.c):
                return self._killed(self.caught_text if self.stage == 0 else "The Beast killed you.")
            if (r, c) == self.lyssa:
                return self._killed("A Slayer carried Lyssa off.")
            if not self.free(r, c):
                r, c = f.r + dc, f.c + dr            # blocked: sidestep
                if not (0 <= r < self.params.height and 0 <= c < self.params.width) or not self.free(r, c):
                    continue
            f.r, f.c = r, c
        return False

    def _glaive(self) -> None:
        """The glaive out: note it; once it stops, it flies back 2 cells a tick, through
        anything, cutting down what it meets, until it is in your hand."""
        if self.gun.thrown is not None:
            self.out, self.gun.thrown = self.gun.thrown, None
        if self.out is not None and not self.out.alive:
            self.back, self.out = Body(self.out.r, self.out.c, glyph=SHOT), None
        g = self.back
        if g is None or self.out is not None:
            return
        for _ in range(2):
            if (g.r, g.c) == (self.r, self.c):
                self.back = None
                return
            dr, dc = chase(g.r, g.c, self.r, self.c)
            g.r, g.c = g.r + dr, g.c + dc
            foe = self.foe_at(g.r, g.c)
            if foe is not None:
                self._hit(foe)
                if self.done:
                    return
        if (g.r, g.c) == (self.r, self.c):
            self.back = None

    def _hit(self, foe) -> None:
        if foe.glyph == BEAST:
            self.stunned = self.tick + self.params.stun
            self.say("The glaive stuns the Beast.")
            return
        self.foes.remove(foe)
        self.kills += 1
        self.say("Slayer cut down!")
        if self.kills >= self.params.slayers:
            self._done("The Slayers are beaten: ride for the Black Fortress!")
        else:
            self._muster()

    def _done(self, text: str) -> None:
        self.say(text)
        self.score.gain()
        if not self.done:
            self._stage(self.stage + 1)

    def _respawn(self) -> None:
        self._reset_stage()

    def _below(self):
        return ((self.back.r, self.back.c, SHOT),) if self.back is not None else ()

    def _extra_hud(self) -> str:
        extra = f" | Slayers {self.kills}/{self.params.slayers}" if self.stage == 0 else ""
        return f"Stage {self.stage + 1} {STAGES[self.stage]}{extra} | {self.stages.hud()}"


register_atari(Krull, "krull", max_turns=1000)
