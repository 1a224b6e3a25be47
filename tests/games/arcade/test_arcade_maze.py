"""Maze chase / collect and lane hopping arcade games: scripted wins and losses on the MiniAtari
presets, a scoring scripted policy on the Atari presets, and the families' core mechanics."""

from __future__ import annotations

from collections import deque

import pytest

from glyphbench_rl import make
from glyphbench_rl.games.arcade.chase import CHASE, STEPS, lattice, loop
from glyphbench_rl.games.arcade.hopping import Drift, Ladders, Pyramid
from glyphbench_rl.games.common.lanes import Lane


def bfs_step(task, goal, danger=frozenset()):
    """The first action of a shortest path over open cells (avoiding ``danger``) to a cell where
    ``goal(r, c)``, or None."""
    start = (task.r, task.c)
    seen = {start: None}
    queue = deque([start])
    while queue:
        cell = queue.popleft()
        if cell != start and goal(*cell):
            while seen[cell] != start:
                cell = seen[cell]
            d = (cell[0] - start[0], cell[1] - start[1])
            return STEPS.index(d)
        for dr, dc in STEPS[1:]:
            nxt = (cell[0] + dr, cell[1] + dc)
            if nxt not in seen and nxt not in danger and task.open(*nxt):
                seen[nxt] = cell
                queue.append(nxt)
    return None


def danger(task, reach=1):
    out = set()
    for g in task.ghosts:
        if task.tick + 1 < task.scared_until and g.data[0] == CHASE:
            continue
        for dr in range(-reach, reach + 1):
            for dc in range(-reach, reach + 1):
                if abs(dr) + abs(dc) <= reach:
                    out.add((g.r + dr, g.c + dc))
    return out


def flee(task):
    def score(a):
        dr, dc = STEPS[a]
        r, c = task.r + dr, task.c + dc
        if not task.open(r, c):
            return -1
        return min((abs(g.r - r) + abs(g.c - c) for g in task.ghosts), default=0)
    return max(range(5), key=score)


def collector(goal, reach=1):
    def policy(task):
        a = bfs_step(task, goal, danger(task, reach))
        return flee(task) if a is None else a
    return policy


def hunter(task):
    """Walk straight at the nearest ghost."""
    a = bfs_step(task, lambda r, c: any((g.r, g.c) == (r, c) for g in task.ghosts))
    return 0 if a is None else a


def play(task_id, policy, seed, **kw):
    task = make(task_id, **kw)
    task.reset(seed=seed)
    total = 0.0
    while not task.done:
        _, r, term, trunc, _ = task.step(policy(task))
        total += r
    return task, total


def mini(game):
    return f"glyphbench/miniatari-{game}-v0"


def atari(game):
    return f"glyphbench/atari-{game}-v0"


# --- the chase engine ---------------------------------------------------------------------------

def test_lattice_and_loop_shapes():
    rows = lattice(7, 7, 1)
    assert rows[0] == "=======" and rows[1] == "=.....=" and rows[2] == "=.=.=.="
    assert loop(1, 1, 3, 4)[:5] == [(1, 1), (1, 2), (1, 3), (1, 4), (2, 4)] and len(loop(1, 1, 3, 4)) == 10


def test_ghosts_close_in_and_never_reverse_in_a_corridor():
    task = make(mini("mspacman"), chance=1.0, scatter=0)
    task.reset(seed=0)
    g = task.ghosts[0]
    far = abs(g.r - task.r) + abs(g.c - task.c)
    for _ in range(task.params.release + 8):
        before = (g.dr, g.dc)
        task.step("NOOP")
        if task.done:
            break
        assert (g.dr, g.dc) != (-before[0], -before[1]) or before == (0, 0)
    assert task.done or abs(g.r - task.r) + abs(g.c - task.c) < far


def test_power_pellet_scares_ghosts_and_a_scared_ghost_is_eaten():
    task = make(mini("mspacman"))
    task.reset(seed=0)
    task.frighten()
    g = task.ghosts[0]
    assert task._sprites()[0][2] == "g"
    g.r, g.c = task.r, task.c
    assert task._touch() is False and not task.done and (g.r, g.c) == g.data[2][:2]


