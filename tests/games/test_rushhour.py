from collections import deque

import pytest

import glyphbench_rl
from glyphbench_rl.core import check_frame
from glyphbench_rl.games.classics.rushhour import EXIT_ROW, N, Lot, solve

VARIANTS = ["easy", "hard"]


def make(variant, **kw):
    return glyphbench_rl.make(f"glyphbench/classics-rushhour-{variant}-v0", **kw)


def reference_moves(grid, limit=60):
    """Independent brute force on the drawn lot: BFS over the 6x6 text, moving letters."""
    start = "".join(row[:N] for row in grid)
    seen, queue = {start: 0}, deque([start])
    while queue:
        lot = queue.popleft()
        d = seen[lot]
        if lot[EXIT_ROW * N + N - 1] == "X":
            return d
        for name in set(lot) - {"·"}:
            cells = [i for i, ch in enumerate(lot) if ch == name]
            step = 1 if cells[1] - cells[0] == 1 else N
            for sign in (-1, 1):
                head = cells[-1] if sign == 1 else cells[0]
                new = head + sign * step
                if not 0 <= new < N * N or (step == 1 and new // N != head // N) or lot[new] != "·":
                    continue
                tail = cells[0] if sign == 1 else cells[-1]
                moved = list(lot)
                moved[new], moved[tail] = name, "·"
                moved = "".join(moved)
                if moved not in seen:
                    seen[moved] = d + 1
                    queue.append(moved)
    return None


@pytest.mark.parametrize("variant", VARIANTS)
def test_generated_levels_have_the_stated_optimum(variant):
    task = make(variant)
    for seed in range(6):
        _, info = task.reset(seed=seed)
        assert check_frame(info["frame"]) == []
        grid = info["frame"].grid
        assert len(grid) == N and {len(row) for row in grid} == {N + 1} and grid[EXIT_ROW][N] == "◎"
        assert task.optimal >= task.params.min_moves
        assert len(solve(task.lot, task.state)) == task.optimal
        if variant == "easy" or seed < 2:   # the brute force is slow on the bigger lots
            assert reference_moves(grid) == task.optimal


@pytest.mark.parametrize("variant", VARIANTS)
@pytest.mark.parametrize("seed", [0, 1, 1_000_003])
def test_win_path_with_optimal_moves(variant, seed):
    task = make(variant)
    task.reset(seed=seed)
    plan = solve(task.lot, task.state)
    assert len(plan) == task.optimal <= task.max_turns
    for action in plan:
        assert not task.done
        _, reward, term, trunc, info = task.step(int(action))
    assert term and task.won and not info["clamped"]
    expected = 1 - task.params.time_weight * task.optimal / task.max_turns
    assert task.episode_return == pytest.approx(expected) and expected > 0.5
    assert info["frame"].grid[EXIT_ROW][N - 2:N] == "XX"


def test_loss_path_shuffling_one_car_times_out():
    task = make("easy")
    task.reset(seed=2)
    while not task.done:
        for name in ("X_LEFT", "X_RIGHT"):   # never gets past its first blocker
            if not task.done:
                task.step(name)
    assert task._truncated and task.won is None and task.episode_return == 0.0


def test_blocked_move_changes_nothing():
    task = make("easy")
    task.reset(seed=0)
    grid = task.frame.grid
    row = grid[EXIT_ROW]
    ahead = row.index("X") + 2
    assert row[ahead] != "·"       # every level starts with the red car blocked
    _, reward, *_, info = task.step("X_RIGHT")
    assert reward == 0 and info["frame"].grid == grid and "X_RIGHT is blocked" in info["frame"].message


def test_solver_and_quick_check_on_a_hand_made_lot():
    # X at columns 0-1 of the exit row; vertical truck A in column 3 rows 0-2 can drop to rows
    # 3-5 in three moves; then X drives four cells: seven moves in all.
    lot = Lot([True, False], [EXIT_ROW, 3], [2, 3])
    state = lot.state([0, 0])
    assert lot.may_clear(state) and lot.distance(state, 1000) == 7 == len(solve(lot, state))
    # a second truck under the first in the same column: neither can clear the exit row
    lot = Lot([True, False, False], [EXIT_ROW, 3, 3], [2, 3, 3])
    state = lot.state([0, 0, 3])
    assert not lot.may_clear(state) and solve(lot, state) is None and lot.distance(state, 1000) is None


def test_actions_and_prompt():
    task = make("hard")
    assert len(task.actions) == 18
    assert task.actions.names[:4] == ("X_LEFT", "X_RIGHT", "A_LEFT", "A_RIGHT")
    assert "D_UP" in task.actions.names and "D_LEFT" not in task.actions.names
    prompt = task.system_prompt()
    assert "6x6 lot" in prompt and "Vehicles A, B, C move left and right" in prompt
    assert "vehicles D, E, F, G, H move up and down" in prompt


@pytest.mark.parametrize("bad, field", [
    (dict(horizontal=-1), "horizontal"), (dict(vertical=9), "vertical"), (dict(vertical=1.0), "vertical"),
    (dict(truck_chance=2), "truck_chance"), (dict(min_moves=0), "min_moves"),
    (dict(time_weight=-0.1), "time_weight"), (dict(colour=1), "unknown parameter 'colour'"),
])
def test_bad_params(bad, field):
    with pytest.raises(ValueError, match=field):
        make("easy", **bad)


def test_legend_says_which_way_each_vehicle_moves():
    task = glyphbench_rl.make("glyphbench/classics-rushhour-hard-v0")
    _, info = task.reset(seed=1)
    legend = info["frame"].legend_dict()
    p = task.params
    assert legend["X"] == "red car left-right"
    for i, name in enumerate(task.names[1:]):
        if name in legend:
            way = "left-right" if i < p.horizontal else "up-down"
            assert legend[name] == f"vehicle {way}", name
