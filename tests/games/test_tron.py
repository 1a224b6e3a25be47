import random

import pytest

import glyphbench_rl
from glyphbench_rl.games.common.grid import bfs_distances
from glyphbench_rl.games.common.palette import WALL
from glyphbench_rl.games.classics.tron import flood

ID = "glyphbench/classics-tron-v0"
NAMES = ("UP", "DOWN", "LEFT", "RIGHT")


def test_flood_matches_bfs():
    task = glyphbench_rl.make(ID, walls=10)
    for seed in range(5):
        task.reset(seed=seed)
        n = task.params.size
        r, c = task.pos[0]
        start = (r, c + 1)
        free = ~task.blocked
        got = flood(1 << task.index(*start), free, task.W)
        want = bfs_distances(start, lambda a, b: 0 <= a < n and 0 <= b < n
                             and not task.blocked >> task.index(a, b) & 1)
        assert got == sum(1 << task.index(a, b) for a, b in want)


def greedy(task):
    """Your own flood-fill player: the safe move with the most reachable space, then the move
    farthest from the opponent's head (fixed order breaks ties)."""
    r, c = task.pos[0]
    orr, oc = task.pos[1]
    free = ~task.blocked
    best, best_key = 0, None
    for d, step in enumerate(task.steps):
        target = task.index(r, c) + step
        if free >> target & 1:
            (dr, dc) = ((-1, 0), (1, 0), (0, -1), (0, 1))[d]
            key = (flood(1 << target, free, task.W).bit_count(), abs(r + dr - orr) + abs(c + dc - oc))
            if best_key is None or key > best_key:
                best, best_key = d, key
    return best


def test_win_path_against_a_random_opponent():
    wins = 0
    for seed in range(10):
        task = glyphbench_rl.make(ID, strength=0.0)
        task.reset(seed=seed)
        while not task.done:
            _, _, term, _, info = task.step(greedy(task))
        if task.won:
            wins += 1
            assert task.episode_return == 1.0 and info["frame"].message.endswith("You win. Reward +1")
            assert "The opponent crashed." in info["frame"].message
    assert wins >= 8


def test_loss_path_riding_off_the_left_edge():
    task = glyphbench_rl.make(ID)
    task.reset(seed=0)
    _, reward, term, _, _ = task.step("LEFT")   # from column B to column A
    assert reward == 0.0 and not term
    _, reward, term, _, info = task.step("LEFT")
    assert term and task.won is False and reward == -1.0 and task.episode_return == -1.0
    assert "You crashed." in info["frame"].message and "*" in "".join(info["frame"].grid)


def test_same_cell_is_a_draw():
    task = glyphbench_rl.make(ID, size=6, walls=0)
    task.reset(seed=0)
    # Put the bikes two cells apart and wall the opponent in, except towards the middle cell.
    for (r, c), glyph in zip(task.pos, ("·", "·")):
        task.cells[r][c] = glyph
    task.pos = [(2, 1), (2, 3)]
    task.cells[2][1], task.cells[2][3] = "@", "E"
    task.blocked = task.border | (1 << task.index(2, 1)) | (1 << task.index(2, 3))
    for r, c in ((1, 3), (3, 3), (2, 4)):
        task.cells[r][c] = WALL
        task.blocked |= 1 << task.index(r, c)
    task.redraw()
    _, reward, term, _, info = task.step("RIGHT")
    assert term and reward == 0.0 and task.won is False
    assert info["frame"].message == "Both bikes crashed. Draw."


def test_trails_and_walls_are_symmetric():
    task = glyphbench_rl.make(ID)
    for seed in range(10):
        task.reset(seed=seed)
        n = task.params.size
        grid = task.frame.grid
        walls = {(r, c) for r in range(n) for c in range(n) if grid[r][c] == WALL}
        assert len(walls) == 2 * task.params.walls
        assert walls == {(n - 1 - r, n - 1 - c) for r, c in walls}
        (ar, ac), (orr, oc) = task.pos
        assert (orr, oc) == (n - 1 - ar, n - 1 - ac) and grid[ar][ac] == "@" and grid[orr][oc] == "E"
    task.step("UP")
    r, c = task.pos[0]
    assert task.frame.grid[r + 1][c] == "o" and task.frame.grid[r][c] == "@"
    assert "e" in "".join(task.frame.grid)


def test_opponent_prefers_the_larger_region():
    task = glyphbench_rl.make(ID, size=8, walls=0, strength=1.0)
    task.reset(seed=0)
    orr, oc = task.pos[1]
    # A wall across the column left of the opponent, open only at the opponent's row: going
    # LEFT leads to the big region, any other move leaves a small strip.
    for r in range(8):
        if r != orr and task.cells[r][oc - 1] == "·":
            task.cells[r][oc - 1] = WALL
            task.blocked |= 1 << task.index(r, oc - 1)
    safe = task.opponent_safe()
    assert task.opponent_best(safe) == [2] and 2 in safe


def test_ring_table_agrees_with_the_fill():
    """The safe moves and the one-region shortcut from the table round the opponent's head give
    the flood fill's choice, on random boards."""
    rng = random.Random(0)
    task = glyphbench_rl.make(ID, size=8, walls=0)
    task.reset(seed=0)
    n, shortcuts = task.params.size, 0
    for _ in range(400):
        density = rng.random() * 0.6
        task.blocked = task.border | sum(1 << task.index(r, c) for r in range(n) for c in range(n)
                                         if rng.random() < density)
        task.pos = rng.sample([(r, c) for r in range(n) for c in range(n)], 2)
        for head in task.heads:
            task.blocked |= 1 << head
        o = task.heads[1]
        safe, joined = task.ring[task.around(o)]
        assert safe == tuple(d for d, step in enumerate(task.steps) if not task.blocked >> o + step & 1)
        assert task.opponent_best(safe, joined) == task.opponent_best(safe)
        shortcuts += joined and len(safe) > 1
    assert shortcuts > 50


def test_bad_params():
    with pytest.raises(ValueError, match="size"):
        glyphbench_rl.make(ID, size=5)
    with pytest.raises(ValueError, match="walls"):
        glyphbench_rl.make(ID, walls=100)
    with pytest.raises(ValueError, match="strength"):
        glyphbench_rl.make(ID, strength=2)


def test_reversing_into_your_trail_crashes_and_the_prompt_says_so():
    task = glyphbench_rl.make(ID, walls=0)
    task.reset(seed=0)
    assert "(reversing) enters your own trail: a crash" in task.system_prompt()
    task.step("RIGHT")
    _, reward, term, _, info = task.step("LEFT")
    assert term and task.won is False and reward == -1.0
    assert "You crashed." in info["frame"].message
