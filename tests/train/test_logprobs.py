import pytest

torch = pytest.importorskip("torch")

from glyphbench_rl.models import load_model  # noqa: E402
from glyphbench_rl.train.logprobs import token_logprobs  # noqa: E402


@pytest.fixture(scope="module")
def model(tiny_model_dir):
    return load_model(str(tiny_model_dir))[0]


def _reference(model, ids, temperature=1.0):
    logits = model(ids).logits.float() / temperature
    lp = torch.log_softmax(logits[:, :-1], -1).gather(-1, ids[:, 1:, None])[..., 0]
    return torch.cat([torch.zeros(ids.shape[0], 1), lp], 1)


@pytest.mark.parametrize("chunk", [1, 7, 64, 4096])
def test_chunked_equals_full(model, chunk):
    ids = torch.randint(0, model.config.vocab_size, (2, 50))
    with torch.no_grad():
        assert torch.allclose(token_logprobs(model, ids, chunk=chunk), _reference(model, ids), atol=1e-5)
        assert torch.allclose(token_logprobs(model, ids, chunk=chunk, temperature=0.7),
                              _reference(model, ids, 0.7), atol=1e-5)


def test_gradients_match_full_computation(model):
    ids = torch.randint(0, model.config.vocab_size, (2, 40))
    grads = []
    for fn in (lambda: token_logprobs(model, ids, chunk=8), lambda: _reference(model, ids)):
        model.zero_grad()
        fn().sum().backward()
        grads.append(torch.cat([p.grad.flatten() for p in model.parameters() if p.grad is not None]))
    assert torch.allclose(grads[0], grads[1], atol=1e-4)


def test_bad_chunk(model):
    with pytest.raises(ValueError, match="chunk"):
        token_logprobs(model, torch.zeros(1, 3, dtype=torch.long), chunk=0)
