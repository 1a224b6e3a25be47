"""Group-relative advantages (paper eq. 2): A_i = R_i - mean of the group's eligible returns.

A group is G rollouts of one task on different seeds. Ineligible rollouts (errored, or truncated
when the config excludes those) get advantage 0 and no say in the baseline. No division by the
standard deviation unless asked for (the paper's runs do not normalise).
"""

from __future__ import annotations

from typing import Sequence

import numpy as np


def group_advantages(returns: Sequence[float], eligible: Sequence[bool] | None = None, *,
                     std_normalize: bool = False, eps: float = 1e-6) -> np.ndarray:
    r = np.asarray(returns, dtype=np.float64)
    if r.ndim != 1:
        raise ValueError(f"returns must be one group (1-D), got shape {r.shape}")
    ok = np.ones(len(r), dtype=bool) if eligible is None else np.asarray(eligible, dtype=bool)
    if ok.shape != r.shape:
        raise ValueError(f"eligible has {ok.size} entries for {r.size} returns")
    adv = np.zeros_like(r)
    if not ok.any():
        return adv
    base = r[ok].mean()
    adv[ok] = r[ok] - base
    if std_normalize:
        adv[ok] /= r[ok].std() + eps
    return adv
