import pytest

import glyphbench_rl
from glyphbench_rl.core import check_frame
from glyphbench_rl.games.classics import warehouse  # noqa: F401  (registers the task)
from glyphbench_rl.games.common.grid import bfs_distances, shortest_path
from glyphbench_rl.games.common.palette import WALL

TASK = "glyphbench/classics-warehouse-v0"


def make(**kw):
    return glyphbench_rl.make(TASK, **kw)


def drive(task, goal):
    for move in shortest_path(task.pos, goal, lambda r, c: task.board[r, c] != WALL):
        _, reward, *_ = task.step(move)
        assert reward == 0


def greedy_plan_length(task):
    ok = lambda r, c: task.board[r, c] != WALL  # noqa: E731
    pos, n = task.pos, 0
    for x in sorted(task.items):
        n += len(shortest_path(pos, task.items[x], ok)) + len(shortest_path(task.items[x], task.docks[x], ok)) + 2
        pos = task.docks[x]
    return n


@pytest.mark.parametrize("seed", range(10))
def test_levels_are_connected_and_fit_the_horizon(seed):
    task = make()
    _, info = task.reset(seed=seed)
    assert check_frame(info["frame"]) == []
    reach = bfs_distances(task.pos, lambda r, c: task.board[r, c] != WALL)
    assert all(cell in reach for cell in [*task.items.values(), *task.docks.values()])
    assert greedy_plan_length(task) <= task.max_turns // 2
    text = "".join(info["frame"].grid)
    assert all(text.count(x) == 1 and text.count(x.upper()) == 1 for x in "abc")


@pytest.mark.parametrize("seed", [0, 1, 2, 1_000_003])
def test_win_path_delivering_in_letter_order(seed):
    task = make()
    task.reset(seed=seed)
    share = task.params.delivery_share
    for i, x in enumerate(sorted(task.items)):
        drive(task, task.items[x])
        assert f"On package {x}" in task.frame.hud
        task.step("PICK")
        assert task.carrying == x and "Carrying " + x in task.frame.hud
        drive(task, task.docks[x])
        _, reward, term, trunc, info = task.step("DROP")
        assert f"Delivered {x}" in info["frame"].message
        if i < 2:
            assert reward == pytest.approx(share / 3) and not term
    assert term and task.won and not info["clamped"]
    expected = share + (1 - share) * (1 - task.params.time_weight * task.turn / task.max_turns)
    assert task.episode_return == pytest.approx(expected) and expected > 0.8
    assert info["frame"].grid[-2].count("■") == 2 and "@" in info["frame"].grid[-2]   # on the last dock


def test_loss_path_idling_times_out_with_zero():
    task = make()
    task.reset(seed=4)
    while not task.done:
        _, reward, *_ = task.step("DROP")    # carrying nothing: nothing happens
        assert reward == 0
    assert task._truncated and task.won is None and task.episode_return == 0.0


def test_pick_and_drop_rules():
    task = make()
    task.reset(seed=0)
    a, b = sorted(task.items)[:2]
    drive(task, task.items[a])
    task.step("PICK")
    drive(task, task.items[b])
    *_, info = task.step("PICK")
    assert "already carry" in info["frame"].message and task.carrying == a
    *_, info = task.step("DROP")                      # on another package
    assert "already lies here" in info["frame"].message and task.carrying == a
    drive(task, task.docks[b])
    _, reward, *_, info = task.step("DROP")           # the wrong dock
    assert reward == 0 and task.carrying == a and f"takes only package {b}" in info["frame"].message
    task.step("UP")
    task.step("DROP")                                 # plain floor: set it down
    assert task.carrying is None and task.items[a] == task.pos
    assert task.frame.grid[task.pos[0]][task.pos[1]] == "@" and "On package " + a in task.frame.hud
    task.step("DOWN")
    assert task.frame.grid[task.pos[0] - 1][task.pos[1]] == a


def test_prompt_shows_the_numbers():
    prompt = make().system_prompt()
    assert "9x9 warehouse" in prompt and "+0.1667 per delivery" in prompt and "0.5 x (1 - 0.5" in prompt


@pytest.mark.parametrize("bad, field", [
    (dict(size=4), "size"), (dict(packages=0), "packages"), (dict(packages=6), "packages"),
    (dict(rack_gap=0), "rack_gap"), (dict(delivery_share=1), "delivery_share"),
    (dict(time_weight=1), "time_weight"), (dict(colour=1), "unknown parameter 'colour'"),
])
def test_bad_params(bad, field):
    with pytest.raises(ValueError, match=field):
        make(**bad)
