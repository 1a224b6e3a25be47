import pytest

import glyphbench_rl
from glyphbench_rl.games.classics.towerdefense import TOWERS, WAYPOINTS, trace
from glyphbench_rl.games.common.waves import Enemy

TASK = "glyphbench/classics-towerdefense-v0"


def coverage(task, cell, reach):
    return sum(abs(r - cell[0]) <= reach and abs(c - cell[1]) <= reach for r, c in task.path)


def greedy(task):
    """Build an arrow tower on the free cell that sees the most path whenever gold allows;
    start each wave at once."""
    tower = TOWERS["ARROW"]
    free = [(cell, name) for cell, name in task.sites if cell not in task.towers]
    if task.gold >= tower.cost and free:
        cell, name = max(free, key=lambda x: (coverage(task, x[0], tower.reach), -x[0][0], -x[0][1]))
        return f"ARROW_{name}"
    return "START" if task.countdown else "WAIT"


@pytest.mark.parametrize("seed", [0, 1, 2, 3, 1_000_000])
def test_win_path_greedy_arrows(seed):
    task = glyphbench_rl.make(TASK)
    task.reset(seed=seed)
    info = {}
    while not task.done:
        _, reward, term, trunc, info = task.step(greedy(task))
    assert term and task.won and task.wave == task.params.waves and task.lives > 0
    assert task.episode_return == pytest.approx(1.0) and not info["clamped"]
    assert "Every wave is cleared." in info["frame"].message


def test_loss_path_building_nothing():
    task = glyphbench_rl.make(TASK)
    task.reset(seed=0)
    rewards = []
    while not task.done:
        _, reward, term, trunc, info = task.step("WAIT")
        rewards.append(reward)
    assert term and task.won is False and task.wave == 1 and task.lives <= 0
    assert task.episode_return == -task.params.loss_penalty and not info["clamped"]
    assert "No lives left." in info["frame"].message


def test_path_and_sites():
    task = glyphbench_rl.make(TASK)
    path = trace(WAYPOINTS)
    assert path[0] == (1, 0) and path[-1] == (5, 9) and len(path) == len(set(path)) == 28
    assert all(abs(a[0] - b[0]) + abs(a[1] - b[1]) == 1 for a, b in zip(path, path[1:]))
    assert len(task.sites) == 7 * 10 - 28 and task.action_space.n == 2 + 2 * len(task.sites)
    obs, _ = task.reset(seed=0)
    assert obs.splitlines()[3] == "2 ░░░░░░░░░·"


def test_waves_start_by_countdown_or_start_and_follow_the_schedule():
    task = glyphbench_rl.make(TASK)
    task.reset(seed=5)
    for _ in range(task.params.build_turns - 1):
        task.step("WAIT")
    assert task.wave == 0
    obs, *_ = task.step("WAIT")
    assert task.wave == 1 and "Wave 1 begins." in obs
    e = task.enemies[0]
    assert e.cell == task.path[0] and 1 <= e.hp <= 1 + task.params.hp_spread
    task.step("WAIT")
    assert e.cell == task.path[task.params.speed]
    task = glyphbench_rl.make(TASK)
    task.reset(seed=5)
    task.step("START")
    assert task.wave == 1 and task.countdown == 0 and len(task.enemies) == 1
    assert task.params.base_count + 1 == len(task.enemies) + len(task.incoming)


def test_towers_cost_gold_and_fire():
    task = glyphbench_rl.make(TASK)
    task.reset(seed=0)
    obs, *_ = task.step("CANNON_E3")
    assert "Not enough gold." in obs and not task.towers
    task.step("ARROW_E3")
    assert task.gold == task.params.start_gold - TOWERS["ARROW"].cost and task.towers[(2, 4)].glyph == "A"
    obs, *_ = task.step("ARROW_E3")
    assert "already has a tower" in obs
    # An arrow hits only the enemy farthest along; a cannon hits everyone in reach.
    task.gold = 99
    task.step("CANNON_H5")                      # (4, 7): next to path cells (3, 6..8) and (5, 6..8)
    near = [Enemy(*task.path[k], hp=5, step=k) for k in (26, 25, 24)]   # farthest first, as they entered
    far = Enemy(*task.path[0], hp=5, step=0)
    task.enemies = near + [far]
    task.countdown = 0
    task.incoming = [(99, 1)]
    task._fire()
    assert far.hp == 5
    cannon = TOWERS["CANNON"].damage
    assert [e.hp for e in near] == [5 - cannon, 5 - cannon, 5 - cannon]


def test_leaks_cost_lives():
    task = glyphbench_rl.make(TASK, lives=2)
    task.reset(seed=0)
    task.step("START")
    task.enemies = [Enemy(*task.path[-1], hp=9, step=len(task.path) - 1)]
    obs, reward, term, *_ = task.step("WAIT")
    assert task.lives == 1 and "1 got through." in obs and not term


def test_prompt_numbers_come_from_the_code():
    prompt = glyphbench_rl.make(TASK).system_prompt()
    arrow = TOWERS["ARROW"]
    assert f"arrow tower A costs {arrow.cost} gold" in prompt and "+0.2 per wave cleared" in prompt
    assert "ARROW_A1" in prompt and "CANNON_J7" in prompt and "ARROW_A2" not in prompt


def test_bad_params():
    with pytest.raises(ValueError, match="waves"):
        glyphbench_rl.make(TASK, waves=0)
    with pytest.raises(ValueError, match="hp_growth"):
        glyphbench_rl.make(TASK, hp_growth=3.0)
    with pytest.raises(ValueError, match="speed"):
        glyphbench_rl.make(TASK, speed=4)
    with pytest.raises(ValueError, match="loss_penalty"):
        glyphbench_rl.make(TASK, loss_penalty=2)
