import numpy as np
import pytest

import glyphbench_rl
from glyphbench_rl.games.common.boards import Bits
from glyphbench_rl.games.classics.floodfill import greedy_plan, lower_bound, pick

VARIANTS = ["easy", "hard"]


def optimum(bits, masks, region):
    """Fewest moves by breadth-first search over flooded regions (the region fixes the state)."""
    frontier, seen, moves = {region}, {region}, 0
    while bits.full not in frontier:
        frontier = {pick(bits, masks, r, c) for r in frontier for c in range(len(masks))} - seen
        seen |= frontier
        moves += 1
    return moves


@pytest.mark.parametrize("size,colours", [(4, 3), (4, 4), (5, 3)])
def test_bounds_bracket_the_optimum(size, colours):
    bits = Bits(size, size)
    rng = np.random.default_rng(size * 10 + colours)
    for _ in range(25):
        colour_of = rng.integers(colours, size=size * size).tolist()
        masks = [sum(1 << i for i, c in enumerate(colour_of) if c == k) for k in range(colours)]
        region = bits.flood(1, masks[colour_of[0]])
        if region == bits.full:
            continue
        plan = greedy_plan(bits, masks, colour_of[0], region, 2)
        r = region
        for c in plan:
            r = pick(bits, masks, r, c)
        assert r == bits.full
        assert lower_bound(bits, masks, region) <= optimum(bits, masks, region) <= len(plan)


@pytest.mark.parametrize("variant", VARIANTS)
@pytest.mark.parametrize("seed", [0, 1, 2, 1_000_000])
def test_win_path_follows_the_solver(variant, seed):
    task = glyphbench_rl.make(f"glyphbench/classics-floodfill-{variant}-v0")
    task.reset(seed=seed)
    assert task.lower_bound <= len(task.plan) <= task.budget <= task.max_turns
    for colour in list(task.plan):
        _, reward, term, trunc, info = task.step(colour)
    assert term and task.won and not info["clamped"]
    assert task.episode_return == pytest.approx(1.0)
    assert len(set(info["frame"].grid[0] + "".join(info["frame"].grid))) == 1


@pytest.mark.parametrize("variant", VARIANTS)
def test_loss_path_spends_the_budget(variant):
    task = glyphbench_rl.make(f"glyphbench/classics-floodfill-{variant}-v0")
    task.reset(seed=3)
    while not task.done:
        _, reward, term, trunc, info = task.step(task.colour)   # repainting the same colour
    assert term and task.won is False and task.moves == task.budget
    assert task.episode_return == -0.5 and "Out of moves." in info["frame"].message


@pytest.mark.parametrize("variant", VARIANTS)
def test_loss_after_progress_is_still_negative(variant):
    task = glyphbench_rl.make(f"glyphbench/classics-floodfill-{variant}-v0")
    task.reset(seed=6)
    for colour in task.plan[:-1]:
        _, reward, *_ = task.step(colour)
        assert reward > 0
    while not task.done:
        task.step(task.colour)
    assert task.won is False and -0.5 < task.episode_return < 0


def test_rendering_and_mechanics():
    task = glyphbench_rl.make("glyphbench/classics-floodfill-easy-v0")
    obs, _ = task.reset(seed=0)
    lines = obs.splitlines()
    assert lines[0] == f"Step 0/30 | Moves 0/{task.budget}"
    assert len(lines[1:7]) == 6 and all(len(row) == 6 for row in lines[1:7])
    colour = task.plan[0]
    before = task.region
    task.step(colour)
    assert task.region & before == before and task.region != before
    grid = task.frame.grid
    assert all(grid[r][c] == "RGBYPO"[colour] for r, c in task.bits.cells(task.region))
    assert [a.name for a in task.actions] == ["RED", "GREEN", "BLUE", "YELLOW", "PURPLE", "ORANGE"]


def test_bad_params():
    with pytest.raises(ValueError, match="size"):
        glyphbench_rl.make("glyphbench/classics-floodfill-easy-v0", size=2)
    with pytest.raises(ValueError, match="colours"):
        glyphbench_rl.make("glyphbench/classics-floodfill-easy-v0", colours=7)
    with pytest.raises(ValueError, match="slack"):
        glyphbench_rl.make("glyphbench/classics-floodfill-easy-v0", slack=-1)
    with pytest.raises(ValueError, match="progress_share"):
        glyphbench_rl.make("glyphbench/classics-floodfill-easy-v0", progress_share=1)
