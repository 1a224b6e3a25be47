from itertools import product

import numpy as np
import pytest

import glyphbench_rl
from glyphbench_rl.games.classics.pipeconnect import COST, DELTAS, KINDS, solve, turn

VARIANTS = ["easy", "medium", "hard"]


def connected(masks, n, source, drain):
    """Independent check: does water from ``source`` reach ``drain``? (masks of the other cells)"""
    seen, stack = {source}, [source]
    while stack:
        i = stack.pop()
        m = 0b1111 if i == source else masks[i]
        for d, (dr, dc) in enumerate(DELTAS):
            r, c = i // n + dr, i % n + dc
            j = r * n + c
            if m >> d & 1 and 0 <= r < n and 0 <= c < n and j not in seen:
                if j == drain:
                    return True
                if j != source and masks[j] >> (d + 2) % 4 & 1:
                    seen.add(j)
                    stack.append(j)
    return False


def test_turn_and_costs():
    assert turn(0b0101, 1) == 0b1010 and turn(0b0011, 3) == 0b1001
    straight, elbow, tee = range(3)   # indices into KINDS
    assert COST[straight][0][0b0101] == 0 and COST[straight][1][0b0101] == 1
    assert COST[straight][0][0b0011] == 99                       # a straight cannot turn a corner
    assert COST[elbow][0][0b1001] == 3 and COST[tee][0][0b1010] == 1


@pytest.mark.parametrize("seed", range(8))
def test_solver_is_minimal_by_brute_force(seed):
    n, source, drain = 3, 0, 8                                   # opposite corners
    rng = np.random.default_rng(seed)
    kinds = rng.integers(3, size=9).tolist()
    rots = rng.integers(4, size=9).tolist()
    free = [i for i in range(9) if i not in (source, drain)]
    best = None
    for quarters in product(range(4), repeat=len(free)):
        cost = sum(quarters)
        if best is not None and cost >= best:
            continue
        masks = [0] * 9
        for i, q in zip(free, quarters):
            masks[i] = turn(KINDS[kinds[i]], rots[i] + q)
        if connected(masks, n, source, drain):
            best = cost
    found = solve(kinds, rots, n, source, drain)
    if best is None:
        assert found is None
    else:
        assert found is not None and found[0] == best


def plan(task):
    """Rotations turning each route tile to join its neighbours on the route (cheapest way)."""
    n, route = task.params.size, [task.source] + task.route
    actions = []
    for prev, cell, nxt in zip(route, route[1:], route[2:]):
        need = 0
        for other in (prev, nxt):
            dr, dc = other // n - cell // n, other % n - cell % n
            need |= 1 << DELTAS.index((dr, dc))
        q = COST[task.kinds[cell]][task.rots[cell]][need]
        actions += [task.actions[cell].name] * q
    return actions


@pytest.mark.parametrize("variant", VARIANTS)
@pytest.mark.parametrize("seed", [0, 1, 2, 1_000_000])
def test_win_path_with_minimal_rotations(variant, seed):
    task = glyphbench_rl.make(f"glyphbench/classics-pipeconnect-{variant}-v0")
    task.reset(seed=seed)
    assert task.optimal_rotations >= task.params.min_rotations
    assert not task.connected
    actions = plan(task)
    assert len(actions) == task.optimal_rotations
    for name in actions:
        _, reward, term, trunc, info = task.step(name)
    assert term and task.won and task.turn == task.optimal_rotations and not info["clamped"]
    assert task.episode_return == pytest.approx(1 - 0.5 * task.turn / task.max_turns)
    assert "Water reaches the drain." in info["frame"].message
    grid = info["frame"].grid
    n = task.params.size
    assert all(grid[c // n][c % n] in "┃━┗┏┓┛┣┳┫┻" for c in task.route[:-1])   # wet all the way


@pytest.mark.parametrize("variant", VARIANTS)
def test_loss_path_turning_the_source(variant):
    task = glyphbench_rl.make(f"glyphbench/classics-pipeconnect-{variant}-v0")
    task.reset(seed=4)
    name = task.actions[task.source].name
    while not task.done:
        _, reward, term, trunc, info = task.step(name)
        assert reward == 0.0
    assert trunc and task.won is None and task.episode_return == 0.0
    assert "do not turn" in info["frame"].message


def test_rotation_and_rendering():
    task = glyphbench_rl.make("glyphbench/classics-pipeconnect-easy-v0")
    obs, _ = task.reset(seed=0)
    assert task.action_space.n == 25
    assert glyphbench_rl.make("glyphbench/classics-pipeconnect-hard-v0").action_space.n == 81
    lines = obs.splitlines()
    assert lines[0] == "Step 0/30" and lines[1] == "  ABCDE"
    n = 5
    cell = next(i for i in range(25) if i not in (task.source, task.drain))
    before = task.masks[cell]
    task.step(cell)
    assert task.masks[cell] == turn(before, 1)
    grid = task.frame.grid
    assert grid[task.source // n][task.source % n] == "◉" and grid[task.drain // n][task.drain % n] == "◎"
    for i in set(range(25)) - {task.source, task.drain}:
        r, c = divmod(i, n)
        wet = grid[r][c] in "┃━┗┏┓┛┣┳┫┻"
        assert wet == bool(task._wet >> i & 1)


def test_bad_params():
    with pytest.raises(ValueError, match="size"):
        glyphbench_rl.make("glyphbench/classics-pipeconnect-easy-v0", size=2)
    with pytest.raises(ValueError, match="min_rotations"):
        glyphbench_rl.make("glyphbench/classics-pipeconnect-easy-v0", min_rotations=0)
    with pytest.raises(ValueError, match="time_weight"):
        glyphbench_rl.make("glyphbench/classics-pipeconnect-easy-v0", time_weight=1.5)
