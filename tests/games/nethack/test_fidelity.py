"""Every MiniHack task built on an upstream MiniHack ID plays upstream's own level: on the same
NetHack seeds, upstream's env (``gymnasium.make(<ID>)``, unwrapped) and our task start on the same
map (dungeon features, objects, monsters: NLE's ``chars`` and ``glyphs``), hero, inventory and
message, our grid is upstream's map through our glyph assignment, and a few moves keep them equal.

Only one of our env options matters here: ``fix_moon_phase``. Upstream's default takes the moon
phase from today's date, which changes the first message ("You are lucky!  Full moon tonight.")
and the hero's Luck, not the level; ours derives it from the seed (reproducible episodes), so
upstream is made with ``fix_moon_phase=True`` too. Our other options (the full action list, yes
to every question, the observation keys, no step cap or penalties) do not touch a reset or a move.
"""

from __future__ import annotations

import warnings

import gymnasium as gym
import numpy as np
import pytest
from nle import nethack

import glyphbench_rl
from glyphbench_rl.core import list_tasks
from glyphbench_rl.core.seeding import nle_seeds
from glyphbench_rl.games.nethack import render
from glyphbench_rl.games.nethack.levels import LEVELS

with warnings.catch_warnings():
    warnings.simplefilter("ignore")
    import minihack  # noqa: F401  (registers upstream's IDs)

SEEDS = (0, 1)
KEYS = ("chars", "glyphs", "screen_descriptions", "blstats", "inv_strs", "message")
MOVES = (("MOVE_E", nethack.CompassDirection.E), ("MOVE_S", nethack.CompassDirection.S),
         ("MOVE_W", nethack.CompassDirection.W), ("MOVE_NE", nethack.CompassDirection.NE))


def _upstream_tasks() -> list[tuple[str, str]]:
    """(our task ID, upstream ID) for every registered task whose level is upstream's."""
    out = []
    for task_id in list_tasks(pattern="glyphbench/minihack-*"):
        level = task_id[len("glyphbench/minihack-"):-len("-v0")]
        source = LEVELS[level].source
        if ":" not in source:           # "module:function" = a level of ours (custom, boxoban)
            out.append((task_id, source))
    return out


UPSTREAM = _upstream_tasks()


def test_every_upstream_level_is_checked():
    # all but our three levels (custom.py) and the three generated Boxoban levels
    assert len(UPSTREAM) == len(LEVELS) - 6 >= 57
    assert all(source.startswith("MiniHack-") for _, source in UPSTREAM)


@pytest.mark.parametrize("task_id,source", UPSTREAM, ids=[t for t, _ in UPSTREAM])
def test_our_level_is_upstreams(task_id, source):
    task = glyphbench_rl.make(task_id)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        up = gym.make(source, fix_moon_phase=True).unwrapped
    index = {k: up._observation_keys.index(k) for k in KEYS}

    def theirs(key: str) -> np.ndarray:
        return up.last_observation[index[key]]

    try:
        for seed in SEEDS:
            task.reset(seed=seed)
            core, disp, lgen = nle_seeds(seed)
            up.seed(core, disp, False, lgen)
            up.reset()
            for key in KEYS:
                assert np.array_equal(task.obs(key), theirs(key)), f"seed {seed}: {key} differs at reset"
            # our grid = upstream's map through our glyph assignment, cell by cell over our crop
            b = theirs("blstats")
            expected = render.grid_rows(theirs("chars"), theirs("glyphs"), theirs("screen_descriptions"),
                                        task._bounds, (int(b[0]), int(b[1])), task.glyph_map)
            assert task.frame.grid == tuple(expected), f"seed {seed}: grid differs"
            y0, y1, x0, x1 = task._bounds
            if not task.view.scrolled(task._bounds):   # (else a window of a wider map is shown)
                outside = theirs("chars").copy()
                outside[y0:y1, x0:x1] = 32
                assert (outside == 32).all(), f"seed {seed}: upstream shows cells our grid leaves out"
            for name, direction in MOVES:     # the same moves keep the two games equal
                _, _, terminated, _, _ = task.step(name)
                _, _, done, _, _ = up.step(up.actions.index(direction))
                assert terminated == done, f"seed {seed}: {name} ends one game only"
                if done:                      # (upstream then quits: its screens differ)
                    break
                for key in ("chars", "glyphs", "blstats"):
                    assert np.array_equal(task.obs(key), theirs(key)), f"seed {seed}: {key} differs after {name}"
    finally:
        task.close()
        up.close()
