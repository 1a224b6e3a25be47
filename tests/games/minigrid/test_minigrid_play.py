"""Win paths (a search-based solver on every MiniGrid task), failure paths (lava, collisions,
time out) and the invariants of the generated levels."""

from __future__ import annotations

import pytest

import glyphbench_rl
from glyphbench_rl.games.minigrid import solver
from glyphbench_rl.games.minigrid.engine import FORWARD, LEFT, RIGHT
from glyphbench_rl.games.minigrid.world import Ball

MINIGRID = glyphbench_rl.list_tasks(suite="MiniGrid")
# Playground has no mission and nothing to win (its episodes are tested in test_playground.py).
WINNABLE = [t for t in MINIGRID if t != "glyphbench/minigrid-playground-v0"]


@pytest.mark.parametrize("task_id", WINNABLE)
def test_solver_wins_every_task(task_id):
    task = glyphbench_rl.make(task_id)
    for seed in (0, 1, 2, 1_000_000, 1_000_001):
        task.reset(seed=seed)
        solver.solve(task, dynamic="dynamic-obstacles" in task_id)
        assert task.won, (task_id, seed)
        assert task.episode_return == pytest.approx(1 - 0.9 * task.turn / task.max_turns)
        assert not task._clamped


def test_full_view_plays_the_same_episode():
    partial = glyphbench_rl.make("glyphbench/minigrid-doorkey-8x8-v0")
    full = glyphbench_rl.make("glyphbench/minigrid-doorkey-8x8-v0", view="full")
    for task in (partial, full):
        task.reset(seed=4)
        solver.solve(task)
    assert partial.won and full.won and partial.turn == full.turn
    assert len(full.frame.grid) == 8 and len(partial.frame.grid) == 7


@pytest.mark.parametrize("task_id", ["glyphbench/minigrid-lavagap-s5-v0", "glyphbench/minigrid-lavagap-s7-v0",
                                     "glyphbench/minigrid-crossing-n1-v0", "glyphbench/minigrid-crossing-n3-v0",
                                     "glyphbench/minigrid-distshift1-v0", "glyphbench/minigrid-distshift2-v0"])
def test_stepping_into_lava_ends_with_nothing(task_id):
    task = glyphbench_rl.make(task_id)
    task.reset(seed=0)
    lava = solver.find(task, "lava")[0]
    steps = solver.plan(task, lava, face=True)
    solver.run(task, steps)
    assert not task.done
    _, reward, term, trunc, info = task.step(FORWARD)
    assert term and not trunc and reward == 0 and task.won is False and task.episode_return == 0
    assert task.agent_pos == lava and "lava" in info["frame"].message


def test_safe_crossing_has_walls_where_lava_was():
    lava = glyphbench_rl.make("glyphbench/minigrid-crossing-n2-v0")
    safe = glyphbench_rl.make("glyphbench/minigrid-crossing-n2-safe-v0")
    lava.reset(seed=8)
    safe.reset(seed=8)
    assert [c.replace("≈", "█") for c in lava.grid.render_full((1, 1), "▶")] == safe.grid.render_full((1, 1), "▶")
    assert not solver.find(safe, "lava")


def test_walking_into_a_wall_among_dynamic_obstacles_costs_one():
    task = glyphbench_rl.make("glyphbench/minigrid-dynamic-obstacles-8x8-v0")
    task.reset(seed=0)
    task.step(LEFT)                                       # at (1, 1) facing north: the wall
    _, reward, term, _, info = task.step(FORWARD)
    assert term and reward == -1 and task.won is False and task.episode_return == -1
    assert "collided" in info["frame"].message


def test_walking_into_a_ball_costs_one_even_if_it_moves_away():
    task = glyphbench_rl.make("glyphbench/minigrid-dynamic-obstacles-5x5-v0")
    task.reset(seed=0)
    for ball in task.obstacles:
        task.grid.set(*ball.pos, None)
    task.obstacles = [Ball()]
    task.grid.set(2, 1, task.obstacles[0])                # right in front of the agent at (1, 1)
    _, reward, term, _, _ = task.step(FORWARD)
    assert term and reward == -1


