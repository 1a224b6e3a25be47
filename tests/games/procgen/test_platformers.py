import numpy as np
import pytest

import glyphbench_rl
from glyphbench_rl.games.procgen.engine import ProcgenTask
from glyphbench_rl.games.procgen.platforms import (BREAKABLE, GROUND, OPEN, THROW, advance,
                                                   jump_arc, patrol_col, search)

GAMES = ["coinrun", "jumper", "ninja", "climber"]


def make(game, seed=0, **params):
    task = glyphbench_rl.make(f"glyphbench/procgen-{game}-v0", **params)
    task.reset(seed=seed)
    return task


def put(task, r, c, vy=0):
    """Stand the player at (r, c), still."""
    task.state = (r, c, vy, task.air_jumps)
    task.pos = (r, c)


def flat_spot(task):
    """A cell with open air above it for a jump and ground below, away from anything."""
    lines = task._lines
    for r in range(4, task.height - 1):
        for c in range(1, task.width - 1):
            if (all(lines[rr][cc] == OPEN for rr in range(r - 4, r + 1) for cc in (c - 1, c, c + 1))
                    and all(lines[r + 1][cc] == GROUND for cc in (c - 1, c, c + 1))
                    and all(p[0] != r or abs(p[1] - c) > 6 for p in task.patrols)):
                return r, c
    raise AssertionError("no flat spot")


@pytest.mark.parametrize("game", GAMES)
def test_fifty_seeds_give_distinct_levels(game):
    task = glyphbench_rl.make(f"glyphbench/procgen-{game}-v0")
    levels = {(tuple(task._lines), tuple(task.patrols)) for seed in range(50) if task.reset(seed=seed)}
    assert len(levels) >= 45


@pytest.mark.parametrize("game", GAMES)
@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_search_path_wins_in_the_real_game(game, seed):
    task = make(game, seed)
    path = task.solution()
    assert path
    for action in path:
        assert not task.done
        _, _, _, _, info = task.step(action)
    assert task.won is True and not info["clamped"] and task.episode_return > 0


@pytest.mark.parametrize("game", ["coinrun", "ninja", "climber"])
def test_the_winning_paths_pass_enemies(game):
    """The search's paths win past live enemies: on most seeds the path crosses a patrolled
    stretch within a jump's height of it."""
    passes = 0
    for seed in range(4):
        task = make(game, seed)
        patrols, crossed = list(task.patrols), False
        for action in task.solution():
            task.step(action)
            r, c = task.pos
            crossed |= any(lo <= c <= hi and abs(r - row) <= 3 for row, lo, hi, _ in patrols)
        assert task.won
        passes += crossed
    assert passes >= 3


def test_ignoring_the_enemies_timing_can_be_fatal():
    """A path planned without enemies dies on some seed: the search's clock matters."""
    deaths = 0
    for seed in range(12):
        task = make("coinrun", seed)
        path, _ = search(task._lines, task.state, task.goals, hazards=task.hazards)
        for action in path:
            task.step(action)
            if task.done:
                break
        deaths += task.won is False
    assert deaths >= 1


def test_jump_arc_over_flat_ground():
    assert jump_arc() == [-2, -1, 0, 1, 2]
    task = make("coinrun")
    r, c = flat_spot(task)
    put(task, r, c)
    rows = []
    for action in ["JUMP"] + ["NOOP"] * 5:
        task.step(action)
        rows.append(task.pos[0] - r)
    assert rows == [-2, -3, -3, -2, 0, 0] and task.pos[1] == c
    assert "2 up, 1 up, hang, 1 down, 2 down (3 rows up and 5 turns in the air" in task.system_prompt()


def test_no_double_jump_in_coinrun_but_one_in_jumper():
    task = make("coinrun")
    r, c = flat_spot(task)
    put(task, r, c)
    task.step("JUMP")
    task.step("NOOP")
    task.step("NOOP")            # at the top: a second jump does nothing
    task.step("JUMP")
    assert task.pos[0] == r - 2
    lines = [OPEN] * 12 + [GROUND]
    state, peak = (11, 0, 0, 1), 11
    for action in [3, 0, 3, 0, 0, 0]:           # jump, then jump again in the air
        state, _ = advance(lines, state, action, air_jumps=1)
        peak = min(peak, state[0])
    assert peak == 11 - 6 and state[3] == 0      # twice as high; the air jump is spent
    for _ in range(8):
        state, _ = advance(lines, state, 0, air_jumps=1)
    assert state == (11, 0, 0, 1)                # landing restores it


