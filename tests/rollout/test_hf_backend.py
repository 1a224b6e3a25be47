"""Token-in/token-out rollouts with a tiny random model (fast, CPU)."""

import math

import pytest

torch = pytest.importorskip("torch")

from glyphbench_rl.agent import HarnessConfig  # noqa: E402
from glyphbench_rl.rollout import EpisodeSpec, GenRequest, RolloutEngine  # noqa: E402
from glyphbench_rl.rollout.chat_tokens import ChatTokens  # noqa: E402
from glyphbench_rl.rollout.factory import make_backend  # noqa: E402


@pytest.fixture(scope="module")
def backend(tiny_model_dir):
    return make_backend("hf", str(tiny_model_dir), max_new_tokens=12, seed=0, batch_size=3)


def _run(backend, history=8, n=4, turns=5):
    eng = RolloutEngine(backend, HarnessConfig(history=history))
    specs = [EpisodeSpec("glyphbench/classics-snake-easy-v0", s, overrides={"max_turns": turns})
             for s in range(n)]
    return eng.run(specs)


def test_prompts_extend_previous_turns_exactly(backend):
    for t in _run(backend):
        for prev, cur in zip(t.steps, t.steps[1:]):
            # the next prompt starts with the previous prompt and the ids sampled after it
            assert cur.prompt_ids[:len(prev.prompt_ids)] == prev.prompt_ids
            sampled = cur.prompt_ids[len(prev.prompt_ids):len(prev.prompt_ids) + len(prev.completion_ids)]
            assert sampled == prev.completion_ids


def test_prompt_ids_match_chat_template_rendering(backend):
    """Per-message tokenisation agrees with the template on the text it renders."""
    t = _run(backend, n=1, turns=3)[0]
    chat = ChatTokens(backend.tokenizer)
    step = t.steps[0]
    text = backend.tokenizer.apply_chat_template(
        [{"role": "system", "content": t.system_prompt}, {"role": "user", "content": step.observation}],
        tokenize=False, add_generation_prompt=True)
    assert backend.tokenizer.decode(step.prompt_ids) == text
    assert chat.system(t.system_prompt) == step.prompt_ids[:len(chat.system(t.system_prompt))]


def test_logprobs_are_sampling_logprobs(backend, tiny_model_dir):
    """Recorded log-probs equal the model's log-softmax of the sampled ids (temperature 1)."""
    t = _run(backend, n=1, turns=2)[0]
    step = t.steps[0]
    ids = torch.tensor([step.prompt_ids + step.completion_ids])
    with torch.no_grad():
        logits = backend.model(ids).logits[0].float()
    logp = torch.log_softmax(logits, -1)
    start = len(step.prompt_ids)
    expect = [float(logp[start + k - 1, tok]) for k, tok in enumerate(step.completion_ids)]
    assert len(step.logprobs) == len(step.completion_ids) == step.completion_tokens
    assert all(math.isclose(a, b, abs_tol=1e-4) for a, b in zip(step.logprobs, expect))


def test_left_padding_does_not_change_results(backend):
    """A prompt alone and in a batch with longer prompts gets the same greedy reply."""
    greedy = make_backend("hf", backend.model_name, max_new_tokens=8, temperature=0.0)
    short = [5, 6, 7]
    longer = list(range(3, 40))
    req = lambda ids: GenRequest(0, "t", 0, [], None, "", ids)  # noqa: E731
    alone = greedy.generate([req(short)])[0]
    batched = greedy.generate([req(longer), req(short)])[1]
    assert alone.token_ids == batched.token_ids


def test_seeded_runs_repeat(backend, tiny_model_dir):
    a = _run(make_backend("hf", str(tiny_model_dir), max_new_tokens=8, seed=4), n=2, turns=3)
    b = _run(make_backend("hf", str(tiny_model_dir), max_new_tokens=8, seed=4), n=2, turns=3)
    assert [s.completion_ids for t in a for s in t.steps] == [s.completion_ids for t in b for s in t.steps]


def test_finish_reasons_and_reply_closing(backend):
    for t in _run(backend, n=2, turns=3):
        for s in t.steps:
            assert s.finish_reason in ("stop", "length")
            assert (s.completion_ids[-1] == backend.tokenizer.eos_token_id) == (s.finish_reason == "stop")


def test_unknown_option_is_a_clear_error(tiny_model_dir):
    with pytest.raises(ValueError, match="backend 'hf'.*temprature"):
        make_backend("hf", str(tiny_model_dir), temprature=0.5)
    with pytest.raises(ValueError, match="needs a model"):
        make_backend("hf")
    with pytest.raises(ValueError, match="unknown backend"):
        make_backend("gpt")


def test_reply_prefix_is_prompt_side_and_part_of_the_reply(backend):
    """harness.reply_prefix: the model continues after the prefix; the prefix is in every later
    prompt, in the recorded reply, and never among the sampled (trainable) ids."""
    eng = RolloutEngine(backend, HarnessConfig(history=8, reply_prefix="<action>"))
    t = eng.run([EpisodeSpec("glyphbench/classics-snake-easy-v0", 0, overrides={"max_turns": 3})])[0]
    prefix_ids = backend.tokenizer.encode("<action>", add_special_tokens=False)
    for step in t.steps:
        assert step.reply.startswith("<action>")
        assert backend.tokenizer.decode(step.prompt_ids).endswith("<action>")
        assert step.completion_ids[:len(prefix_ids)] != prefix_ids or len(step.completion_ids) < len(prefix_ids)
    for prev, cur in zip(t.steps, t.steps[1:]):      # token-in/token-out still holds
        assert cur.prompt_ids[:len(prev.prompt_ids)] == prev.prompt_ids
        assert cur.prompt_ids[len(prev.prompt_ids):len(prev.prompt_ids) + len(prev.completion_ids)] \
            == prev.completion_ids


def test_reply_prefix_needs_a_token_backend():
    from glyphbench_rl.rollout.backend import RandomBackend
    with pytest.raises(ValueError, match="reply_prefix needs a token backend"):
        RolloutEngine(RandomBackend(), HarnessConfig(reply_prefix="<action>"))
    with pytest.raises(ValueError, match="reply_prefix"):
        HarnessConfig(reply_prefix=3)
