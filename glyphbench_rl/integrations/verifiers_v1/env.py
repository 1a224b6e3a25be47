"""One episode: the game plays the user, the agent answers each observation.

The prompt and parse code are the rollout engine's own: ``BasicHarness`` composes every turn's
messages (system prompt, history window, legend mode, context budget) and ``parse_action``
reads the reply; a reply without a valid action is a forfeit turn. The reward is the episode
return; the metrics are the episode length, forfeit rate, terminated and truncated.
"""

from __future__ import annotations

from collections import Counter

import verifiers.v1 as vf

from ...agent.harness import BasicHarness
from ...agent.parse import parse_action
from ...core import get_spec
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
        game = get_spec(row.task_id).make()
        game.reset(seed=row.seed)
        taskset = self.taskset.config
        # a system-prompt override (e.g. from GEPA) arrives on the row, like for any taskset
        prompt = BasicHarness(row.system_prompt or game.system_prompt(), taskset.prompt_config())
        forfeits: Counter[str] = Counter()
        terminated = truncated = False
        async with agents.agent.interaction(task) as interaction:
            while not game.done:
                prompt.observe(game.frame)
                segment = await interaction.turn(prompt.messages())
                if segment.terminated:   # the run ended (a model error, a turn or token limit)
                    break
                reply = _reply(segment)
                prompt.record(reply)
                parsed = parse_action(reply, game.actions)
                if parsed.valid:
                    _, _, terminated, truncated, _ = game.step(parsed.index)
                else:
                    _, _, terminated, truncated, _ = game.forfeit(parsed.reason)
                    forfeits[parsed.reason] += 1
            # recorded before the context closes, so the rollout's own summary line shows them
            trace = interaction.trace
            turns = game.turn
            trace.record_reward("episode_return", game.episode_return)
            trace.record_metrics({
                "episode_length": turns,
                "forfeit_rate": sum(forfeits.values()) / turns if turns else 0.0,
                "terminated": float(terminated),
                "truncated": float(truncated),
                "won": float(bool(game.won)),
            })
            trace.info["glyphbench"] = {"task_id": row.task_id, "seed": row.seed,
                                        "forfeit_reasons": dict(forfeits),
                                        "context_drops": prompt.context_drops}


def _reply(segment: vf.Segment) -> str:
    """The sampled reply as the engine sees it: separate reasoning wrapped in <think>."""
    for message in reversed(segment.messages):
        if isinstance(message, vf.AssistantMessage):
            return reply_text({"content": message.content, "reasoning_content": message.reasoning_content})
    return ""