# --- games ---------------------------------------------------------------------------------------

def tiles(glyphs):
    return lambda task: collector(lambda r, c: task.still[r][c] in glyphs)(task)


def robber(task):
    return collector(lambda r, c: (r, c) == task.bank)(task)


def gatherer(task):
    """Asterix: step where no lyre is or is about to be, nearest to a potion."""
    p = task.params

    def cost(a):
        dr, dc = STEPS[a]
        r, c = min(p.height - 1, max(0, task.r + dr)), min(p.width - 1, max(0, task.c + dc))
        for t in task.things:
            if t is not None and t.glyph == "E" and t.r == r and abs(t.c - c) <= 2:
                return 999
        food = [abs(t.r - r) + abs(t.c + t.dc - c) for t in task.things if t is not None and t.glyph == "*"]
        return min(food, default=0)
    return min(range(5), key=cost)


def lyre_seeker(task):
    lyres = [t for t in task.things if t is not None and t.glyph == "E"]
    if not lyres:
        return 0
    t = min(lyres, key=lambda t: abs(t.r - task.r) + abs(t.c - task.c))
    if t.r != task.r:
        return 3 if t.r < task.r else 4
    return 1 if t.c < task.c else 2 if t.c > task.c else 0


def frost_next(task, action):
    """Frostbite: where ``action`` puts you next turn and whether you stand there."""
    p, t = task.params, task.tick + 1
    dr, dc = ((0, 0), (0, -1), (0, 1), (-2, 0), (2, 0))[action]
    r, c = task.r + dr, (task.c + task.drift.carry(task.r, t) + dc) % p.width
    if not 0 <= r < p.height:
        r, c = task.r, (task.c + task.drift.carry(task.r, t)) % p.width
    return r, r == 0 or task.drift.solid(r, c, t)


def hopper(task):
    for a in (4, 3):
        r, safe = frost_next(task, a)
        if safe and r != task.r and r != 0 and r not in task.blue:
            return a
    return 0 if frost_next(task, 0)[1] else 3


def diver(task):
    r, safe = frost_next(task, 4)
    return 0 if safe else 4


def painter(task):
    """Q*bert: the first hop of a shortest hop path to an unpainted cube, clear of the balls."""
    pyr = task.pyramid
    risky = set(task.balls) | {(k + 1, i + d) for k, i in task.balls for d in (0, 1)}
    seen, queue = {task.cube: None}, deque([task.cube])
    while queue:
        cube = queue.popleft()
        if cube not in task.painted and cube != task.cube:
            while seen[cube][0] != task.cube:
                cube = seen[cube][0]
            return seen[cube][1]
        for a in range(1, 5):
            nxt = pyr.hop(cube, a)
            if nxt is not None and nxt not in seen and nxt not in risky:
                seen[nxt] = (cube, a)
                queue.append(nxt)
    return 0


def kangaroo_safe(task, r, c):
    bad = set(task.nuts) | {(m[0], m[1] + d) for m in task.monkeys for d in (-1, 0, 1)}
    return (r, c) not in bad and (r - 1, c) not in bad


def climber(task):
    """Kangaroo: the first step of a shortest walk to the top floor; punch a coconut overhead."""
    lad, w = task.ladders, task.params.width
    if (task.r - 1, task.c) in task.nuts:
        return 5

    def nexts(r, c):
        for a in (1, 2, 3, 4):
            dr, dc = STEPS[a]
            if dc and lad.floor_of(r) is not None and 0 <= c + dc < w:
                yield a, (r, c + dc)
            elif dr and lad.climb(r, c, dr):
                yield a, (r + dr, c)
    start, top = (task.r, task.c), lad.floors[-1]
    seen, queue = {start: None}, deque([start])
    while queue:
        cell = queue.popleft()
        if cell[0] == top and cell != start:
            while seen[cell][0] != start:
                cell = seen[cell][0]
            a = seen[cell][1]
            return a if kangaroo_safe(task, *cell) else (0 if kangaroo_safe(task, *start) else 5)
        for a, nxt in nexts(*cell):
            if nxt not in seen:
                seen[nxt] = (cell, a)
                queue.append(nxt)
    return 0


