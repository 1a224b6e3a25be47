from itertools import product

import numpy as np
import pytest

import glyphbench_rl
from glyphbench_rl.games.classics.lightsout import press_masks, solve

VARIANTS = ["easy", "hard"]


def board_from_mask(mask, size):
    return [[bool(mask >> (r * size + c) & 1) for c in range(size)] for r in range(size)]


def apply(lights, presses):
    """The board state (bitmask) after pressing ``presses`` on ``lights``."""
    size = len(lights)
    state = sum(1 << (r * size + c) for r in range(size) for c in range(size) if lights[r][c])
    masks = press_masks(size)
    for r, c in presses:
        state ^= masks[r * size + c]
    return state


def chase_optimum(lights):
    """Fewest presses by light chasing, independent of the GF(2) solver: once the first row's
    presses are chosen, each later row must press exactly under the lights left above it."""
    size = len(lights)
    masks = press_masks(size)
    best = None
    for first in range(1 << size):
        state = apply(lights, [])
        count = 0
        for c in range(size):
            if first >> c & 1:
                state ^= masks[c]
                count += 1
        for r in range(1, size):
            for c in range(size):
                if state >> ((r - 1) * size + c) & 1:
                    state ^= masks[r * size + c]
                    count += 1
        if state == 0 and (best is None or count < best):
            best = count
    return best


@pytest.mark.parametrize("size", [2, 3, 4])
def test_solver_is_minimal_by_brute_force(size):
    n = size * size
    masks = press_masks(size)
    best = {}
    for presses in product((0, 1), repeat=n):  # every press set: the lightest per board
        state = 0
        for j, on in enumerate(presses):
            if on:
                state ^= masks[j]
        best[state] = min(best.get(state, n + 1), sum(presses))
    for state in range(0, 1 << n, max(1, (1 << n) // 97)):
        sol = solve(board_from_mask(state, size))
        if state not in best:
            assert sol is None
        else:
            assert sol is not None and apply(board_from_mask(state, size), sol) == 0
            assert len(sol) == best[state]


@pytest.mark.parametrize("size", [5, 6, 7, 9])
def test_solver_clears_random_boards_minimally(size):
    rng = np.random.default_rng(size)
    for _ in range(40 if size < 9 else 10):  # 9x9 chasing tries 512 first rows per board
        lights = rng.random((size, size)) < 0.5
        lights = [[bool(x) for x in row] for row in lights]
        sol = solve(lights)
        optimum = chase_optimum(lights)
        if optimum is None:
            assert sol is None
        else:
            assert sol is not None and apply(lights, sol) == 0 and len(sol) == optimum
            assert len(set(sol)) == len(sol)


def test_single_corner_on_5x5_is_unsolvable():
    lights = [[False] * 5 for _ in range(5)]
    lights[0][0] = True
    assert solve(lights) is None
    assert solve([[False] * 5 for _ in range(5)]) == []
    with pytest.raises(ValueError):
        solve([[True, False]])


@pytest.mark.parametrize("variant", VARIANTS)
@pytest.mark.parametrize("seed", [0, 1, 2, 1_000_000])
def test_win_path_with_optimal_presses(variant, seed):
    task = glyphbench_rl.make(f"glyphbench/classics-lightsout-{variant}-v0")
    task.reset(seed=seed)
    plan = solve(task.lights())
    assert len(plan) == task.optimal_presses >= task.params.min_presses
    for r, c in plan:
        _, reward, term, trunc, info = task.step(f"{chr(65 + c)}{r + 1}")
    assert term and not trunc and task.won and not info["clamped"]
    assert task.turn == task.optimal_presses
    assert 0.5 <= task.episode_return <= 1
    assert task.episode_return == pytest.approx(1 - 0.5 * len(plan) / task.max_turns)
    assert "All lights are off." in info["frame"].message


@pytest.mark.parametrize("variant", VARIANTS)
def test_loss_path_pressing_one_cell_back_and_forth(variant):
    task = glyphbench_rl.make(f"glyphbench/classics-lightsout-{variant}-v0")
    task.reset(seed=4)
    while not task.done:
        _, reward, term, trunc, info = task.step("C3")
        assert reward == 0.0
    assert trunc and not term and task.won is None
    assert task.episode_return == 0.0 and not info["clamped"]


@pytest.mark.parametrize("variant", VARIANTS)
def test_generated_boards_are_solvable_and_unsolved(variant):
    task = glyphbench_rl.make(f"glyphbench/classics-lightsout-{variant}-v0")
    for seed in range(30):
        obs, _ = task.reset(seed=seed)
        plan = solve(task.lights())
        assert task.state != 0 and plan is not None and apply(task.lights(), plan) == 0
        assert len(plan) == task.optimal_presses >= task.params.min_presses
        assert f"Lit {task.state.bit_count()}" in obs.splitlines()[0]


def test_same_seed_same_board():
    a = glyphbench_rl.make("glyphbench/classics-lightsout-hard-v0")
    b = glyphbench_rl.make("glyphbench/classics-lightsout-hard-v0")
    assert a.reset(seed=7)[0] == b.reset(seed=7)[0]
    assert a.reset(seed=8)[0] != b.reset(seed=7)[0]


def test_cell_actions_axes_and_rendering():
    task = glyphbench_rl.make("glyphbench/classics-lightsout-easy-v0")
    assert task.action_space.n == 25 and task.actions.names[:6] == ("A1", "B1", "C1", "D1", "E1", "A2")
    assert glyphbench_rl.make("glyphbench/classics-lightsout-hard-v0").action_space.n == 49
    obs, _ = task.reset(seed=0)
    lines = obs.splitlines()
    assert lines[1] == "  ABCDE"
    grid = [line[2:] for line in lines[2:7]]
    assert grid == ["".join("●" if on else "·" for on in row) for row in task.lights()]
    before = task.lights()
    task.step("A1")  # corner press: toggles A1, B1 and A2 only
    after = task.lights()
    changed = {(r, c) for r in range(5) for c in range(5) if before[r][c] != after[r][c]}
    assert changed == {(0, 0), (0, 1), (1, 0)}
    prompt = task.system_prompt()
    assert "named like C4" in prompt and "1 minus 0.5 x (turns used / 50)" in prompt


def test_bad_params():
    with pytest.raises(ValueError, match="size"):
        glyphbench_rl.make("glyphbench/classics-lightsout-easy-v0", size=1)
    with pytest.raises(ValueError, match="min_presses"):
        glyphbench_rl.make("glyphbench/classics-lightsout-easy-v0", min_presses=11)
    with pytest.raises(ValueError, match="time_weight"):
        glyphbench_rl.make("glyphbench/classics-lightsout-easy-v0", time_weight=1.0)
    with pytest.raises(ValueError, match="max_turns"):
        glyphbench_rl.make("glyphbench/classics-lightsout-easy-v0", max_turns=513)


def test_impossible_min_presses_fails_loudly():
    # 5x5 optima never exceed 15 presses, so a floor of 20 can never be met
    task = glyphbench_rl.make("glyphbench/classics-lightsout-easy-v0", min_presses=20, max_scramble=25)
    with pytest.raises(RuntimeError, match="min_presses"):
        task.reset(seed=0)
