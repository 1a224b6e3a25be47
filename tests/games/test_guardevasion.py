from collections import deque

import pytest

import glyphbench_rl
from glyphbench_rl.core import check_frame
from glyphbench_rl.games.common.grid import MOVES
from glyphbench_rl.games.common.palette import WALL
from glyphbench_rl.games.classics.guardevasion import patrol_steps, sentry_steps
from glyphbench_rl.games.common.sight import view_cone

VARIANTS = ["easy", "medium", "hard"]
UP, DOWN, LEFT, RIGHT = range(4)


def make(variant, **kw):
    return glyphbench_rl.make(f"glyphbench/classics-guardevasion-{variant}-v0", **kw)


def reference_turns(task, start):
    """Independent check: cones recomputed by brute force (every cell in range; sight blocked by
    a wall whose inside a fine sampling of the segment visits), then a BFS over (cell, time)."""
    board, reach = task.board, task.params.reach
    vec = {UP: (-1, 0), DOWN: (1, 0), LEFT: (0, -1), RIGHT: (0, 1)}

    cache = {}

    def sees(origin, facing, cell):
        if (origin, facing, cell) not in cache:
            cache[origin, facing, cell] = look(origin, facing, cell)
        return cache[origin, facing, cell]

    def look(origin, facing, cell):
        dr, dc = vec[facing]
        ahead = (cell[0] - origin[0]) * dr + (cell[1] - origin[1]) * dc
        side = abs((cell[0] - origin[0]) * dc + (cell[1] - origin[1]) * dr)
        if cell == origin:
            return True
        if not 1 <= ahead <= reach or side > ahead // 2 or board[cell] == WALL:
            return False
        for k in range(1, 600):
            r = origin[0] + (cell[0] - origin[0]) * k / 600
            c = origin[1] + (cell[1] - origin[1]) * k / 600
            if abs(r - round(r)) < 0.49 and abs(c - round(c)) < 0.49:   # inside, not on a corner
                x = (round(r), round(c))
                if x not in (origin, cell) and board[x] == WALL:
                    return False
        return True

    floor = [(r, c) for r in range(board.height) for c in range(board.width) if board[r, c] != WALL]
    watched = [{cell for (g, f) in (s[t] for s in task.steps) for cell in floor
                if abs(cell[0] - g[0]) + abs(cell[1] - g[1]) <= 2 * reach and sees(g, f, cell)}
               for t in range(task.period)]
    seen, queue = {(start, 0): 0}, deque([(start, 0)])
    while queue:
        state = queue.popleft()
        (cell, t) = state
        if cell == task.exit:
            return seen[state], watched
        nt = (t + 1) % task.period
        for dr, dc in [*MOVES.values(), (0, 0)]:
            nxt = (cell[0] + dr, cell[1] + dc)
            if board[nxt] == WALL:
                nxt = cell
            if nxt != task.exit and (nxt in watched[t] or nxt in watched[nt]):
                continue
            if (nxt, nt) not in seen:
                seen[nxt, nt] = seen[state] + 1
                queue.append((nxt, nt))
    return None, watched


def test_patrols_and_sentries():
    steps = patrol_steps([(1, 1), (1, 2), (1, 3)], phase=0, period=8)
    assert [cell for cell, _ in steps] == [(1, 1), (1, 2), (1, 3), (1, 2)] * 2
    assert [f for _, f in steps[:4]] == [RIGHT, RIGHT, LEFT, LEFT]
    assert patrol_steps([(1, 1), (1, 2), (1, 3)], phase=1, period=4)[0] == ((1, 2), RIGHT)
    turns = sentry_steps((2, 2), UP, every=2, phase=0, period=8)
    assert [f for _, f in turns] == [UP, UP, RIGHT, RIGHT, DOWN, DOWN, LEFT, LEFT]


