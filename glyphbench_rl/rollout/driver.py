"""The one episode driver: a turn is observe, prompt, reply, parse, step or forfeit, record.

``EpisodeDriver`` plays one episode of one task on one seed, a turn at a time: ``prompt()``
composes what the policy reads (chat messages, and token ids with a token backend) through the
harness, ``apply(prompt, generation)`` records the reply, parses it with the agent protocol,
steps the game (a forfeit turn when the reply names no valid action) and appends the ``Step``.
Whoever holds the policy decides how replies are produced: the ``RolloutEngine`` batches many
drivers into one backend call per turn; the verifiers adapter sends each prompt through a
rollout's interception. Both therefore compose, parse and record identically.
"""

from __future__ import annotations

from typing import Any, Mapping

from ..agent.harness import HarnessConfig, MessageTokens, make_harness
from ..agent.parse import parse_action
from ..core.task import GlyphTask
from .backend import Generation
from .trajectory import Step, Trajectory


class Prompt:
    """What the policy reads this turn."""

    __slots__ = ("messages", "observation", "prompt_ids")

    def __init__(self, messages: list[dict[str, str]], observation: str,
                 prompt_ids: list[int] | None) -> None:
        self.messages = messages          # chat messages (text backends, endpoints)
        self.observation = observation    # the current observation message, as sent
        self.prompt_ids = prompt_ids      # exact prompt ids (token backends), else None


class EpisodeDriver:
    def __init__(self, task: GlyphTask, seed: int, harness: HarnessConfig | None = None, *,
                 tokens: MessageTokens | None = None, system_prompt: str | None = None,
                 meta: Mapping[str, Any] | None = None, group: int | None = None) -> None:
        self.task = task
        obs, _ = task.reset(seed=seed)
        system = system_prompt or task.system_prompt()
        self.harness = make_harness(system, harness, tokens)
        self.traj = Trajectory(task.task_id, seed, system_prompt=system, initial_observation=obs,
                               meta=dict(meta or {}), group=group)

    @property
    def done(self) -> bool:
        return self.task.done

    def prompt(self) -> Prompt:
        turn = self.harness.observe(self.task.frame)
        return Prompt(self.harness.messages(), turn.user, self.harness.prompt_ids())

    def apply(self, prompt: Prompt, gen: Generation) -> Step:
        """Play the reply ``gen`` to ``prompt`` (the latest prompt) and record the step."""
        task = self.task
        text = self.harness.record(gen.text if isinstance(gen.text, str) else "", gen.token_ids)
        parsed = parse_action(text, task.actions)
        if parsed.valid:
            _, reward, term, trunc, _ = task.step(parsed.index)
        else:
            _, reward, term, trunc, _ = task.forfeit(parsed.reason)
        ids = prompt.prompt_ids
        step = Step(
            turn=task.turn, observation=prompt.observation, reply=text, action=parsed.name,
            forfeit_reason=parsed.reason, reward=reward, terminated=term, truncated=trunc,
            prompt_tokens=gen.prompt_tokens or (len(ids) if ids is not None else 0),
            completion_tokens=gen.completion_tokens or len(gen.token_ids or ()),
            finish_reason=gen.finish_reason, prompt_ids=ids, completion_ids=gen.token_ids,
            logprobs=gen.logprobs)
        traj = self.traj
        traj.steps.append(step)
        traj.context_drops = self.harness.context_drops
        traj.episode_return = task.episode_return
        if task.done:
            traj.terminated, traj.truncated, traj.won = term, trunc, task.won
            traj.final_observation = task.frame.render()
        return step
