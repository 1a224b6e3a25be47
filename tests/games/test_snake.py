import pytest

import glyphbench_rl
from glyphbench_rl.games.common.grid import shortest_path


def chase_food(task):
    """Greedy scripted player: shortest safe path to the food, treating the body as walls."""
    size = task.params.size
    body = set(task.body)
    path = shortest_path(task.body[0], task.food,
                         lambda r, c: 0 <= r < size and 0 <= c < size and (r, c) not in body)
    return path[0] if path else None


@pytest.mark.parametrize("variant", ["easy", "medium", "hard"])
def test_win_path(variant):
    wins = 0
    for seed in range(5):
        task = glyphbench_rl.make(f"glyphbench/classics-snake-{variant}-v0")
        task.reset(seed=seed)
        while not task.done:
            move = chase_food(task)
            if move is None:
                break
            _, reward, term, trunc, info = task.step(move)
        if task.won:
            wins += 1
            assert task.episode_return == pytest.approx(1.0)
            assert task.eaten == task.params.target and not info["clamped"]
    assert wins >= 4


def test_loss_path_crash_into_edge():
    task = glyphbench_rl.make("glyphbench/classics-snake-easy-v0")
    task.reset(seed=0)
    for _ in range(task.params.size):
        _, reward, term, trunc, info = task.step("UP")
        if term:
            break
    assert term and task.won is False
    assert task.episode_return <= -task.params.death_penalty + task.eaten / task.params.target
    assert task.episode_return < 0
    assert "crashed" in info["frame"].message


def test_reversing_is_ignored_and_biting_kills():
    task = glyphbench_rl.make("glyphbench/classics-snake-medium-v0", start_length=5)
    task.reset(seed=1)
    head = task.body[0]
    task.step("LEFT")  # heading right: straight back is ignored, the snake moves right
    assert task.body[0] == (head[0], head[1] + 1)
    for move in ("DOWN", "LEFT"):
        task.step(move)
    _, _, term, _, info = task.step("UP")  # length 5: turning into the body bites it
    assert term and "bit itself" in info["frame"].message


def test_food_reward_sums_to_one_and_rules_show_the_numbers():
    task = glyphbench_rl.make("glyphbench/classics-snake-medium-v0")
    prompt = task.system_prompt()
    assert "+0.08333 per food" in prompt and "12 food wins" in prompt and "10x10" in prompt


def test_bad_params():
    with pytest.raises(ValueError, match="size"):
        glyphbench_rl.make("glyphbench/classics-snake-easy-v0", size=2)
    with pytest.raises(ValueError, match="unknown parameter 'colour'"):
        glyphbench_rl.make("glyphbench/classics-snake-easy-v0", colour=3)
