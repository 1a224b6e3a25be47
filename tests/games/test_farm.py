import pytest

import glyphbench_rl
from glyphbench_rl.core import check_frame
from glyphbench_rl.games.classics import farm  # noqa: F401  (registers the task)
from glyphbench_rl.games.classics.farm import GRASS, POND, RIPE, SEED, SEED_WET, SPROUT, SPROUT_WET, TILLED
from glyphbench_rl.games.common.grid import DELTAS, MOVES, shortest_path
from glyphbench_rl.games.common.palette import WALL

TASK = "glyphbench/classics-farm-v0"
WORK = {RIPE: "HARVEST", SEED: "WATER", SPROUT: "WATER", TILLED: "PLANT", GRASS: "TILL"}


def make(**kw):
    return glyphbench_rl.make(TASK, **kw)


def walkable(task):
    return lambda r, c: task.rows[r][c] not in (WALL, POND)


def farmer(task, plots):
    """Scripted player: keep the can filled, and tend the nearest plot that needs something."""
    ok = walkable(task)
    ponds = [(r, c) for r, row in enumerate(task.rows) for c, ch in enumerate(row) if ch == POND]
    if task.water == 0 or (task.water < task.params.can_size and not any(
            task.rows[r][c] in WORK for r, c in plots)):
        for r, c in ponds:   # walk next to the pond, then into it
            for name, (dr, dc) in MOVES.items():
                shore = (r - dr, c - dc)
                if ok(*shore):
                    path = shortest_path(task.pos, shore, ok)
                    return path[0] if path else name
    todo = [cell for cell in plots if task.rows[cell[0]][cell[1]] in WORK
            and not (task.water == 0 and task.rows[cell[0]][cell[1]] in (SEED, SPROUT))]
    if not todo:
        return "HARVEST"   # nothing ripe: a wasted turn while the crops grow
    paths = [shortest_path(task.pos, cell, ok) for cell in todo]
    path, cell = min(zip(paths, todo), key=lambda pc: len(pc[0]))
    return path[0] if path else WORK[task.rows[cell[0]][cell[1]]]


def plots_near_pond(task, k):
    ponds = [(r, c) for r, row in enumerate(task.rows) for c, ch in enumerate(row) if ch == POND]
    cells = [(r, c) for r, row in enumerate(task.rows) for c, ch in enumerate(row) if ch == GRASS]
    return sorted(cells, key=lambda x: min(abs(x[0] - r) + abs(x[1] - c) for r, c in ponds))[:k]


@pytest.mark.parametrize("seed", [0, 1, 2, 1_000_003])
def test_win_path_scripted_farmer(seed):
    task = make()
    _, info = task.reset(seed=seed)
    assert check_frame(info["frame"]) == []
    plots = plots_near_pond(task, 6)
    while not task.done:
        _, reward, term, trunc, info = task.step(farmer(task, plots))
        assert check_frame(info["frame"]) == []
    assert term and task.won and not info["clamped"]
    assert task.harvested == task.params.target and task.episode_return == pytest.approx(1.0)


def test_loss_path_idling_times_out_with_zero():
    task = make()
    task.reset(seed=3)
    while not task.done:
        _, reward, *_, info = task.step("HARVEST")   # nothing ripe: nothing happens
        assert reward == 0 and "Nothing to harvest" in info["frame"].message
    assert task._truncated and task.won is None and task.episode_return == 0.0


def test_crop_cycle_timing_and_water():
    task = make(grow_time=3, can_size=2)
    task.reset(seed=0)
    r, c = task.pos
    hud = lambda: task.frame.hud  # noqa: E731
    for action, cell, in [("TILL", TILLED), ("PLANT", SEED), ("WATER", SEED_WET)]:
        task.step(action)
        assert task.rows[r][c] == cell
    assert "Can 1/2" in hud() and "On watered seed" in hud()
    task.step("TILL")   # wasted turns: growing takes grow_time turns after the watering
    task.step("TILL")
    assert task.rows[r][c] == SEED_WET
    task.step("TILL")
    assert task.rows[r][c] == SPROUT
    task.step("WATER")
    assert task.rows[r][c] == SPROUT_WET and task.water == 0
    for _ in range(2):
        *_, info = task.step("HARVEST")
        assert "Nothing to harvest" in info["frame"].message
    _, reward, *_ = task.step("HARVEST")    # the third turn after watering: it ripens, then is cut
    assert reward == pytest.approx(1 / task.params.target) and task.rows[r][c] == TILLED
    task.step("PLANT")
    *_, info = task.step("WATER")
    assert task.rows[r][c] == SEED and "can is empty" in info["frame"].message


def test_pond_refills_and_blocks():
    task = make()
    task.reset(seed=1)
    task.water = 0
    ponds = [(r, c) for r, row in enumerate(task.rows) for c, ch in enumerate(row) if ch == POND]
    for name, (dr, dc) in MOVES.items():
        shore = (ponds[0][0] - dr, ponds[0][1] - dc)
        if walkable(task)(*shore):
            for move in shortest_path(task.pos, shore, walkable(task)):
                task.step(move)
            *_, info = task.step(name)
            assert task.pos == shore and task.water == task.params.can_size
            assert "filled the can" in info["frame"].message
            return
    pytest.fail("no shore")


def test_prompt_shows_the_numbers():
    prompt = make().system_prompt()
    assert "7x7 field" in prompt and "+0.125 per harvest; 8 harvests win" in prompt
    assert "after 4 turns" in prompt and "holds 4 waterings" in prompt


@pytest.mark.parametrize("bad, field", [
    (dict(size=3), "size"), (dict(target=0), "target"), (dict(grow_time=0), "grow_time"),
    (dict(can_size=0), "can_size"), (dict(pond=7), "pond"), (dict(colour=1), "unknown parameter 'colour'"),
])
def test_bad_params(bad, field):
    with pytest.raises(ValueError, match=field):
        make(**bad)
