"""Boxoban level generation, the solver, and the levels played in real NetHack (MiniHack)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from glyphbench_rl.games.common.pushing import PushRoom, bits, pull_layers, search
from glyphbench_rl.games.nethack import boxoban
from glyphbench_rl.games.nethack.boxoban import (BOXES, DIFFICULTIES, PUSHES, SIZE, Level, generate,
                                                 solve, to_des)

ROOT = Path(__file__).resolve().parents[3]
STEP = {"N": (-1, 0), "S": (1, 0), "E": (0, 1), "W": (0, -1)}
SEEDS = range(50)


def play(level: Level, moves: list[str]) -> tuple[set, int, list]:
    """A tiny Sokoban of its own: the boxes at the end, the pushes, and the player's cells.
    Fails on a move into a wall or a push into a wall or a box."""
    walls, boxes = set(level.cells("#")), set(level.cells("$"))
    (r, c), pushes, trail = level.player, 0, []
    for move in moves:
        dr, dc = STEP[move]
        r, c = r + dr, c + dc
        assert (r, c) not in walls, f"walked into a wall at {(r, c)}"
        if (r, c) in boxes:
            beyond = (r + dr, c + dc)
            assert beyond not in walls and beyond not in boxes, f"blocked push at {(r, c)}"
            boxes.remove((r, c))
            boxes.add(beyond)
            pushes += 1
        trail.append((r, c))
    return boxes, pushes, trail


def pad(*rows: str) -> Level:
    """A small level drawn in the top-left corner of a SIZE x SIZE walled room."""
    rows = [row.ljust(SIZE, "#") for row in rows]
    return Level(tuple(rows + ["#" * SIZE] * (SIZE - len(rows))))


@pytest.fixture(scope="module")
def levels() -> dict[tuple[str, int], Level]:
    return {(d, seed): generate(np.random.default_rng(seed), d) for d in DIFFICULTIES for seed in SEEDS}


def test_levels_have_boxoban_form(levels):
    for level in levels.values():
        assert len(level.rows) == SIZE and all(len(row) == SIZE for row in level.rows)
        assert len(level.cells("$")) == len(level.cells(".")) == BOXES and len(level.cells("@")) == 1
        assert set(level.rows[0] + level.rows[-1]) == {"#"}
        assert all(row[0] == row[-1] == "#" for row in level.rows)
        floor = {(r, c) for r in range(SIZE) for c in range(SIZE) if level.rows[r][c] != "#"}
        seen, todo = {level.player}, [level.player]     # one connected room
        while todo:
            r, c = todo.pop()
            for dr, dc in STEP.values():
                if (r + dr, c + dc) in floor and (r + dr, c + dc) not in seen:
                    seen.add((r + dr, c + dc))
                    todo.append((r + dr, c + dc))
        assert seen == floor
        assert Level.from_text(level.text) == level


def test_every_level_is_solved_with_pushes_in_its_band(levels):
    for (difficulty, seed), level in levels.items():
        moves = solve(level)
        assert moves is not None, (difficulty, seed)
        boxes, pushes, _ = play(level, moves)
        assert boxes == set(level.cells(".")), (difficulty, seed)
        fewest, most = PUSHES[difficulty]
        # the solver is push-optimal, so these are the level's fewest pushes
        assert pushes >= fewest and (most is None or pushes <= most), (difficulty, seed, pushes)


def test_pull_layers_are_exact_push_counts():
    """A state in reverse play's layer k needs exactly k pushes, by the push-optimal solver."""
    level = generate(np.random.default_rng(11), "hard")
    room = PushRoom(level.cells("#"), SIZE, SIZE, level.cells("."))
    layers = pull_layers(room, 5000)
    rng = np.random.default_rng(0)
    for k, layer in enumerate(layers):
        for i in rng.choice(len(layer), size=min(3, len(layer)), replace=False):
            boxes, region = layer[int(i)]
            found = search(room, boxes, bits(region)[0])
            assert found is not None and found[1] == k


def test_the_docstring_states_the_bands():
    (m_lo, m_hi), (h_lo, _) = PUSHES["medium"], PUSHES["hard"]
    assert f"needing {m_lo} to {m_hi} pushes" in boxoban.__doc__
    assert f"needing {h_lo} or more" in boxoban.__doc__


def test_same_seed_same_level_and_seeds_vary(levels):
    for difficulty in DIFFICULTIES:
        assert generate(np.random.default_rng(7), difficulty) == levels[difficulty, 7]
        assert len({levels[difficulty, seed] for seed in SEEDS}) == len(SEEDS)


