"""The 60 Craftax scenarios as data: each compiles, pays within [-1, 1], and plays."""

from __future__ import annotations

import numpy as np
import pytest

from glyphbench_rl.core import registry
from glyphbench_rl.games.craftax.scenarios import SCENARIOS
from glyphbench_rl.games.craftax.task import Tally

IDS = sorted(SCENARIOS)


def test_sixty_scenarios_each_registered():
    assert len(SCENARIOS) == 60
    for name in IDS:
        assert registry.is_registered(f"glyphbench/craftax-{name}-v0")


@pytest.mark.parametrize("name", IDS)
def test_scenario_compiles_and_pays_within_bounds(name):
    s = SCENARIOS[name]
    task = registry.make(f"glyphbench/craftax-{name}-v0")
    task.reset(seed=0)
    s.check(Tally(task.packed))
    top = sum(t.unit * t.cap for t in s.terms)
    assert top <= 1 + 1e-9, f"{name} can pay {top}"
    assert s.death <= 0 and top + s.death >= -1 - 1e-9
    assert s.horizon <= 512


def test_a_bad_counter_is_named():
    task = registry.make("glyphbench/craftax-choptrees-v0")
    task.reset(seed=0)
    with pytest.raises(KeyError, match="holds.unobtainium"):
        Tally(task.packed).getter("holds.unobtainium")


@pytest.mark.parametrize("name", IDS)
def test_random_play_stays_in_bounds(name):
    task = registry.make(f"glyphbench/craftax-{name}-v0")
    rng = np.random.default_rng(1)
    task.reset(seed=3)
    total = 0.0
    for _ in range(60):
        total += task.step(int(rng.integers(task.action_space.n)))[1]
        if task.done:
            break
    assert -1 - 1e-9 <= total <= 1 + 1e-9
