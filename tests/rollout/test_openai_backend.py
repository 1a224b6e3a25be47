"""OpenAIBackend against the loopback stub server: episodes, auth, retries, errors, concurrency."""

import logging
import re
import time

import pytest
from stub_openai import StubOpenAI

from glyphbench_rl.rollout import BackendError, EpisodeSpec, GenRequest, RolloutEngine, ScriptedBackend
from glyphbench_rl.rollout.factory import make_backend
from glyphbench_rl.rollout.openai_backend import OpenAIBackend, reply_text

KEY = "sk-test-0123456789abcdef-secret"
SNAKE = "glyphbench/classics-snake-easy-v0"
ACTIONS = ["UP", "LEFT", None, "UP", "RIGHT"]   # None: a reply without an action tag


def step_of(messages) -> int:
    """The turn number shown in the current observation ("Step t/N")."""
    return int(re.search(r"Step (\d+)/", messages[-1]["content"]).group(1))


def policy_text(messages) -> dict:
    """A scripted 'model': cycles actions, forfeits every few turns, and keeps a decoy action
    in its reasoning that the parser must ignore."""
    name = ACTIONS[step_of(messages) % len(ACTIONS)]
    content = "I will wait." if name is None else f"Moving.\n<action>{name}</action>"
    return {"content": content, "reasoning_content": "maybe <action>RIGHT</action>? no."}


@pytest.fixture(autouse=True)
def _env(monkeypatch):
    monkeypatch.setenv("GB_TEST_KEY", KEY)
    monkeypatch.setenv("NO_PROXY", "127.0.0.1,localhost")
    monkeypatch.delenv("OPENAI_BASE_URL", raising=False)


def backend(stub, **kw) -> OpenAIBackend:
    kw = {"api_key_env": "GB_TEST_KEY", "backoff_s": 0.01, "timeout_s": 10, **kw}
    return OpenAIBackend("stub-model", base_url=stub.base_url, **kw)


def request(messages=None) -> GenRequest:
    return GenRequest(0, SNAKE, 0, messages or [{"role": "user", "content": "hi"}], None, "")


def test_full_episode_matches_scripted_engine():
    specs = [EpisodeSpec(SNAKE, 1_000_000 + s) for s in range(3)]
    with StubOpenAI(lambda body: policy_text(body["messages"])) as stub:
        got = RolloutEngine(backend(stub, max_tokens=64, temperature=0.5)).run(specs)
        bodies = stub.chat_bodies()
        headers = [r["headers"] for r in stub.requests]
    seen = []

    def scripted(req):
        seen.append(req.messages)
        return reply_text(policy_text(req.messages))

    want = RolloutEngine(ScriptedBackend(scripted)).run(specs)
    assert [t.episode_return for t in got] == [t.episode_return for t in want]
    assert [[s.action for s in t.steps] for t in got] == [[s.action for s in t.steps] for t in want]
    assert all(t.terminated for t in got) and sum(t.forfeits for t in got) > 0
    # the parser saw the reasoning as <think> and took the action after it, not the decoy
    step = got[0].steps[0]
    assert step.reply.startswith("<think>maybe <action>RIGHT</action>? no.</think>")
    assert step.action == ACTIONS[0] and step.prompt_tokens > 0 and step.completion_tokens > 0
    # exactly the engine's prompts went out, with the configured sampling and the key as Bearer
    assert sorted(map(str, (b["messages"] for b in bodies))) == sorted(map(str, seen))
    assert {(b["model"], b["temperature"], b["max_tokens"], b["top_p"]) for b in bodies} == {("stub-model", 0.5, 64, 1.0)}
    assert all(h["Authorization"] == f"Bearer {KEY}" for h in headers)


def test_no_key_no_authorization_header(monkeypatch):
    monkeypatch.delenv("GB_TEST_KEY")
    with StubOpenAI() as stub:
        gen = backend(stub).generate([request()])
        assert gen[0].text == "<action>UP</action>" and gen[0].finish_reason == "stop"
        assert "Authorization" not in stub.requests[0]["headers"]


