"""Base-class invariants, checked on small purpose-built games."""

from dataclasses import dataclass

import pytest

from glyphbench_rl.core import ActionSet, GlyphTask, TaskSpec, make, register, seeding
from glyphbench_rl.core.registry import UnknownTaskError, get_spec


@dataclass(frozen=True)
class CoinParams:
    gain: float = 0.3
    cost: float = 0.1


class Coins(GlyphTask):
    """GRAB earns gain and pays cost in the same step; END finishes."""
    title = "Coins"
    rules = "Grab coins."
    rewards = "+{gain:g} per grab minus {cost:g}."
    Params = CoinParams
    ACTIONS = ActionSet([("GRAB", "grab a coin"), ("END", "stop")], aliases={"take": "GRAB"})
    glyphs = {"$": "coin", "·": "empty"}
    default_max_turns = 10

    def _setup(self, rng):
        self.coins = int(rng.integers(3, 9))

    def _act(self, action):
        if action == 0:
            self.coins -= 1
            self.reward(self.params.gain)
            self.reward(-self.params.cost)
        else:
            self.finish(won=True)

    def _grid(self):
        return ["$" * self.coins + "·" * (10 - self.coins)]

    def _hud(self):
        return f"Coins {self.coins}"


def test_penalties_add_to_progress_in_the_same_step():
    task = Coins()
    task.reset(seed=0)
    _, reward, *_ = task.step("GRAB")
    assert reward == pytest.approx(0.2)


def test_clamp_is_applied_and_flagged_for_standard_tasks_only():
    task = Coins(gain=0.6, cost=0.0)
    task.reset(seed=1)
    task.step(0)
    _, reward, _, _, info = task.step(0)
    assert task.episode_return == 1.0 and reward == pytest.approx(0.4) and info["clamped"]
    ext = Coins(gain=0.6, cost=0.0, tier="extended", max_turns=2000)
    ext.reset(seed=1)
    ext.step(0)
    ext.step(0)
    assert ext.episode_return == pytest.approx(1.2)


def test_turn_cap_truncates_and_standard_cap_is_enforced():
    task = Coins(max_turns=3, gain=0.0, cost=0.0)
    task.reset(seed=0)
    flags = [task.step("take")[2:4] for _ in range(3)]
    assert flags == [(False, False), (False, False), (False, True)]
    with pytest.raises(ValueError, match="end by 512 turns"):
        Coins(max_turns=513)


def test_unseeded_reset_continues_the_seeded_stream():
    a, b = Coins(), Coins()
    assert a.reset(seed=5)[1]["seed"] == 5
    b.reset(seed=5)
    assert [a.reset()[0] for _ in range(5)] == [b.reset()[0] for _ in range(5)]
    assert a.reset()[1]["seed"] is None      # reproduced by the first seed and the resets since


def test_first_reset_without_a_seed_draws_one_and_reports_it():
    task = Coins()
    obs, info = task.reset()
    seed = info["seed"]
    assert isinstance(seed, int) and 0 <= seed <= seeding.MAX_SEED
    assert Coins().reset(seed=seed)[0] == obs
    assert Coins().reset()[1]["seed"] != seed     # drawn from entropy, not fixed
    with pytest.raises(TypeError, match="int seed"):
        Coins().reset(seed=1.5)


def test_a_step_that_pays_says_so_in_the_message_line():
    task = Coins(gain=0.5, cost=0.25)
    task.reset(seed=0)
    obs, reward, *_ , info = task.step("GRAB")
    assert info["frame"].message == "Reward +0.25" and obs.endswith("\nReward +0.25")
    task = Coins(gain=0.0, cost=0.125)
    task.reset(seed=0)
    assert task.step("GRAB")[-1]["frame"].message == "Reward -0.125"
    task = Coins(gain=0.0, cost=0.0)
    task.reset(seed=0)
    assert task.step("GRAB")[-1]["frame"].message == ""     # nothing paid, nothing said
    assert task.forfeit()[-1]["frame"].message == "No valid action: nothing happened."
    assert "Reward +x" in task.system_prompt()


def test_unknown_parameter_names_the_valid_ones():
    with pytest.raises(ValueError, match="unknown parameter 'gian'; valid parameters: gain, cost, max_turns"):
        Coins(gian=1)


def test_registry_rejects_bad_specs_and_names_close_ids():
    with pytest.raises(ValueError, match="does not match"):
        TaskSpec("coins", "Classics", "standard", Coins)
    with pytest.raises(ValueError, match="unknown suite"):
        TaskSpec("glyphbench/coins-v0", "Board", "standard", Coins)
    with pytest.raises(ValueError, match="512"):
        TaskSpec("glyphbench/coins-v0", "Classics", "standard", Coins, max_turns=600)
    with pytest.raises(UnknownTaskError, match="closest: glyphbench/classics-maze-easy-v0"):
        get_spec("glyphbench/classics-maze-esay-v0")


def test_lazy_entry_point_and_overrides():
    spec = TaskSpec("glyphbench/classics-testcoins-v0", "Classics", "standard",
                    "tests.test_task_base:Coins", {"gain": 0.5}, 7)
    task = spec.make(cost=0.2)
    assert (task.params.gain, task.params.cost, task.max_turns) == (0.5, 0.2, 7)
    assert "Rewards: +0.5 per grab minus 0.2." in task.system_prompt()
