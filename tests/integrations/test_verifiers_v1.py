"""The verifiers v1 adapter end to end, offline: `vf-eval glyphbench-rl` against the stub server.

The stub plays a scripted policy (with a decoy action in its reasoning and some replies without
an action); the same policy through the built-in RolloutEngine gives the expected returns, and
the prompts the stub received from both must be identical (a past reply goes back as the model
returned it: reasoning in its own field, where the engine's OpenAI backend inlines it in <think>).
The trace must branch exactly where the engine's packing starts a new training sequence.
"""

import asyncio
import json
import logging
import os
import re
import subprocess
import sys
from collections import Counter
from pathlib import Path

import pytest

pytest.importorskip("verifiers")

from stub_openai import StubOpenAI  # noqa: E402

import glyphbench_rl  # noqa: E402
from glyphbench_rl.agent import HarnessConfig  # noqa: E402
from glyphbench_rl.core.seeding import heldout_seeds  # noqa: E402
from glyphbench_rl.rollout import EpisodeSpec, RolloutEngine, ScriptedBackend  # noqa: E402
from glyphbench_rl.rollout.openai_backend import OpenAIBackend, reply_text  # noqa: E402

KEY = "sk-vf-test-key-0123456789"
TASKS = ["glyphbench/classics-snake-easy-v0", "glyphbench/classics-snake-medium-v0"]   # short episodes
ACTIONS = ["UP", "LEFT", None, "UP", "RIGHT", "DOWN", "DOWN"]
EXPORTS = ("GlyphbenchTaskset", "GlyphbenchEnv", "GlyphbenchHarness")


def policy(body: dict) -> dict:
    step = int(re.search(r"Step (\d+)/", body["messages"][-1]["content"]).group(1))
    name = ACTIONS[step % len(ACTIONS)]
    return {"content": "no idea" if name is None else f"<action>{name}</action>",
            "reasoning_content": "or <action>RIGHT</action>?"}


def vf_eval(tmp_path: Path, stub: StubOpenAI, *args: str, timeout: int = 240) -> subprocess.CompletedProcess:
    cmd = [str(Path(sys.executable).with_name("vf-eval"))]
    cmd += ["glyphbench-rl", "-m", "stub-model", "--client.base-url", stub.base_url,
            "--client.api-key-var", "GB_VF_KEY", "--no-push", "--no-rich", "-o", str(tmp_path / "out"),
            "--run.name", "t", *args]
    env = {**os.environ, "GB_VF_KEY": KEY, "HOME": str(tmp_path), "NO_PROXY": "127.0.0.1,localhost"}
    return subprocess.run(cmd, cwd=tmp_path, env=env, capture_output=True, text=True, timeout=timeout)


def read_traces(tmp_path: Path) -> list[dict]:
    lines = (tmp_path / "out" / "t" / "traces.jsonl").read_text().splitlines()
    return [trace for line in lines for trace in json.loads(line)["traces"]]


