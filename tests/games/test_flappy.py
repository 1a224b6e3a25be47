import pytest

import glyphbench_rl
from glyphbench_rl.games.classics.flappy import FLAP, MAX_FALL

ID = "glyphbench/classics-flappy-v0"


def plan(task, horizon=200):
    """Depth-first search over FLAP/WAIT through the whole known course: the first action of a path
    that survives ``horizon`` ticks (WAIT tried first)."""
    def survives(pos, y, vy, depth):
        if depth == 0 or pos + 3 >= len(task.course[0]) - task.params.width:
            return True
        key = (pos, y, vy)
        if key in seen:
            return False
        seen.add(key)
        for flap in (False, True):
            ny, nvy, crashed = task.advance(pos, y, vy, flap)
            if not crashed and survives(pos + 1, ny, nvy, depth - 1):
                return True
        return False

    for name, flap in (("WAIT", False), ("FLAP", True)):
        seen = set()
        ny, nvy, crashed = task.advance(task.pos, task.y, task.vy, flap)
        if not crashed and survives(task.pos + 1, ny, nvy, horizon):
            return name
    return "WAIT"


@pytest.mark.parametrize("seed", range(6))
def test_win_path(seed):
    task = glyphbench_rl.make(ID)
    task.reset(seed=seed)
    while not task.done:
        task.step(plan(task))
    assert task.won and task.passed == task.params.target
    assert task.episode_return == pytest.approx(1.0)


def test_every_course_is_passable():
    """Exhaustive forward search over (row, speed) states: some flap sequence survives."""
    for seed in range(40):
        task = glyphbench_rl.make(ID)
        task.reset(seed=seed)
        front = {(task.y, task.vy)}
        for pos in range(task.pipes[-1] + 2):
            front = {(y, vy) for y0, vy0 in front for flap in (False, True)
                     for y, vy, crashed in [task.advance(pos, y0, vy0, flap)] if not crashed}
            assert front, f"seed {seed}: no way past column {pos}"


def test_loss_path_falls_to_the_ground():
    task = glyphbench_rl.make(ID)
    task.reset(seed=0)
    while not task.done:
        _, reward, term, trunc, info = task.step("WAIT")
    assert term and task.won is False and task.passed == 0
    assert task.episode_return == pytest.approx(-task.params.crash_penalty)
    assert task.y == task.params.height - 1 and "crashed" in info["frame"].message


def test_flap_and_gravity():
    task = glyphbench_rl.make(ID)
    task.reset(seed=1)
    y = task.y
    task.step("FLAP")
    assert (task.y, task.vy) == (y + FLAP, FLAP)
    for _ in range(6):
        task.step("WAIT")
    assert task.vy == MAX_FALL and "Vy +2" in task.frame.hud


def test_bad_params():
    with pytest.raises(ValueError, match="gap"):
        glyphbench_rl.make(ID, gap=1)
    with pytest.raises(ValueError, match="spacing"):
        glyphbench_rl.make(ID, spacing=2)
