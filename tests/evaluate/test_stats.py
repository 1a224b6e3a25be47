import math

import pytest

from glyphbench_rl.evaluate.stats import betainc, mean_ci, t_cdf, t_critical


@pytest.mark.parametrize("df, expected", [
    (1, 12.7062), (2, 4.3027), (4, 2.7764), (10, 2.2281), (30, 2.0423), (100, 1.9840),
    (1000, 1.9623), (10**8, 1.9600), (math.inf, 1.9600)])
def test_t_critical_matches_published_tables(df, expected):
    assert t_critical(df) == pytest.approx(expected, abs=1e-4)


def test_other_levels_and_bad_input():
    assert t_critical(4, 0.99) == pytest.approx(4.6041, abs=1e-4)
    assert t_critical(1, 0.999) == pytest.approx(636.619, abs=1e-2)
    assert t_critical(10, 0.90) == pytest.approx(1.8125, abs=1e-4)
    with pytest.raises(ValueError):
        t_critical(0)
    with pytest.raises(ValueError):
        t_critical(5, 1.0)


def test_cdf_and_incomplete_beta_identities():
    assert t_cdf(0.0, 3) == pytest.approx(0.5)
    assert t_cdf(1.0, 1) == pytest.approx(0.75)            # Cauchy: 1/2 + atan(1)/pi
    assert t_cdf(-2.0, 7) == pytest.approx(1 - t_cdf(2.0, 7))
    assert betainc(2, 3, 0.4) == pytest.approx(0.5248)     # closed form 1 - (1-x)^3 (1+3x)
    assert betainc(1, 1, 0.3) == pytest.approx(0.3)


def test_mean_ci_by_hand():
    ci = mean_ci([1.0, 0.0, 0.5])
    assert (ci.n, ci.mean, ci.sd) == (3, 0.5, pytest.approx(0.5))
    assert ci.ci95 == pytest.approx(4.302653 * 0.5 / math.sqrt(3))
    one = mean_ci([0.25])
    assert (one.mean, one.sd, one.ci95) == (0.25, None, None)
    assert mean_ci([]).mean is None
    assert mean_ci([0.3, 0.3, 0.3]).ci95 == 0.0
