"""MiniHack's environment classes with less copying per step, the same behaviour.

``MiniHack.step`` keeps a copy of every NLE array as ``_previous_obs`` (for its reward manager),
then calls ``NLE.step``, which makes a second, identical copy as ``last_observation`` (for the
reward function): 16 arrays, the 133 KB ``screen_descriptions`` among them, twice a step, about
half of a raw step's time. ``lean(cls)`` is ``cls`` with the two steps merged into one: the
statements are upstream's (``minihack`` 1.0.2 ``MiniHack.step``, ``nle`` 1.3.0 ``NLE.step``) in
their order, and the copy is made once and handed to both readers (neither writes into it).

Who reads that copy: the reward function (MiniHack's reads ``blstats`` for the time penalty, and
only when a penalty is set), the end check (MiniHack's hands it to the reward manager), and the
reward manager's events and custom reward functions. When the class keeps upstream's plain
reward function and end check and its manager holds only the standard events (stand on, reach,
message, use an object at a place: none looks at the previous observation), only ``blstats`` is
copied, and nothing when both time penalties are zero (the time penalty is then 0 without
looking). The places not copied hold ``None``: a reader we did not foresee fails loudly instead
of reading wrong arrays. Any other reward function, end check, event or custom reward function
gets the full copy. The observation dict the step returns is built straight from NLE's arrays
when it holds plain NLE keys (no crops, no pixels): the same dict without the intermediate one;
``turn_function(env)`` steps without building that dict and the info at all, for a caller that
reads NLE's arrays itself (our task).

A class that overrides these methods itself (``MiniHackKeyDoor.step``) still runs its own first:
the merged methods sit just above ``MiniHack`` in the method order, where upstream's were.
"""

from __future__ import annotations

from contextlib import contextmanager
from functools import lru_cache
from importlib.metadata import version

from minihack import MiniHack
from minihack.reward_manager import (CoordEvent, LocActionEvent, LocEvent, MessageEvent, RewardManager,
                                     SequentialRewardManager)
from nle.env.tasks import NetHackScore

# the versions whose steps the merged one repeats; with others the upstream class is used as is
MERGED_FROM = {"minihack": "1.0.2", "nle": "1.3.0"}
_MATCHES = all(version(name) == v for name, v in MERGED_FROM.items())
# events whose check ignores the previous observation, and managers that only ask their events
_PLAIN_EVENTS = (LocActionEvent, LocEvent, CoordEvent, MessageEvent)
_PLAIN_MANAGERS = (RewardManager, SequentialRewardManager)


_PENALTY_MODES = ("constant", "exp", "square", "linear", "always")


class _LeanStep(MiniHack):
    _lean_plain = False        # set per merged class: upstream's plain reward function and end check

    def step(self, action: int):
        observation, reward, done, truncated, end_status = self._lean_turn(action)
        return (self._get_observation(observation), reward, done, truncated,
                self._get_information(end_status))

    def _lean_turn(self, action: int):
        """``step`` up to the observation dict and info it returns: (NLE's arrays, reward, done,
        truncated, end status)."""
        reads = self._previous_reads()
        if reads is None:
            last_observation = tuple([a.copy() for a in self.last_observation])
        else:
            last_observation = [None] * len(self.last_observation)
            for i in reads:
                last_observation[i] = self.last_observation[i].copy()
            last_observation = tuple(last_observation)
        self._previous_obs = last_observation          # MiniHack.step's copy, shared
        self._previous_action = action
        observation, done = self.nethack.step(self.actions[action])
        truncated = self._check_abort(observation)
        is_game_over = observation[self._program_state_index][0] == 1
        if is_game_over or not self._allow_all_modes:
            observation, done = self._perform_known_steps(observation, done, exceptions=True)
        self._steps += 1
        self.last_observation = observation
        end_status = self._get_end_status(observation, done)
        reward = float(self._reward_fn(last_observation, action, observation, end_status))
        if end_status and not done:
            self._quit_game(observation, done)
            done = True
        return observation, reward, done, truncated, end_status

    def _previous_reads(self) -> tuple[int, ...] | None:
        """The arrays of the previous observation something reads (indices), or None for all."""
        if not self._lean_plain:
            return None
        manager = self.reward_manager
        if manager is not None and not (type(manager) in _PLAIN_MANAGERS and not manager.custom_reward_functions
                                        and all(type(e) in _PLAIN_EVENTS for e in manager.events)):
            return None
        return () if self._no_time_penalty() else (self._blstats_index,)

    def _no_time_penalty(self) -> bool:
        return self.penalty_step == 0 and self.penalty_time == 0 and self.penalty_mode in _PENALTY_MODES

    def _get_time_penalty(self, last_observation, observation):
        if self._no_time_penalty():     # (0 in every mode; the frozen-step count feeds only it)
            return 0.0
        return super()._get_time_penalty(last_observation, observation)

    def _get_observation(self, observation):
        keys = self.__dict__.get("_lean_keys")
        if keys is None:
            keys = self._lean_keys = self._plain_keys()
        if not keys:
            return super()._get_observation(observation)
        out = {key: observation[i] for key, i in keys}
        if self.remove_alignment_blstats and "blstats" in out:
            out["blstats"] = out["blstats"][:-1]
        return out

    def _plain_keys(self) -> tuple[tuple[str, int], ...]:
        """(key, index) of the returned observation when it holds NLE arrays only, else ()."""
        if not all(k in self._observation_keys and "pixel" not in k for k in self._minihack_obs_keys):
            return ()
        return tuple((k, self._observation_keys.index(k)) for k in self._minihack_obs_keys)


def turn_function(env):
    """action -> (NLE's arrays, reward, done, truncated, end status) for ``env``: its lean step
    without the observation dict and info ``step`` builds (pure functions of NLE's arrays, which
    a caller that reads those arrays itself does not need), or, when its class steps its own way
    (``MiniHackKeyDoor``) or is not lean, its ``step``'s answer."""
    if type(env).step is _LeanStep.step:
        return env._lean_turn

    def turn(action: int):
        observation, reward, done, truncated, info = env.step(action)
        return observation, reward, done, truncated, info["end_status"]
    return turn


def _plain_class(cls: type) -> bool:
    return (cls._reward_fn is MiniHack._reward_fn and cls._is_episode_end is MiniHack._is_episode_end
            and cls._get_time_penalty is NetHackScore._get_time_penalty)


_upstream_only = False


def lean(cls: type) -> type:
    """``cls`` (a MiniHack environment class) with the lean step; ``cls`` itself when it is no
    MiniHack class, the installed versions are not those the merged step repeats, or inside
    ``upstream_classes()``."""
    if _upstream_only or not _MATCHES or not issubclass(cls, MiniHack):
        return cls
    return _merged(cls)


@lru_cache(maxsize=None)
def _merged(cls: type) -> type:
    return type(cls.__name__, (cls, _LeanStep), {"__module__": cls.__module__, "__doc__": cls.__doc__,
                                                 "_lean_plain": _plain_class(cls)})


@contextmanager
def upstream_classes():
    """Within it, tasks build upstream's classes unchanged (the benchmark's raw step)."""
    global _upstream_only
    before, _upstream_only = _upstream_only, True
    try:
        yield
    finally:
        _upstream_only = before
