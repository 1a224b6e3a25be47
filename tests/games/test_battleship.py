import pytest

import glyphbench_rl
from glyphbench_rl.games.classics.battleship import HIT, MISS, SUNK

ID = "glyphbench/classics-battleship-v0"


def cell_name(task, index):
    return task.actions[index].name


@pytest.mark.parametrize("seed", range(20))
def test_fleet_is_straight_in_bounds_and_apart(seed):
    task = glyphbench_rl.make(ID)
    task.reset(seed=seed)
    n = task.params.size
    assert sorted(len(s) for s in task.ships) == sorted(task.params.fleet)
    assert len(task.ship_at) == sum(task.params.fleet)
    for number, cells in enumerate(task.ships):
        rows = {x // n for x in cells}
        cols = {x % n for x in cells}
        assert len(rows) == 1 or len(cols) == 1
        span = sorted(x % n for x in cells) if len(rows) == 1 else sorted(x // n for x in cells)
        assert span == list(range(span[0], span[0] + len(cells)))
        assert all(task.ship_at[x] == number for x in cells)


@pytest.mark.parametrize("seed", [0, 1, 2, 1_000_000])
def test_win_path_firing_at_every_ship_cell(seed):
    task = glyphbench_rl.make(ID)
    task.reset(seed=seed)
    for cells in task.ships:
        for x in cells:
            _, reward, term, trunc, info = task.step(cell_name(task, x))
            assert reward > 0
    assert term and task.won and not info["clamped"]
    assert task.turn == sum(task.params.fleet)
    assert task.episode_return == pytest.approx(1.0)
    assert "You win." in info["frame"].message and info["frame"].hud.endswith("Afloat none")


def test_loss_path_firing_only_at_water():
    task = glyphbench_rl.make(ID)
    task.reset(seed=3)
    water = [x for x in range(task.params.size ** 2) if x not in task.ship_at]
    for x in water:
        if task.done:
            break
        _, reward, *_ = task.step(cell_name(task, x))
        assert reward == 0.0
    assert task.done and task.won is None and task.episode_return == 0.0
    assert task.turn == task.max_turns


def test_hits_sinking_and_repeats():
    task = glyphbench_rl.make(ID)
    task.reset(seed=5)
    ship = min(task.ships, key=len)
    n = task.params.size
    *first, last = ship
    for x in first:
        _, reward, *_ = task.step(cell_name(task, x))
        assert reward == pytest.approx(0.5 / 17) and task.frame.message == f"Hit. Reward {0.5 / 17:+.3g}"
        assert task.frame.grid[x // n][x % n] == HIT
    _, reward, _, _, info = task.step(cell_name(task, first[0]))   # again: wasted
    assert reward == 0.0 and info["frame"].message.endswith("was already fired at.")
    _, reward, *_ = task.step(cell_name(task, last))
    assert task.frame.message == f"Hit: you sank a ship of length {len(ship)}. Reward {reward:+.3g}"
    assert all(task.frame.grid[x // n][x % n] == SUNK for x in ship)
    afloat = sorted(task.params.fleet)
    afloat.remove(len(ship))
    assert sorted(map(int, task.frame.hud.split("Afloat ")[1].split())) == afloat
    water = next(x for x in range(n * n) if x not in task.ship_at)
    task.step(cell_name(task, water))
    assert task.frame.grid[water // n][water % n] == MISS and task.frame.message == "Miss."


def density_shot(task):
    """Hunt by counting, for every unfired cell, the placements of the ships still afloat that
    fit the board (placements through hits weigh far more): a standard strong strategy."""
    n, cells = task.params.size, task.frame.grid
    afloat = [len(s) for s, k in zip(task.ships, task.left) if k]
    score = {}
    for length in afloat:
        for r in range(n):
            for c in range(n):
                for dr, dc in ((0, 1), (1, 0)):
                    if r + dr * (length - 1) >= n or c + dc * (length - 1) >= n:
                        continue
                    run = [(r + dr * i, c + dc * i) for i in range(length)]
                    marks = [cells[a][b] for a, b in run]
                    if any(m not in ("·", HIT) for m in marks):
                        continue
                    weight = 1 + 50 * marks.count(HIT)
                    for (a, b), m in zip(run, marks):
                        if m == "·":
                            score[a * n + b] = score.get(a * n + b, 0) + weight
    return max(score, key=lambda x: (score[x], -x))


def test_shot_budget_leaves_room_for_good_play():
    wins = 0
    for seed in range(4):
        task = glyphbench_rl.make(ID)
        task.reset(seed=seed)
        while not task.done:
            task.step(density_shot(task))
        wins += bool(task.won)
    assert wins == 4


def test_rendering_and_prompt():
    task = glyphbench_rl.make(ID)
    obs, _ = task.reset(seed=0)
    lines = obs.splitlines()
    assert lines[0] == "Step 0/75 | Afloat 5 4 3 3 2" and lines[1] == "   ABCDEFGHIJ"
    assert lines[-1] == "Legend: · not fired at" and task.action_space.n == 100
    prompt = task.system_prompt()
    assert "lengths 5 4 3 3 2" in prompt and "each hit gives 0.02941" in prompt


def test_bad_params():
    with pytest.raises(ValueError, match="size"):
        glyphbench_rl.make(ID, size=3)
    with pytest.raises(ValueError, match="fleet"):
        glyphbench_rl.make(ID, fleet=(11,))
    with pytest.raises(ValueError, match="fleet"):
        glyphbench_rl.make(ID, size=4, fleet=(4, 4, 4))
    with pytest.raises(ValueError, match="fleet_bonus"):
        glyphbench_rl.make(ID, fleet_bonus=2.0)
