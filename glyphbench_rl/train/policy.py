"""What the trainer needs of a policy: sample rollouts, score token sequences, update, save.

``Policy`` is that interface; the trainer calls nothing else, so another implementation (a
policy whose rollouts run on a vLLM server, say) plugs in without touching the loop.
``HFPolicy`` is the built-in one: a transformers causal LM that samples through ``HFBackend``
and scores with chunked, checkpointed token log-probs.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Iterable, Protocol

from ..rollout.backend import PolicyBackend


class Policy(Protocol):
    name: str                      # recorded with every trajectory (``meta["model"]``)
    tokenizer: Any                 # a transformers-style tokenizer (pad id, chat template)

    def sampler(self, *, seed: int, temperature: float, top_p: float, max_new_tokens: int,
                batch_size: int) -> PolicyBackend:
        """A token-in/token-out backend sampling from the current weights."""

    def token_logprobs(self, ids: Any, attention: Any, *, chunk: int, temperature: float) -> Any:
        """Log-probabilities of ``ids[:, 1:]`` given their prefixes, shaped like ``ids`` (the first
        position 0), differentiable with respect to ``parameters()``."""

    def parameters(self) -> Iterable[Any]: ...

    def train_mode(self, on: bool) -> None:
        """Switch between updating (dropout etc. as in training) and sampling."""

    def save(self, path: Path) -> None:
        """Weights and tokenizer, loadable again by ``load_weights`` or as a model folder."""

    def load_weights(self, path: Path) -> None: ...

    @property
    def device(self) -> Any: ...


class HFPolicy:
    """A transformers causal LM with its tokenizer."""

    def __init__(self, model: Any, tokenizer: Any, name: str, *,
                 gradient_checkpointing: bool = False) -> None:
        self.model, self.tokenizer, self.name = model, tokenizer, name
        if gradient_checkpointing:
            model.gradient_checkpointing_enable()

    @classmethod
    def load(cls, source: str, name: str, *, device: str | None = None, dtype: str | None = None,
             gradient_checkpointing: bool = False) -> "HFPolicy":
        from ..models import load_model
        model, tokenizer = load_model(source, device=device, dtype=dtype)
        return cls(model, tokenizer, name, gradient_checkpointing=gradient_checkpointing)

    def sampler(self, *, seed: int, temperature: float, top_p: float, max_new_tokens: int,
                batch_size: int) -> PolicyBackend:
        from ..rollout.hf_backend import HFBackend
        self.model.eval()
        return HFBackend(self.model, tokenizer=self.tokenizer, temperature=temperature, top_p=top_p,
                         max_new_tokens=max_new_tokens, batch_size=batch_size, seed=seed)

    def token_logprobs(self, ids: Any, attention: Any, *, chunk: int, temperature: float) -> Any:
        from .logprobs import token_logprobs
        return token_logprobs(self.model, ids, attention, chunk=chunk, temperature=temperature)

    def parameters(self) -> Iterable[Any]:
        return self.model.parameters()

    def train_mode(self, on: bool) -> None:
        self.model.train(on)

    def save(self, path: Path) -> None:
        from transformers.utils import logging as hf_logging
        bars = hf_logging.is_progress_bar_enabled()
        hf_logging.disable_progress_bar()          # no "Writing model shards" bar in a run's log
        try:
            self.model.save_pretrained(path)
            self.tokenizer.save_pretrained(path)
        finally:
            if bars:
                hf_logging.enable_progress_bar()

    def load_weights(self, path: Path) -> None:
        from safetensors.torch import load_file
        self.model.load_state_dict(load_file(str(Path(path) / "model.safetensors")), strict=False)

    @property
    def device(self) -> Any:
        return next(self.model.parameters()).device
