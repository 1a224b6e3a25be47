import heapq

import numpy as np
import pytest

import glyphbench_rl
from glyphbench_rl.core import check_frame
from glyphbench_rl.games.common.grid import MOVES
from glyphbench_rl.games.common.pushing import solve

VARIANTS = ["easy", "medium", "hard"]


def make(variant, **kw):
    return glyphbench_rl.make(f"glyphbench/classics-sokoban-{variant}-v0", **kw)


def parse(lines):
    """A level in the usual text notation: # wall, @ you, $ box, . goal, * box on goal, + you on goal."""
    walls, boxes, goals, player = set(), set(), set(), None
    for r, row in enumerate(lines):
        for c, ch in enumerate(row):
            if ch == "#":
                walls.add((r, c))
            if ch in "$*":
                boxes.add((r, c))
            if ch in ".*+":
                goals.add((r, c))
            if ch in "@+":
                player = (r, c)
    return walls, boxes, goals, player


def reference_pushes(walls, boxes, goals, player):
    """Independent brute force: Dijkstra over (boxes, player) with walks free and pushes cost 1."""
    start = (frozenset(boxes), player)
    best = {start: 0}
    heap = [(0, 0, start)]
    tie = 0
    while heap:
        cost, _, state = heapq.heappop(heap)
        bx, (r, c) = state
        if cost > best[state]:
            continue
        if bx == goals:
            return cost
        for dr, dc in MOVES.values():
            nxt = (r + dr, c + dc)
            if nxt in walls:
                continue
            nb, step = bx, 0
            if nxt in bx:
                dest = (r + 2 * dr, c + 2 * dc)
                if dest in walls or dest in bx:
                    continue
                nb, step = (bx - {nxt}) | {dest}, 1
            new = (nb, nxt)
            if cost + step < best.get(new, 1 << 30):
                best[new] = cost + step
                tie += 1
                heapq.heappush(heap, (cost + step, tie, new))
    return None


def replay_pushes(walls, boxes, player, plan):
    boxes, pushes = set(boxes), 0
    for name in plan:
        dr, dc = MOVES[name]
        nxt = (player[0] + dr, player[1] + dc)
        assert nxt not in walls
        if nxt in boxes:
            dest = (nxt[0] + dr, nxt[1] + dc)
            assert dest not in walls and dest not in boxes
            boxes = (boxes - {nxt}) | {dest}
            pushes += 1
        player = nxt
    return boxes, pushes


# -- the solver ---------------------------------------------------------------------------------
def test_solver_on_hand_made_levels():
    level = parse(["######",
                   "#@$ .#",
                   "######"])
    assert solve(*level) == ["RIGHT", "RIGHT"]
    # one push down, then walk round behind the box and two pushes right
    level = parse(["######",
                   "#    #",
                   "# $  #",
                   "#@  .#",
                   "######"])
    plan = solve(*level)
    walls, boxes, goals, player = level
    assert replay_pushes(walls, boxes, player, plan) == (goals, 3)
    assert solve(*parse(["#####",       # a box in a corner never moves
                         "#$ .#",
                         "#  @#",
                         "#####"])) is None
    assert solve(*parse(["#######",     # two boxes in a row in a corridor: neither can move
                         "#@$$..#",
                         "#######"])) is None


def test_solver_is_push_optimal_against_brute_force():
    rng = np.random.default_rng(7)
    checked = unsolvable = 0
    for _ in range(40):
        n = 5
        cells = [(r, c) for r in range(1, n + 1) for c in range(1, n + 1)]
        picks = rng.choice(len(cells), size=8, replace=False)
        walls = {(r, c) for r in range(n + 2) for c in range(n + 2) if r in (0, n + 1) or c in (0, n + 1)}
        walls |= {cells[i] for i in picks[5:]}
        boxes, goals, player = {cells[i] for i in picks[:2]}, {cells[i] for i in picks[2:4]}, cells[picks[4]]
        expected = reference_pushes(walls, frozenset(boxes), frozenset(goals), player)
        plan = solve(walls, boxes, goals, player)
        if expected is None:
            assert plan is None
            unsolvable += 1
        else:
            assert replay_pushes(walls, boxes, player, plan) == (goals, expected)
        checked += 1
    assert 0 < unsolvable < checked


def test_solver_rejects_malformed_levels():
    walls, boxes, goals, player = parse(["######", "#@$ .#", "######"])
    with pytest.raises(ValueError, match="as many boxes as goals"):
        solve(walls, boxes, set(), player)
    with pytest.raises(ValueError, match="floor"):
        solve(walls, boxes, goals, (0, 0))


