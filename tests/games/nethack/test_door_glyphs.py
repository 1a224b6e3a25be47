"""The direction rule's "nearest door" knows NetHack's door glyphs: every doorway, open and
closed door (vertical and horizontal) and no wall piece."""

from __future__ import annotations

import numpy as np

import glyphbench_rl
from glyphbench_rl.games.nethack import engine, render


def test_door_glyphs_are_the_doors_on_the_map():
    task = glyphbench_rl.make("glyphbench/minihack-corridor-r3-v0")
    doors, walls = set(), set()
    for seed in range(4):
        task.reset(seed=seed)
        for turn in range(120):
            if task.done:
                break
            task.step(turn * 5 % 8)
            glyphs, descriptions = task.obs("glyphs"), task.obs("screen_descriptions")
            for y, x in zip(*np.nonzero(glyphs >= 2359)):
                text = render.text(descriptions[y, x])
                if text.endswith(("door", "doorway")):
                    doors.add(int(glyphs[y, x]))
                elif text == "wall":
                    walls.add(int(glyphs[y, x]))
    assert doors and walls
    assert doors <= set(engine._DOOR_GLYPHS.tolist()) and not walls & set(engine._DOOR_GLYPHS.tolist())
