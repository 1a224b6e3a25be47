"""The vLLM adapter against a stand-in ``vllm`` module (the real one needs a GPU machine).

Checks the mapping of vLLM's offline API (token prompts in; sampled ids, per-token log-prob
dicts and finish reasons out) onto the engine's Generation records.
"""

import sys
import types
from dataclasses import dataclass

import pytest

pytest.importorskip("transformers")

from glyphbench_rl.rollout import EpisodeSpec, RolloutEngine  # noqa: E402
from glyphbench_rl.rollout.factory import make_backend  # noqa: E402


@dataclass
class _Logprob:
    logprob: float


class _LLM:
    calls: list = []

    def __init__(self, model, logprobs_mode=None, **kw):
        self.model, self.kw, self.mode = model, kw, logprobs_mode

    def generate(self, prompts, params, use_tqdm=True):
        _LLM.calls.append((prompts, params))
        outs = []
        for p in prompts:
            ids = self.tokenizer_ids[:3] if len(p["prompt_token_ids"]) % 2 else self.tokenizer_ids
            comp = types.SimpleNamespace(
                token_ids=ids, text="<action>UP</action>",
                logprobs=[{t: _Logprob(-0.5), 99999: _Logprob(-9.0)} for t in ids],
                finish_reason="stop" if len(ids) > 3 else "length")
            outs.append(types.SimpleNamespace(outputs=[comp]))
        return outs


@pytest.fixture
def fake_vllm(monkeypatch, tiny_model_dir):
    mod = types.ModuleType("vllm")
    mod.LLM = _LLM
    mod.SamplingParams = lambda **kw: kw
    monkeypatch.setitem(sys.modules, "vllm", mod)
    _LLM.calls = []
    return mod


def test_vllm_backend_maps_outputs(fake_vllm, tiny_model_dir):
    b = make_backend("vllm", str(tiny_model_dir), max_new_tokens=7, temperature=0.7)
    b.llm.tokenizer_ids = b.tokenizer.encode("<action>UP</action>") + [b.tokenizer.eos_token_id]
    assert b.llm.mode == "processed_logprobs" and b.llm.model == str(tiny_model_dir)
    trajs = RolloutEngine(b).run([EpisodeSpec("glyphbench/classics-snake-easy-v0", s,
                                              overrides={"max_turns": 3}) for s in range(3)])
    prompts, params = _LLM.calls[0]
    assert len(prompts) == 3 and params == dict(temperature=0.7, top_p=1.0, max_tokens=7, logprobs=0)
    for t in trajs:
        for s in t.steps:
            assert prompts and s.action == "UP"
            assert s.logprobs == [-0.5] * len(s.completion_ids)
            assert s.finish_reason == ("stop" if len(s.completion_ids) > 3 else "length")
    assert len(_LLM.calls) == 3   # one batched call per turn


def test_missing_vllm_is_a_clear_error(monkeypatch, tiny_model_dir):
    monkeypatch.setitem(sys.modules, "vllm", None)
    with pytest.raises(ImportError, match="pip install vllm"):
        make_backend("vllm", str(tiny_model_dir))
