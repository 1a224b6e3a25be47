"""The shooter games: distinct levels, scripted (look-ahead) win or positive-score paths, loss
paths, and their swept collisions."""

import copy

import pytest

import glyphbench_rl
from glyphbench_rl.games.common.grid import bfs_distances
from glyphbench_rl.games.procgen.shooting import FOE, FOE_SHOT, FRIEND, PLAYER, SHOT, Body

GAMES = ["starpilot", "bossfight", "plunder", "caveflyer"]


def make(game, **kw):
    return glyphbench_rl.make(f"glyphbench/procgen-{game}-v0", **kw)


def fingerprint(task):
    return tuple(task._rows()), tuple(sorted(task._sprites())), tuple(sorted(task._movers())), task.pos


@pytest.mark.parametrize("game", GAMES)
def test_fifty_seeds_give_distinct_levels(game):
    task = make(game)
    levels = set()
    for seed in range(50):
        task.reset(seed=seed)
        levels.add(fingerprint(task))
    assert len(levels) >= 45


def survive(task, first, then=("NOOP", "UP", "DOWN", "LEFT", "RIGHT"), depth=3):
    """Look ahead: the reward of ``first`` and whether some steady move keeps you alive
    ``depth`` more turns (the world's streams are copied, so this is the real future)."""
    sim = copy.deepcopy(task)
    _, gain, term, trunc, _ = sim.step(first)
    if term or trunc:
        return gain, sim.won is not False
    for move in then:
        branch = copy.deepcopy(sim)
        total, done = 0.0, False
        for _ in range(depth):
            _, r, term, trunc, _ = branch.step(move)
            total += r
            if term or trunc:
                done = True
                break
        if not done or branch.won is not False:
            return gain + max(total, 0.0), True
    return gain, False


def lookahead(task, actions, heuristic, **kw):
    """The action with the best (alive, reward, heuristic) outlook."""
    def value(action):
        gain, alive = survive(task, action, **kw)
        return alive, gain, heuristic(task, action)
    return max(actions, key=value)


# -- StarPilot --------------------------------------------------------------------------------------
def starpilot_aim(task, action):
    """Prefer firing at an enemy ahead in your row, else moving to the nearest enemy's row."""
    r, c = task.pos
    ahead = [b for b in task.world.bodies if b.side == FOE and b.c > c]
    if not ahead:
        return -abs(c - 4) if action in ("LEFT", "RIGHT") else 0
    target = min(ahead, key=lambda b: b.c - c + 3 * abs(b.r - r))
    if action == "FIRE":
        return 2 if target.r == r and task.gun.ready <= task.turn + 1 else -1
    dr = {"UP": -1, "DOWN": 1}.get(action, 0)
    return 1 - abs(target.r - (r + dr)) if dr or action == "NOOP" else -1


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_starpilot_scripted_pilot_scores(seed):
    task = make("starpilot")
    task.reset(seed=seed)
    while not task.done:
        task.step(lookahead(task, task.actions.names, starpilot_aim))
    assert task.won is not False and task.kills >= 6 and task.episode_return > 0.3


def test_starpilot_sitting_still_gets_destroyed():
    task = make("starpilot")
    for seed in range(5):
        task.reset(seed=seed)
        while not task.done:
            task.step("NOOP")
        if task.won is False:
            break
    assert task.won is False and task.episode_return < 0 and "destroyed you" in task.frame.message


def test_starpilot_fast_enemy_cannot_jump_over_you_or_a_bolt():
    task = make("starpilot", rocks=0)
    task.reset(seed=3)
    task.world.bodies[1:] = []
    task.wobble = 0                            # (no drifting out of the row)
    r, c = task.pos
    fast = task.world.add(Body("V", r, c + 2, 0, -2, side=FOE, hits=PLAYER))
    task.step("NOOP")                          # the ship at c+2 moves to c: through your cell
    assert task.done and task.won is False and fast.alive
    task.reset(seed=3)
    task.world.bodies[1:] = []
    task.wobble = 0
    r, c = task.pos
    task.world.add(Body("V", r, c + 3, 0, -2, side=FOE, hits=PLAYER))
    _, reward, *_ = task.step("FIRE")          # bolt c -> c+2, ship c+3 -> c+1: they cross
    assert reward == pytest.approx(0.8 / 12) and not task.done and task.world.count(FOE | SHOT) == 0


