"""HFBackend's cross-turn prefix (KV) cache: same samples as full prefill, exact log-probs,
eviction and budget (tiny random model, CPU)."""

import math

import pytest

torch = pytest.importorskip("torch")

from glyphbench_rl.agent import HarnessConfig  # noqa: E402
from glyphbench_rl.rollout import EpisodeSpec, GenRequest, RolloutEngine  # noqa: E402
from glyphbench_rl.rollout.hf_backend import (  # noqa: E402
    CachedPrefix, HFBackend, reusable_length, supports_prefix_cache)

TASK = "glyphbench/classics-snake-easy-v0"


@pytest.fixture(scope="module")
def tiny(tiny_model_dir):
    """The tiny model with sharpened attention: at its initial scale attention is so diffuse that
    even wrong cached keys move log-probs by only ~1e-5; sharpened, by ~1e-3 (exact code: ~1e-6)."""
    from glyphbench_rl.models import load_model
    model, tokenizer = load_model(str(tiny_model_dir))
    with torch.no_grad():
        for name, p in model.named_parameters():
            if name.endswith(("q_proj.weight", "k_proj.weight")):
                p.mul_(10.0)
            elif "embed_tokens" in name:
                p.mul_(5.0)
    return model, tokenizer


def _backend(tiny, **kw):
    model, tokenizer = tiny
    return HFBackend(model, tokenizer=tokenizer, **{"max_new_tokens": 10, "batch_size": 3, **kw})


def _play(backend, history, episodes=5, at_once=3):
    """Episodes ending at different turns, more than fit at once (new ones join cached ones)."""
    eng = RolloutEngine(backend, HarnessConfig(history=history), max_episodes=at_once)
    return eng.run([EpisodeSpec(TASK, s, overrides={"max_turns": 2 + s}) for s in range(episodes)])


@pytest.mark.parametrize("history", [8, 2])
def test_greedy_rollouts_match_full_prefill(tiny, history):
    cached, full = _backend(tiny, temperature=0.0), _backend(tiny, temperature=0.0, prefix_cache=False)
    a, b = _play(cached, history), _play(full, history)
    assert [len(t.steps) for t in a] == [2, 3, 4, 5, 6]
    assert [s.completion_ids for t in a for s in t.steps] == [s.completion_ids for t in b for s in t.steps]
    assert [s.reply for t in a for s in t.steps] == [s.reply for t in b for s in t.steps]
    assert [s.prompt_ids for t in a for s in t.steps] == [s.prompt_ids for t in b for s in t.steps]
    logprobs = [(x, y) for ta, tb in zip(a, b) for sa, sb in zip(ta.steps, tb.steps)
                for x, y in zip(sa.logprobs, sb.logprobs)]
    assert len(logprobs) > 100 and all(math.isclose(x, y, abs_tol=1e-4) for x, y in logprobs)
    assert full.reused_tokens == 0 and full.prefix_cache is None
    # the cache really served most prompt ids (with a sliding window, the shared system prompt)
    assert cached.reused_tokens > 0.4 * cached.prompt_tokens
    slid = any(cur.prompt_ids[:len(prev.prompt_ids)] != prev.prompt_ids
               for t in a for prev, cur in zip(t.steps, t.steps[1:]))
    assert slid == (history == 2)           # the short window slides: prompts stop extending


def test_sampled_logprobs_with_cache_are_full_sequence_logprobs(tiny):
    backend = _backend(tiny, temperature=1.0, seed=3)
    trajs = _play(backend, history=3)
    model = tiny[0]
    later = [s for t in trajs for s in t.steps[1:]]       # the steps whose prompt came from the cache
    assert len(later) == 15 and backend.reused_tokens > 0
    for step in later:
        ids = torch.tensor([step.prompt_ids + step.completion_ids])
        with torch.no_grad():
            logp = torch.log_softmax(model(ids).logits[0].float(), -1)
        start = len(step.prompt_ids)
        expect = [float(logp[start + k - 1, tok]) for k, tok in enumerate(step.completion_ids)]
        assert len(step.logprobs) == len(expect)
        assert all(math.isclose(x, y, abs_tol=1e-4) for x, y in zip(step.logprobs, expect))


def _req(key, ids):
    return GenRequest(key, TASK, 0, [], None, "", list(ids))


