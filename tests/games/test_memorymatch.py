import pytest

import glyphbench_rl
from glyphbench_rl.games.classics.memorymatch import DOWN, FACES

VARIANTS = ["easy", "hard"]


@pytest.mark.parametrize("variant", VARIANTS)
@pytest.mark.parametrize("seed", [0, 1, 1_000_000])
def test_win_path_with_perfect_recall(variant, seed):
    task = glyphbench_rl.make(f"glyphbench/classics-memorymatch-{variant}-v0")
    task.reset(seed=seed)
    where = {}
    for i, face in enumerate(task.faces):
        where.setdefault(face, []).append(i)
    rewards = []
    for a, b in where.values():
        task.step(a)
        _, reward, term, trunc, info = task.step(b)
        rewards.append(reward)
    assert term and task.won and task.turn == 2 * task.pairs and not info["clamped"]
    assert task.episode_return == pytest.approx(1.0)
    assert rewards[0] == pytest.approx(0.5 / task.pairs) and rewards[-1] == pytest.approx(0.5 + 0.5 / task.pairs)
    assert DOWN not in "".join(info["frame"].grid)


@pytest.mark.parametrize("variant", VARIANTS)
def test_loss_path_never_matching(variant):
    task = glyphbench_rl.make(f"glyphbench/classics-memorymatch-{variant}-v0")
    task.reset(seed=2)
    a = 0
    b = next(i for i, f in enumerate(task.faces) if f != task.faces[a])
    while not task.done:
        _, reward, *_ = task.step(a)
        if not task.done:
            _, reward, *_ = task.step(b)
        assert reward == 0.0
    assert task.won is None and task.episode_return == 0.0


def test_mismatch_shows_then_hides():
    task = glyphbench_rl.make("glyphbench/classics-memorymatch-easy-v0")
    obs, _ = task.reset(seed=0)
    assert obs.splitlines()[0] == "Step 0/60 | Pairs 0/10" and obs.splitlines()[1] == "  ABCDE"
    assert task.action_space.n == 20
    assert glyphbench_rl.make("glyphbench/classics-memorymatch-hard-v0").action_space.n == 36
    a = 0
    b = next(i for i, f in enumerate(task.faces) if f != task.faces[a])
    c = next(i for i in range(20) if i not in (a, b))
    task.step(a)
    task.step(b)
    flat = "".join(task.frame.grid)
    assert flat[a] == FACES[task.faces[a]] and flat[b] == FACES[task.faces[b]]
    assert task.frame.message == "No match."
    task.step(c)     # the failed pair turns back
    flat = "".join(task.frame.grid)
    assert flat[a] == DOWN and flat[b] == DOWN and flat[c] == FACES[task.faces[c]]
    _, reward, *_ = task.step(c)
    assert reward == 0.0 and "already face up" in task.frame.message


def test_every_letter_appears_twice():
    task = glyphbench_rl.make("glyphbench/classics-memorymatch-hard-v0")
    task.reset(seed=4)
    assert sorted(task.faces) == sorted(list(range(18)) * 2)
    assert "18 pairs" in task.system_prompt()


def test_bad_params():
    with pytest.raises(ValueError, match="rows x cols"):
        glyphbench_rl.make("glyphbench/classics-memorymatch-easy-v0", rows=3, cols=3)
    with pytest.raises(ValueError, match="rows"):
        glyphbench_rl.make("glyphbench/classics-memorymatch-easy-v0", rows=1)
    with pytest.raises(ValueError, match="pair_share"):
        glyphbench_rl.make("glyphbench/classics-memorymatch-easy-v0", pair_share=2)
