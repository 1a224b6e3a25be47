from functools import cache, reduce
from itertools import product
from operator import xor

import pytest

import glyphbench_rl
from glyphbench_rl.games.classics.nim import winning_moves

VARIANTS = {"easy": 5, "hard": 7}


@cache
def mover_wins(heaps: tuple[int, ...]) -> bool:
    """Brute force: can the player to move take the last object? (normal play)"""
    return any(not mover_wins(heaps[:h] + (n - k,) + heaps[h + 1:])
               for h, n in enumerate(heaps) for k in range(1, n + 1))


def test_nim_sum_strategy_matches_brute_force():
    for heaps in product(range(5), repeat=3):
        moves = winning_moves(list(heaps))
        assert bool(moves) == mover_wins(heaps) == bool(reduce(xor, heaps))
        for h, k in moves:
            after = list(heaps)
            after[h] -= k
            assert 1 <= k <= heaps[h] and not mover_wins(tuple(after))


def name(h, k):
    return f"H{h + 1}T{k}"


@pytest.mark.parametrize("variant", VARIANTS)
@pytest.mark.parametrize("seed", [0, 1, 2, 3, 1_000_000])
def test_win_path_by_nim_sum_against_a_perfect_opponent(variant, seed):
    task = glyphbench_rl.make(f"glyphbench/classics-nim-{variant}-v0", strength=1.0)
    task.reset(seed=seed)
    assert reduce(xor, task.heaps)          # the start is a win for the first mover: you
    while not task.done:
        h, k = winning_moves(task.heaps)[0]
        _, reward, term, trunc, info = task.step(name(h, k))
    assert term and task.won and task.episode_return == 1.0 and not info["clamped"]
    assert not any(task.heaps) and info["frame"].message == "You win. Reward +1"


@pytest.mark.parametrize("variant", VARIANTS)
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_loss_path_never_zeroing_the_nim_sum(variant, seed):
    task = glyphbench_rl.make(f"glyphbench/classics-nim-{variant}-v0", strength=1.0)
    task.reset(seed=seed)
    while not task.done:
        heaps = task.heaps
        bad = [(h, k) for h, n in enumerate(heaps) for k in range(1, n + 1)
               if reduce(xor, heaps[:h] + [n - k] + heaps[h + 1:])]
        h, k = (bad or [(next(h for h, n in enumerate(heaps) if n), 1)])[0]
        _, _, term, _, info = task.step(name(h, k))
    assert term and task.won is False and task.episode_return == -1.0
    assert info["frame"].message.endswith("You lose. Reward -1")


def test_taking_too_many_wastes_the_turn():
    task = glyphbench_rl.make("glyphbench/classics-nim-hard-v0")
    task.reset(seed=0)
    heaps = list(task.heaps)
    h = min(range(3), key=lambda i: heaps[i])
    obs, reward, term, _, info = task.step(name(h, heaps[h] + 1))
    assert reward == 0.0 and not term and task.heaps == heaps and task.turn == 1
    assert info["frame"].message == f"Heap {h + 1} has only {heaps[h]}."


def test_opponent_reply_and_rendering():
    task = glyphbench_rl.make("glyphbench/classics-nim-easy-v0")
    obs, _ = task.reset(seed=0)
    assert task.frame.grid == tuple("●" * n + "·" * (5 - n) for n in task.heaps)
    assert task.action_space.n == 15
    assert glyphbench_rl.make("glyphbench/classics-nim-hard-v0").action_space.n == 21
    before = sum(task.heaps)
    h = next(i for i, n in enumerate(task.heaps) if n)
    _, _, term, _, info = task.step(name(h, 1))
    if not term:
        assert sum(task.heaps) < before - 1 and info["frame"].message.startswith("Opponent took")


def test_starts_cover_the_range():
    task = glyphbench_rl.make("glyphbench/classics-nim-hard-v0")
    seen = set()
    for seed in range(40):
        task.reset(seed=seed)
        assert all(1 <= n <= 7 for n in task.heaps) and reduce(xor, task.heaps)
        seen.update(task.heaps)
    assert seen == set(range(1, 8))


def test_bad_params():
    with pytest.raises(ValueError, match="heaps"):
        glyphbench_rl.make("glyphbench/classics-nim-easy-v0", heaps=1)
    with pytest.raises(ValueError, match="max_heap"):
        glyphbench_rl.make("glyphbench/classics-nim-easy-v0", max_heap=10)
    with pytest.raises(ValueError, match="strength"):
        glyphbench_rl.make("glyphbench/classics-nim-easy-v0", strength=-0.1)
