import pytest

import glyphbench_rl
from glyphbench_rl.games.common.waves import Enemy, march

TASK = "glyphbench/classics-wavedefense-v0"


def bot(task):
    """Walk under the nearest invader (lowest first on ties), shoot when one is overhead, and
    never end a turn under a bomb about to land."""
    p, bottom = task.params, task.params.height - 1
    landing = {c for r, c in task.bombs if r + 1 >= bottom}

    def after(action):
        return {"LEFT": max(0, task.x - 1), "RIGHT": min(p.width - 1, task.x + 1)}.get(action, task.x)

    want = "WAIT"
    if task.enemies:
        e = min(task.enemies, key=lambda e: (abs(e.c - task.x), -e.r))
        if e.c != task.x:
            want = "RIGHT" if e.c > task.x else "LEFT"
        elif task.shot is None:
            want = "SHOOT"
    for action in (want, "WAIT", "LEFT", "RIGHT"):
        if after(action) not in landing:
            return action
    return want


def test_win_path_scripted_bot():
    wins = 0
    for seed in [0, 1, 2, 3, 4, 1_000_000]:
        task = glyphbench_rl.make(TASK)
        task.reset(seed=seed)
        info = {}
        while not task.done:
            _, reward, term, trunc, info = task.step(bot(task))
        if task.won:
            wins += 1
            assert task.kills == task.params.target and task.wave >= 2
            assert task.episode_return == pytest.approx(1.0) and not info["clamped"]
            assert "Target reached." in info["frame"].message
    assert wins >= 5


def test_loss_path_standing_still():
    task = glyphbench_rl.make(TASK)
    task.reset(seed=0)
    while not task.done:
        _, reward, term, trunc, info = task.step("WAIT")
    assert term and task.won is False and task.episode_return == -task.params.death_penalty
    assert info["frame"].message in (f"{m} Reward {-task.params.death_penalty:+.3g}"
                                      for m in ("A bomb hit you.", "An invader reached the bottom row."))


def test_bomb_landing_on_you_loses():
    task = glyphbench_rl.make(TASK, fire_chance=0.0)
    task.reset(seed=1)
    bottom = task.params.height - 1
    task.bombs = [(bottom - 2, task.x)]
    _, reward, term, *_ = task.step("WAIT")
    assert not term and task.bombs == [(bottom - 1, task.x)]
    obs, reward, term, *_ = task.step("WAIT")
    assert term and reward == -task.params.death_penalty and "A bomb hit you." in obs


def test_dodging_a_bomb():
    task = glyphbench_rl.make(TASK, fire_chance=0.0)
    task.reset(seed=1)
    task.bombs = [(task.params.height - 2, task.x)]
    _, reward, term, *_ = task.step("LEFT")
    assert not term and task.bombs == []


def test_shot_climbs_and_armor_takes_two_hits():
    task = glyphbench_rl.make(TASK, fire_chance=0.0, march_period=9)
    task.reset(seed=2)
    bottom, speed = task.params.height - 1, task.params.shot_speed
    task.enemies = [Enemy(bottom - 2 * speed, task.x, hp=2), Enemy(1, 0)]
    task.step("SHOOT")
    assert task.shot == (bottom - speed, task.x)
    obs, reward, *_ = task.step("WAIT")
    assert task.shot is None and task.enemies[0].hp == 1 and reward == 0 and "Armor hit." in obs
    task.step("SHOOT")
    obs, reward, *_ = task.step("WAIT")
    assert len(task.enemies) == 1 and task.kills == 1 and reward == pytest.approx(1 / task.params.target)


def test_formation_marches_and_descends_at_the_edge():
    enemies = [Enemy(1, 5), Enemy(1, 7)]
    direction, down = march(enemies, 9, 1)
    assert (direction, down) == (1, False) and [e.c for e in enemies] == [6, 8]
    direction, down = march(enemies, 9, direction)
    assert (direction, down) == (-1, True) and [(e.r, e.c) for e in enemies] == [(2, 6), (2, 8)]


def test_new_wave_after_clearing_and_waves_are_seeded():
    task = glyphbench_rl.make(TASK, fire_chance=0.0)
    task.reset(seed=3)
    task.enemies = [Enemy(task.params.height - 3, task.x)]
    obs, *_ = task.step("SHOOT")
    assert task.wave == 2 and task.enemies and "Wave 1 destroyed." in obs
    a = glyphbench_rl.make(TASK)
    assert a.reset(seed=7)[0] == glyphbench_rl.make(TASK).reset(seed=7)[0]


def test_bad_params():
    with pytest.raises(ValueError, match="cols"):
        glyphbench_rl.make(TASK, cols=5)
    with pytest.raises(ValueError, match="rows"):
        glyphbench_rl.make(TASK, rows=4, height=6)
    with pytest.raises(ValueError, match="fire_chance"):
        glyphbench_rl.make(TASK, fire_chance=1.5)
    with pytest.raises(ValueError, match="target"):
        glyphbench_rl.make(TASK, target=0)
