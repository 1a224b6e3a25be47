"""Means with Student-t intervals, computed exactly with ``math`` (core depends on numpy only).

The t quantile inverts the t distribution's CDF, written with the regularized incomplete beta
function (continued fraction, as in Numerical Recipes §6.4), by bisection: exact to ~1e-12,
which a small table plus an approximation would not be at small df, where evaluation
intervals over 5 episodes or a handful of tasks live.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Iterable


def _betacf(a: float, b: float, x: float) -> float:
    """Continued fraction of the incomplete beta function (modified Lentz)."""
    tiny, eps = 1e-300, 1e-15
    qab, qap, qam = a + b, a + 1.0, a - 1.0
    c, d = 1.0, 1.0 - qab * x / qap
    d = 1.0 / (d if abs(d) > tiny else tiny)
    h = d
    for m in range(1, 10_000):
        m2 = 2 * m
        for num in (m * (b - m) * x / ((qam + m2) * (a + m2)),
                    -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2))):
            d = 1.0 + num * d
            d = 1.0 / (d if abs(d) > tiny else tiny)
            c = 1.0 + num / c
            c = c if abs(c) > tiny else tiny
            h *= d * c
        if abs(d * c - 1.0) < eps:
            break
    return h


def betainc(a: float, b: float, x: float) -> float:
    """Regularized incomplete beta I_x(a, b)."""
    if x <= 0.0:
        return 0.0
    if x >= 1.0:
        return 1.0
    front = math.exp(math.lgamma(a + b) - math.lgamma(a) - math.lgamma(b)
                     + a * math.log(x) + b * math.log1p(-x))
    # the fraction converges fast only below the mean; use the symmetry relation above it
    if x < (a + 1.0) / (a + b + 2.0):
        return front * _betacf(a, b, x) / a
    return 1.0 - front * _betacf(b, a, 1.0 - x) / b


def t_cdf(t: float, df: float) -> float:
    # beyond 1e7 df the t and normal quantiles agree to 1e-7, and the beta form loses precision
    if df > 1e7:
        return 0.5 * math.erfc(-t / math.sqrt(2.0))
    tail = 0.5 * betainc(df / 2.0, 0.5, df / (df + t * t))
    return 1.0 - tail if t >= 0 else tail


@lru_cache(maxsize=4096)
def t_critical(df: float, level: float = 0.95) -> float:
    """Two-sided critical value: P(|T_df| <= t) = level. ``df=math.inf`` gives the normal one."""
    if not df > 0:
        raise ValueError(f"degrees of freedom must be > 0, got {df}")
    if not 0 < level < 1:
        raise ValueError(f"level must be in (0, 1), got {level}")
    p = 0.5 + level / 2.0
    lo, hi = 0.0, 2.0
    while t_cdf(hi, df) < p:        # df=1 at 99.9% needs ~637: grow the bracket
        lo, hi = hi, hi * 2.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if t_cdf(mid, df) < p:
            lo = mid
        else:
            hi = mid
        if hi - lo < 1e-13 * max(1.0, hi):
            break
    return 0.5 * (lo + hi)


@dataclass(frozen=True)
class MeanCI:
    n: int
    mean: float | None
    sd: float | None        # sample standard deviation (n - 1)
    ci95: float | None      # half-width of the 95% t-interval; None below two values

    def as_dict(self) -> dict:
        return {"n": self.n, "mean": self.mean, "sd": self.sd, "ci95": self.ci95}


def mean_ci(values: Iterable[float], level: float = 0.95) -> MeanCI:
    xs = [float(v) for v in values]
    n = len(xs)
    if n == 0:
        return MeanCI(0, None, None, None)
    mean = math.fsum(xs) / n
    if n < 2:
        return MeanCI(n, mean, None, None)
    sd = math.sqrt(math.fsum((x - mean) ** 2 for x in xs) / (n - 1))
    return MeanCI(n, mean, sd, t_critical(n - 1, level) * sd / math.sqrt(n))


def fmean(values: Iterable[float]) -> float | None:
    xs = [float(v) for v in values]
    return math.fsum(xs) / len(xs) if xs else None
