"""The speed work changes nothing the agent sees or gets: the lean environment step gives
upstream's rewards, ends and arrays, and the incremental grid painter draws what the plain
one-shot renderer draws."""

from __future__ import annotations

import numpy as np
import pytest
from minihack.envs.room import MiniHackRoom5x5

import glyphbench_rl
from glyphbench_rl.games.nethack import render
from glyphbench_rl.games.nethack.lean import lean, upstream_classes


def _play(task, seed: int, actions) -> list:
    seen = [task.reset(seed=seed)[0]]
    for a in actions:
        if task.done:
            break
        seen.append(task.step(int(a))[:4])
    return seen


@pytest.mark.parametrize("name, reads", [
    ("room-monster-5x5", "none"),       # no reward manager: nothing of the previous step is read
    ("memento-short", "none"),          # message and kill events only
    ("keyroom-s5", "none"),             # its own step (opens doors) runs first, then the lean one
    ("boxoban-medium", "all"),          # its own reward function reads the previous boulders
])
def test_lean_step_plays_as_upstream(name, reads):
    task_id = f"glyphbench/minihack-{name}-v0"
    ours = glyphbench_rl.make(task_id)
    with upstream_classes():
        theirs = glyphbench_rl.make(task_id)
        theirs.reset(seed=0)                        # (the env is built at the first reset)
    ours.reset(seed=0)
    assert type(ours.env) is lean(type(theirs.env)) is not type(theirs.env)
    assert ours.env._previous_reads() == {"none": (), "all": None}[reads]
    actions = np.random.default_rng(5).integers(ours.action_space.n, size=80)
    for seed in (1, 2):
        assert _play(ours, seed, actions) == _play(theirs, seed, actions)


def test_lean_step_with_a_time_penalty_copies_blstats_and_pays_the_same():
    def run(env):
        env.seed(3, 4, False)
        env.reset()
        out = []
        for key in np.random.default_rng(1).integers(len(env.actions), size=60):
            obs, reward, done, _, info = env.step(int(key))
            out.append((reward, done, int(info["end_status"]), obs["blstats"].tolist()))
            if done:
                break
        return out
    kwargs = dict(observation_keys=("blstats",), penalty_step=-0.01, penalty_time=-0.001, max_episode_steps=50)
    lean_env, upstream = lean(MiniHackRoom5x5)(**kwargs), MiniHackRoom5x5(**kwargs)
    assert lean_env._previous_reads() == (lean_env._blstats_index,)
    ours, theirs = run(lean_env), run(upstream)
    assert ours == theirs and any(r < 0 for r, *_ in ours)
    lean_env.close(), upstream.close()


@pytest.mark.parametrize("name", ["mazewalk-mapped-45x19", "room-monster-15x15", "eat-distract", "room-dark-15x15",
                                  "river-monster", "corridor-r3"])
def test_painter_draws_what_the_one_shot_renderer_draws(name):
    task = glyphbench_rl.make(f"glyphbench/minihack-{name}-v0")
    actions = np.random.default_rng(2).integers(task.action_space.n, size=150)
    for seed in (0, 1):
        task.reset(seed=seed)
        spec = render.Glyphs()               # the plain renderer's own assignment, fed every turn
        scrolled = False
        for a in [None, *actions]:
            if a is not None:
                if task.done:
                    break
                task.step(int(a))
            if task.status == 1:             # (dead: NetHack shows its end screens)
                break
            rows = render.grid_rows(task.obs("chars"), task.obs("glyphs"), task.obs("screen_descriptions"),
                                    task._bounds, task.hero, spec)
            assert list(task.frame.grid) == rows
            assert dict(task.frame.legend).items() <= spec.vocab.items()
            scrolled |= task.view.scrolled(task._bounds)
        assert scrolled == (name == "mazewalk-mapped-45x19")


def _arrays(cells: dict[tuple[int, int], tuple[int, str, str]]):
    """NLE-shaped arrays: every cell blank stone but ``cells`` {(x, y): (glyph, char, description)}."""
    glyphs = np.full((render.ROWS, render.COLS), 2359, np.int16)
    chars = np.full((render.ROWS, render.COLS), 32, np.uint8)
    descriptions = np.zeros((render.ROWS, render.COLS, 80), np.uint8)
    for (x, y), (glyph, char, text) in cells.items():
        glyphs[y, x], chars[y, x] = glyph, ord(char)
        descriptions[y, x, :len(text)] = np.frombuffer(text.encode(), np.uint8)
    return chars, glyphs, descriptions


def test_painter_looks_again_at_varying_glyphs_on_synthetic_maps():
    varies = np.zeros(6000, bool)
    varies[:2000] = True                               # "monsters" and "objects"
    floor = {(x, y): (2378, ".", "floor of a room") for x in range(2, 12) for y in range(2, 5)}
    turns = [   # (hero, extra cells): a jackal turns peaceful where it stands; two stacks of apples
        ((2, 2), {(4, 3): (20, "d", "jackal"), (5, 4): (1990, "%", "apple"), (6, 4): (1990, "%", "2 apples")}),
        ((3, 2), {(4, 3): (20, "d", "peaceful jackal"), (5, 4): (1990, "%", "apple"), (6, 4): (1990, "%", "2 apples")}),
        ((11, 2), {(4, 3): (20, "d", "peaceful jackal"), (6, 4): (1990, "%", "apple")}),   # (the view scrolls)
        ((2, 2), {(4, 3): (20, "d", "jackal"), (6, 4): (1990, "%", "apple")}),
    ]
    painter, spec = render.Painter(render.Glyphs(), varies, view=(21, 6)), render.Glyphs()
    shown = []
    for hero, extra in turns:
        cells = {**floor, **extra, hero: (337, "@", "human rogue called Agent")}
        chars, glyphs, descriptions = _arrays(cells)
        bounds = painter.update(chars, glyphs, descriptions, hero)
        rows = painter.rows()
        assert rows == render.grid_rows(chars, glyphs, descriptions, bounds, hero, spec)
        shown.append({painter.assign.vocab[c] for row in rows for c in row})
    assert {"jackal", "apple", "2 apples"} <= shown[0] and "peaceful jackal" in shown[1]
    assert "jackal" not in shown[2] and "apple" in shown[2] and "2 apples" not in shown[2]
    assert "jackal" in shown[3] and "peaceful jackal" not in shown[3]