def test_vf_eval_streaming_matches_engine(tmp_path):
    harness = HarnessConfig(history=2)
    with StubOpenAI(policy) as stub:
        proc = vf_eval(tmp_path, stub, "--env.taskset.tasks", json.dumps(TASKS),
                       "--env.taskset.episodes", "2", "--env.taskset.harness.history", "2")
        assert proc.returncode == 0, proc.stderr[-3000:]
        assert KEY not in proc.stdout + proc.stderr
        bodies = stub.chat_bodies()
        headers = [r["headers"] for r in stub.requests]
    traces = read_traces(tmp_path)
    assert len(traces) == 4 and all(t["ok"] for t in traces)
    # the harness streamed, and the interception relayed to the stub with the real key
    assert all(b.get("stream") is True for b in bodies)
    assert all(h.get("Authorization") == f"Bearer {KEY}" for h in headers)

    # the same episodes through the built-in engine, against a fresh stub
    specs = [EpisodeSpec(t, s) for t in TASKS for s in heldout_seeds(2)]
    with StubOpenAI(policy) as stub2:
        want = RolloutEngine(OpenAIBackend("stub-model", base_url=stub2.base_url), harness).run(specs)
        engine_bodies = stub2.chat_bodies()
    expected = {(t.task_id, t.seed): t for t in want}
    for trace in traces:
        data = trace["task"]["data"]
        t = expected[(data["task_id"], data["seed"])]
        assert trace["task"]["key"] == f"{t.task_id}@{t.seed}"
        assert trace["rewards"]["episode_return"]["score"] == pytest.approx(t.episode_return)
        m = trace["metrics"]
        assert m["episode_length"] == t.length and m["forfeit_rate"] == pytest.approx(t.forfeits / t.length)
        assert (m["terminated"], m["truncated"]) == (float(t.terminated), float(t.truncated))
        assert "won" in m
    assert any(t.forfeits for t in want) and len({t.episode_return for t in want}) > 1
    # every prompt was the engine's prompt, message for message (history window included); past
    # replies went back as returned, their reasoning in its own field
    replies = [m for b in bodies for m in b["messages"] if m["role"] == "assistant"]
    assert replies and all(m["reasoning_content"] == "or <action>RIGHT</action>?" for m in replies)
    prompts = Counter(json.dumps(engine_form(b["messages"]), sort_keys=True) for b in bodies)
    assert prompts == Counter(json.dumps(b["messages"], sort_keys=True) for b in engine_bodies)


def engine_form(messages: list[dict]) -> list[dict]:
    """Messages as the engine's OpenAI backend sends them: a reply's reasoning inlined in <think>."""
    return [{"role": "assistant", "content": reply_text(m)} if m["role"] == "assistant" else m
            for m in messages]


def engine_packing(bodies: list[dict], reply) -> tuple[int, int]:
    """(training sequences, distinct messages) of the engine's packing of these prompts: a turn
    joins the last sequence while its prompt extends that sequence (prompt + reply); the
    sequences' messages counted once per distinct prefix, as a trace graph stores them."""
    sequences, current, prefixes = 0, None, set()
    for body in bodies:
        prompt = engine_form(body["messages"])
        if current is None or prompt[:len(current)] != current:
            sequences += 1
        current = prompt + [{"role": "assistant", "content": reply_text(reply(body))}]
        prefixes.update(json.dumps(current[:i]) for i in range(1, len(current) + 1))
    return sequences, len(prefixes)


def reasoning_policy(body: dict) -> dict:
    step = int(re.search(r"Step (\d+)/", body["messages"][-1]["content"]).group(1))
    return {"content": f"<action>{['UP', 'LEFT', 'DOWN', 'RIGHT'][step % 4]}</action>",
            "reasoning_content": f"step {step}: try {'ULDR'[step % 4]}"}


@pytest.mark.parametrize("turns, harness, nodes, branches", [
    (60, {"history": 8}, 937, 52),          # the window slides from turn 9 on: one sequence each
    (40, {"history": 40}, 81, 1),           # it never slides: one sequence (60 branches before)
    (30, {"history": 30, "max_context_tokens": 1200}, None, None),   # the budget drops turns
])
def test_trace_branches_only_where_the_engine_packing_does(plugin, tmp_path, turns, harness, nodes,
                                                           branches):
    """A 60-turn 2048 episode with reasoning replies stored 945 nodes in 60 branches (one per
    turn) when past replies went back as the engine's text; as returned, 937 in 52, the engine's
    52 sequences. Plain replies gave 937 in 52 either way."""
    from verifiers.v1 import graph
    from verifiers.v1.cli.eval.runner import run_eval
    from verifiers.v1.configs.cli.eval import EvalConfig

    with StubOpenAI(reasoning_policy) as stub:
        config = EvalConfig.model_validate({
            "env": {"taskset": {"id": "glyphbench-rl", "tasks": ["glyphbench/classics-2048-v0"],
                                "harness": harness},
                    "agent": {"max_turns": turns, "harness": {"id": "glyphbench-rl"}}},
            "model": "stub-model", "client": {"base_url": stub.base_url, "api_key_var": "GB_VF_KEY"},
            "push": False, "rich": None, "output_dir": str(tmp_path), "run": {"name": "t"}})
        [episode] = asyncio.run(run_eval(config))
        bodies = stub.chat_bodies()
    [trace] = episode.traces
    assert episode.ok and trace.num_turns == len(bodies) == turns
    sequences, messages = engine_packing(bodies, reasoning_policy)
    assert (len(graph.leaves(trace)), len(trace.nodes)) == (sequences, messages)
    if nodes is not None:
        assert (len(trace.nodes), sequences) == (nodes, branches)
    else:
        assert trace.metrics["episode_length"] == turns and 1 < sequences < turns


