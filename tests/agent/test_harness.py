import pytest

import glyphbench_rl
from glyphbench_rl.agent import BasicHarness, HarnessConfig, observation_text


def _play(harness, task, actions):
    for a in actions:
        harness.observe(task.frame)
        harness.record(f"<action>{a}</action>")
        task.step(a)


def test_window_keeps_last_frames_and_system():
    task = glyphbench_rl.make("glyphbench/classics-maze-easy-v0")
    task.reset(seed=1)
    h = BasicHarness(task.system_prompt(), HarnessConfig(history=3))
    _play(h, task, ["UP"] * 6)
    h.observe(task.frame)
    msgs = h.messages()
    assert msgs[0] == {"role": "system", "content": task.system_prompt()}
    # 3 past (user, assistant) pairs + the current observation
    assert [m["role"] for m in msgs[1:]] == ["user", "assistant"] * 3 + ["user"]
    assert msgs[-1]["content"] == task.frame.render()
    assert "Step 3/" in msgs[1]["content"] and "Step 6/" in msgs[-1]["content"]


def test_history_zero_is_stateless():
    task = glyphbench_rl.make("glyphbench/classics-snake-easy-v0")
    task.reset(seed=0)
    h = BasicHarness("S", HarnessConfig(history=0))
    _play(h, task, ["UP", "UP"])
    h.observe(task.frame)
    assert len(h.messages()) == 2


def test_legend_sent_only_when_changed_and_always_present():
    task = glyphbench_rl.make("glyphbench/classics-maze-easy-v0")
    task.reset(seed=2)
    h = BasicHarness("S", HarnessConfig(history=2, legend="changed"))
    first = h.observe(task.frame)
    assert "Legend: " in first.user
    h.record("<action>UP</action>")
    task.step("UP")
    second = h.observe(task.frame)
    assert "Legend: " not in second.user   # the first message still holds the same legend
    for _ in range(4):                     # the window slides past the message with the legend
        h.record("<action>UP</action>")
        task.step("UP")
        h.observe(task.frame)
        assert sum("Legend: " in m["content"] for m in h.messages()) >= 1
    assert observation_text(task.frame, legend=False).count("\n") == task.frame.render().count("\n") - 1


def test_context_budget_drops_oldest_turns_and_counts_them():
    task = glyphbench_rl.make("glyphbench/classics-maze-hard-v0")
    task.reset(seed=0)
    system = task.system_prompt()
    obs_tokens = len(task.frame.render()) // 4 + 1
    budget = len(system) // 4 + 1 + 3 * obs_tokens + 20
    h = BasicHarness(system, HarnessConfig(history=8, max_context_tokens=budget))
    _play(h, task, ["UP"] * 6)
    h.observe(task.frame)
    msgs = h.messages()
    assert msgs[0]["content"] == system and msgs[-1]["content"] == task.frame.render()
    assert len(msgs) < 1 + 2 * 6 + 1
    assert h.context_drops > 0


@pytest.mark.parametrize("kw", [dict(history=-1), dict(legend="sometimes"), dict(max_context_tokens=0),
                                dict(history=True)])
def test_bad_config(kw):
    with pytest.raises(ValueError, match="harness"):
        HarnessConfig(**kw)
