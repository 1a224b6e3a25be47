"""Policy losses over sampled tokens (paper appendix D).

All take ``logprobs`` (current policy, log p), ``sampling_logprobs`` (the rollout's, log q),
``mask`` (1 for trainable sampled tokens) as [B, T] tensors and ``advantages`` as [B], and
return the scalar loss normalised by ``num_tokens``: the number of trainable tokens in the whole
batch, so micro-batches with gradient accumulation add up to the full-batch loss.

Ratios are computed only where a token is kept: a dropped token whose ratio would overflow
contributes neither inf nor NaN, to the value or to the gradient.
"""

from __future__ import annotations

import torch


def _prepare(logprobs, sampling_logprobs, mask, num_tokens):
    mask = mask.to(logprobs.dtype)
    valid = mask > 0
    # padding may hold -inf log-probs: zero them out before any arithmetic
    log_rho = torch.where(valid, logprobs - sampling_logprobs, torch.zeros_like(logprobs))
    n = mask.sum() if num_tokens is None else torch.as_tensor(num_tokens, dtype=logprobs.dtype)
    return mask, valid, log_rho, n.clamp(min=1)


def _policy_term(keep, log_rho, advantages):
    # exp only where kept, so a huge ratio on a dropped token never reaches the graph
    rho = torch.exp(torch.where(keep, log_rho, torch.zeros_like(log_rho)))
    return torch.where(keep, -advantages[:, None] * rho, torch.zeros_like(rho))


def ipo_loss(logprobs: torch.Tensor, sampling_logprobs: torch.Tensor, advantages: torch.Tensor,
             mask: torch.Tensor, *, threshold: float = 0.1, kl_coef: float = 1e-3,
             num_tokens: int | float | torch.Tensor | None = None) -> torch.Tensor:
    """L = 1/N sum m [ -1{|p - q| <= threshold} A rho + kl_coef (log rho)^2 ], rho = p / q."""
    mask, valid, log_rho, n = _prepare(logprobs, sampling_logprobs, mask, num_tokens)
    p = torch.exp(torch.where(valid, logprobs, torch.zeros_like(logprobs)))
    q = torch.exp(torch.where(valid, sampling_logprobs, torch.zeros_like(logprobs)))
    keep = valid & ((p - q).abs() <= threshold)
    per_token = _policy_term(keep, log_rho, advantages.to(logprobs.dtype)) + kl_coef * log_rho ** 2
    return (per_token * mask).sum() / n


def default_loss(logprobs: torch.Tensor, sampling_logprobs: torch.Tensor, advantages: torch.Tensor,
                 mask: torch.Tensor, *, mask_low: float = 0.2, mask_high: float = 0.2,
                 adv_tau: float = 1.0, kl_coef: float = 1e-3,
                 num_tokens: int | float | torch.Tensor | None = None) -> torch.Tensor:
    """The same objective with DPPO's one-sided masks: for A > 0 tokens whose probability rose by
    more than ``mask_high`` are dropped, otherwise tokens whose probability fell by more than
    ``mask_low``; advantages are scaled by ``adv_tau``."""
    mask, valid, log_rho, n = _prepare(logprobs, sampling_logprobs, mask, num_tokens)
    p = torch.exp(torch.where(valid, logprobs, torch.zeros_like(logprobs)))
    q = torch.exp(torch.where(valid, sampling_logprobs, torch.zeros_like(logprobs)))
    adv = advantages.to(logprobs.dtype) * adv_tau
    positive = (adv > 0)[:, None]
    keep = valid & torch.where(positive, (p - q) <= mask_high, (p - q) >= -mask_low)
    per_token = _policy_term(keep, log_rho, adv) + kl_coef * log_rho ** 2
    return (per_token * mask).sum() / n


def masked_fraction(logprobs, sampling_logprobs, mask, advantages=None, *, threshold: float = 0.1) -> float:
    """Share of trainable tokens the ipo mask drops (a training metric)."""
    valid = mask > 0
    diff = (logprobs.exp() - sampling_logprobs.exp()).abs()
    dropped = valid & (diff > threshold)
    return float(dropped.sum()) / max(1, int(valid.sum()))
