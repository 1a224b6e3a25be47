"""Unit tests of the shooter engine: swept movement, collisions, edges, guns, spawners, and a
minimal ShooterTask."""

import numpy as np
from glyphbench_rl.games.procgen.engine import PLAYER_GLYPHS, ProcgenTask
import pytest

from glyphbench_rl.games.procgen.shooting import (FAR, FIRE, FIRE_ACTIONS, FOE, FOE_SHOT, GONE,
                                                  PLAYER, SHOT, STOP, WRAP, Body, Gun,
                                                  ShooterTask, Spawner, World, pair)

OPEN_ROWS = ["." * 10] * 5


def shot(r, c, vr, vc, **kw):
    return Body("*", r, c, vr, vc, side=SHOT, hits=FOE, **kw)


def foe(r, c, vr=0, vc=0, **kw):
    return Body("E", r, c, vr, vc, side=FOE, **kw)


def test_a_fast_shot_passes_through_the_middle_cell():
    world = World(OPEN_ROWS, "#")
    s, e = world.add(shot(2, 0, 0, 2)), world.add(foe(2, 1))
    assert world.step(1) == [(s, e)]
    assert s.cell == (2, 2)


def test_bodies_crossing_head_on_collide():
    world = World(OPEN_ROWS, "#")
    s, e = world.add(shot(2, 3, 0, 1)), world.add(foe(2, 4, 0, -1))
    assert world.step(1) == [(s, e)]
    assert s.cell == (2, 4) and e.cell == (2, 3)       # they swapped cells: no tunnelling


def test_crossing_at_different_speeds_collides():
    world = World(OPEN_ROWS, "#")
    s, e = world.add(shot(2, 0, 0, 2)), world.add(foe(2, 2, 0, -1))
    assert world.step(1) == [(s, e)]


def test_a_follower_at_the_same_speed_does_not_collide():
    world = World(OPEN_ROWS, "#")
    world.add(shot(2, 3, 0, 1))
    world.add(foe(2, 4, 0, 1))
    assert world.step(1) == []


def test_entering_a_cell_just_left_is_no_collision_but_a_still_body_is_hit():
    world = World(OPEN_ROWS, "#")
    world.add(shot(1, 4, 1, 0))
    world.add(foe(2, 4, 0, 1))          # leaves (2, 4) as the shot enters it
    assert world.step(1) == []
    s = world.add(shot(3, 2, 0, -3))
    e = world.add(foe(3, 0))
    assert world.step(2) == [(s, e)]                   # (pairs come in the order bodies were added)


def test_bodies_on_one_side_pass_through_each_other():
    world = World(OPEN_ROWS, "#")
    world.add(foe(2, 3, 0, 1))
    world.add(foe(2, 4, 0, -1))
    assert world.step(1) == []
    a, b = world.add(Body("A", 0, 0, 0, 1, side=PLAYER, hits=FOE_SHOT)), world.add(Body("b", 0, 1, side=FOE_SHOT))
    assert world.step(2) == [(a, b)]                   # one side's hits is enough


def test_events_come_in_time_order_and_a_wall_stops_a_body():
    world = World(["..E.E#...."], "#")
    near, far = foe(0, 2), foe(0, 4)
    s = world.add(shot(0, 0, 0, 5))
    world.add(far)
    world.add(near)
    events = world.step(1)
    assert events == [(s, near), (s, far), (s, None)]
    assert s.cell == (0, 4) and s.bump == (0, 5)


def test_reach_ends_a_shot():
    world = World(OPEN_ROWS, "#")
    s = world.add(shot(0, 0, 0, 2, reach=3))
    world.step(1)
    assert s.alive and s.cell == (0, 2) and s.reach == 1
    world.step(2)
    assert s.spent and s.cell == (0, 3)
    assert world.cull() == [] and world.bodies == []   # spent, not gone off the world


