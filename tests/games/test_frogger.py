import pytest

import glyphbench_rl
from glyphbench_rl.games.classics.frogger import Frogger

ID = "glyphbench/classics-frogger-v0"


def plan_home(task, horizon=80):
    """Breadth-first search over (tick, row, col) through the lanes' known future: the shortest
    action sequence that fills a home without dying."""
    layer = {task.frog: []}
    for tick in range(task.tick + 1, task.tick + 1 + horizon):
        nxt = {}
        for (r, c), path in layer.items():
            for a in range(len(task.actions)):
                nr, nc, outcome = task.advance(tick, r, c, a)
                if outcome == "home":
                    return path + [a]
                if outcome == "ok" and (nr, nc) not in nxt:
                    nxt[(nr, nc)] = path + [a]
        layer = nxt
    return None


@pytest.mark.parametrize("seed", range(5))
def test_win_path(seed):
    task = glyphbench_rl.make(ID)
    task.reset(seed=seed)
    while not task.done:
        path = plan_home(task)
        assert path is not None, "no way home"
        for a in path:
            task.step(a)
    assert task.won and task.lives == task.params.lives
    assert task.episode_return == pytest.approx(1.0)


def test_loss_path_waits_in_traffic():
    task = glyphbench_rl.make(ID)
    task.reset(seed=0)
    while not task.done:
        r, c = task.frog
        _, reward, term, trunc, info = task.step("UP" if r == task.height - 1 else "WAIT")
    assert term and task.won is False and task.lives == 0
    assert task.episode_return <= 0
    assert "squashed" in info["frame"].message


def test_logs_carry_the_frog():
    task = glyphbench_rl.make(ID)
    task.reset(seed=3)
    r = 1
    lane = task.lanes[r]
    tick = next(t for t in range(1, 10) if lane.moves_at(t))
    row = lane.row(tick - 1)
    c = next(c for c in range(1, task.params.width - 1) if row[c] != "~" and row[c + lane.direction] != "~")
    assert task.advance(tick, r, c, 4) == (r, c + lane.direction, "ok")
    water = row.index("~")
    assert task.advance(tick, r, water, 4)[2] == "drowned"


def test_rewards_add_to_one_and_penalties_fit():
    task = glyphbench_rl.make(ID)
    assert task.params.homes * (task.home_reward + task.step_reward * (task.height - 2)) == pytest.approx(1)
    with pytest.raises(ValueError, match="death_penalty"):
        Frogger(lives=5, death_penalty=0.3)
    with pytest.raises(ValueError, match="homes"):
        glyphbench_rl.make(ID, homes=9)


def test_right_column_shows_which_rows_move_on_the_coming_turn():
    task = glyphbench_rl.make(ID)
    _, info = task.reset(seed=0)
    seen = set()
    for _ in range(12):                        # WAIT on the start row is always safe
        frame, before = info["frame"], {r: lane.row(task.tick) for r, lane in task.lanes.items()}
        assert all(len(row) == task.params.width + 1 for row in frame.grid)
        _, _, _, _, info = task.step("WAIT")
        for r, row in enumerate(frame.grid):
            mark = row[-1]
            seen.add(mark)
            if r not in task.lanes:
                assert mark == "|"
                continue
            was, now = before[r], task.lanes[r].row(task.tick)
            assert now == {"|": was, "→": was[-1] + was[:-1], "←": was[1:] + was[0]}[mark], (r, mark)
    assert seen == {"|", "→", "←"}
    legend = info["frame"].legend_dict()
    assert legend["→"] == "row moves right next turn" and legend["|"] == "row still next turn"
