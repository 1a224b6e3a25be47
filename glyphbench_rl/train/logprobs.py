"""Log-probabilities of given tokens without materialising [tokens x vocab] logits.

The backbone runs once over the sequence; the output head and log-softmax then run over chunks
of positions, each under activation checkpointing, so both the forward and the backward pass hold
at most ``chunk x vocab`` logits at a time (the paper trains at 32k-64k tokens with a ~150k
vocabulary, where full logits would need tens of GB).
"""

from __future__ import annotations

import torch
from torch.utils.checkpoint import checkpoint


def _head(model):
    head = model.get_output_embeddings()
    if head is None:
        raise ValueError(f"{type(model).__name__} has no output embeddings to compute logits with")
    return head


def _backbone(model):
    base = getattr(model, "base_model_prefix", None)
    body = getattr(model, base, None) if base else None
    if body is None or body is model:
        raise ValueError(f"cannot find the backbone of {type(model).__name__}")
    return body


def _chunk_logprobs(head, hidden, targets, temperature):
    logits = head(hidden).float()
    if temperature != 1.0:
        logits = logits / temperature
    return torch.log_softmax(logits, dim=-1).gather(-1, targets[..., None])[..., 0]


def token_logprobs(model, input_ids: torch.Tensor, attention_mask: torch.Tensor | None = None, *,
                   chunk: int = 1024, temperature: float = 1.0,
                   position_ids: torch.Tensor | None = None) -> torch.Tensor:
    """log p(input_ids[:, t] | input_ids[:, :t]) for t >= 1, as a [B, T] tensor whose column 0
    is 0 (the first token has no context). ``chunk`` counts token positions across the whole
    batch; ``temperature`` divides the logits, matching the distribution the rollout sampled
    from."""
    if chunk < 1:
        raise ValueError(f"chunk must be >= 1, got {chunk}")
    body, head = _backbone(model), _head(model)
    hidden = body(input_ids=input_ids, attention_mask=attention_mask,
                  position_ids=position_ids).last_hidden_state       # [B, T, H]
    hidden, targets = hidden[:, :-1], input_ids[:, 1:]
    batch, length = targets.shape
    # chunk over (row, position) pairs, so a chunk holds ``chunk`` x vocab logits whatever the
    # batch size is
    flat_h, flat_y = hidden.reshape(batch * length, -1), targets.reshape(batch * length)
    parts = []
    for start in range(0, flat_y.shape[0], chunk):
        h, y = flat_h[start:start + chunk], flat_y[start:start + chunk]
        if torch.is_grad_enabled() and h.requires_grad:
            parts.append(checkpoint(_chunk_logprobs, head, h, y, temperature, use_reentrant=False))
        else:
            parts.append(_chunk_logprobs(head, h, y, temperature))
    out = (torch.cat(parts) if parts else flat_h.new_zeros(0)).reshape(batch, length)
    return torch.cat([out.new_zeros(out.shape[0], 1), out], dim=1)
