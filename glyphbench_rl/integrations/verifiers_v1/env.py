"""One episode: the game plays the user, the agent answers each observation.

The turn is the rollout engine's own ``EpisodeDriver``: the harness composes every turn's
messages (system prompt, history window, legend mode, context budget), the agent protocol parses
the reply, and a reply without a valid action is a forfeit turn. The reward is the episode
return; the metrics are the episode length, forfeit rate, terminated, truncated and won.
"""

from __future__ import annotations

from collections import Counter

import verifiers.v1 as vf

from ...core import get_spec
from ...rollout.backend import Generation
from ...rollout.driver import EpisodeDriver
from ...rollout.openai_backend import reply_text
from .harness import GlyphbenchHarness
from .taskset import GlyphbenchTask


class GlyphbenchEnvConfig(vf.EnvConfig):
    # Local by default: the harness runs in-process and needs no sandbox (v1's default is Prime).
    agent: vf.AgentConfig = vf.AgentConfig(runtime=vf.SubprocessConfig())
    """The one seat: the policy under evaluation or training (--env.agent.*)."""


class GlyphbenchEnv(vf.Env[GlyphbenchEnvConfig]):
    def __init__(self, config: GlyphbenchEnvConfig) -> None:
        super().__init__(config)
        for name, harness in self._harnesses.items():
            if not isinstance(harness, GlyphbenchHarness):
                # other harnesses keep their own conversation: the prompts would differ
                raise ValueError(f"glyphbench-rl plays through its own harness (the rollout "
                                 f"engine's prompts); --env.{name}.harness.id is "
                                 f"{harness.config.id!r}, leave it unset")

    async def run(self, task: GlyphbenchTask, agents: vf.Agents) -> None:
        row = task.data
        # a system-prompt override (e.g. from GEPA) arrives on the row, like for any taskset
        driver = EpisodeDriver(get_spec(row.task_id).make(), row.seed, self.taskset.config.harness,
                               system_prompt=row.system_prompt or None)
        async with agents.agent.interaction(task) as interaction:
            while not driver.done:
                prompt = driver.prompt()
                segment = await interaction.turn(prompt.messages)
                if segment.terminated:   # the run ended (a model error, a turn or token limit)
                    break
                driver.apply(prompt, Generation(_reply(segment)))
            # recorded before the context closes, so the rollout's own summary line shows them
            traj = driver.traj
            forfeits = Counter(s.forfeit_reason for s in traj.steps if s.action is None)
            trace = interaction.trace
            trace.record_reward("episode_return", driver.task.episode_return)
            trace.record_metrics({
                "episode_length": traj.length,
                "forfeit_rate": traj.forfeits / traj.length if traj.length else 0.0,
                "terminated": float(traj.terminated),
                "truncated": float(traj.truncated),
                "won": float(bool(driver.task.won)),
            })
            trace.info["glyphbench"] = {"task_id": row.task_id, "seed": row.seed,
                                        "forfeit_reasons": dict(forfeits),
                                        "context_drops": traj.context_drops}


def _reply(segment: vf.Segment) -> str:
    """The sampled reply as the engine sees it: separate reasoning wrapped in <think>."""
    for message in reversed(segment.messages):
        if isinstance(message, vf.AssistantMessage):
            return reply_text({"content": message.content, "reasoning_content": message.reasoning_content})
    return ""
