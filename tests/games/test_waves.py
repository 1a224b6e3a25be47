"""The shared wave/enemy mechanics of Bomberman, Tower Defense and Wave Defense."""

import numpy as np
import pytest

from glyphbench_rl.games.common.waves import (Enemy, Rolls, covered_steps, hit, spawn_cells,
                                             spawn_schedule, volley, walk_path, wander)


def test_spawn_schedule_and_cells_are_seeded_and_bounded():
    a = spawn_schedule(np.random.default_rng(1), 6, 1, 2)
    assert a == spawn_schedule(np.random.default_rng(1), 6, 1, 2)
    assert a[0] == 0 and all(1 <= y - x <= 2 for x, y in zip(a, a[1:]))
    with pytest.raises(ValueError):
        spawn_schedule(np.random.default_rng(0), 3, 0, 2)
    cells = [(r, c) for r in range(5) for c in range(5)]
    picks = spawn_cells(np.random.default_rng(2), cells, 3, (0, 0), 6)
    assert len(set(picks)) == 3 and all(r + c >= 6 for r, c in picks)
    assert len(spawn_cells(np.random.default_rng(2), cells, 5, (0, 0), 99)) == 5   # falls back to the farthest


def test_walk_path_leaks_and_hit_points():
    path = [(0, c) for c in range(4)]
    a, b = Enemy(0, 0, hp=2), Enemy(0, 2, step=2)
    assert walk_path([a, b], path, 2) == [b] and a.cell == (0, 2)
    assert not hit(a) and hit(a)


def test_wander_keeps_heading_and_turns_when_blocked():
    open_cells = {(1, 1), (1, 2), (1, 3), (2, 3)}
    e = Enemy(1, 1, heading=3)                       # heading right along a corridor
    assert wander(e, lambda r, c: (r, c) in open_cells, 0.0, 0.0) and e.cell == (1, 2)
    assert wander(e, lambda r, c: (r, c) in open_cells, 0.0, 0.0) and e.cell == (1, 3)
    assert wander(e, lambda r, c: (r, c) in open_cells, 0.0, 0.0) and e.cell == (2, 3)   # blocked: down or back
    assert not wander(Enemy(5, 5), lambda r, c: False, 0.5, 0.5)


def test_volley_hits_the_farthest_live_walker_or_everyone_in_reach():
    path = [(0, c) for c in range(6)]
    assert covered_steps(path, (1, 2), 1) == (3, 2, 1)
    watch = [[] for _ in path]
    for i in covered_steps(path, (1, 2), 1):
        watch[i].append(("arrow", 1, False))
    walkers = [Enemy(0, i, hp=1, step=i) for i in (5, 3, 1)]        # farthest first
    assert volley(walkers, watch) == 1 and [e.hp for e in walkers] == [1, 0, 1]
    assert volley(walkers[1:], watch) == 1 and walkers[2].hp == 0   # the dead are skipped
    for i in range(6):
        watch[i] = [("cannon", 2, True)]
    walkers = [Enemy(0, i, hp=3, step=i) for i in (4, 2)]
    assert volley(walkers, watch) == 0 and [e.hp for e in walkers] == [1, 1]


def test_rolls_follow_the_generator_across_blocks():
    rolls = Rolls(np.random.default_rng(4), block=3)
    draws = [rolls.next() for _ in range(7)]
    gen = np.random.default_rng(4)
    assert draws == np.concatenate([gen.random(3), gen.random(3), gen.random(3)])[:7].tolist()
    assert all(0 <= rolls.pick(5) < 5 for _ in range(50))
