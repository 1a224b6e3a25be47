import pytest

import glyphbench_rl
from glyphbench_rl.games.procgen.engine import DELTAS
from glyphbench_rl.games.procgen.shooting import FOE, GONE, Body

GAMES = ["bigfish"]


@pytest.mark.parametrize("game", GAMES)
def test_fifty_seeds_give_distinct_levels(game):
    task = glyphbench_rl.make(f"glyphbench/procgen-{game}-v0")
    levels = set()
    for seed in range(50):
        task.reset(seed=seed)
        levels.add((tuple(task._rows()), tuple(sorted(task._sprites())), tuple(sorted(task._movers()))))
    assert len(levels) >= 45


# -- bigfish -----------------------------------------------------------------------------------
def eat_small_avoid_big(task):
    """A greedy fish: a step no bigger fish can reach within two turns, towards the nearest fish
    it may eat (where that fish will be next turn)."""
    p, world = task.player, task.world
    fish = [b for b in world.bodies if b.alive and b.side & FOE]
    danger = set()
    for f in fish:
        if f.hp > task.size:
            step = 1 if f.vc > 0 else -1
            danger.update((f.r, x) for x in range(f.c - step, f.c + 2 * f.vc + step, step))
    food = [(f.r, f.c + f.vc) for f in fish if f.hp <= task.size]
    best, choice = None, 0
    for action, (dr, dc) in enumerate(DELTAS):
        r, c = p.r + dr, p.c + dc
        if not world.inside(r, c) or (r, c) in danger:
            continue
        far = min((abs(r - fr) + abs(c - fc) for fr, fc in food), default=0)
        if best is None or far < best:
            best, choice = far, action
    return choice


def test_bigfish_greedy_policy_scores_positive_and_wins_seeds():
    task = glyphbench_rl.make("glyphbench/procgen-bigfish-v0")
    returns = []
    for seed in range(10):
        task.reset(seed=seed)
        while not task.done:
            task.step(eat_small_avoid_big(task))
        returns.append(task.episode_return)
        if seed in (0, 1, 2):
            assert task.won and task.size == 6 and task.episode_return == pytest.approx(1.0)
    assert sum(returns) / len(returns) > 0.5


def place(task, size, r, c, vc):
    return task.world.add(Body(str(size), r, c, 0, vc, side=FOE, hp=size, edge=GONE))


def test_bigfish_eat_equal_grow_and_die_to_a_bigger_fish():
    task = glyphbench_rl.make("glyphbench/procgen-bigfish-v0", min_fish=1)
    task.reset(seed=0)
    task.world.bodies = [task.player]
    task.spawner.next = 10 ** 6
    r, c = task.pos
    place(task, 1, r, c + 2, -1)            # a size-1 fish swims into you: eaten
    _, reward, term, _, _ = task.step("RIGHT")
    assert reward == pytest.approx(0.1) and task.eaten == 1 and task.size == 1 and not term
    place(task, 1, r, task.pos[1] - 1, 2)   # a fast one passing through you: met on its way
    _, reward, _, _, _ = task.step("NOOP")
    assert task.eaten == 2 and task.size == 2 and "grew to size 2" in task.frame.message
    place(task, 3, r + 1, task.pos[1], 0)   # a bigger fish: touching it ends the game
    _, reward, term, _, info = task.step("DOWN")
    assert term and info["won"] is False and reward == pytest.approx(-1.0)
    assert task.episode_return == pytest.approx(-0.8)
