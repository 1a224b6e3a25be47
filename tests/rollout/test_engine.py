import pytest

import glyphbench_rl
from glyphbench_rl.agent import HarnessConfig
from glyphbench_rl.core import UnknownTaskError
from glyphbench_rl.rollout import (BackendError, EpisodeSpec, Generation, RandomBackend,
                                   RolloutEngine, ScriptedBackend)


class CountingBackend(RandomBackend):
    def __init__(self, seed=0):
        super().__init__(seed=seed)
        self.batches = []

    def generate(self, requests):
        self.batches.append(len(requests))
        return super().generate(requests)


def test_one_batched_call_per_turn_and_slots_refill():
    b = CountingBackend(seed=3)
    specs = [EpisodeSpec("glyphbench/classics-snake-easy-v0", s, overrides={"max_turns": 4}) for s in range(5)]
    trajs = RolloutEngine(b, max_episodes=3).run(specs)
    assert [t.seed for t in trajs] == list(range(5))
    assert all(t.length == 4 and t.truncated for t in trajs if not t.terminated)
    assert max(b.batches) == 3 and sum(b.batches) == sum(t.length for t in trajs)


def test_matches_direct_play():
    """The engine's record equals stepping the task by hand with the same actions."""
    trajs = RolloutEngine(RandomBackend(seed=1)).run(
        [EpisodeSpec("glyphbench/classics-2048-v0", 1_000_000)])
    t = trajs[0]
    task = glyphbench_rl.make("glyphbench/classics-2048-v0")
    obs, _ = task.reset(seed=1_000_000)
    assert t.initial_observation == obs and t.system_prompt == task.system_prompt()
    total = 0.0
    for step in t.steps:
        assert step.observation == obs
        obs, r, term, trunc, _ = task.step(step.action)
        assert (r, term, trunc) == (step.reward, step.terminated, step.truncated)
        total += r
    assert t.final_observation == obs and t.episode_return == pytest.approx(total)
    assert t.terminated == term and t.truncated == trunc


def test_garbage_replies_forfeit_and_never_crash():
    junk = ["", "\x00\xff" * 50, "<action>", "<action>FLY</action>", "x" * 100_000,
            "<think><action>UP</action>", None]
    backend = ScriptedBackend(lambda r: junk[r.turn % len(junk)] or "")
    t = RolloutEngine(backend).run([EpisodeSpec("glyphbench/classics-maze-easy-v0", 0,
                                                overrides={"max_turns": 14})])[0]
    assert t.length == 14 and t.forfeits == 14 and t.episode_return == 0
    assert {s.forfeit_reason for s in t.steps} >= {"empty", "no_tag", "unknown_name", "unclosed_think"}
    # a forfeit leaves the world unchanged: every observation shows the same grid
    grids = {s.observation.split("\n", 1)[1].split("Legend")[0] for s in t.steps}
    assert len(grids) == 1


def test_scripted_indices_and_tags():
    t = RolloutEngine(ScriptedBackend(lambda r: 0), meta={"run": "x"}).run(
        [EpisodeSpec("glyphbench/classics-snake-easy-v0", 5, group=7, meta={"step": 2})])[0]
    assert t.forfeits == 0 and t.group == 7 and t.meta["step"] == 2 and t.meta["run"] == "x"
    assert t.meta["backend"] == "scripted" and t.meta["harness"]["history"] == 8


@pytest.mark.parametrize("index", [99, -1, 4])
def test_out_of_range_indices_are_forfeits(index):
    """A policy's index outside the action list is an invalid action, not a crash or a wrap-around."""
    t = RolloutEngine(ScriptedBackend(lambda r: index)).run(
        [EpisodeSpec("glyphbench/classics-snake-easy-v0", 5, overrides={"max_turns": 3})])[0]
    assert t.length == 3 and t.forfeits == 3
    assert {s.forfeit_reason for s in t.steps} == {"unknown_name"}


def test_unknown_task_fails_before_any_call():
    b = CountingBackend()
    with pytest.raises(UnknownTaskError, match="closest"):
        RolloutEngine(b).run([EpisodeSpec("glyphbench/classics-snake-easy-v0", 0),
                              EpisodeSpec("glyphbench/classics-snak-easy-v0", 0)])
    assert b.batches == []


def test_backend_errors_propagate():
    def boom(r):
        raise BackendError("endpoint down")
    with pytest.raises(BackendError):
        RolloutEngine(ScriptedBackend(boom)).run([EpisodeSpec("glyphbench/classics-2048-v0", 0)])


def test_short_answer_from_backend_is_an_error():
    class Short:
        name, tokenizer = "short", None

        def generate(self, requests):
            return [Generation("<action>UP</action>")][: len(requests) - 1]
    with pytest.raises(RuntimeError, match="answered 1 of 2"):
        RolloutEngine(Short()).run([EpisodeSpec("glyphbench/classics-2048-v0", s) for s in (0, 1)])


def test_overhead_is_measured():
    eng = RolloutEngine(RandomBackend())
    eng.run([EpisodeSpec("glyphbench/classics-snake-easy-v0", s) for s in range(4)])
    assert eng.stats.turns > 0 and eng.stats.calls > 0
    assert 0 <= eng.stats.backend_s <= eng.stats.total_s


def test_random_episodes_do_not_depend_on_batching():
    specs = [EpisodeSpec(t, s) for t in ("glyphbench/classics-2048-v0", "glyphbench/classics-snake-easy-v0")
             for s in range(3)]
    a = RolloutEngine(RandomBackend(seed=2), max_episodes=1).run(specs)
    b = RolloutEngine(RandomBackend(seed=2), max_episodes=6).run(specs[::-1])[::-1]
    assert [[s.action for s in t.steps] for t in a] == [[s.action for s in t.steps] for t in b]
    c = RolloutEngine(RandomBackend(seed=3), max_episodes=6).run(specs)
    assert [[s.action for s in t.steps] for t in a] != [[s.action for s in t.steps] for t in c]


def test_keep_false_hands_episodes_over_without_holding_them():
    seen = []
    out = RolloutEngine(RandomBackend()).run([EpisodeSpec("glyphbench/classics-snake-easy-v0", s) for s in range(3)],
                                             seen.append, keep=False)
    assert out == [] and sorted(t.seed for t in seen) == [0, 1, 2]
