"""Our own MiniHack levels (games/nethack/custom.py): quaff, quaff-distract and memento-hard,
won and lost by small scripted players on the real NetHack engine."""

from __future__ import annotations

import re

import numpy as np
import pytest
from nle import nethack

import glyphbench_rl
from glyphbench_rl.games.nethack import custom, render

STEPS = {(0, -1): "MOVE_N", (0, 1): "MOVE_S", (1, 0): "MOVE_E", (-1, 0): "MOVE_W",
         (1, -1): "MOVE_NE", (-1, -1): "MOVE_NW", (1, 1): "MOVE_SE", (-1, 1): "MOVE_SW"}


def make(level: str):
    return glyphbench_rl.make(f"glyphbench/minihack-{level}-v0")


def toward(task, target: tuple[int, int]) -> str:
    hx, hy = task.hero
    return STEPS[(int(np.sign(target[0] - hx)), int(np.sign(target[1] - hy)))]


class Episode:
    """Steps one task, keeping the return and the last step's outcome."""

    def __init__(self, task, seed: int):
        self.task, self.ret, self.done, self.info = task, 0.0, False, {}
        self.obs, _ = task.reset(seed=seed)

    def step(self, action: str) -> None:
        self.obs, r, term, trunc, self.info = self.task.step(action)
        self.ret += r
        self.done = term or trunc


# -- quaff ------------------------------------------------------------------------------------------
def potions_carried(task) -> int:
    classes = task.obs("inv_oclasses").tolist()
    return sum(1 for c in classes[:len(render.inventory(task.obs("inv_letters"), task.obs("inv_strs")))]
               if c == nethack.POTION_CLASS)


def quaff_player(ep: Episode, budget: int = 120) -> None:
    """Walks to the nearest object pile, picks it all up, quaffs every potion carried; again
    until the episode ends (a pile may hide the potion, or hold the other, distracting one)."""
    task = ep.task
    while not ep.done and task.turn < budget:
        if potions_carried(task):
            ep.step("QUAFF")
            continue
        glyphs = task.obs("glyphs")
        hx, hy = task.hero
        objects = [(int(x), int(y)) for y, x in np.argwhere((glyphs >= nethack.GLYPH_OBJ_OFF)
                                                            & (glyphs < nethack.GLYPH_CMAP_OFF))]
        monsters = [(int(x), int(y)) for y, x in np.argwhere(glyphs < nethack.GLYPH_INVIS_OFF)
                    if (x, y) != (hx, hy)]
        targets = objects or monsters            # a monster may stand on the last pile
        if not targets:
            ep.step("PICKUP")                    # the pile under us (we hide it ourselves)
            continue
        target = min(targets, key=lambda t: max(abs(t[0] - hx), abs(t[1] - hy)))
        ep.step(toward(task, target))
        if task.hero == target and not ep.done:
            ep.step("PICKUP")


@pytest.mark.parametrize("level,seed", [("quaff", 0), ("quaff", 1), ("quaff-distract", 1),
                                        ("quaff-distract", 3), ("quaff-distract", 18)])
def test_quaffing_the_potion_wins(level, seed):
    # quaff-distract seeds 3 and 18: the hero starts on the potion (hidden under @, seen once
    # the hero steps off); in seed 3 the other object is a second potion, drunk first for nothing
    ep = Episode(make(level), seed)
    quaff_player(ep)
    assert ep.done and ep.info["won"] is True and ep.ret == 1.0
    assert "You feel better." in ep.task.frame.message


def test_quaff_without_quaffing_is_not_won():
    ep = Episode(make("quaff"), 0)
    ys, xs = np.nonzero(ep.task.obs("chars") == ord("!"))
    target = int(xs[0]), int(ys[0])
    while ep.task.hero != target:
        ep.step(toward(ep.task, target))
    ep.step("PICKUP")
    assert potions_carried(ep.task) == 1 and ep.ret == 0 and not ep.done
    while not ep.done:                          # carried to the end, never drunk
        ep.step("SEARCH")
    assert ep.info["won"] is None and ep.ret == 0 and ep.task.turn == ep.task.max_turns == 250


def test_quaff_distract_monster_kills_an_idle_hero():
    ep = Episode(make("quaff-distract"), 0)     # a newt, and the hero never fights back
    assert "newt" in ep.obs
    while not ep.done:
        ep.step("SEARCH")
    assert ep.info["won"] is False and ep.ret == -1.0 and ep.task.turn < 250


# -- memento-hard -----------------------------------------------------------------------------------
def cues(task) -> tuple[tuple[int, ...], tuple[int, int]]:
    """The cue kinds shown at the start (0 or 1 each) and the level's offset on the screen."""
    ox, oy = task.hero[0] - custom.START[0], task.hero[1] - custom.START[1]
    names = [render.text(task.obs("screen_descriptions")[y + oy, x + ox]) for (x, y), _ in custom.CUES]
    kinds = tuple([name for _, name in options].index(seen) for seen, (_, options) in zip(names, custom.CUES))
    return kinds, (ox, oy)


def memento_player(ep: Episode, row: int, offset: tuple[int, int]) -> None:
    """East along the corridor, up or down the junction column to branch ``row``, then east to
    its end (attacking what waits there)."""
    ox, oy = offset
    for x, y in ((custom.JUNCTION_X, custom.CORRIDOR_Y), (custom.JUNCTION_X, row), (custom.END_X, row)):
        while not ep.done and ep.task.hero != (x + ox, y + oy) and ep.task.turn < 400:
            ep.step(toward(ep.task, (x + ox, y + oy)))


@pytest.mark.parametrize("seed", [0, 2])
def test_memento_hard_right_branch_wins(seed):
    ep = Episode(make("memento-hard"), seed)
    kinds, offset = cues(ep.task)
    memento_player(ep, custom.branch_row(kinds), offset)
    assert ep.done and ep.info["won"] is True and ep.ret == 1.0
    assert "You kill the grid bug!" in ep.task.frame.message


@pytest.mark.parametrize("seed", [0, 1])
def test_memento_hard_wrong_branch_loses(seed):
    ep = Episode(make("memento-hard"), seed)
    kinds, offset = cues(ep.task)
    right = custom.branch_row(kinds)
    wrong = custom.BRANCH_ROWS[(custom.BRANCH_ROWS.index(right) + 3) % len(custom.BRANCH_ROWS)]
    memento_player(ep, wrong, offset)
    assert ep.done and ep.info["won"] is False and ep.ret == -1.0
    assert re.search(r"A board beneath you squeaks", ep.task.frame.message)
    assert ep.task.hero == (custom.BOARD_X + offset[0], wrong + offset[1])


def test_memento_hard_shows_three_cues_at_the_start_and_covers_all_eight_branches():
    task = make("memento-hard")
    seen = set()
    for seed in range(24):
        task.reset(seed=seed)
        kinds, _ = cues(task)                   # (raises if a cue cell shows no cue monster)
        seen.add(custom.branch_row(kinds))
    assert seen == set(custom.BRANCH_ROWS)


def test_memento_hard_differs_from_upstream_memento_f4():
    des = custom.memento_hard_des()
    assert des.count("IF [50%]") == 7 and des.count('"grid bug"') == 8
    assert des.count('TRAP:"board"') == 8 * 7
    assert sorted(custom.branch_row(k) for k in np.ndindex(2, 2, 2)) == list(custom.BRANCH_ROWS)
