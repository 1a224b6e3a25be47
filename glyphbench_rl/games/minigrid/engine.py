"""MiniGridTask: Farama MiniGrid's rules, once, for every MiniGrid family.

The agent stands on a cell facing east, south, west or north and plays MiniGrid's seven
egocentric actions with MiniGrid's semantics (``MiniGridEnv.step``): turning changes only the
facing; FORWARD enters the cell in front if it is empty or overlappable (walls, closed doors and
objects block, silently); PICKUP takes the object in front into the single inventory slot;
DROP puts the carried object onto the empty cell in front; TOGGLE asks the object in front to
react (doors open and close, a locked door opens for the key of its colour, a box turns into
its contents); DONE does nothing unless a family gives it a meaning. Entering the goal wins
``1 - 0.9 * (turns used / max_turns)``, entering lava ends the episode with 0.

A family module only generates its level: it subclasses MiniGridTask with a ``Params``
dataclass (deriving from :class:`MiniGridParams`), a mission, an ``about`` sentence for the
system prompt and ``_gen(rng)``, which builds ``self.grid`` with the helpers below (named as in
MiniGrid: ``put_obj``, ``place_obj``, ``place_agent``, ``rand_int`` ...). Those helpers draw
from the episode generator exactly as MiniGrid's do, so a generator ported call for call makes
the same level as MiniGrid for the same seed. Families with extra rules (moving obstacles, a
target object) override ``_act`` and call ``super()._act(action)``, as MiniGrid's envs
override ``step``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Callable, ClassVar, Iterable, Sequence, TypeVar

import numpy as np

from ...core import STANDARD_TURN_CAP, ActionSet, GlyphTask
from ...core.params import param
from ...core.seeding import int_sampler
from .grid import VIEW_PAD, Grid
from .world import AGENT, COLOR_NAMES, DIR_VEC, KINDS, PORTABLE, UNSEEN, WorldObj, from_glyph, vocabulary

T = TypeVar("T")

# MiniGrid's Actions enum, in its order (the indices are MiniGrid's action ids).
LEFT, RIGHT, FORWARD, PICKUP, DROP, TOGGLE, DONE = range(7)
MINIGRID_ACTIONS = ActionSet([
    ("TURN_LEFT", "turn left in place"),
    ("TURN_RIGHT", "turn right in place"),
    ("FORWARD", "step into the cell you face (a wall, closed door or object there blocks you)"),
    ("PICKUP", "pick up the object you face (you carry at most one)"),
    ("DROP", "put what you carry on the empty cell you face"),
    ("TOGGLE", "open or close the door you face (a locked door opens only with the key of its "
               "colour in hand) or open the box you face, which turns into what it held"),
    ("DONE", "signal that the mission is complete (nothing happens unless the mission asks for it)"),
], aliases={"LEFT": "TURN_LEFT", "RIGHT": "TURN_RIGHT", "MOVE_FORWARD": "FORWARD", "OPEN": "TOGGLE"})
NAV_ACTIONS = ActionSet([(a.name, a.description) for a in list(MINIGRID_ACTIONS)[:3]],
                        aliases={"LEFT": "TURN_LEFT", "RIGHT": "TURN_RIGHT", "MOVE_FORWARD": "FORWARD"})

SUCCESS_DECAY = 0.9       # MiniGrid's _reward: 1 - 0.9 * (step_count / max_steps)


def capped(max_steps: int) -> int:
    """MiniGrid's horizon for an env, capped at the standard tasks' turn cap."""
    return min(max_steps, STANDARD_TURN_CAP)


@dataclass(frozen=True)
class MiniGridParams:
    # "partial": MiniGrid's 7x7 egocentric view; "full": the whole grid
    view: str = param("partial", choices=("partial", "full"))


def beside(a: tuple[int, int], b: tuple[int, int]) -> bool:
    """MiniGrid's test for DONE missions: the cells share an edge."""
    return abs(a[0] - b[0]) + abs(a[1] - b[1]) == 1