def test_entries_follow_the_episodes_of_each_call(tiny):
    backend = _backend(tiny, temperature=0.0)
    store = backend.prefix_cache
    prompts = {0: [5, 6, 7, 8], 1: list(range(3, 30)), 2: [9, 10]}
    gens = dict(zip(prompts, backend.generate([_req(k, p) for k, p in prompts.items()])))
    assert len(store) == 3
    for k, p in prompts.items():              # each entry: its prompt, then the sampled ids fed back
        entry = store._entries[k]
        assert entry.ids[:len(p)] == p and entry.ids[len(p):] == gens[k].token_ids[:len(entry.ids) - len(p)]
        assert all(key.shape[1] == len(entry.ids) for key, _ in entry.layers)
    assert store.tokens == sum(len(e.ids) for e in store._entries.values())
    # keys 0 and 1 continue (their prompts extend what they were given), key 2 has finished
    before = backend.reused_tokens
    nxt = {k: prompts[k] + gens[k].token_ids + [11, 12] for k in (0, 1)}
    backend.generate([_req(k, p) for k, p in nxt.items()])
    assert sorted(store._entries) == [0, 1]
    assert backend.reused_tokens - before == sum(len(prompts[k]) + len(gens[k].token_ids) for k in (0, 1)) \
        - sum(1 for k in (0, 1) if len(gens[k].token_ids) == 10)   # a reply's last id is never fed back
    backend.generate([])
    assert len(store) == 0 and store.tokens == 0


def test_budget_drops_entries_and_results_stay_exact(tiny):
    unlimited = _backend(tiny, temperature=0.0)
    small = _backend(tiny, temperature=0.0, prefix_cache_max_tokens=700)
    none = _backend(tiny, temperature=0.0, prefix_cache_max_tokens=0)
    runs = [_play(b, history=8) for b in (unlimited, small, none)]
    ids = [[s.completion_ids for t in trajs for s in t.steps] for trajs in runs]
    assert ids[0] == ids[1] == ids[2]
    assert none.reused_tokens == 0 and len(none.prefix_cache) == 0
    assert 0 < small.reused_tokens < unlimited.reused_tokens
    assert small.prefix_cache.tokens <= 700


def test_changed_weights_drop_the_cache(tiny):
    backend = _backend(tiny, temperature=0.0)
    model = tiny[0]
    first = backend.generate([_req(0, [5, 6, 7, 8, 9])])[0]
    follow = [5, 6, 7, 8, 9] + first.token_ids + [4]
    with torch.no_grad():
        model.lm_head.weight.mul_(1.0)            # an in-place update (as an optimizer step makes)
    backend.generate([_req(0, follow)])
    assert backend.reused_tokens == 0
    backend.generate([_req(0, follow + [3])])
    assert backend.reused_tokens > len(follow) - 2


def test_reusable_length():
    cached = CachedPrefix([1, 2, 3, 4], [])
    assert reusable_length(None, [1, 2, 3]) == 0
    assert reusable_length(cached, [1, 2, 3, 4, 5, 6]) == 4
    assert reusable_length(cached, [1, 2, 9, 4, 5]) == 2
    assert reusable_length(cached, [1, 2, 3, 4]) == 3      # the last prompt id is always fed
    assert reusable_length(cached, [1, 2]) == 1
    assert reusable_length(cached, [7]) == 0


def test_models_without_a_full_kv_cache_fall_back(tiny_model_dir):
    from transformers import Qwen2Config, Qwen2ForCausalLM

    from glyphbench_rl.models import load_tokenizer
    config = Qwen2Config(vocab_size=600, hidden_size=32, intermediate_size=64, num_hidden_layers=2,
                         num_attention_heads=4, num_key_value_heads=2, use_sliding_window=True,
                         sliding_window=16, max_window_layers=0)
    sliding = Qwen2ForCausalLM(config)
    assert not supports_prefix_cache(sliding)
    with pytest.warns(UserWarning, match="prefix cache off"):
        backend = HFBackend(sliding, tokenizer=load_tokenizer(str(tiny_model_dir)))
    assert backend.prefix_cache is None


def test_bad_budget_is_a_clear_error(tiny):
    with pytest.raises(ValueError, match="prefix_cache_max_tokens >= 0"):
        _backend(tiny, prefix_cache_max_tokens=-1)


def test_cached_turns_use_no_deprecated_transformers_argument(tiny):
    """The cache goes to generate() under the name this transformers uses (no FutureWarning)."""
    import warnings
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        _play(_backend(tiny), history=8, episodes=2, at_once=2)
    assert not [w for w in caught if issubclass(w.category, (FutureWarning, DeprecationWarning))
                and "deprecated" in str(w.message)], [str(w.message) for w in caught]