def test_balls_move_every_turn_and_never_onto_the_agent():
    task = glyphbench_rl.make("glyphbench/minigrid-dynamic-obstacles-16x16-v0")
    task.reset(seed=2)
    moved = 0
    for _ in range(30):
        before = [b.pos for b in task.obstacles]
        task.step(RIGHT)
        after = [b.pos for b in task.obstacles]
        moved += sum(a != b for a, b in zip(after, before))
        assert all(max(abs(a[0] - b[0]), abs(a[1] - b[1])) <= 1 for a, b in zip(after, before))
        assert task.agent_pos not in after and len(set(after)) == len(after)
    assert moved > 0.8 * 30 * len(task.obstacles)


def test_time_out_gives_nothing():
    task = glyphbench_rl.make("glyphbench/minigrid-fourrooms-v0")
    task.reset(seed=0)
    while not task.done:
        task.step(LEFT)
    assert task._truncated and task.turn == task.max_turns == 100 and task.episode_return == 0


# -- level invariants ------------------------------------------------------------------------------

@pytest.mark.parametrize("n", [5, 6, 8, 16])
def test_doorkey_levels(n):
    task = glyphbench_rl.make(f"glyphbench/minigrid-doorkey-{n}x{n}-v0")
    for seed in range(8):
        task.reset(seed=seed)
        doors, keys, goals = (solver.find(task, k) for k in ("door", "key", "goal"))
        assert len(doors) == len(keys) == len(goals) == 1 and goals[0] == (n - 2, n - 2)
        split = doors[0][0]
        column = [task.grid.get(split, y) for y in range(n)]
        assert sum(o.kind == "wall" for o in column) == n - 1          # the dividing wall
        assert task.grid.get(*doors[0]).is_locked and task.grid.get(*doors[0]).color == "yellow"
        assert keys[0][0] < split and task.agent_pos[0] < split
        assert solver.plan(task, goals[0]) is None                     # the door must be opened


@pytest.mark.parametrize("task_id,rivers", [("crossing-n1", 1), ("crossing-n3", 3), ("simplecrossing-n2", 2),
                                            ("simplecrossing-easy-n3", 3)])
def test_crossing_levels_have_one_opening_per_river(task_id, rivers):
    task = glyphbench_rl.make(f"glyphbench/minigrid-{task_id}-v0")
    obstacle = "lava" if task.has_lava else "wall"
    n = task.params.size
    for seed in range(8):
        task.reset(seed=seed)
        inner = [[task.grid.get(x, y) for x in range(1, n - 1)] for y in range(1, n - 1)]
        full_rows = [r for r in inner if sum(o is not None and o.kind == obstacle for o in r) >= n - 3]
        full_cols = [c for c in zip(*inner) if sum(o is not None and o.kind == obstacle for o in c) >= n - 3]
        assert len(full_rows) + len(full_cols) == rivers
        assert solver.plan(task, (n - 2, n - 2)) is not None


@pytest.mark.parametrize("task_id,rooms", [("multiroom-n2-s4", 2), ("multiroom-n4-s5", 4), ("multiroom-n6", 6)])
def test_multiroom_levels_chain_their_rooms(task_id, rooms):
    task = glyphbench_rl.make(f"glyphbench/minigrid-{task_id}-v0")
    for seed in range(6):
        task.reset(seed=seed)
        assert len(task.rooms) == rooms and len(solver.find(task, "door")) == rooms - 1
        doors = [task.grid.get(*room.entry_door) for room in task.rooms[1:]]   # in chain order
        assert all(d.kind == "door" and not d.is_open and not d.is_locked for d in doors)
        assert all(a.color != b.color for a, b in zip(doors, doors[1:]))   # next doors differ
        (x, y), (w, h) = task.rooms[0].top, task.rooms[0].size
        assert x < task.agent_pos[0] < x + w - 1 and y < task.agent_pos[1] < y + h - 1


def test_fourrooms_walls_and_gaps():
    task = glyphbench_rl.make("glyphbench/minigrid-fourrooms-v0")
    for seed in range(5):
        task.reset(seed=seed)
        middle_col = [task.grid.get(9, y) for y in range(1, 18)]
        middle_row = [task.grid.get(x, 9) for x in range(1, 18)]
        assert sum(o is None for o in middle_col) == 2 and sum(o is None for o in middle_row) == 2
        assert len(solver.find(task, "goal")) == 1


def test_dynamic_obstacle_counts():
    for n, k in ((5, 2), (6, 3), (8, 4), (16, 8)):
        task = glyphbench_rl.make(f"glyphbench/minigrid-dynamic-obstacles-{n}x{n}-v0")
        task.reset(seed=0)
        assert len(solver.find(task, "ball")) == k