# -- generated levels ------------------------------------------------------------------------------
@pytest.mark.parametrize("variant", VARIANTS)
def test_generated_levels_are_valid(variant):
    task = make(variant)
    p = task.params
    for seed in range(20):
        obs, info = task.reset(seed=seed)
        grid = info["frame"].grid
        assert check_frame(info["frame"]) == []
        assert len(grid) == p.size + 2 and {len(row) for row in grid} == {p.size + 2}
        assert set(grid[0]) == set(grid[-1]) == {"█"}
        assert len(task.boxes) == len(task.goals) == p.boxes
        assert not task.boxes & task.goals and task.on_goal == 0
        assert task.player not in task.walls | task.boxes
        text = "".join(grid)
        assert text.count("$") == p.boxes and text.count("◎") + text.count("+") == p.boxes
        plan = solve(task.walls, task.boxes, task.goals, task.player)
        assert plan is not None and p.min_pushes <= task.optimal_pushes
        assert len(task.solution) <= p.max_moves <= task.max_turns


def test_generation_is_reproducible_and_varied():
    a, b = make("medium"), make("medium")
    grids = set()
    for seed in range(10):
        ga = a.reset(seed=seed)[0]
        assert ga == b.reset(seed=seed)[0]
        grids.add(ga)
    assert len(grids) == 10


# -- play --------------------------------------------------------------------------------------------
@pytest.mark.parametrize("variant", VARIANTS)
@pytest.mark.parametrize("seed", [0, 1, 2, 1_000_003])
def test_win_path_with_optimal_pushes(variant, seed):
    task = make(variant)
    task.reset(seed=seed)
    plan = solve(task.walls, task.boxes, task.goals, task.player)
    assert len(plan) <= task.max_turns
    for i, move in enumerate(plan):
        assert not task.done
        _, reward, term, trunc, info = task.step(move)
    assert term and not trunc and task.won is True and not info["clamped"]
    assert 0.99 < task.episode_return <= 1.0
    assert task.pushes == task.optimal_pushes
    assert "solved" in info["frame"].message


@pytest.mark.parametrize("variant", VARIANTS)
def test_loss_path_never_pushing_runs_out_of_turns(variant):
    task = make(variant)
    task.reset(seed=3)
    grid0 = task.frame.grid
    while not task.done:  # wander without ever touching a box
        r, c = task.player
        free = [m for m, (dr, dc) in MOVES.items() if (r + dr, c + dc) not in task.boxes]
        _, reward, term, trunc, info = task.step(free[task.turn % len(free)])
        assert reward == 0.0
    assert trunc and not term and task.turn == task.max_turns
    assert task.episode_return <= 0 and task.won is None
    assert {(r, c) for r, row in enumerate(grid0) for c, ch in enumerate(row) if ch == "$"} == task.boxes


def test_bumps_change_nothing_but_say_so():
    task = make("medium")
    task.reset(seed=0)
    task._install(*parse(["######",
                          "#@$$ #",
                          "#. . #",
                          "######"]))
    before = task._grid()
    _, reward, *_, info = task.step("LEFT")
    assert reward == 0 and task._grid() == before and "wall" in info["frame"].message
    _, reward, *_, info = task.step("RIGHT")
    assert reward == 0 and task._grid() == before and "blocked" in info["frame"].message


def test_box_rewards_on_and_off_goals():
    task = make("easy")
    task.reset(seed=0)
    task._install(*parse(["######",
                          "#@*  #",
                          "#    #",
                          "######"]))
    assert task._grid()[1] == "█@*··█"
    _, reward, *_ = task.step("RIGHT")          # push the box off its goal
    assert reward == pytest.approx(-0.5) and task.on_goal == 0
    assert task._grid()[1] == "█·+$·█"
    for move in ("DOWN", "RIGHT", "RIGHT", "UP"):
        assert task.step(move)[1] == 0
    _, reward, term, _, info = task.step("LEFT")  # and back on: box reward plus the solve bonus
    assert reward == pytest.approx(1.0) and term and task.won
    assert task.episode_return == pytest.approx(0.5) and not info["clamped"]


def test_prompt_shows_the_numbers():
    prompt = make("hard").system_prompt()
    assert "8x8 room with 3 boxes" in prompt
    assert "+0.1667 each time a box lands" in prompt and "+0.5 when every box" in prompt
    assert "1 box and" in make("easy").system_prompt()


@pytest.mark.parametrize("bad, field", [
    (dict(boxes=0), "boxes"), (dict(boxes=1.5), "boxes"), (dict(size=3), "size"),
    (dict(size=True), "size"), (dict(inner_walls=-1), "inner_walls"), (dict(min_pushes=0), "min_pushes"),
    (dict(max_moves=2), "max_moves"), (dict(colour=1), "unknown parameter 'colour'"),
])
def test_bad_params(bad, field):
    with pytest.raises(ValueError, match=field):
        make("easy", **bad)
