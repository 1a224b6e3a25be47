"""A test helper the arcade test files share: play a task with a policy to its end."""

from glyphbench_rl import make


def play(task_id: str, policy, seed: int, turns: int | None = None):
    """Reset ``task_id`` on ``seed`` and step ``policy(env)`` until the episode ends (or
    ``turns`` steps); returns the task and the last info."""
    env = make(task_id)
    env.reset(seed=seed)
    done, n, info = False, 0, {}
    while not done and (turns is None or n < turns):
        _, _, term, trunc, info = env.step(policy(env))
        done, n = term or trunc, n + 1
    return env, info
