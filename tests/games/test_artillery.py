import math

import pytest

import glyphbench_rl
from glyphbench_rl.games.classics.artillery import MAX_ANGLE, MIN_ANGLE
from glyphbench_rl.games.common.physics import flight, launch_velocity

ID = "glyphbench/classics-artillery-v0"


def test_flight_matches_the_range_formula_on_flat_ground():
    heights = [1] * 200
    for angle, speed in ((45, 6.0), (30, 8.0), (60, 5.0)):
        vx, vy = launch_velocity(angle, speed)
        path, impact = flight(10.5, 1.0, vx, vy, 0.0, -1.0, heights)
        expected = 10.5 + speed ** 2 * math.sin(math.radians(2 * angle))
        assert impact is not None and impact[1] == 0 and abs(impact[0] - expected) <= 1.0
        assert path and all(r >= 1 for _, r in path)
    vx, vy = launch_velocity(45, 6.0, leftward=True)
    assert vx < 0 and flight(150.5, 1.0, vx, vy, 0.0, -1.0, heights)[1][0] < 150
    _, with_wind = flight(10.5, 1.0, *launch_velocity(45, 6.0), 0.3, -1.0, heights)
    assert with_wind[0] > expected - 1   # a tailwind carries the shell further
    assert flight(1.5, 1.0, *launch_velocity(45, 6.0, leftward=True), 0.0, -1.0, heights)[1] is None


def aim_and_fire(task, angle, power):
    while task.angle != angle:
        task.step("RAISE" if task.angle < angle else "LOWER")
    while task.power != power:
        task.step("MORE" if task.power < power else "LESS")
    return task.step("FIRE")


@pytest.mark.parametrize("seed", [0, 1, 2, 3, 1_000_000])
def test_win_path_with_a_solved_aim(seed):
    task = glyphbench_rl.make(ID)
    task.reset(seed=seed)
    angle, power = task.find_aim(0)
    _, reward, term, _, info = aim_and_fire(task, angle, power)
    assert term and task.won and reward == 1.0 and task.episode_return == 1.0
    assert task.enemy_shots == 0 and not info["clamped"]
    assert info["frame"].message == "The enemy cannon is destroyed. You win. Reward +1"


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_loss_path_firing_into_the_hill(seed):
    task = glyphbench_rl.make(ID)
    task.reset(seed=seed)
    while task.angle > MIN_ANGLE:
        task.step("LOWER")
    while not task.done:
        _, reward, term, trunc, info = task.step("FIRE")
    assert term and task.won is False and task.episode_return == -1.0 and task.enemy_shots >= 1
    assert info["frame"].message.endswith("Your cannon is destroyed. You lose. Reward -1")


def test_shooting_yourself_loses():
    task = glyphbench_rl.make(ID)
    task.reset(seed=0)
    while task.angle < MAX_ANGLE:
        task.step("RAISE")
    while task.power > 1:
        task.step("LESS")
    _, reward, term, _, info = task.step("FIRE")
    assert term and reward == -1.0 and task.enemy_shots == 0
    assert info["frame"].message == "Your cannon is destroyed. You lose. Reward -1"


def test_aiming_is_free_of_enemy_fire_and_bounded():
    task = glyphbench_rl.make(ID)
    task.reset(seed=4)
    for _ in range(20):
        task.step("RAISE")
    assert task.angle == MAX_ANGLE and task.enemy_shots == 0
    _, reward, term, _, info = task.step("RAISE")
    assert reward == 0.0 and not term
    assert info["frame"].message == f"The angle stays within {MIN_ANGLE}..{MAX_ANGLE}."
    assert info["frame"].hud.startswith(f"Step 21/100 | Angle {MAX_ANGLE} | Power 15 | Wind ")


def test_fire_reports_and_draws_the_shot():
    task = glyphbench_rl.make(ID)
    task.reset(seed=2)
    task.step("LOWER")
    _, _, term, _, info = task.step("FIRE")
    grid = "".join(info["frame"].grid)
    assert "*" in grid and ("x" in grid or "flew off" in info["frame"].message)
    assert "Your shell" in info["frame"].message
    if not term:
        assert task.enemy_shots == 1 and "The enemy shell" in info["frame"].message


def test_both_sides_can_hit_and_the_enemy_closes_in():
    task = glyphbench_rl.make(ID)
    for seed in range(10):
        task.reset(seed=seed)
        assert task.find_aim(0) is not None and task.find_aim(1) == task.enemy_aim
        _, impact = task.shoot(1, *task.enemy_aim)
        assert task.hit(impact, 0)
        c, r = task.cannons[0]
        assert task.heights[c - 1] == task.heights[c] == task.heights[c + 1] == r


def test_bad_params():
    with pytest.raises(ValueError, match="width"):
        glyphbench_rl.make(ID, width=8)
    with pytest.raises(ValueError, match="max_wind"):
        glyphbench_rl.make(ID, max_wind=5.0)
    with pytest.raises(ValueError, match="aim_decay"):
        glyphbench_rl.make(ID, aim_decay=1.5)
