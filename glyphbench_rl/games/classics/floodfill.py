"""Flood-It: pick a colour and the flooded region at the top-left takes it, absorbing every
neighbouring cell of that colour; flood the whole board within the move budget.

The budget is the length of a greedy lookahead solution (plus ``slack``), so every board can
be won within it; ``lower_bound`` (region-graph eccentricity, colours left) brackets the optimum
from below for tests and baselines.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import ActionSet, GlyphTask, register_variants
from ...core.params import param
from ..common.boards import Bits

COLOURS = (("R", "RED"), ("G", "GREEN"), ("B", "BLUE"), ("Y", "YELLOW"), ("P", "PURPLE"), ("O", "ORANGE"))
_TRIES = 100


@dataclass(frozen=True)
class FloodFillParams:
    size: int = param(8, 3, 16)              # the board is size x size
    colours: int = param(6, 2, len(COLOURS))
    slack: int = param(0, 0, 20)             # moves allowed beyond the solver's solution
    # the return flooding earns along the way; the rest is for finishing
    progress_share: float = param(0.5, 0, 1, open_hi=True)


def pick(bits: Bits, masks: list[int], region: int, colour: int) -> int:
    """The flooded region after choosing ``colour``: it absorbs touching cells of that colour."""
    return bits.flood(region, region | masks[colour])


def lower_bound(bits: Bits, masks: list[int], region: int) -> int:
    """Moves any solution needs at least: a move absorbs at most the regions touching the flood,
    so the region-graph distance to the farthest region counts; so does each colour left."""
    left = sum(1 for m in masks if m & ~region)
    layers, reach = 0, region
    while reach != bits.full:
        reach = _absorb(bits, masks, bits.grow(reach))
        layers += 1
    return max(layers, left)


def _absorb(bits: Bits, masks: list[int], reach: int) -> int:
    """Extend ``reach`` to whole same-colour regions of every cell it touches."""
    return sum(bits.flood(reach & m, m) for m in masks)


def greedy_plan(bits: Bits, masks: list[int], colour: int, region: int, depth: int) -> list[int]:
    """A solution by lookahead: each move maximises (colours wiped out, flooded area) after the
    best ``depth``-move continuation; ties go to the lower colour index."""
    plan = []
    while region != bits.full:
        best = None
        for c in range(len(masks)):
            nxt = pick(bits, masks, region, c)
            if c == colour or nxt == region:
                continue
            key = _score(bits, masks, nxt, c, depth - 1)
            if best is None or key > best[0]:
                best = (key, c, nxt)
        _, colour, region = best
        plan.append(colour)
    return plan


def _score(bits: Bits, masks: list[int], region: int, colour: int, depth: int) -> tuple[int, int]:
    wiped = sum(1 for m in masks if m and not m & ~region)
    key = (wiped, region.bit_count())
    if depth > 0 and region != bits.full:
        for c in range(len(masks)):
            if c != colour:
                nxt = pick(bits, masks, region, c)
                if nxt != region:
                    key = max(key, _score(bits, masks, nxt, c, depth - 1))
    return key


class FloodFill(GlyphTask):
    title = "Flood-It"
    rules = ("The {size}x{size} board is covered in {colours} colours. The flooded region is the "
             "top-left cell and every cell joined to it through orthogonal neighbours of its "
             "colour. Choosing a colour repaints the flooded region with it, so it absorbs the "
             "neighbouring cells of that colour. Flood the whole board within the move budget "
             "shown in the status line; every action uses a move.")
    # Running out of moves costs the whole progress share, so a lost game nets less than 0 while
    # flooding more of the board still loses less.
    rewards = ("each move earns {progress_share:g} x (cells it floods / cells not flooded at the "
               "start); flooding the whole board adds {win_bonus:g}; running out of moves costs "
               "{progress_share:g}.")
    ends = "when the board is one colour or the budget is spent"
    Params = FloodFillParams
    default_max_turns = 40

    def prompt_fields(self) -> dict:
        return super().prompt_fields() | {"win_bonus": 1 - self.params.progress_share}

    def _init(self) -> None:
        k = self.params.colours
        self._glyphs = {g: name.lower() for g, name in COLOURS[:k]}
        self.bits = Bits(self.params.size, self.params.size)

    def vocab(self):
        return self._glyphs

    def _make_actions(self) -> ActionSet:
        return ActionSet([(name, f"repaint the flooded region {name.lower()}")
                          for _, name in COLOURS[:self.params.colours]])

    def _setup(self, rng: np.random.Generator) -> None:
        p, bits = self.params, self.bits
        for _ in range(_TRIES):
            colour_of = rng.integers(p.colours, size=p.size * p.size).tolist()
            masks = [0] * p.colours
            for i, c in enumerate(colour_of):
                masks[c] |= 1 << i
            region = bits.flood(1, masks[colour_of[0]])
            if region != bits.full:
                break
        else:
            raise RuntimeError(f"{self.task_id}: every board drawn was flooded from the start")
        plan = min((greedy_plan(bits, masks, colour_of[0], region, d) for d in (1, 2)), key=len)
        self.masks, self.colour, self.region, self.plan = masks, colour_of[0], region, plan
        self.budget = len(plan) + p.slack
        self._to_flood = (bits.full & ~region).bit_count()
        self.lower_bound = lower_bound(bits, masks, region)
        self.moves = 0
        w = p.size
        self._base = ["".join(COLOURS[colour_of[r * w + c]][0] for c in range(w)) for r in range(w)]
        self._shown, self._rows, self._partial = None, [], {}

    def _act(self, action: int) -> None:
        self.moves += 1
        if action == self.colour:
            self.say("The region already has that colour.")
        else:
            grown = pick(self.bits, self.masks, self.region, action)
            self.reward(self.params.progress_share * (grown ^ self.region).bit_count() / self._to_flood)
            self.region, self.colour = grown, action
        if self.region == self.bits.full:
            self.reward(1 - self.params.progress_share)
            self.say("The board is flooded.")
            self.finish(won=True)
        elif self.moves >= self.budget:
            self.reward(-self.params.progress_share)
            self.say("Out of moves.")
            self.finish(won=False)

    def _grid(self) -> list[str]:
        key = (self.region, self.colour)
        if key != self._shown:   # repeated colours and forfeits change nothing
            self._shown, self._rows = key, self._draw()
        return self._rows

    def _draw(self) -> list[str]:
        w, region = self.params.size, self.region
        g, whole = COLOURS[self.colour][0], (1 << w) - 1
        out = []
        for r, base in enumerate(self._base):
            line = region >> r * w & whole
            if line == 0:
                out.append(base)
            elif line == whole:
                out.append(g * w)
            else:
                key = (r, line, g)
                text = self._partial.get(key)
                if text is None:
                    text = self._partial[key] = "".join(g if line >> c & 1 else ch for c, ch in enumerate(base))
                out.append(text)
        return out

    def _hud(self) -> str:
        return f"Moves {self.moves}/{self.budget}"


register_variants(FloodFill, "Classics", {
    "glyphbench/classics-floodfill-easy-v0": dict(size=6, colours=6, slack=2, max_turns=30),
    "glyphbench/classics-floodfill-hard-v0": dict(size=10, colours=6, slack=0, max_turns=50),
})