def test_base_url_from_env(monkeypatch):
    with StubOpenAI() as stub:
        monkeypatch.setenv("OPENAI_BASE_URL", stub.base_url)
        b = OpenAIBackend("stub-model", api_key_env="GB_TEST_KEY")
        assert b.generate([request()])[0].text == "<action>UP</action>"
    assert OpenAIBackend("m", base_url="http://h:1/v1/").url == "http://h:1/v1/chat/completions"


def test_500_twice_then_ok(caplog):
    with caplog.at_level(logging.WARNING), StubOpenAI(fail_times=2, fail_message="bad key {auth}") as stub:
        gen = backend(stub).generate([request()])
        assert gen[0].text == "<action>UP</action>" and stub.chat_calls == 3
    assert len([r for r in caplog.records if "retry" in r.getMessage()]) == 2
    assert KEY not in caplog.text


def test_always_500_is_one_line_backend_error_without_key(caplog):
    with caplog.at_level(logging.WARNING), StubOpenAI(fail_times=10**6, fail_message="echo {auth}") as stub:
        with pytest.raises(BackendError) as e:
            backend(stub, max_retries=2).generate([request()])
        assert stub.chat_calls == 3
    msg = str(e.value)
    assert "\n" not in msg and KEY not in msg and KEY not in caplog.text
    assert stub.base_url + "/chat/completions" in msg and "HTTP 500" in msg and "3 attempts" in msg
    assert KEY not in repr(backend(stub))


def test_4xx_is_not_retried():
    with StubOpenAI(fail_times=1, fail_status=401, fail_message="Incorrect API key {auth}") as stub:
        with pytest.raises(BackendError, match="HTTP 401") as e:
            backend(stub).generate([request()])
        assert stub.chat_calls == 1 and KEY not in str(e.value)


def test_429_is_retried():
    with StubOpenAI(fail_times=1, fail_status=429) as stub:
        assert backend(stub).generate([request()])[0].text == "<action>UP</action>"
        assert stub.chat_calls == 2


def test_timeout_is_retried_then_fails():
    with StubOpenAI(delay_s=2.0) as stub:
        t0 = time.perf_counter()
        with pytest.raises(BackendError, match="timed out") as e:
            backend(stub, timeout_s=0.2, max_retries=1).generate([request()])
        assert stub.chat_calls == 2 and time.perf_counter() - t0 < 2.0
    assert "\n" not in str(e.value) and "2 attempts" in str(e.value)


def test_timeout_then_ok():
    with StubOpenAI(delay_s=2.0, delay_times=1) as stub:
        assert backend(stub, timeout_s=0.3).generate([request()])[0].text == "<action>UP</action>"
        assert stub.chat_calls == 2


def test_connection_refused_is_backend_error():
    with StubOpenAI() as stub:
        url = stub.base_url
    with pytest.raises(BackendError, match="connection failed"):
        OpenAIBackend("m", base_url=url, max_retries=1, backoff_s=0.01).generate([request()])


def test_concurrency_bound_and_order():
    def reply(body):
        time.sleep(0.05)
        return f"<action>{body['messages'][-1]['content']}</action>"

    with StubOpenAI(reply) as stub:
        b = backend(stub, max_concurrency=3)
        reqs = [request([{"role": "user", "content": f"m{i}"}]) for i in range(12)]
        gens = b.generate(reqs)
        assert [g.text for g in gens] == [f"<action>m{i}</action>" for i in range(12)]
        assert stub.max_in_flight == 3
        b.close()


def test_null_content_is_an_empty_reply():
    with StubOpenAI(lambda body: {"content": None}) as stub:
        assert backend(stub).generate([request()])[0].text == ""


def test_factory_and_bad_options():
    b = make_backend("openai", model="m", base_url="http://127.0.0.1:9/v1", max_concurrency=2)
    assert isinstance(b, OpenAIBackend) and b.name == "openai" and b.tokenizer is None
    with pytest.raises(ValueError, match="openai"):
        make_backend("openai", model="m", no_such_option=1)
    with pytest.raises(ValueError, match="max_concurrency"):
        OpenAIBackend("m", max_concurrency=0)
    with pytest.raises(ValueError, match="base_url"):
        OpenAIBackend("m", base_url="ftp://user:pw@h/v1")