def test_air_control_and_walls_stop_you():
    lines = ["....", "..#.", "....", "####"]
    state, passed = advance(lines, (2, 1, 0, 0), 2)     # RIGHT: one column
    assert state == (2, 2, 0, 0) and passed == [(2, 2)]
    state, passed = advance(lines, (2, 1, 0, 0), 3)     # JUMP: two rows up, then slower
    assert state == (0, 1, -1, 0) and passed == [(1, 1), (0, 1)]
    state, passed = advance(lines, (2, 2, 0, 0), 3)     # JUMP under rock: a bump, no move
    assert state == (2, 2, 0, 0) and passed == []
    state, passed = advance(lines, (1, 1, -1, 0), 2)    # RIGHT in the air into rock: blocked
    assert state == (0, 1, 0, 0) and passed == [(0, 1)]
    state, _ = advance(lines, (0, 3, 0, 0), 0)          # nothing below: gravity
    assert state == (0, 3, 1, 0)


@pytest.mark.parametrize("game", ["coinrun", "ninja"])
def test_falling_into_a_pit_kills(game):
    for seed in range(10):
        task = make(game, seed)
        bottom = task._lines[-1]
        edge = next((c for c in range(3, task.width - 1) if bottom[c] == GROUND and bottom[c + 1] == OPEN), None)
        if edge is not None:
            break
    top = next(r for r in range(task.height) if task._lines[r][edge] == GROUND)
    put(task, top - 1, edge)
    task.step("RIGHT")
    while not task.done:
        task.step("NOOP")
    assert task.won is False and "fell" in task.frame.message
    assert task.episode_return == (-task.params.death_penalty if game == "ninja" else 0.0)


@pytest.mark.parametrize("game, hazard", [("coinrun", "S"), ("jumper", "^")])
def test_hazards_kill_on_touch(game, hazard):
    task = make(game)
    r, c = flat_spot(task)
    task.set_tile(r, c + 1, hazard)
    put(task, r, c)
    _, reward, term, _, info = task.step("RIGHT")
    assert term and info["won"] is False and reward == 0.0 and "hazard" in task.frame.message


@pytest.mark.parametrize("game", ["coinrun", "ninja", "climber"])
def test_walking_into_an_enemy_kills(game):
    task = next(t for t in (make(game, s) for s in range(10)) if t.patrols)
    row, lo, hi, phase = task.patrols[0]
    nxt = patrol_col(task.patrols[0], 1)
    put(task, row, nxt)                  # where the enemy walks next
    task.step("NOOP")
    assert task.done and task.won is False and "enemy" in task.frame.message
    assert task.episode_return == (-task.params.death_penalty if game == "ninja" else 0.0)


def test_enemies_patrol_back_and_forth_and_show_in_the_hud():
    task = next(t for t in (make("coinrun", s) for s in range(10)) if t.patrols)
    patrol = task.patrols[0]
    cols = [patrol_col(patrol, t) for t in range(4 * (patrol[2] - patrol[1]))]
    assert min(cols) == patrol[1] and max(cols) == patrol[2]
    assert all(abs(a - b) == 1 for a, b in zip(cols, cols[1:]))
    put(task, patrol[0], patrol[1] - 3 if patrol[1] > 3 else patrol[2] + 3)
    task.step("NOOP")
    assert "Moving: E@" in task.frame.hud and "Vel" in task.frame.hud


