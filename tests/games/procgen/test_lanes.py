import random

import pytest

import glyphbench_rl
from glyphbench_rl.games.common.lanes import Lane
from glyphbench_rl.games.procgen.engine import ARROWS
from glyphbench_rl.games.procgen.scrolling import LaneLevel, Strip, fall_route, fall_turn

GAMES = ["leaper", "fruitbot"]
NOOP, LEFT, RIGHT, UP, DOWN = range(5)


@pytest.mark.parametrize("game", GAMES)
def test_fifty_seeds_give_distinct_levels(game):
    task = glyphbench_rl.make(f"glyphbench/procgen-{game}-v0")
    levels = {tuple(task._rows()) for seed in range(50) if task.reset(seed=seed)}
    assert len(levels) >= 45


# -- leaper ------------------------------------------------------------------------------------
def river(pattern, direction=1, period=1):
    return Strip(Lane(pattern, direction, period), "~", True, ">")


def road(pattern, direction=1, period=1):
    return Strip(Lane(pattern, direction, period), "C", False, ">")


def test_lane_level_step_rules():
    level = LaneLevel([None, river("==~~~"), road("C...."), None], 5)
    # a car one cell left of you drives into you; a car where you step kills you
    assert level.move(3, 1, 0, UP)[2] == "car"
    assert level.move(3, 0, 0, UP)[2] == "car"
    assert level.move(3, 3, 0, UP) == (2, 3, "")
    # water drowns, a log carries you, and carries you off the edge
    assert level.move(2, 2, 0, UP)[2] == "water"
    assert level.move(2, 0, 0, UP) == (1, 1, "")
    assert level.move(1, 4, 3, NOOP) == (1, 5, "edge")
    # a slow lane moves every second tick only
    slow = LaneLevel([None, river("=~~~~", 1, 2), None], 5)
    assert slow.move(2, 0, 0, UP) == (1, 0, "") and slow.move(1, 0, 1, NOOP) == (1, 1, "")


def test_lane_level_search_finds_a_path_or_none():
    level = LaneLevel([None, river("=~~~~"), None], 5)
    path = level.solve((2, 2))
    r, c, t = 2, 2, 0
    for action in path:
        r, c, death = level.move(r, c, t, action)
        t += 1
        assert not death
    assert r == 0
    assert LaneLevel([None, river("~~~~~"), None], 5).solve((2, 2)) is None


@pytest.mark.parametrize("seed", [0, 1, 2, 3, 4])
def test_leaper_search_win_path(seed):
    task = glyphbench_rl.make("glyphbench/procgen-leaper-v0")
    task.reset(seed=seed)
    for action in task.solution():
        _, _, term, _, info = task.step(action)
    assert term and task.won and task.episode_return == 1.0


def test_leaper_loss_path_ends_with_nothing():
    task = glyphbench_rl.make("glyphbench/procgen-leaper-v0")
    task.reset(seed=0)
    while not task.done:
        task.step("UP")
    assert task.won is False and task.episode_return == 0.0
    assert task.frame.message in ("A car hit you.", "You fell into the water.")


def test_leaper_log_carries_the_player_and_the_row_shows_its_marker():
    task = glyphbench_rl.make("glyphbench/procgen-leaper-v0")
    task.reset(seed=0)
    r = next(i for i, s in enumerate(task.level.strips) if s and s.ride and s.lane.period == 1)
    lane, width = task.level.strips[r].lane, task.params.width
    c = next(c for c, ch in enumerate(lane.row(0)) if ch == "=" and 0 <= c + lane.direction < width)
    task.pos = (r, c)
    task.step("NOOP")
    assert task.pos == (r, c + lane.direction) and not task.done
    assert task._rows()[r] == lane.row(1) + ("»" if lane.direction == 1 else "«")


