"""One episode: the game plays the user, the agent answers each observation.

The turn is the rollout engine's own ``EpisodeDriver``: the harness composes every turn's
messages (system prompt, history window, legend mode, context budget), the agent protocol parses
the reply, and a reply without a valid action is a forfeit turn. The reward is the episode
return; the metrics are the episode length, forfeit rate, terminated, truncated and won.

Each past reply in a prompt goes back as the model returned it (the trace's own sampled message,
reasoning in the field the server put it in), not as the engine's text of it (reasoning inlined
in ``<think>``): verifiers' trace graph matches a prompt against the recorded messages, so a prompt
that extends the last one continues its branch, and in training (Prime-RL's renderer client)
the turn bridges onto the sampled token ids. The trace then branches only where the engine's
own packing starts a new training sequence: where the history window slid or the context budget
dropped a turn.
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
            replies: list[vf.AssistantMessage | None] = []     # each turn's, as the model returned it
            while not driver.done:
                prompt = driver.prompt()
                segment = await interaction.turn(as_returned(prompt.messages, replies))
                if segment.terminated:   # the run ended (a model error, a turn or token limit)
                    break
                reply = _sampled(segment)
                replies.append(reply)
                driver.apply(prompt, Generation(_text(reply)))
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


def _sampled(segment: vf.Segment) -> vf.AssistantMessage | None:
    """The reply this segment sampled (the trace's message), None if it holds none."""
    for message in reversed(segment.messages):
        if isinstance(message, vf.AssistantMessage):
            return message
    return None


def _text(message: vf.AssistantMessage | None) -> str:
    """The reply as the engine reads it: separate reasoning wrapped in <think>."""
    if message is None:
        return ""
    return reply_text({"content": message.content, "reasoning_content": message.reasoning_content})


def as_returned(messages: list[dict], replies: list[vf.AssistantMessage | None]) -> list:
    """``messages`` (the engine's prompt) with each past reply as the model returned it.

    A prompt's assistant messages are the replies of the turns its window keeps, which are the
    latest ones, in order; each is swapped for its sampled message when that reads as the same
    text (``_text``), so a reply whose reasoning the server split off goes back the same way.
    """
    n = sum(1 for m in messages if m["role"] == "assistant")
    if n > len(replies):
        raise RuntimeError(f"the prompt holds {n} replies but only {len(replies)} were sampled")
    kept = iter(replies[len(replies) - n:])
    out: list = []
    for message in messages:
        if message["role"] == "assistant":
            reply = next(kept)
            if reply is not None and _text(reply) == message["content"]:
                out.append(reply)
                continue
        out.append(message)
    return out
