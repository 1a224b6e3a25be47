import pytest

import glyphbench_rl
from glyphbench_rl.games.classics.lunarlander import UNIT

ID = "glyphbench/classics-lunarlander-v0"


def control(t):
    """A hand-written autopilot: clear the hills, glide to the pad, brake in time to land."""
    p = t.params
    pad_mid = (t.pad.start + t.pad.stop - 1) * UNIT // 2
    dx = pad_mid - t.x
    c = t.column(t.x)
    if c in t.pad:
        alt = (t.top[c] - 1) * UNIT - t.y
        want_vy = max(p.safe_vy - 1, int((3 * alt) ** 0.5))   # braking takes about v*v/4
        want_vx = 0
        turns = alt // max(t.vy, 2) + 2
        drift_ok = abs(t.vx) <= 1 and t.column(t.x + turns * t.vx) in t.pad
    else:
        lo, hi = sorted((c, min(max(c, t.pad.start), t.pad.stop - 1)))
        clear = (min(t.top[lo:hi + 1]) - 3) * UNIT - t.y        # room above the hills on the way
        want_vy = int((3 * clear) ** 0.5) if clear > 0 else -1
        want_vx = max(-3, min(3, dx // 8 if dx > 0 else -(-dx // 8)))
        drift_ok = want_vx == t.vx
    if t.vy + p.gravity > want_vy:
        return "MAIN"
    if not drift_ok:
        if t.vx < want_vx:
            return "RIGHT"
        if t.vx > want_vx:
            return "LEFT"
    return "NOOP"


def test_win_path():
    for seed in range(30):
        task = glyphbench_rl.make(ID)
        task.reset(seed=seed)
        while not task.done:
            task.step(control(task))
        assert task.won and task.landed, seed
        expected = 0.5 + 0.5 * task.fuel / task.params.fuel
        assert task.episode_return == pytest.approx(expected) and task.episode_return > 0.5


def test_loss_path_free_fall_crashes():
    task = glyphbench_rl.make(ID)
    task.reset(seed=0)
    while not task.done:
        _, reward, term, trunc, info = task.step("NOOP")
    assert term and task.won is False
    assert task.episode_return == pytest.approx(-task.params.crash_penalty)
    assert "crashed" in info["frame"].message or "left the screen" in info["frame"].message


def test_physics_and_hud():
    task = glyphbench_rl.make(ID)
    task.reset(seed=2)
    task.vx, task.vy, task.x, task.y = 0, 0, 5 * UNIT, 0
    task.step("MAIN")                      # 1 - 3 = -2, but the top edge stops the lander
    assert (task.y, task.vy, task.fuel) == (0, 0, task.params.fuel - 1)
    task.step("RIGHT")
    assert (task.vx, task.vy, task.x, task.y) == (2, 1, 5 * UNIT + 2, 1)
    assert "Vx +2 | Vy +1" in task.frame.hud and f"Fuel {task.params.fuel - 2}/" in task.frame.hud
    task.fuel = 0
    _, _, _, _, info = task.step("MAIN")
    assert task.vy == 2 and "Out of fuel." in info["frame"].message


def test_fast_touchdown_on_the_pad_crashes():
    task = glyphbench_rl.make(ID)
    task.reset(seed=4)
    c = task.pad.start
    task.x, task.y, task.vx, task.vy = c * UNIT, (task.top[c] - 1) * UNIT - 3, 0, task.params.safe_vy + 1
    task.step("NOOP")
    assert task.done and task.won is False and task.episode_return < 0


def test_bad_params():
    with pytest.raises(ValueError, match="main_thrust"):
        glyphbench_rl.make(ID, main_thrust=1)
    with pytest.raises(ValueError, match="pad_width"):
        glyphbench_rl.make(ID, pad_width=40)