# -- BossFight --------------------------------------------------------------------------------------
def boss_aim(task, action):
    """Stay low, under where the boss will be when a bolt gets there; fire when lined up."""
    boss, (r, c) = task.boss, task.pos
    eta = (r - boss.r + 1) // 2
    col = boss.c + boss.vc * (eta // 2)
    col = min(max(col, 0), task.params.width - 1)
    if action == "FIRE":
        return 3 if abs(col - c) <= 0 and task.gun.ready <= task.turn + 1 else -2
    dc = {"LEFT": -1, "RIGHT": 1}.get(action, 0)
    dr = {"UP": -1, "DOWN": 1}.get(action, 0)
    return -abs(col - (c + dc)) - 0.5 * abs(task.params.height - 1 - (r + dr))


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_bossfight_scripted_fighter_wins(seed):
    task = make("bossfight")
    task.reset(seed=seed)
    while not task.done:
        task.step(lookahead(task, task.actions.names, boss_aim))
    assert task.won and task.episode_return == pytest.approx(1.0)


def test_bossfight_standing_still_gets_you_hit():
    task = make("bossfight")
    task.reset(seed=0)
    while not task.done:
        task.step("NOOP")
    assert task.won is False and task.episode_return == -1.0 and "You were hit." in task.frame.message


def test_bossfight_cover_stops_shots_and_a_fast_shot_cannot_skip_you():
    task = make("bossfight", covers=0)
    task.reset(seed=5)
    task.rhythm = [10 ** 6] * 3                      # (the boss holds its fire)
    r, c = task.pos
    task.world.put(r - 2, c, "#")
    task.world.add(Body("!", r - 4, c, 2, 0, side=FOE_SHOT, hits=PLAYER))
    task.step("NOOP")                                 # r-4 -> r-2 is cover: stopped at r-3
    task.step("NOOP")
    assert not task.done and task.world.count(FOE_SHOT) == 0
    task.world.put(r - 2, c, ".")
    task.step("FIRE")                                 # your bolt is stopped by nothing now...
    task.world.add(Body("!", r - 1, c, 2, 0, side=FOE_SHOT, hits=PLAYER))
    _, reward, term, *_ = task.step("UP")             # you r -> r-1, the shot r-1 -> r+1: crossing
    assert term and reward == -1.0


def test_bossfight_phases_follow_the_boss_hit_points():
    task = make("bossfight")
    task.reset(seed=3)
    seen = []
    for hp in (5, 4, 3, 2, 1):
        task.boss.hp = hp
        seen.append(task.phase)
    assert seen == [0, 0, 1, 1, 2] and sorted(task.order) == ["aimed", "spread", "straight"]
    orders = set()
    for seed in range(12):
        task.reset(seed=seed)
        orders.add(tuple(task.order))
    assert len(orders) >= 4


# -- Plunder ----------------------------------------------------------------------------------------
def outlook(task, action, turns):
    """The reward of ``action`` followed by ``turns`` NOOPs (the real future: streams are copied)."""
    sim = copy.deepcopy(task)
    total = 0.0
    for move in [action] + ["NOOP"] * turns:
        _, r, term, trunc, _ = sim.step(move)
        total += r
        if term or trunc:
            break
    return total


def plunder_gunner(task):
    """Fire when the shot would sink an enemy (and no friend); else move under the enemy ship
    that will be nearest above you."""
    if task.gun.ready <= task.turn + 1 and outlook(task, "FIRE", 6) > outlook(task, "NOOP", 6):
        return "FIRE"                         # (what this shot adds, not what earlier ones do)
    r, c = task.pos
    foes = [b for b in task.world.bodies if b.side == FOE]
    if not foes:
        return "NOOP"
    # where a ship will be when a ball fired from here reaches its lane (2 rows a turn)
    def landing(b):
        eta = (r - b.r + 1) // 2
        return b.c + b.vc * (eta // b.period)
    col = min((landing(b) for b in foes), key=lambda x: abs(x - c))
    return "LEFT" if col < c else "RIGHT" if col > c else "NOOP"


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_plunder_scripted_gunner_scores(seed):
    task = make("plunder")
    task.reset(seed=seed)
    while not task.done:
        task.step(plunder_gunner(task))
    assert task.sunk >= 3 and task.friendly == 0 and task.episode_return >= 0.3


def test_plunder_wasting_shots_runs_out_the_clock():
    task = make("plunder")
    task.reset(seed=0)
    while not task.done:
        task.step("FIRE")
    assert task.done and task.clock == 0 and task.turn < task.params.timer
    assert "Time is up." in task.frame.message


def test_plunder_friendly_fire_costs_and_a_ball_cannot_skip_a_ship():
    task = make("plunder", rocks=0)
    task.reset(seed=4)
    task.world.bodies[1:] = []
    r, c = task.pos
    friend = "B" if task.target == "A" else "A"
    task.world.add(Body(friend, r - 2, c + 1, 0, -1, side=FRIEND))   # sails into your column
    _, reward, *_ = task.step("FIRE")        # the ball r -> r-2 meets it arriving at (r-2, c)
    assert reward == pytest.approx(-0.1) and task.friendly == 1
    assert "You hit a friendly ship." in task.frame.message


# -- CaveFlyer --------------------------------------------------------------------------------------
def cave_pilot(dist):
    """Head down the distance map to the exit."""
    def heuristic(task, action):
        r, c = task.pos
        if action == "FIRE":                  # (a shot that hits shows in the look-ahead's gain)
            return -dist.get((r, c), 999) - 1
        dr, dc = {"NOOP": (0, 0), "LEFT": (0, -1), "RIGHT": (0, 1), "UP": (-1, 0), "DOWN": (1, 0)}[action]
        return -dist.get((r + dr, c + dc), 999)
    return heuristic


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_caveflyer_scripted_flight_reaches_the_exit(seed):
    task = make("caveflyer")
    task.reset(seed=seed)
    dist = bfs_distances(task.exit, lambda r, c: task.world.rows[r][c] != "#")
    while not task.done:
        task.step(lookahead(task, task.actions.names, cave_pilot(dist)))
    assert task.won and task.episode_return >= 0.6 - 1e-9


def test_caveflyer_flying_into_the_wall_is_fatal():
    task = make("caveflyer")
    task.reset(seed=0)
    while not task.done:
        task.step("UP")
    assert task.won is False and task.episode_return == -1.0
    assert "You crashed into the cave wall." in task.frame.message


def test_caveflyer_enemy_crossing_your_path_and_bolt_hits():
    task = make("caveflyer")
    task.reset(seed=2)
    task.world.bodies[1:] = []
    r, c = task.pos
    task.world.add(Body("E", r - 1, c + 1, 1, 0, side=FOE))     # moves down into (r, c+1)...
    _, reward, term, *_ = task.step("RIGHT")                    # ...as you move there
    assert term and reward == -1.0 and "An enemy got you." in task.frame.message
    task.reset(seed=2)
    task.world.bodies[1:] = []
    r, c = task.pos
    foe = task.world.add(Body("E", r, c + 3, 0, -1, side=FOE))  # coming at you
    _, reward, term, *_ = task.step("FIRE")                      # bolt c -> c+2 meets it at c+2
    assert not term and not foe.alive and reward == pytest.approx(0.1)


def test_caveflyer_every_cave_connects_start_and_exit():
    task = make("caveflyer")
    for seed in range(30):
        task.reset(seed=seed)
        targets = {b.cell for b in task.world.bodies if b.glyph == "o"}
        dist = bfs_distances(task.pos, lambda r, c: task.world.rows[r][c] != "#" and (r, c) not in targets)
        assert task.exit in dist