def test_a_shot_leaving_the_world_still_hits_on_its_way_out():
    world = World(OPEN_ROWS, "#")
    s, e = world.add(shot(1, 2, -2, 0)), world.add(foe(0, 2))
    assert world.step(1) == [(s, e)] and s.alive and s.spent
    assert world.cull() == [s] and world.bodies == [e]


def test_edges_gone_wrap_stop():
    world = World(OPEN_ROWS, "#")
    gone = world.add(foe(0, 1, 0, -2, edge=GONE))
    wrap = world.add(foe(1, 9, 0, 2, edge=WRAP))
    stop = world.add(foe(2, 8, 0, 3, edge=STOP))
    events = world.step(1)
    assert (stop, None) in events and stop.cell == (2, 9) and stop.bump == (2, 10)
    assert wrap.cell == (1, 1) and wrap.alive
    assert world.cull() == [gone] and gone not in world.bodies


def test_a_wrapping_body_collides_across_the_seam():
    world = World(OPEN_ROWS, "#")
    s = world.add(shot(1, 9, 0, 2, edge=WRAP))
    e = world.add(foe(1, 0))
    assert world.step(1) == [(s, e)]


def test_slow_bodies_move_on_their_period():
    world = World(OPEN_ROWS, "#")
    b = world.add(foe(0, 5, 0, -1, period=2, phase=1))
    cells = []
    for turn in range(1, 5):
        world.step(turn)
        cells.append(b.c)
    assert cells == [4, 4, 3, 3]


def test_diagonal_move_is_swept_along_its_line():
    world = World(OPEN_ROWS, "#")
    s = world.add(shot(0, 0, 2, 2))
    e = world.add(foe(2, 2))
    assert world.step(1) == [(s, e)]


def test_gun_cooldown_and_direction():
    world = World(OPEN_ROWS, "#")
    gun = Gun("*", 2, 6, 3)
    first = gun.fire(world, 2, 2, 0, 1, turn=1)
    assert first is not None and (first.vr, first.vc, first.reach) == (0, 2, 6)
    assert gun.fire(world, 2, 2, 0, 1, turn=2) is None
    assert gun.fire(world, 2, 2, 0, 1, turn=3) is None
    assert gun.fire(world, 2, 2, -1, 0, turn=4).vr == -2


def test_spawner_period_jitter_and_determinism():
    def turns(seed):
        sp = Spawner(np.random.default_rng(seed), period=5, jitter=2, first=3)
        return [t for t in range(1, 60) if sp.due(t)]
    a = turns(1)
    assert a == turns(1) and a[0] == 3
    gaps = np.diff(a)
    assert gaps.min() >= 3 and gaps.max() <= 7 and len(set(gaps)) > 1
    assert turns(1) != turns(2)


class Toy(ShooterTask):
    title = "Toy"
    rules = "A toy."
    solid = "#"
    glyphs = {".": "open", "#": "wall", "E": "enemy", "*": "shot", **PLAYER_GLYPHS}

    def _setup(self, rng):
        self.start(["#" * 12] + ["#" + "." * 10 + "#"] * 4 + ["#" * 12], (2, 2), Gun("*", 2, FAR, 2))
        self.enemy = self.world.add(foe(2, 9, 0, -1))
        self.log = []

    def _hit(self, a, b):
        self.log.append((a.glyph, b and b.glyph))
        if pair(a, b, SHOT):
            a.alive = b.alive = False
            self.reward(0.5)
        elif pair(a, b, PLAYER):
            self.finish(won=False)

    def _left(self, body):
        self.log.append(("left", body.glyph))


def test_shooter_task_fire_kills_the_incoming_enemy_and_reports_motion():
    task = Toy()
    assert task.actions.names[-1] == "FIRE" and FIRE_ACTIONS.names[FIRE] == "FIRE"
    task.reset(seed=0)
    assert task._movers() == [("E", 2, 9, 0, -1)] and task._velocity() == (0, 0)
    assert "E@+0,+7←1" in task.frame.hud and "status line lists moving things" in task.system_prompt()
    _, r, *_ = task.step("RIGHT")
    assert task.pos == (2, 3) and task._velocity() == (0, 1) and r == 0
    _, r, *_ = task.step("FIRE")                      # the shot 3 -> 5, the enemy 8 -> 7
    assert r == 0 and "Gun wait 1" in task.frame.hud
    _, r, *_ = task.step("NOOP")                      # shot 5 -> 7 crosses the enemy 7 -> 6
    assert r == 0.5 and task.world.count(FOE) == 0
    assert task._movers() == []