def test_view_cone_shape_and_walls():
    open_ = lambda r, c: not (0 <= r < 9 and 0 <= c < 9)  # noqa: E731
    cone = view_cone((4, 1), RIGHT, 4, open_)
    assert cone == {(4, 1), (4, 2), (3, 3), (4, 3), (5, 3), (3, 4), (4, 4), (5, 4),
                    (2, 5), (3, 5), (4, 5), (5, 5), (6, 5)}
    walled = lambda r, c: open_(r, c) or (r, c) == (4, 3)  # noqa: E731
    cone = view_cone((4, 1), RIGHT, 4, walled)
    assert (4, 3) not in cone and (4, 4) not in cone and (4, 5) not in cone and (3, 3) in cone


@pytest.mark.parametrize("variant", VARIANTS)
def test_generated_levels_have_the_stated_optimum(variant):
    task = make(variant)
    for seed in range(3):
        _, info = task.reset(seed=seed)
        assert check_frame(info["frame"]) == []
        assert task.pos not in task.watched[0] and task.optimal >= task.params.min_moves
        optimal, watched = reference_turns(task, task.pos)
        assert [set(w) for w in task.watched] == watched
        assert optimal == task.optimal
        grid = info["frame"].grid
        shaded = {(r, c) for r, row in enumerate(grid) for c, ch in enumerate(row) if ch == "░"}
        assert shaded <= set(task.watched[0])


@pytest.mark.parametrize("variant", VARIANTS)
@pytest.mark.parametrize("seed", [0, 1, 1_000_003])
def test_win_path_with_optimal_turns(variant, seed):
    task = make(variant)
    task.reset(seed=seed)
    plan = task.solve(task.pos, task.phase)
    assert len(plan) == task.optimal <= task.max_turns
    for action in plan:
        assert not task.done
        _, reward, term, trunc, info = task.step(action)
    assert term and task.won and not info["clamped"]
    expected = 1 - task.params.time_weight * task.optimal / task.max_turns
    assert task.episode_return == pytest.approx(expected) and expected > 0.5


def test_loss_path_walking_into_sight():
    task = make("medium")
    task.reset(seed=0)
    # search safe states for the first one with a move that gets caught, then play there
    start = (task.pos, task.phase)
    prev, queue = {start: None}, deque([start])
    while queue:
        cell, t = state = queue.popleft()
        moves = [(a, task._move(cell, a)) for a in range(5)]
        bad = next((a for a, nxt in moves if nxt != task.exit and task._caught(nxt, t)), None)
        if bad is not None:
            break
        for a, nxt in moves:
            new = (nxt, (t + 1) % task.period)
            if new not in prev and nxt != task.exit:
                prev[new] = (state, a)
                queue.append(new)
    plan = [bad]
    while prev[state] is not None:
        state, a = prev[state]
        plan.append(a)
    for action in reversed(plan):
        _, reward, term, trunc, info = task.step(action)
    assert term and task.won is False and reward == -task.params.caught_penalty
    assert task.episode_return < 0 and "saw you" in info["frame"].message


def test_timeout_hiding_is_zero():
    task = make("easy")
    task.reset(seed=3)
    while not task.done:   # bump into walls or wait where it is safe, never leaving the start
        safe = [a for a in range(5)
                if task._move(task.pos, a) == task.pos and not task._caught(task.pos, task.phase)]
        if not safe:
            pytest.skip("the start is not safe to stay on")
        task.step(safe[0])
    assert task._truncated and task.episode_return == 0.0


def test_prompt_names_the_numbers():
    prompt = make("hard").system_prompt()
    assert "12x12 room" in prompt and "up to 5 cells" in prompt and "every 2 turns" in prompt
    assert "sentries" not in make("easy").system_prompt()


@pytest.mark.parametrize("bad, field", [
    (dict(size=4), "size"), (dict(pillars=-1), "pillars"), (dict(guards=9), "guards"),
    (dict(sentries=5), "sentries"), (dict(patrol=1), "patrol"), (dict(reach=0), "reach"),
    (dict(sentry_turn=0), "sentry_turn"), (dict(min_moves=0), "min_moves"),
    (dict(caught_penalty=1.5), "caught_penalty"), (dict(time_weight=1), "time_weight"),
    (dict(colour=1), "unknown parameter 'colour'"),
])
def test_bad_params(bad, field):
    with pytest.raises(ValueError, match=field):
        make("easy", **bad)
