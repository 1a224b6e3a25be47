"""RolloutEngine: many episodes at once, one batched policy call per turn.

Each iteration every live episode (an ``EpisodeDriver``) contributes its prompt as one request;
the backend answers them all in one call; each driver parses its reply with the agent protocol,
steps its game (a forfeit when the reply names no valid action) and records the step. Finished episodes
are handed to ``on_episode`` at once (so a job can write them before the next turn) and their
slots are refilled from the queue.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Any, Callable, Iterable, Mapping

from ..agent.harness import HarnessConfig, check_prompt_kind
from ..core.registry import get_spec
from .backend import GenRequest, PolicyBackend
from .chat_tokens import ChatTokens
from .driver import EpisodeDriver, Prompt
from .trajectory import Trajectory


@dataclass(frozen=True)
class EpisodeSpec:
    task_id: str
    seed: int
    overrides: Mapping[str, Any] = field(default_factory=dict)
    group: int | None = None                     # the rollout group (training), on the trajectory
    meta: Mapping[str, Any] = field(default_factory=dict)   # extra trajectory meta (run step, ...)


@dataclass
class EngineStats:
    turns: int = 0
    calls: int = 0
    backend_s: float = 0.0
    total_s: float = 0.0

    @property
    def overhead_ms_per_turn(self) -> float:
        return 1000 * (self.total_s - self.backend_s) / max(1, self.turns)


class RolloutEngine:
    def __init__(self, backend: PolicyBackend, harness: HarnessConfig | None = None, *,
                 max_episodes: int = 64, meta: Mapping[str, Any] | None = None) -> None:
        if max_episodes < 1:
            raise ValueError(f"max_episodes must be >= 1, got {max_episodes}")
        self.backend = backend
        self.harness = harness or HarnessConfig()
        self.max_episodes = max_episodes
        self.meta = {"backend": getattr(backend, "name", type(backend).__name__),
                     "harness": self.harness.model_dump(), **(meta or {})}
        tokenizer = getattr(backend, "tokenizer", None)
        self.chat = ChatTokens(tokenizer, self.harness.reply_prefix) if tokenizer is not None else None
        check_prompt_kind(self.harness, self.chat is not None, self.meta["backend"])
        self.stats = EngineStats()

    # -- public ------------------------------------------------------------------------------------
    def run(self, episodes: Iterable[EpisodeSpec],
            on_episode: Callable[[Trajectory], None] | None = None, *,
            keep: bool = True) -> list[Trajectory]:
        """Play every episode to its end; trajectories come back in input order.

        ``keep=False`` returns nothing and holds no finished trajectory (for jobs that hand each
        one to ``on_episode`` and write it out)."""
        queue = list(episodes)
        for spec in queue:           # fail before any model call on a bad task ID
            get_spec(spec.task_id)
        results: list[Trajectory | None] = [None] * len(queue)
        live: dict[int, EpisodeDriver] = {}
        next_index = 0
        t0 = time.perf_counter()
        try:
            while live or next_index < len(queue):
                while len(live) < self.max_episodes and next_index < len(queue):
                    live[next_index] = self._start(queue[next_index])
                    next_index += 1
                keys = list(live)
                prompts = [live[k].prompt() for k in keys]
                requests = [self._request(k, live[k], p) for k, p in zip(keys, prompts)]
                tb = time.perf_counter()
                replies = self.backend.generate(requests)
                self.stats.backend_s += time.perf_counter() - tb
                self.stats.calls += 1
                if len(replies) != len(requests):
                    raise RuntimeError(f"backend {self.meta['backend']} answered {len(replies)} "
                                       f"of {len(requests)} requests")
                for k, prompt, gen in zip(keys, prompts, replies):
                    ep = live[k]
                    ep.apply(prompt, gen)
                    self.stats.turns += 1
                    if ep.done:
                        del live[k]
                        if keep:
                            results[k] = ep.traj
                        if on_episode is not None:
                            on_episode(ep.traj)
        finally:
            self.stats.total_s += time.perf_counter() - t0
        return [t for t in results if t is not None]

    # -- one episode ---------------------------------------------------------------------------------
    def _start(self, spec: EpisodeSpec) -> EpisodeDriver:
        task = get_spec(spec.task_id).make(**dict(spec.overrides))
        return EpisodeDriver(task, spec.seed, self.harness, tokens=self.chat,
                             meta={**self.meta, **spec.meta}, group=spec.group)

    @staticmethod
    def _request(key: int, ep: EpisodeDriver, prompt: Prompt) -> GenRequest:
        return GenRequest(key, ep.traj.task_id, ep.task.turn, prompt.messages, ep.task.actions,
                          prompt.observation, prompt.prompt_ids, ep.traj.seed)