# -- fruitbot ----------------------------------------------------------------------------------
def test_fall_turn_rules():
    wall = {(2, 0), (2, 1), (1, 3)}
    def is_wall(r, c):
        return (r, c) in wall
    assert fall_turn(is_wall, 5, 4, 0, 0, 0, 1) == (1, 0, False, [(1, 0)])
    assert fall_turn(is_wall, 5, 4, 1, 0, 0, 1) == (1, 0, True, [])          # wall below
    assert fall_turn(is_wall, 5, 4, 1, 2, 1, 1) == (2, 2, True, [(2, 2)])    # wall beside
    assert fall_turn(is_wall, 5, 4, 0, 2, 0, 2) == (2, 2, False, [(1, 2), (2, 2)])
    assert fall_turn(is_wall, 5, 4, 0, 0, -1, 1) == (1, 0, False, [(1, 0)])  # the edge stops
    moves = ((0, 0, 1), (1, -1, 1), (2, 1, 1))
    route = fall_route(is_wall, lambda r, c: False, 5, 4, (0, 0), moves)
    assert route is not None and len(route) == 4 and 2 in route


@pytest.mark.parametrize("seed", [0, 1, 2, 3, 4])
def test_fruitbot_clean_run_wins(seed):
    task = glyphbench_rl.make("glyphbench/procgen-fruitbot-v0")
    task.reset(seed=seed)
    fruit = sum(row.count("%") for row in task.rows)
    for action in task.solution():
        task.step(action)
    assert task.won and task.junk == 0 and task.bumps == 0
    assert task.episode_return == pytest.approx(0.3 + 0.1 * min(task.fruit, 7))
    assert task.fruit <= fruit


def test_fruitbot_bumps_and_junk_cost_and_the_return_stays_in_range():
    task = glyphbench_rl.make("glyphbench/procgen-fruitbot-v0")
    task.reset(seed=0)
    r = next(i for i, row in enumerate(task.rows) if "█" in row)
    c = task.rows[r].index("█")
    task.pos = (r - 1, c)
    _, reward, _, _, _ = task.step("NOOP")
    assert task.pos == (r - 1, c) and task.bumps == 1 and reward == pytest.approx(-0.05)
    for seed in range(20):         # random play stays within [-1, 1]
        task.reset(seed=seed)
        rng = random.Random(seed)
        while not task.done:
            task.step(rng.randrange(4))
        assert -1.0 <= task.episode_return <= 1.0


def test_fruitbot_collects_fruit_and_junk_when_falling_through():
    task = glyphbench_rl.make("glyphbench/procgen-fruitbot-v0")
    task.reset(seed=2)
    r, c = task.pos
    task.rows[r + 1][c] = "%"
    task.rows[r + 2][c] = "x"
    task.rows[r + 3][c] = "%"
    _, reward, _, _, _ = task.step("DOWN")
    assert reward == pytest.approx(0.0) and task.fruit == 1 and task.junk == 1
    _, reward, _, _, _ = task.step("NOOP")
    assert reward == pytest.approx(0.1) and task.rows[r + 3][c] == "."


def test_fruitbot_sitting_on_a_wall_runs_out_the_clock_with_the_bump_cap():
    task = glyphbench_rl.make("glyphbench/procgen-fruitbot-v0")
    for seed in range(20):                 # a seed whose start column runs into a wall
        task.reset(seed=seed)
        c = task.pos[1]
        column = [row[c] for row in task.rows]
        if "█" in column and not {"%", "x"} & set(column[:column.index("█")]):
            break
    while not task.done:
        task.step("NOOP")
    assert not task.won and task.turn == task.max_turns
    assert task.bumps == task.max_turns - column.index("█") + 1
    assert task.episode_return == pytest.approx(-0.05 * 8)


def test_fruitbot_view_keeps_the_robot_near_its_top():
    task = glyphbench_rl.make("glyphbench/procgen-fruitbot-v0")
    task.reset(seed=1)
    for action in task.solution()[:6]:
        task.step(action)
    r, c = task.pos
    grid = task._grid()
    assert len(grid) == 20 and all(len(row) == 14 for row in grid) and r > task.lead
    assert grid[task.lead][c] == ARROWS[task.facing]
    assert grid[task.lead + 1:] == task._rows()[r + 1:r + 20 - task.lead]
