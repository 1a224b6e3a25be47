from itertools import product

import pytest

import glyphbench_rl
from glyphbench_rl.games.classics.mirrorlaser import BACKSLASH, PRESSES, SLASH, solve, trace

ID = "glyphbench/classics-mirrorlaser-v0"


def name(task, i):
    return task.actions[i].name


def brute_force(cells, n, start, heading, max_mirrors):
    """Fewest actions over every placement of up to ``max_mirrors`` mirrors on the empty cells
    the beam could ever cross (any cell in the laser's row, column or a turn away is too many,
    so this tries every empty cell: fine on a 5x5 board)."""
    empty = [i for i, ch in enumerate(cells) if ch == "·"]
    best = None
    for k in range(max_mirrors + 1):
        for chosen in product(empty, repeat=k):
            if list(chosen) != sorted(set(chosen)):
                continue
            for kinds in product((SLASH, BACKSLASH), repeat=k):
                cost = sum(PRESSES[m] for m in kinds)
                if best is not None and cost >= best:
                    continue
                trial = list(cells)
                for i, m in zip(chosen, kinds):
                    trial[i] = m
                if trace(trial, n, start, heading)[1]:
                    best = cost
    return best


@pytest.mark.parametrize("seed", range(4))
def test_solver_is_minimal_by_brute_force(seed):
    task = glyphbench_rl.make(ID, size=5, mirrors=2, min_mirrors=1, walls=4)
    task.reset(seed=seed)
    n = 5
    plan = solve(task.cells, n, task.laser, task.heading, 2, 4)
    assert sum(PRESSES[m] for _, m in plan) == brute_force(task.cells, n, task.laser, task.heading, 2)


@pytest.mark.parametrize("seed", [0, 1, 2, 3, 1_000_000])
def test_win_path_places_the_solver_mirrors(seed):
    task = glyphbench_rl.make(ID)
    task.reset(seed=seed)
    assert len(task.plan) >= task.params.min_mirrors
    assert solve(task.cells, 7, task.laser, task.heading, task.params.min_mirrors - 1, 4) is None
    for i, mirror in task.plan:
        for _ in range(PRESSES[mirror]):
            _, reward, term, trunc, info = task.step(name(task, i))
    assert term and task.won and task.turn == task.optimal_presses and not info["clamped"]
    assert task.episode_return == pytest.approx(1 - 0.5 * task.turn / task.max_turns)
    assert "The beam hits the target." in info["frame"].message


def test_loss_path_cycling_a_mirror_off_the_beam():
    task = glyphbench_rl.make(ID)
    task.reset(seed=4)
    route = {i for i, _ in trace(task.cells, 7, task.laser, task.heading)[0]}
    spare = next(i for i, ch in enumerate(task.cells) if ch == "·" and i not in route)
    while not task.done:
        _, reward, *_ = task.step(name(task, spare))
        assert reward == 0.0
    assert task.won is None and task.episode_return == 0.0 and task.turn == task.max_turns


def test_mirror_cycle_stock_and_beam():
    task = glyphbench_rl.make(ID, mirrors=1, min_mirrors=1)
    obs, _ = task.reset(seed=0)
    assert obs.splitlines()[0] == "Step 0/40 | Mirrors left 1"
    path, hit = trace(task.cells, 7, task.laser, task.heading)
    assert not hit and path
    first, d = path[0]
    grid = task.frame.grid
    assert grid[first // 7][first % 7] == ("|" if d % 2 == 0 else "-")
    task.step(name(task, first))
    assert task.cells[first] == "/" and task.frame.hud.endswith("Mirrors left 0")
    other = next(i for i, ch in enumerate(task.cells) if ch == "·")
    task.step(name(task, other))
    assert task.cells[other] == "·" and "No mirrors left." in task.frame.message
    if not task.done:
        task.step(name(task, first))
        assert task.cells[first] == "\\"
    if not task.done:
        task.step(name(task, first))
        assert task.cells[first] == "·" and task.frame.hud.endswith("Mirrors left 1")
    task.reset(seed=0)
    task.step(name(task, task.laser))
    assert "cannot hold a mirror" in task.frame.message


def test_trace_turns_at_mirrors():
    n = 5
    cells = ["·"] * 25
    cells[10] = "▶"          # A3 facing east
    cells[12] = "/"          # C3: east -> north
    cells[2] = "◎"           # C1
    path, hit = trace(cells, n, 10, 1)
    assert hit and [i for i, _ in path] == [11, 12, 7]
    cells[12] = "\\"         # east -> south: off the board
    assert trace(cells, n, 10, 1) == ([(11, 1), (12, 2), (17, 2), (22, 2)], False)


def test_bad_params():
    with pytest.raises(ValueError, match="size"):
        glyphbench_rl.make(ID, size=4)
    with pytest.raises(ValueError, match="min_mirrors"):
        glyphbench_rl.make(ID, min_mirrors=5)
    with pytest.raises(ValueError, match="walls"):
        glyphbench_rl.make(ID, walls=40)
    with pytest.raises(ValueError, match="mirrors"):
        glyphbench_rl.make(ID, mirrors=0)