@pytest.fixture
def plugin(monkeypatch):
    """The adapter, resolvable as `glyphbench-rl` (glyphbench_rl exports its classes)."""
    from glyphbench_rl.integrations import verifiers_v1
    monkeypatch.setenv("GB_VF_KEY", KEY)
    monkeypatch.setenv("NO_PROXY", "127.0.0.1,localhost")
    return verifiers_v1


def test_unknown_task_fails_before_running(plugin, tmp_path, capfd):
    """The CLI's own entry point, in-process: the config fails to parse, nothing runs."""
    from verifiers.v1.cli.eval.main import main

    with StubOpenAI(policy) as stub:
        with pytest.raises(SystemExit) as e:
            main(["glyphbench-rl", "-m", "stub-model", "--client.base-url", stub.base_url, "--no-push",
                  "-o", str(tmp_path), "--env.taskset.tasks", '["glyphbench/classics-snak-easy-v0"]'])
        assert stub.requests == []
    captured = capfd.readouterr()
    out = " ".join(re.sub(r"[│╭╮╰╯─]", " ", captured.out + captured.err).split())
    assert e.value.code not in (0, None)
    assert ("unknown task 'glyphbench/classics-snak-easy-v0'; closest: glyphbench/classics-snake-easy-v0"
            in out), out
    assert list(tmp_path.iterdir()) == []


def run_in_process(stub: StubOpenAI, tmp_path: Path, tasks: list[str], **agent) -> list:
    """v1's evaluation entry point in-process (the CLI minus argv parsing and signal handlers).
    Harness knobs need the harness id named, as on the command line."""
    from verifiers.v1.cli.eval.runner import run_eval
    from verifiers.v1.configs.cli.eval import EvalConfig

    agent.setdefault("harness", {})["id"] = "glyphbench-rl"
    config = EvalConfig.model_validate({
        "env": {"taskset": {"id": "glyphbench-rl", "tasks": tasks}, "agent": agent},
        "model": "stub-model", "client": {"base_url": stub.base_url, "api_key_var": "GB_VF_KEY"},
        "push": False, "rich": None, "output_dir": str(tmp_path), "run": {"name": "t"}})
    return asyncio.run(run_eval(config))


def test_model_errors_fail_the_episode(plugin, tmp_path, caplog):
    with StubOpenAI(policy, fail_times=10**6) as stub, caplog.at_level(logging.INFO):
        [episode] = run_in_process(stub, tmp_path, TASKS[:1], harness={"max_retries": 1, "backoff_s": 0})
        assert stub.chat_calls == 2          # one retry of the only turn, then the episode fails
        assert stub.requests[0]["headers"]["Authorization"] == f"Bearer {KEY}"
    [trace] = episode.traces
    assert not episode.ok and not trace.ok and "500" in trace.errors[-1].message
    assert trace.metrics["episode_length"] == 0 and trace.rewards["episode_return"].score == 0
    assert KEY not in caplog.text + episode.model_dump_json()