def test_shooter_task_wall_stops_the_player_and_contact_kills():
    task = Toy()
    task.reset(seed=0)
    for _ in range(3):
        task.step("UP")
    assert task.pos == (1, 2) and not task.done
    task.enemy.r, task.enemy.c, task.enemy.vc = 1, 4, -2
    _, r, term, *_ = task.step("RIGHT")             # the player 2 -> 3, the enemy 4 -> 2: crossed
    assert term and task.won is False


@pytest.mark.parametrize("speed", [1, 2, 3])
def test_no_tunnelling_at_any_speed(speed):
    for gap in range(1, 8):
        world = World(["." * 20], "#")
        s = world.add(shot(0, 0, 0, speed))
        e = world.add(foe(0, gap, 0, -1))
        hit = False
        for turn in range(1, 10):
            if world.step(turn):
                hit = True
                break
        assert hit, (speed, gap)
        assert s.c >= e.c - speed


def test_pair_sorts_an_event_by_side():
    s, e = shot(0, 0, 0, 1), foe(0, 1)
    assert pair(e, s, SHOT) == (s, e) and pair(s, e, FOE) == (e, s)
    assert pair(s, e, PLAYER) is None and pair(s, None, SHOT) is None


@pytest.mark.parametrize("game", ["starpilot", "bossfight", "plunder", "caveflyer"])
def test_the_fast_motion_text_is_the_engines(game):
    import glyphbench_rl
    from glyphbench_rl.games.procgen.engine import ProcgenTask
    task = glyphbench_rl.make(f"glyphbench/procgen-{game}-v0")
    rng = np.random.default_rng(0)
    task.reset(seed=0)
    for _ in range(150):
        assert task._motion() == ProcgenTask._motion(task)
        if task.step(int(rng.integers(task.action_space.n)))[2]:
            task.reset(seed=int(rng.integers(100)))


def test_shooter_task_reports_bodies_leaving_the_world():
    task = Toy()
    task.reset(seed=0)
    task.world.put(2, 11, ".")                       # a gap in the right wall
    task.world.add(Body("z", 2, 10, 0, 2, side=FOE))
    task.step("NOOP")
    assert ("left", "z") in task.log and all(b.glyph != "z" for b in task.world.bodies)


@pytest.mark.parametrize("game", ["starpilot", "bossfight", "plunder", "caveflyer", "bigfish",
                                  "dodgeball"])
def test_the_fast_frame_is_the_engines(game):
    """The shooter's own grid (one pass over the bodies, a cached still window) and HUD draw
    what the generic ProcgenTask code draws from ``_rows`` and ``_sprites``, over random play
    that changes still cells (walls shot away, exits opening) and crosses episodes."""
    import glyphbench_rl
    task = glyphbench_rl.make(f"glyphbench/procgen-{game}-v0")
    rng = np.random.default_rng(1)
    task.reset(seed=1)
    for _ in range(400):
        assert list(task.frame.grid) == ProcgenTask._grid(task)
        assert task.frame.hud.split(" | ", 1)[1] == ProcgenTask._hud(task)
        if task.done:
            task.reset(seed=int(rng.integers(100)))
        else:
            task.step(int(rng.integers(task.action_space.n)))


def test_a_changed_still_cell_shows_in_the_next_frame():
    task = Toy()
    task.reset(seed=0)
    before = task.frame.grid
    task.world.put(2, 11, ".")                       # a gap in the right wall, in view
    task.step("NOOP")
    assert task.frame.grid != before and ProcgenTask._grid(task) == list(task.frame.grid)
