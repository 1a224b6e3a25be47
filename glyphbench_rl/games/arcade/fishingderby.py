"""Fishing Derby: two anglers fish one lake, you on the left half, a scripted rival on the right.
Fish swim in lanes below the surface, one per lane, across both halves. A fish that swims onto
your hook is hooked and rises a row a turn (two while you REEL); at the surface it is caught. A
shark patrols the row under the surface and eats a hooked fish that rises through its cell.
The rival moves its hook toward the nearest free fish with a probability and reels with another. Pattern C:
first to ``goal`` fish."""

from __future__ import annotations

from dataclasses import dataclass

from ...core.actions import ActionSet
from ...core.params import param, require
from .duel import pursue
from .engine import EMPTY, ArcadeParams, ArcadeTask, register_arcade

SURFACE, FISH, HOOKED, SHARK, YOU, CPU = "~", "f", "F", "S", "J", "K"
ACTIONS = ActionSet([("NOOP", "leave the hook where it is"), ("UP", "raise the hook one row"),
                     ("DOWN", "lower the hook one row"), ("LEFT", "move the hook one column left"),
                     ("RIGHT", "move the hook one column right"), ("REEL", "reel a hooked fish in fast")],
                    noop="NOOP")
MOVES = ((0, 0), (-1, 0), (1, 0), (0, -1), (0, 1), (0, 0))
REEL = 5


@dataclass(frozen=True)
class DerbyParams(ArcadeParams):
    width: int = param(14, 8, 60)
    height: int = param(10, 6, 40)
    goal: int = param(3, 1, 200)
    unit: float = param(1 / 3, 0, 10)
    lanes: int = param(4, 1, 12)          # fish lanes, every other row from the bottom up
    chance: float = param(0.5, 0, 1)      # the rival's hook steps toward a fish this often
    reel: float = param(0.5, 0, 1)        # the rival reels a hooked fish this often

    def check(self) -> None:
        require(2 * self.lanes + 2 <= self.height, "lanes", "fit under the shark's row", self.lanes)


