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


@pytest.mark.parametrize("kw, message", [
    (dict(history=-1), "harness.history must be an int >= 0, got -1"),
    (dict(history=True), "harness.history must be an int >= 0, got True"),
    (dict(history="5"), "harness.history must be an int >= 0, got '5'"),
    (dict(legend="sometimes"), "harness.legend must be one of 'always', 'changed', got 'sometimes'"),
    (dict(max_context_tokens=0), "harness.max_context_tokens must be an int >= 1 or null, got 0"),
    (dict(reply_prefix=None), "harness.reply_prefix must be a string of at most 200 characters, got None"),
    (dict(histroy=3), "unknown config key 'harness.histroy'; did you mean 'harness.history'?"),
])
def test_bad_config_is_one_line_naming_the_key(kw, message):
    with pytest.raises(ValueError) as e:
        HarnessConfig(**kw)
    assert str(e.value) == message


def test_config_is_frozen_and_hashable_by_value():
    a, b = HarnessConfig(history=2, legend="changed"), HarnessConfig(history=2, legend="changed")
    assert a == b and hash(a) == hash(b) and len({a, b, HarnessConfig()}) == 2
    assert a.model_dump() == {"history": 2, "legend": "changed", "max_context_tokens": None,
                              "reply_prefix": ""}
    with pytest.raises(ValueError, match="harness.history cannot be changed"):
        a.history = 3
