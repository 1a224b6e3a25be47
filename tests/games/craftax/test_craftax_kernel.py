"""The compiled step (``kernel.step`` on the packed state) plays as the reference step
(``rules.step`` on the ``State``): from every scenario's start, with the same draws and actions,
the two states are the same after every step, field for field, and so are the rewards."""

import copy

import numpy as np
import pytest

from glyphbench_rl.games.common.lanes import Draws
from glyphbench_rl.games.craftax import kernel, rules
from glyphbench_rl.games.craftax.packed import DRAW_AT, DRAWS_RESERVE, STEP_FLAGS, KernelDraws, pack, unpack
from glyphbench_rl.games.craftax.scenarios import SCENARIOS
from glyphbench_rl.games.craftax.state import Mobs, State
from glyphbench_rl.games.craftax.tables import Action, light_level


def snapshot(state: State) -> dict:
    """Every field of ``state`` as comparable values (arrays as dtype and bytes, numbers with
    their type's kind)."""
    out = {}
    for name, value in vars(state).items():
        if isinstance(value, np.ndarray):
            out[name] = (value.dtype.str, value.shape, value.tobytes())
        elif isinstance(value, Mobs):
            out[name] = {k: v for k, v in vars(value).items()}
        elif hasattr(value, "__dataclass_fields__"):
            out[name] = snapshot(value)
        else:
            out[name] = float(value)
    return out


def differences(a: dict, b: dict) -> list[str]:
    return [k for k in a if a[k] != b[k]]


# actions a player who does things takes: moves and DO mostly, then everything else
BUSY = ([int(a) for a in (Action.LEFT, Action.RIGHT, Action.UP, Action.DOWN)] * 6
        + [int(Action.DO)] * 8 + [int(a) for a in Action])


def play(name: str, seed: int, turns: int) -> int:
    """Play the scenario's start on both; returns the draws taken."""
    scenario = SCENARIOS[name]
    state, _ = scenario.build(np.random.default_rng(seed))
    settings = scenario.settings
    ours = copy.deepcopy(state)
    p = pack(ours, settings)
    draws = Draws(np.random.default_rng(100 + seed))
    kernel_draws = KernelDraws(np.random.default_rng(100 + seed))
    kernel_draws.top_up(p)
    rng = np.random.default_rng(200 + seed)
    for turn in range(turns):
        action = BUSY[int(rng.integers(len(BUSY)))]
        want = rules.step(state, action, settings, draws)
        got = kernel.step(p, action)
        if p.ints[STEP_FLAGS] & kernel.REFILL:
            kernel_draws.top_up(p)
        unpack(p, ours)
        diff = differences(snapshot(state), snapshot(ours))
        assert not diff and got == want, (name, seed, turn, Action(action).name, diff, got, want)
        assert draws.random() == p.draws[p.ints[DRAW_AT]]       # (the same draws taken)
        p.ints[DRAW_AT] += 1
        if len(p.draws) - p.ints[DRAW_AT] < DRAWS_RESERVE:
            kernel_draws.top_up(p)
        if state.player_health <= 0:
            break
    return turn


@pytest.mark.parametrize("name", sorted(SCENARIOS))
def test_kernel_plays_as_the_rules(name):
    for seed in range(2):
        play(name, seed, 120)


def test_light_level_as_the_tables():
    for day_length in (300, 100, 7):
        for timestep in range(0, 3 * day_length + 1):
            assert kernel.light_level(timestep, day_length) == light_level(timestep, day_length)
