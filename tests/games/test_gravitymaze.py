from collections import deque

import pytest

import glyphbench_rl
from glyphbench_rl.core import check_frame
from glyphbench_rl.games.classics.gravitymaze import fall, solve, turn
from glyphbench_rl.games.common.grid import Board, bfs_search
from glyphbench_rl.games.common.palette import WALL

TASK = "glyphbench/classics-gravitymaze-v0"
DOWN, LEFT, UP, RIGHT = 1, 2, 0, 3   # DELTAS indices


def reference_turns(grid, spikes, goal, ball):
    """Independent BFS on the drawn grid: gravity as a unit vector rotated by hand."""
    start = (ball, (1, 0))
    seen, queue = {start: 0}, deque([start])
    while queue:
        (pos, g) = state = queue.popleft()
        if pos == goal:
            return seen[state]
        if pos in spikes:
            continue
        # clockwise on screen turns (dr, dc) into (dc, -dr): down (1, 0) into left (0, -1)
        for ng in ((g[1], -g[0]), (-g[1], g[0]), g):
            r, c = pos[0] + ng[0], pos[1] + ng[1]
            new = ((r, c) if grid[r][c] != WALL else pos, ng)
            if new not in seen:
                seen[new] = seen[state] + 1
                queue.append(new)
    return None


def test_turning_order():
    assert [turn(DOWN, 0), turn(LEFT, 0), turn(UP, 0), turn(RIGHT, 0)] == [LEFT, UP, RIGHT, DOWN]
    assert [turn(g, 1) for g in (DOWN, LEFT, UP, RIGHT)] == [RIGHT, DOWN, LEFT, UP]
    assert turn(UP, 2) == UP


def test_fall_stops_at_walls():
    board = Board.from_lines(["████", "█··█", "█··█", "████"])
    assert fall(board, ((1, 1), DOWN), 2) == ((2, 1), DOWN)
    assert fall(board, ((2, 1), DOWN), 2) == ((2, 1), DOWN)        # resting on the floor
    assert fall(board, ((2, 1), DOWN), 1) == ((2, 2), RIGHT)       # counterclockwise: right
    assert fall(board, ((2, 2), DOWN), 0) == ((2, 1), LEFT)


@pytest.mark.parametrize("seed", range(12))
def test_generated_levels_have_the_stated_optimum(seed):
    task = glyphbench_rl.make(TASK)
    _, info = task.reset(seed=seed)
    assert check_frame(info["frame"]) == []
    p = task.params
    grid = info["frame"].grid
    assert len(grid) == p.size + 2 and len(task.spikes) == p.spikes
    assert task.board[task.ball[0] + 1, task.ball[1]] == WALL      # the ball starts at rest
    assert task.optimal >= p.min_moves
    assert reference_turns(grid, task.spikes, task.goal, task.ball) == task.optimal


@pytest.mark.parametrize("seed", [0, 1, 2, 1_000_003])
def test_win_path_with_optimal_turns(seed):
    task = glyphbench_rl.make(TASK)
    task.reset(seed=seed)
    plan = solve(task.board, (task.ball, task.gravity), task.goal, task.spikes)
    assert len(plan) == task.optimal
    for action in plan:
        assert not task.done
        _, reward, term, trunc, info = task.step(action)
    assert term and task.won and not info["clamped"]
    expected = 1 - task.params.time_weight * task.optimal / task.max_turns
    assert task.episode_return == pytest.approx(expected) and expected > 0.5
    assert "goal" in info["frame"].message


def test_loss_path_into_spikes():
    task = glyphbench_rl.make(TASK)
    for seed in range(20):
        task.reset(seed=seed)

        def neighbours(s):
            if s[0] not in task.spikes and s[0] != task.goal:
                for a in range(3):
                    yield a, fall(task.board, s, a)
        plan = bfs_search((task.ball, task.gravity), neighbours, lambda s: s[0] in task.spikes)
        if plan:
            for action in plan:
                _, reward, term, trunc, info = task.step(action)
            assert term and task.won is False and reward == -task.params.spike_penalty
            assert task.episode_return < 0 and "spikes" in info["frame"].message
            return
    pytest.fail("no level with reachable spikes")


def test_loss_path_waiting_times_out_with_zero():
    task = glyphbench_rl.make(TASK)
    task.reset(seed=5)
    grid = task.frame.grid
    while not task.done:
        _, reward, *_ = task.step("WAIT")   # the ball rests on a wall: nothing ever moves
        assert reward == 0
    assert task._truncated and task.episode_return == 0.0 and task.frame.grid == grid


def test_prompt_and_hud():
    task = glyphbench_rl.make(TASK)
    assert "8x8 room" in task.system_prompt() and "spikes costs 0.5" in task.system_prompt()
    task.reset(seed=0)
    assert task.frame.hud.endswith("Gravity down")
    task.step("ROTATE_CW")
    assert task.frame.hud.endswith("Gravity left")


@pytest.mark.parametrize("bad, field", [
    (dict(size=3), "size"), (dict(walls=-1), "walls"), (dict(spikes=50), "spikes"),
    (dict(min_moves=0), "min_moves"), (dict(spike_penalty=2), "spike_penalty"),
    (dict(time_weight=1.0), "time_weight"), (dict(colour=1), "unknown parameter 'colour'"),
])
def test_bad_params(bad, field):
    with pytest.raises(ValueError, match=field):
        glyphbench_rl.make(TASK, **bad)