def test_same_level_across_processes(levels):
    code = ("import numpy as np\n"
            "from glyphbench_rl.games.nethack.boxoban import DIFFICULTIES, generate\n"
            "for d in DIFFICULTIES:\n"
            "    for s in range(3):\n"
            "        print(generate(np.random.default_rng(s), d).text)\n")
    here = "\n".join(levels[d, s].text for d in DIFFICULTIES for s in range(3)) + "\n"
    for hashseed in ("0", "4242"):
        env = dict(os.environ, PYTHONHASHSEED=hashseed,
                   PYTHONPATH=os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]))
        out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env,
                             check=True, cwd=ROOT)
        assert out.stdout == here


def test_solver_on_hand_made_levels():
    assert solve(pad("#####", "#@$.#", "#####")) == ["E"]
    moves = solve(pad("######", "#@   #", "# $$ #", "# .. #", "######"))
    assert moves is not None and play(pad("######", "#@   #", "# $$ #", "# .. #", "######"), moves)[1] == 2
    assert solve(pad("#####", "#$ .#", "# @ #", "#####")) is None        # a box in a corner
    assert solve(pad("######", "#@$$.#", "#   .#", "######")) is None    # a box behind a box on a wall


def test_level_rejects_bad_text():
    good = pad("#####", "#@$.#", "#####")
    with pytest.raises(ValueError):
        Level(good.rows[:-1])
    with pytest.raises(ValueError):
        Level(("@" + good.rows[0][1:],) + good.rows[1:])                  # no wall ring
    with pytest.raises(ValueError):
        Level((good.rows[0], "#@$.x#####") + good.rows[2:])               # unknown character
    with pytest.raises(ValueError):
        Level((good.rows[0], "#@$$.#####") + good.rows[2:])               # boxes != targets
    with pytest.raises(ValueError):
        generate(np.random.default_rng(0), "expert")


# -- real NetHack ----------------------------------------------------------------------------------
SCREEN = {"#": "#", " ": ".", "$": "`", ".": "{", "@": "@"}   # how NetHack draws each level cell


def test_des_is_what_minihack_boxohack_builds(levels):
    """MiniHack's own BoxoHack.get_lvl_gen, fed our level as one line of a level file."""
    from types import SimpleNamespace

    from minihack.envs.boxohack import BoxoHack

    for difficulty in DIFFICULTIES:
        level = levels[difficulty, 0]
        upstream = SimpleNamespace(_levels=[level.text + "\n"], _flags=(),
                                   get_env_map=lambda rows: BoxoHack.get_env_map(None, rows))
        assert to_des(level) == BoxoHack.get_lvl_gen(upstream).get_des()


@pytest.mark.parametrize("difficulty", DIFFICULTIES)
def test_solution_solves_the_level_in_minihack(levels, difficulty):
    """The level built from ``to_des`` in MiniHack shows what the level says, and the solver's
    moves, played as NetHack cardinal moves, walk where the Sokoban rules say and end with every
    boulder on a fountain, the success test of MiniHack's BoxoHack (fountain cells at reset ==
    boulder cells)."""
    from minihack import MiniHackNavigation
    from nle.nethack import CompassCardinalDirection

    level = levels[difficulty, 3]
    moves = solve(level)
    actions = tuple(CompassCardinalDirection)          # what BoxoHack allows, in its order
    env = MiniHackNavigation(des_file=to_des(level), observation_keys=("chars",), actions=actions,
                             max_episode_steps=len(moves) + 10)
    try:
        env.unwrapped.seed(1, 2, False)
        obs, _ = env.reset()
        chars = obs["chars"]
        (y0,), (x0,) = np.nonzero(chars == ord("@"))
        top, left = y0 - level.player[0], x0 - level.player[1]
        screen = [bytes(row).decode("ascii") for row in chars]
        for r, row in enumerate(level.rows):
            assert screen[top + r][left:left + SIZE] == "".join(SCREEN[ch] for ch in row)
        outside = "".join(row[:left] + row[left + SIZE:] for row in screen[top:top + SIZE])
        assert set(outside + "".join(screen[:top] + screen[top + SIZE:])) <= {" "}
        cells = lambda ch: set(zip(*np.nonzero(obs["chars"] == ord(ch))))  # noqa: E731
        fountains = cells("{")
        assert len(fountains) == BOXES
        _, _, trail = play(level, moves)
        for move, (r, c) in zip(moves, trail):
            action = actions.index(getattr(CompassCardinalDirection, move))
            obs, _, terminated, truncated, _ = env.step(action)
            assert not terminated and not truncated
            assert cells("@") == {(top + r, left + c)}
        assert cells("`") == fountains
    finally:
        env.close()
