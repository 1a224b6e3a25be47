"""Our own MiniHack levels, for the three GlyphBench MiniHack IDs upstream MiniHack lacks.

Each builder returns ``(env_class, kwargs)`` for ``MiniHackTask._new_env`` (a ``levels.LEVELS``
source ``"glyphbench_rl.games.nethack.custom:<builder>"``); only the engine imports this module.
The levels are written in upstream's own style, on upstream's classes and reward events:

- ``quaff`` / ``quaff_distract``: the skill tasks ``Eat``/``Read`` and their ``-Distr`` variants
  with a potion: a lit 5x5 room holding a potion of healing (a caveman, autopickup off: PICKUP,
  then QUAFF). MiniHack has no quaff event, so the reward is a message event on the potion's
  message, as upstream's Read and Zap tasks reward their item's message. Healing's message does
  not depend on the potion being blessed or cursed, so the potion's curse state stays random.
  The distract variant adds a random monster and a random object, as upstream's ``-Distr`` do.
- ``memento_hard``: upstream's Memento-F4 (``memento_hard.des``) shows two cue monsters and ends
  its corridor in four branches; this level shows three cues behind iron bars (a jelly, a mold
  and another mold, each one of two kinds) and ends in eight branches, one per combination of
  the three: three bits to remember over the dark corridor instead of two. As upstream, the
  right branch ends with a sleeping grid bug (kill it: +1) and every other one holds a squeaky
  board (-1); both end the episode (upstream's ``MiniHackMemento`` reward events).
"""

from __future__ import annotations

from minihack import LevelGenerator, MiniHackSkill, RewardManager
from minihack.envs.memento import MiniHackMemento

QUAFF_MESSAGES = ["You feel better."]   # a potion of healing, whatever its curse state


def _quaff_level(distract: bool) -> tuple[type, dict]:
    gen = LevelGenerator(w=5, h=5, lit=True)
    gen.add_object("healing", "!")
    if distract:
        gen.add_monster()
        gen.add_object()
    rewards = RewardManager()
    rewards.add_message_event(QUAFF_MESSAGES)
    return MiniHackSkill, dict(des_file=gen.get_des(), reward_manager=rewards)


def quaff() -> tuple[type, dict]:
    return _quaff_level(distract=False)


def quaff_distract() -> tuple[type, dict]:
    return _quaff_level(distract=True)


# -- memento-hard -------------------------------------------------------------------------------
# the cue cells, lit, behind iron bars beside the start; each shows one of two sessile monsters
CUES = (((1, 6), (("j", "blue jelly"), ("j", "spotted jelly"))),
        ((3, 6), (("F", "red mold"), ("F", "green mold"))),
        ((2, 10), (("F", "brown mold"), ("F", "yellow mold"))))
CORRIDOR_Y, JUNCTION_X, BOARD_X, END_X = 8, 60, 67, 71
BRANCH_ROWS = tuple(range(1, 16, 2))      # eight branches east of the junction column
START = (2, CORRIDOR_Y)


def _memento_map() -> str:
    rows = [[" "] * (END_X + 2) for _ in range(BRANCH_ROWS[-1] + 2)]

    def put(x: int, y: int, s: str) -> None:
        rows[y][x:x + len(s)] = s

    # the branches: a junction column at JUNCTION_X with a dead end east of it on each branch row
    put(JUNCTION_X - 1, 0, "-" * (END_X - JUNCTION_X + 3))
    put(JUNCTION_X - 1, BRANCH_ROWS[-1] + 1, "-" * (END_X - JUNCTION_X + 3))
    for y in range(1, BRANCH_ROWS[-1] + 1):
        inner = "." * (END_X - JUNCTION_X + 1) if y in BRANCH_ROWS else "." + "-" * (END_X - JUNCTION_X)
        put(JUNCTION_X - 1, y, "|" + inner + "|")
    # the corridor from the start to the junction, walled, iron bars before each cue cell
    put(0, CORRIDOR_Y - 1, "-" * (JUNCTION_X - 1))
    put(0, CORRIDOR_Y + 1, "-" * (JUNCTION_X - 1))
    put(0, CORRIDOR_Y, "|" + "." * JUNCTION_X)
    for (x, y), _ in CUES:
        side = -1 if y < CORRIDOR_Y else 1
        put(x, CORRIDOR_Y + side, "F")
        put(x - 1, y, "|.|")
        put(x - 1, y + side, "---")
    return "".join("".join(r).rstrip() + "\n" for r in rows)


def _memento_cases(level: int = 0, index: int = 0) -> str:
    """Nested 50% choices, one per cue: the leaves place the grid bug and the boards."""
    if level == len(CUES):
        right = BRANCH_ROWS[index]
        lines = [f'MONSTER:(\'x\',"grid bug"),({END_X},{right}),asleep']
        lines += [f'TRAP:"board",({BOARD_X},{y})' for y in BRANCH_ROWS if y != right]
        return "\n".join(lines) + "\n"
    (x, y), kinds = CUES[level]
    out = ""
    for bit, (sym, name) in enumerate(kinds):
        body = f"MONSTER:('{sym}',\"{name}\"),({x},{y}),asleep\n" + _memento_cases(level + 1, 2 * index + bit)
        out += ("IF [50%] {\n" if bit == 0 else "} ELSE {\n") + body
    return out + "}\n"


def memento_hard_des() -> str:
    lit = "".join(f'REGION:({x - 1},{y},{x + 1},{y}),lit,"ordinary"\n' for (x, y), _ in CUES)
    return ("MAZE: \"mylevel\",' '\nINIT_MAP:solidfill,' '\nGEOMETRY:left,top\nMAP\n" + _memento_map()
            + "ENDMAP\n" + f'REGION:(0,0,{END_X + 1},{BRANCH_ROWS[-1] + 1}),unlit,"ordinary"\n' + lit + _memento_cases()
            + f"BRANCH:({START[0]},{START[1]},{START[0]},{START[1]}),(0,0,0,0)\n")


def branch_row(kinds: tuple[int, ...]) -> int:
    """The right branch's row for the cue kinds shown (0 or 1 per cue, in ``CUES`` order)."""
    index = 0
    for k in kinds:
        index = 2 * index + k
    return BRANCH_ROWS[index]


def memento_hard() -> tuple[type, dict]:
    return MiniHackMemento, dict(des_file=memento_hard_des())