class FishingDerby(ArcadeTask):
    title = "Fishing Derby"
    rules = ("A {width}x{height} lake; row 0 is the surface (~). You move your hook (J) in the left "
             "half, the rival its hook (K) in the right half; it steps toward a fish with chance "
             "{chance} a turn. {lanes} fish (f) swim across, one per lane, wrapping at the sides. A "
             "fish that meets your hook is hooked (F) and rises one row a turn, two while you REEL "
             "(the rival reels with chance {reel}); at the surface it is caught. The shark (S) swims "
             "to and fro on row 1 and eats a hooked fish that rises through its cell.")
    rewards = "+{unit} for each fish you catch, -{unit} for each fish the rival catches."
    ends = "when either angler has caught {goal} fish"
    ACTIONS = ACTIONS
    Params = DerbyParams
    pattern = "C"
    inside = True    # (the shark, hooks and fish stay in the water)
    glyphs = {EMPTY: "water", SURFACE: "surface", FISH: "fish", HOOKED: "hooked fish", SHARK: "shark",
              YOU: "your hook", CPU: "rival's hook"}

    def _still(self) -> list[str]:
        p = self.params
        return [SURFACE * p.width] + [EMPTY * p.width] * (p.height - 1)

    def _setup(self, rng) -> None:
        self.start(rng)
        p = self.params
        self.fish = [[p.height - 1 - 2 * i, self.draws.below(p.width), 1 if i % 2 else -1, 1 + i % 2]
                     for i in range(p.lanes)]        # row, column, direction, turns per cell
        self.shark = [1, p.width // 2, 1]
        self.half = p.width // 2
        self.me, self.cpu = [2, self.half // 2], [2, self.half + (p.width - self.half) // 2]
        self.caught = {"you": None, "cpu": None}     # the fish on each hook
        self.lane = {f[0]: f for f in self.fish}     # each lane's row: its fish

    def _play(self, action: int) -> None:
        p, me, cpu = self.params, self.me, self.cpu
        sh = self.shark
        sh[1] += sh[2]
        if not 0 <= sh[1] < p.width:
            sh[2] = -sh[2]
            sh[1] += 2 * sh[2]
        mine, theirs, w, tick = self.caught["you"], self.caught["cpu"], p.width, self.tick
        for f in self.fish:
            if tick % f[3] == 0 and f is not mine and f is not theirs:
                f[1] = (f[1] + f[2]) % w
        if mine:
            self._rise("you", me, 2 if action == REEL else 1)
        else:
            dr, dc = MOVES[action]
            if dr or dc:   # (clamp written out)
                r, c, top = me[0] + dr, me[1] + dc, p.height - 1
                me[0] = 2 if r < 2 else top if r > top else r
                me[1] = 0 if c < 0 else self.half - 1 if c > self.half - 1 else c
        if self.done:
            return
        caught = self.caught
        if caught["cpu"]:
            self._rise("cpu", cpu, 2 if self.draws.random() < p.reel else 1)
        else:
            near, best, r, c = None, w + p.height, cpu[0], cpu[1]
            for f in self.fish:   # the nearest fish not on your hook (the first on a tie)
                if f is not mine:
                    d = f[0] - r
                    e = f[1] - c
                    d = (d if d >= 0 else -d) + (e if e >= 0 else -e)
                    if d < best:
                        near, best = f, d
            c = near[1]
            c = self.half if c < self.half else w - 1 if c > w - 1 else c
            dr, dc = pursue(cpu[0], cpu[1], near[0], c, p.chance, self.draws)
            cpu[0], cpu[1] = cpu[0] + dr, cpu[1] + dc
        lane = self.lane
        f = lane.get(me[0])   # a fish on a free hook is hooked (yours first)
        if f and f[1] == me[1] and f[0] == me[0] and caught["you"] is None and f is not caught["cpu"]:
            caught["you"] = f
        f = lane.get(cpu[0])
        if f and f[1] == cpu[1] and f[0] == cpu[0] and caught["cpu"] is None and f is not caught["you"]:
            caught["cpu"] = f

    def _hooked(self, f: list) -> bool:
        return f is self.caught["you"] or f is self.caught["cpu"]

    def _rise(self, side: str, hook: list, rows: int) -> None:
        f = self.caught[side]
        for _ in range(rows):
            hook[0] -= 1
            f[0], f[1] = hook[0], hook[1]
            if hook[0] == self.shark[0] and hook[1] == self.shark[1]:
                self.say("The shark eats your fish." if side == "you" else "The shark eats the rival's fish.")
                self._release(side, hook)
                return
            if hook[0] == 0:
                self.say("You catch a fish." if side == "you" else "The rival catches a fish.")
                self._release(side, hook)
                self.score.point(side == "you")
                return

    def _release(self, side: str, hook: list) -> None:
        """The fish swims again from its lane's edge; the hook drops back under the shark."""
        p, f = self.params, self.caught[side]
        lane = self.fish.index(f)
        f[0], f[1] = p.height - 1 - 2 * lane, 0 if f[2] > 0 else p.width - 1
        hook[0] = 2
        self.caught[side] = None

    def _rows(self) -> list[str]:
        rows, lines = self.still[:], self._lines
        mine, theirs = self.caught["you"], self.caught["cpu"]
        for f in self.fish:                          # a free fish is alone on its lane's row
            if f is not mine and f is not theirs:
                rows[f[0]] = lines[f[1]]
        return rows

    def _init(self) -> None:
        w = self.params.width
        self._lines = [EMPTY * c + FISH + EMPTY * (w - 1 - c) for c in range(w)]   # a lane's row by its fish's column

    def _sprites(self):
        out = [(self.shark[0], self.shark[1], SHARK), (self.cpu[0], self.cpu[1], CPU), (self.me[0], self.me[1], YOU)]
        if self.caught["you"]:
            out.append((self.me[0], self.me[1], HOOKED))
        if self.caught["cpu"]:
            out.append((self.cpu[0], self.cpu[1], HOOKED))
        return out


register_arcade(FishingDerby, "fishingderby",
                mini=dict(max_turns=200),
                atari=dict(width=20, height=16, goal=30, unit=1.0, lanes=6, max_turns=10000))
