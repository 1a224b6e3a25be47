import pytest

import glyphbench_rl
from glyphbench_rl.games.classics.ski import FLAG, SKIER_ROW, TREE

ID = "glyphbench/classics-ski-v0"


def best_run(task):
    """Dynamic programming down the known course: the steering (0 left, 1 straight, 2 right)
    that passes the most gates without hitting a tree, from the skier's current cell."""
    p = task.params
    start = task.pos + SKIER_ROW

    def gain(r, c):
        if r not in task.gate_rows:
            return 0
        left = task.course[r].index(FLAG)
        return int(left < c <= left + p.gate_width)

    # value[c]: most gates from row r at column c to the finish; None where a tree ends the run
    value = [0] * p.width
    choice = {}
    for r in range(task.finish_row - 1, start - 1, -1):
        new = [None] * p.width
        for c in range(p.width):
            for a in (1, 0, 2):
                nc = min(p.width - 1, max(0, c + a - 1))
                if task.course[r + 1][nc] == TREE or value[nc] is None:
                    continue
                v = value[nc] + gain(r + 1, nc)
                if new[c] is None or v > new[c]:
                    new[c], choice[(r, c)] = v, a
        value = new
    plan, c = [], task.col
    for r in range(start, task.finish_row):
        a = choice[(r, c)]
        plan.append(a)
        c = min(p.width - 1, max(0, c + a - 1))
    return plan


@pytest.mark.parametrize("seed", range(8))
def test_win_path(seed):
    task = glyphbench_rl.make(ID)
    task.reset(seed=seed)
    for a in best_run(task):
        task.step(a)
    assert task.done and task.won and task.passed == task.params.gates
    assert task.episode_return == pytest.approx(1.0)


def test_loss_path_crashes():
    task = glyphbench_rl.make(ID, tree_density=0.5)
    task.reset(seed=0)
    while not task.done:
        _, reward, term, trunc, info = task.step("STRAIGHT")
    assert task.won is False and task.passed == 0
    assert task.episode_return == pytest.approx(-task.params.crash_penalty)
    assert "crashed" in info["frame"].message


def test_missing_every_gate_finishes_without_reward():
    task = glyphbench_rl.make(ID, tree_density=0.0)
    task.reset(seed=1)
    while not task.done:
        task.step("LEFT")                  # hug the left edge: every gate is to the right
    assert task.won is False and task.missed == task.params.gates and task.episode_return == 0


def test_bad_params():
    with pytest.raises(ValueError, match="gate_width"):
        glyphbench_rl.make(ID, gate_width=4)
    with pytest.raises(ValueError, match="tree_density"):
        glyphbench_rl.make(ID, tree_density=0.9)