def test_ninja_shuriken_breaks_walls_and_kills_enemies():
    task = make("ninja")
    r, c = flat_spot(task)
    task.set_tile(r, c + 4, BREAKABLE)
    task.set_tile(r - 1, c + 4, BREAKABLE)
    put(task, r, c)
    task.heading = 1
    task.step("THROW")
    assert task.stars and task.stars[0][1] == c + 2
    task.step("NOOP")
    assert not task.stars and task._lines[r][c + 4] == OPEN and task._lines[r - 1][c + 4] == OPEN
    assert "broke a wall" in task.frame.message
    # an enemy in the shuriken's way dies and pays
    task.patrols.append((r, c + 3, c + 3, 0))
    task.alive.append(True)
    task.step("THROW")
    assert task.alive[-1] and task.stars[0][1] == c + 2
    task.step("NOOP")
    assert task.alive[-1] is False and task.kills == 1 and not task.stars
    assert task.episode_return == pytest.approx(task.params.kill_reward)


def test_climber_stars_pay_and_are_taken():
    task = make("climber")
    r, c = next((rr, line.index("*")) for rr, line in enumerate(task._lines) if "*" in line)
    task.set_tile(r, c - 1, OPEN)
    put(task, r, c - 1)
    _, reward, _, _, _ = task.step("RIGHT")
    assert reward == pytest.approx(0.1) and task.taken == 1 and task._lines[r][c] == OPEN


def test_jumper_compass_points_at_the_carrot():
    task = make("jumper")
    (gr, gc), (r, c) = next(iter(task.goals)), task.pos
    assert task._lines[gr][gc] == "%" and abs(gr - r) + abs(gc - c) >= task.params.min_distance
    hud = task.frame.hud
    assert f"Carrot {abs(gc - c)}{'←' if gc < c else '→'} {abs(gr - r)}{'↑' if gr < r else '↓'}" in hud


@pytest.mark.parametrize("game", ["coinrun", "ninja", "climber"])
def test_quick_motion_text_is_the_engines(game):
    rng = np.random.default_rng(1)
    task = make(game)
    for _ in range(300):
        if task.done:
            task.reset(seed=int(rng.integers(100)))
        task.step(int(rng.integers(task.action_space.n)))
        assert task._motion() == ProcgenTask._motion(task)


@pytest.mark.parametrize("game", GAMES)
def test_quick_view_is_the_engines(game):
    rng = np.random.default_rng(2)
    task = make(game)
    for _ in range(300):
        if task.done:
            task.reset(seed=int(rng.integers(100)))
        task.step(int(rng.integers(task.action_space.n)))
        assert task._grid() == ProcgenTask._grid(task)


def test_views_kept_per_patrol_phase_follow_kills_and_broken_walls():
    """The views and HUD movers kept per place and patrol phase are dropped when an enemy dies
    or a tile changes: throwing often, they stay the engine's at every turn."""
    rng = np.random.default_rng(5)
    task, kills, breaks = make("ninja"), 0, 0
    for _ in range(1500):
        if task.done:
            kills += task.kills
            task.reset(seed=int(rng.integers(1000)))
        task.step(THROW if rng.random() < 0.4 else int(rng.integers(6)))
        breaks += "broke a wall" in task.frame.message
        assert task._grid() == ProcgenTask._grid(task)
        assert task._motion() == ProcgenTask._motion(task)
    assert kills + task.kills > 0 and breaks > 0


@pytest.mark.parametrize("game, hazard", [("coinrun", "S"), ("jumper", "^")])
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_a_searched_path_into_a_hazard_loses(game, hazard, seed):
    """The search aimed at the nearest hazard instead of the goal: played, it dies there."""
    for seed_ in range(seed, seed + 20):
        task = make(game, seed_)
        cells = frozenset((r, c) for r, line in enumerate(task._lines) for c, ch in enumerate(line)
                          if ch == hazard)
        path, _ = search(task._lines, task.state, cells, air_jumps=task.air_jumps,
                         patrols=task.patrols)
        if path:
            break
    for action in path:
        assert not task.done
        task.step(action)
    assert task.done and task.won is False and task.episode_return == 0.0
    assert "hazard" in task.frame.message


@pytest.mark.parametrize("game", GAMES)
def test_the_fallback_level_after_the_retries_is_winnable(game):
    task = make(game)
    for seed in range(5):
        task._build(np.random.default_rng(seed), easy=True)
        lines = ["".join(row) for row in task.rows]
        path, _ = search(lines, (*task.start, 0, task.air_jumps), task.goals, air_jumps=task.air_jumps,
                         hazards=task.hazards, patrols=task.patrols)
        assert path