WINS = {"kangaroo": (climber, (0, 1)), "qbert": (painter, (0, 1)), "frostbite": (hopper, (0, 1)), "asterix": (gatherer, (0, 1)), "mspacman": (tiles(".o"), (0, 1)), "amidar": (tiles("+"), (0, 1)), "bankheist": (robber, (0, 2))}


@pytest.mark.parametrize("game", sorted(WINS))
def test_mini_win(game):
    policy, seeds = WINS[game]
    for seed in seeds:
        task, total = play(mini(game), policy, seed)
        assert task.won is True and total == pytest.approx(1.0), seed


@pytest.mark.parametrize("game", sorted(WINS))
def test_atari_scores(game):
    task, total = play(atari(game), WINS[game][0], 0)
    assert total > 0 and task.score.done > 0


LOSERS = {"kangaroo": lambda task: 0, "qbert": lambda task: 1, "frostbite": diver, "mspacman": hunter, "amidar": hunter, "bankheist": hunter, "asterix": lyre_seeker}


@pytest.mark.parametrize("game", sorted(LOSERS))
@pytest.mark.parametrize("seed", [0, 1])
def test_mini_loss(game, seed):
    task, total = play(mini(game), LOSERS[game], seed)
    assert task.won is False and (total == 0 if task.params.death == 0 else total < 0)


def test_bankheist_dynamite_blows_a_cop_back_and_gas_runs_out():
    task = make(atari("bankheist"), release=500)      # the police stay put
    task.reset(seed=0)
    cop = task.ghosts[0]
    task.step("FIRE")
    cop.r, cop.c = task.bomb[0], task.bomb[1] + 1
    for _ in range(task.params.fuse - 1):
        task.step("NOOP")
        assert (cop.r, cop.c) != cop.data[2][:2]
    task.step("NOOP")
    assert (cop.r, cop.c) == cop.data[2][:2] and task.lives == 2      # blown back; you were beside it
    task.tank.left = 1
    task.step("NOOP")
    assert task.lives == 1 and task.tank.left == task.params.gas


# --- the hopping engine -------------------------------------------------------------------------

def test_pyramid_hops_and_edges():
    pyr = Pyramid(4, 1, 4)
    assert pyr.cell((0, 0)) == (1, 4) and pyr.cell((3, 3)) == (4, 7) and len(pyr.cubes) == 10
    assert pyr.hop((0, 0), 4) == (1, 1) and pyr.hop((0, 0), 1) is None and pyr.hop((3, 0), 3) is None
    assert pyr.hop((2, 1), 2) == (1, 1) and pyr.hop((2, 1), 1) == (1, 0)


def test_a_floe_carries_its_rider_and_open_water_drowns():
    drift = Drift({2: Lane("##..", 1, 1)}, ".")
    assert drift.solid(2, 1, 0) and drift.solid(2, 2, 1) and not drift.solid(2, 0, 1)
    assert drift.carry(2, 1) == 1 and drift.carry(3, 1) == 0
    task = make(mini("frostbite"))
    task.reset(seed=0)
    while not frost_next(task, 4)[1]:
        task.step("NOOP")
    task.step("DOWN")
    assert task.r == 2 and task.score.done == 1 and 2 in task.blue
    for _ in range(6):
        c, shift = task.c, task.drift.carry(2, task.tick + 1)
        task.step("NOOP")
        assert task.c == (c + shift) % task.params.width and not task.done


def test_ladders_join_floors():
    lad = Ladders([8, 4, 0], [[2], [5]])
    assert lad.climb(8, 2, -1) and lad.climb(5, 2, -1) and not lad.climb(4, 2, -1)
    assert not lad.climb(8, 3, -1) and lad.floor_of(4) == 1 and lad.floor_of(5) is None


def test_kangaroo_punch_breaks_a_coconut_overhead_and_ladders_lead_up():
    task = make(mini("kangaroo"), drop=50)
    task.reset(seed=0)
    task.nuts = [(task.r - 1, task.c)]
    task.step("FIRE")
    assert task.nuts == [] and not task.done
    col = task.ladders.ladders[0][0]
    task.c = col
    for _ in range(task.params.gap):
        task.step("UP")
    assert task.r == task.ladders.floors[1] and task.score.done == 1
