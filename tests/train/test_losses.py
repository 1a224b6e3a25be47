import math

import numpy as np
import pytest

torch = pytest.importorskip("torch")

from glyphbench_rl.train.advantages import group_advantages  # noqa: E402
from glyphbench_rl.train.losses import default_loss, ipo_loss, masked_fraction  # noqa: E402


def test_group_advantages():
    assert group_advantages([1.0, 0.0, 0.5]).tolist() == [0.5, -0.5, 0.0]
    # an ineligible rollout gets 0 and is left out of the baseline
    assert group_advantages([1.0, 0.0, -1.0], [True, True, False]).tolist() == [0.5, -0.5, 0.0]
    assert group_advantages([1.0, 1.0], [False, False]).tolist() == [0.0, 0.0]
    a = group_advantages([2.0, 0.0], std_normalize=True, eps=0.0)
    assert a.tolist() == [1.0, -1.0]
    with pytest.raises(ValueError, match="eligible"):
        group_advantages([1.0, 2.0], [True])


def _lp(p):
    return torch.tensor(p, dtype=torch.float64).log()


def test_ipo_loss_by_hand():
    # two trajectories, two tokens each; the last token of row 1 is padding
    p = [[0.50, 0.30], [0.90, 0.5]]
    q = [[0.45, 0.60], [0.85, 1.0]]
    mask = torch.tensor([[1, 1], [1, 0]])
    adv = torch.tensor([0.5, -1.0], dtype=torch.float64)
    loss = ipo_loss(_lp(p), _lp(q), adv, mask, threshold=0.1, kl_coef=1e-3)
    # token (0,0): |.05| <= .1 kept; (0,1): |-.3| dropped from the policy term; (1,0): kept
    terms = [-0.5 * (0.50 / 0.45) + 1e-3 * math.log(0.50 / 0.45) ** 2,
             1e-3 * math.log(0.30 / 0.60) ** 2,
             1.0 * (0.90 / 0.85) + 1e-3 * math.log(0.90 / 0.85) ** 2]
    assert loss.item() == pytest.approx(sum(terms) / 3, rel=1e-12)
    # the global token count normalises across micro-batches
    half = ipo_loss(_lp(p), _lp(q), adv, mask, num_tokens=6)
    assert half.item() == pytest.approx(sum(terms) / 6, rel=1e-12)


def test_default_loss_by_hand():
    p = [[0.9, 0.2], [0.1, 0.6]]
    q = [[0.6, 0.1], [0.5, 0.55]]
    mask = torch.ones(2, 2)
    adv = torch.tensor([1.0, -2.0], dtype=torch.float64)
    loss = default_loss(_lp(p), _lp(q), adv, mask, mask_low=0.2, mask_high=0.2, kl_coef=1e-3)
    kl = sum(1e-3 * math.log(a / b) ** 2 for ra, rb in zip(p, q) for a, b in zip(ra, rb))
    # A>0 row: (0.9-0.6)=.3 > .2 dropped; (0.2-0.1)=.1 kept. A<0 row: (0.1-0.5)=-.4 < -.2 dropped; .05 kept
    pg = -1.0 * (0.2 / 0.1) + 2.0 * (0.6 / 0.55)
    assert loss.item() == pytest.approx((pg + kl) / 4, rel=1e-12)
    tau = default_loss(_lp(p), _lp(q), adv, mask, adv_tau=0.5)
    assert tau.item() == pytest.approx((pg / 2 + kl) / 4, rel=1e-12)


def test_gradient_direction_and_no_nan_on_overflow():
    logits = torch.tensor([[0.0, 0.0]], requires_grad=True)
    lp = torch.log_softmax(logits, -1)
    sampled = torch.tensor([[math.log(0.5), -200.0]])    # a token the rollout almost never drew
    loss = ipo_loss(lp, sampled, torch.tensor([1.0]), torch.ones(1, 2))
    loss.backward()
    assert torch.isfinite(loss) and torch.isfinite(logits.grad).all()
    for fn in (ipo_loss, default_loss):
        lp = torch.tensor([[-1e-3, -0.5]], requires_grad=True)
        out = fn(lp, torch.tensor([[-80.0, -0.5]]), torch.tensor([-1.0]), torch.ones(1, 2))
        out.backward()
        assert torch.isfinite(out) and torch.isfinite(lp.grad).all()
    # positive advantage pushes a kept token's log-prob up (the gradient of the loss is negative)
    lp = torch.tensor([[math.log(0.5)]], requires_grad=True)
    ipo_loss(lp, torch.tensor([[math.log(0.5)]]), torch.tensor([1.0]), torch.ones(1, 1)).backward()
    assert lp.grad.item() < 0


def test_padding_with_minus_inf_is_ignored():
    lp = torch.tensor([[-0.1, float("-inf")]])
    loss = ipo_loss(lp, torch.tensor([[-0.2, float("-inf")]]), torch.tensor([1.0]), torch.tensor([[1, 0]]))
    assert torch.isfinite(loss)
    assert masked_fraction(_lp([[0.5, 0.1]]), _lp([[0.2, 0.1]]), torch.ones(1, 2)) == 0.5