def test_non_streaming_and_turn_limit(plugin, tmp_path):
    with StubOpenAI(policy) as stub:
        [full] = run_in_process(stub, tmp_path / "a", TASKS[:1], harness={"stream": False})
        [capped] = run_in_process(stub, tmp_path / "b", TASKS[:1], max_turns=3)
        assert not any(b.get("stream") for b in stub.chat_bodies()[:full.traces[0].num_turns])
    scripted = ScriptedBackend(lambda r: reply_text(policy({"messages": r.messages})))
    [want] = RolloutEngine(scripted).run([EpisodeSpec(TASKS[0], heldout_seeds(1)[0])])
    [t] = full.traces
    assert full.ok and t.metrics["episode_length"] == t.num_turns == want.length > 3
    assert t.rewards["episode_return"].score == pytest.approx(want.episode_return)
    # the agent's turn cap ends the exchange: the episode stops early, neither won nor lost
    [c] = capped.traces
    assert capped.ok and c.metrics["episode_length"] == 3 and c.stop_condition == "max_turns"
    assert (c.metrics["terminated"], c.metrics["truncated"]) == (0.0, 0.0)


def test_rows_and_config():
    from glyphbench_rl.integrations.verifiers_v1 import GlyphbenchTaskset, GlyphbenchTasksetConfig

    cfg = GlyphbenchTasksetConfig(id="glyphbench-rl", tasks=["glyphbench/classics-maze-*"], episodes=3,
                                  seed_start=5)
    rows = [t.data for t in GlyphbenchTaskset(cfg)]
    assert [(r.task_id, r.seed) for r in rows] == [
        (t, s) for t in glyphbench_rl.list_tasks(pattern="glyphbench/classics-maze-*")
        for s in range(1_000_005, 1_000_008)]
    assert all(r.prompt is None for r in rows)
    assert len(list(GlyphbenchTaskset(GlyphbenchTasksetConfig(id="glyphbench-rl")))) == len(
        glyphbench_rl.list_tasks(tier="standard"))
    with pytest.raises(ValueError, match="harness.legend"):
        GlyphbenchTasksetConfig(id="glyphbench-rl", harness={"legend": "sometimes"})
    with pytest.raises(ValueError, match="reply_prefix needs a token backend"):
        GlyphbenchTasksetConfig(id="glyphbench-rl", harness={"reply_prefix": "<action>"})
    assert GlyphbenchTasksetConfig(id="glyphbench-rl", harness={"history": 3}).harness == HarnessConfig(history=3)
    with pytest.raises(ValueError, match="held-out"):
        GlyphbenchTasksetConfig(id="glyphbench-rl", episodes=2, seed_start=999_999)


def test_discoverable_as_glyphbench_rl():
    assert set(EXPORTS) <= set(glyphbench_rl.__all__)
    from verifiers.v1.utils.loaders import environment_class, harness_class, taskset_class

    from glyphbench_rl.integrations import verifiers_v1 as plugin
    assert taskset_class("glyphbench-rl") is plugin.GlyphbenchTaskset
    assert environment_class("glyphbench-rl") is plugin.GlyphbenchEnv
    assert harness_class("glyphbench-rl") is plugin.GlyphbenchHarness


def test_import_glyphbench_rl_stays_light():
    code = "import sys, glyphbench_rl; print(sorted(m for m in sys.modules if m.split('.')[0] in ('verifiers', 'httpx', 'torch')))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


def test_an_incompatible_verifiers_is_an_import_error_naming_it(monkeypatch):
    """verifiers' loader swallows AttributeError ("exports no Taskset"): a verifiers without the
    v1 names the adapter uses must surface as an ImportError that says so."""
    import sys
    import verifiers.v1 as vf
    monkeypatch.delattr(vf, "TaskData")
    import glyphbench_rl.integrations as integrations
    for mod in [m for m in sys.modules if m.startswith("glyphbench_rl.integrations.verifiers_v1")]:
        monkeypatch.delitem(sys.modules, mod)
    monkeypatch.delattr(integrations, "verifiers_v1", raising=False)
    with pytest.raises(ImportError, match="verifiers v1 API"):
        glyphbench_rl.GlyphbenchTaskset