_VIEW_RULES = {
    "partial": ("You see the {view_size}x{view_size} square in front of you, standing in the "
                "middle of its back row; walls and closed doors block sight ({unseen} is unseen). "
                "North is up, so where you are in the view shows which way you face."),
    "see_through": ("You see the {view_size}x{view_size} square in front of you, standing in "
                    "the middle of its back row; sight passes through walls, and past the edge "
                    "of the world shows wall. North is up, so where you are in the view shows "
                    "which way you face."),
    "full": "You see the whole grid, north up.",
}


class MiniGridTask(GlyphTask):
    # -- declared by each family -----------------------------------------------------------------
    title = "MiniGrid"
    about: ClassVar[str] = ""               # the family's level and goal, for the system prompt
    mission: str = "get to the green goal square"
    see_through_walls: ClassVar[bool] = False   # MiniGrid's per-env see_through_walls
    agent_view_size: ClassVar[int] = 7
    Params = MiniGridParams
    ACTIONS = MINIGRID_ACTIONS
    _int_sampler: Callable[[int, int], int] | None = None
    _vocab: dict[str, str] | None = None

    rules = "{about} {view_rules}"
    has_lava: ClassVar[bool] = False            # lava in the level: the prompt says it kills
    rewards = ("reaching the goal gives 1 - {decay:g} x (turns used / {max_turns}); "
               "{lava_or}running out of time gives 0.")
    ends = "when you reach the goal{or_lava}"
    kinds: ClassVar[tuple[str, ...]] = KINDS    # object kinds a level may hold: the legend's vocabulary
    default_max_turns = 100

    # -- system prompt -----------------------------------------------------------------------------
    def prompt_fields(self) -> dict[str, Any]:
        fields = super().prompt_fields()
        fields.update(max_turns=self.max_turns, decay=SUCCESS_DECAY, view_size=self.agent_view_size,
                      unseen=UNSEEN)
        fields.update(self.family_fields())
        view = "full" if self.params.view == "full" else "see_through" if self.see_through_walls else "partial"
        fields["view_rules"] = _VIEW_RULES[view].format_map(fields)
        lava = self.has_lava
        fields.update(lava_or="stepping into lava or " if lava else "", or_lava=" or step into lava" if lava else "")
        fields["about"] = self.about.format_map(fields)
        return fields

    def vocab(self) -> dict[str, str]:
        vocab = self._vocab
        if vocab is None:   # asked every turn: looked up once
            vocab = self._vocab = vocabulary(self.kinds, self.params.view == "partial" and not self.see_through_walls)
        return vocab

    def family_fields(self) -> dict[str, Any]:
        """Extra values a family's ``about``/``rewards``/``ends`` templates name."""
        return {}

    # -- episode -------------------------------------------------------------------------------------
    def _setup(self, rng: np.random.Generator) -> None:
        size = self.agent_view_size
        if size % 2 == 0 or not 3 <= size <= VIEW_PAD + 1:
            raise ValueError(f"agent_view_size must be odd and in 3..{VIEW_PAD + 1}, got {size}")
        self.rng = rng
        self._int_sampler = None
        self.grid: Grid | None = None
        self.agent_pos: tuple[int, int] = (-1, -1)
        self.agent_dir = -1
        self.carrying: WorldObj | None = None
        self._gen(rng)
        if self.grid is None or not self.grid.inside(*self.agent_pos) or not 0 <= self.agent_dir < 4:
            raise RuntimeError(f"{type(self).__name__}._gen must build self.grid and place the agent")
        start = self.grid.get(*self.agent_pos)
        if start is not None and not start.overlap:
            raise RuntimeError(f"{type(self).__name__}: the agent starts on a {start.name}")

    def _gen(self, rng: np.random.Generator) -> None:
        """Build the level: ``self.new_grid(w, h)``, objects, ``self.agent_pos/agent_dir``."""
        raise NotImplementedError

    def _act(self, action: int) -> None:
        fx, fy = self.front_pos
        front = self.grid.get(fx, fy)
        if action == LEFT:
            self.agent_dir = (self.agent_dir - 1) % 4
        elif action == RIGHT:
            self.agent_dir = (self.agent_dir + 1) % 4
        elif action == FORWARD:
            if front is None or front.overlap:
                self.agent_pos = (fx, fy)
            if front is not None and front.kind == "goal":
                self.succeed("You reached the goal.")
            elif front is not None and front.kind == "lava":
                self.fail("You stepped into lava.")
        elif action == PICKUP:
            if front is not None and front.pickup and self.carrying is None:
                self.carrying = front
                self.grid.set(fx, fy, None)
                front.pos = None
                self.say(f"You picked up the {front.name}.")
        elif action == DROP:
            if front is None and self.carrying is not None:
                self.grid.set(fx, fy, self.carrying)
                self.say(f"You dropped the {self.carrying.name}.")
                self.carrying = None
        elif action == TOGGLE:
            if front is not None:
                front.toggle(self, (fx, fy))

    def succeed(self, message: str = "") -> None:
        """Win now with MiniGrid's time-discounted reward."""
        self.reward(1 - SUCCESS_DECAY * self.turn / self.max_turns)
        if message:
            self.say(message)
        self.finish(won=True)

    def fail(self, message: str = "", penalty: float = 0.0) -> None:
        if penalty:
            self.reward(-penalty)
        if message:
            self.say(message)
        self.finish(won=False)

    # -- observation -----------------------------------------------------------------------------------
    def _grid(self) -> list[str]:
        glyph = AGENT[self.agent_dir]
        if self.params.view == "full":
            return self.grid.render_full(self.agent_pos, glyph)
        return self.grid.render_view(self.agent_pos, self.agent_dir, glyph, self.agent_view_size,
                                     self.see_through_walls)

    def _hud(self) -> str:
        hud = f"Mission: {self.mission}"
        if PICKUP < len(self.actions):
            hud += f" | Carrying: {self.carrying.name if self.carrying is not None else 'nothing'}"
        return hud

    # -- geometry ----------------------------------------------------------------------------------------
    @property
    def dir_vec(self) -> tuple[int, int]:
        return DIR_VEC[self.agent_dir]

    @property
    def front_pos(self) -> tuple[int, int]:
        dx, dy = DIR_VEC[self.agent_dir]
        return self.agent_pos[0] + dx, self.agent_pos[1] + dy

    # -- level building (MiniGrid's helpers, same random draws) -------------------------------------------
    def new_grid(self, width: int, height: int) -> Grid:
        self.grid = Grid(width, height)
        return self.grid

    def put_obj(self, obj: WorldObj, x: int, y: int) -> None:
        self.grid.set(x, y, obj)

    def place_obj(self, obj: WorldObj | None, top: tuple[int, int] | None = None,
                  size: tuple[int, int] | None = None,
                  reject_fn: Callable[["MiniGridTask", tuple[int, int]], bool] | None = None,
                  max_tries: float = math.inf) -> tuple[int, int]:
        """Put ``obj`` on a random empty cell of the rectangle (rejection sampling as MiniGrid:
        never on an object or the agent); RecursionError after ``max_tries`` failed draws."""
        grid = self.grid
        width, height = grid.width, grid.height
        if top is None:
            x_lo = y_lo = 0
        else:
            x_lo, y_lo = max(top[0], 0), max(top[1], 0)
        x_hi = width if size is None else min(x_lo + size[0], width)
        y_hi = height if size is None else min(y_lo + size[1], height)
        # every turn for moving obstacles, often many tries: cells are read by their index
        draw = self._int_sampler
        if draw is None or draw.rng is not self.rng:
            draw = self.int_sampler()
        cells, origin, stride = grid.cells, grid.index(0, 0), grid.stride
        tries = 0
        while True:
            if tries > max_tries:
                raise RecursionError("rejection sampling failed in place_obj")
            tries += 1
            x = draw(x_lo, x_hi)
            y = draw(y_lo, y_hi)
            if cells[origin + y * stride + x] is not None:
                continue
            pos = (x, y)
            if pos == self.agent_pos or (reject_fn is not None and reject_fn(self, pos)):
                continue
            break
        if obj is not None:
            grid.set(x, y, obj)
        return pos

    def place_agent(self, top: tuple[int, int] | None = None, size: tuple[int, int] | None = None,
                    rand_dir: bool = True, max_tries: float = math.inf) -> tuple[int, int]:
        self.agent_pos = (-1, -1)
        self.agent_pos = self.place_obj(None, top, size, max_tries=max_tries)
        if rand_dir:
            self.agent_dir = self.rand_int(0, 4)
        return self.agent_pos

    def place_distinct_objects(self, count: int, *, apart: bool = False
                               ) -> tuple[list[tuple[str, str]], list[tuple[int, int]]]:
        """``count`` objects of distinct (kind, colour) on random cells, drawn as MiniGrid's
        GoToObject and PutNear draw them; ``apart`` keeps each off the 8 cells around earlier ones."""
        objs: list[tuple[str, str]] = []
        positions: list[tuple[int, int]] = []

        def near(_task: MiniGridTask, p1: tuple[int, int]) -> bool:
            return any(abs(p1[0] - p2[0]) <= 1 and abs(p1[1] - p2[1]) <= 1 for p2 in positions)

        while len(objs) < count:
            kind = self.rand_elem(list(PORTABLE))
            color = self.rand_elem(COLOR_NAMES)
            if (kind, color) in objs:
                continue
            positions.append(self.place_obj(PORTABLE[kind](color), reject_fn=near if apart else None))
            objs.append((kind, color))
        return objs, positions

    def int_sampler(self) -> Callable[[int, int], int]:
        """``int(self.rng.integers(low, high))`` as a function, the same numbers at a third of
        the cost (``seeding.int_sampler``): obstacles re-place themselves every turn."""
        draw = self._int_sampler
        if draw is None or draw.rng is not self.rng:
            draw = self._int_sampler = int_sampler(self.rng)
        return draw

    def rand_int(self, low: int, high: int) -> int:
        """An int in [low, high)."""
        return self.int_sampler()(low, high)

    def rand_float(self, low: float, high: float) -> float:
        return float(self.rng.uniform(low, high))

    def rand_bool(self) -> bool:
        return self.int_sampler()(0, 2) == 0

    def rand_elem(self, items: Iterable[T]) -> T:
        items = list(items)
        return items[self.rand_int(0, len(items))]

    def rand_subset(self, items: Iterable[T], count: int) -> list[T]:
        pool, out = list(items), []
        while len(out) < count:
            elem = self.rand_elem(pool)
            pool.remove(elem)
            out.append(elem)
        return out

    def rand_color(self) -> str:
        return self.rand_elem(COLOR_NAMES)

    def rand_pos(self, x_low: int, x_high: int, y_low: int, y_high: int) -> tuple[int, int]:
        return self.rand_int(x_low, x_high), self.rand_int(y_low, y_high)

    def load_level(self, rows: Sequence[str], mission: str | None = None) -> None:
        """Replace the level by one drawn in glyphs, the agent as one of ▶▼◀▲ (for tests and
        hand-made levels); call after ``reset``."""
        self.grid = self.new_grid(len(rows[0]), len(rows))
        for y, row in enumerate(rows):
            for x, ch in enumerate(row):
                if ch in AGENT:
                    self.agent_pos, self.agent_dir = (x, y), AGENT.index(ch)
                elif ch != "·":
                    self.grid.set(x, y, from_glyph(ch))
        self.carrying = None
        if mission is not None:
            self.mission = mission
        self._frame = self._build_frame()

    def objects_of(self, kind: str, colors: Sequence[str] | None = None) -> list[WorldObj]:
        return [o for o in self.grid.objects() if o.kind == kind and (colors is None or o.color in colors)]
