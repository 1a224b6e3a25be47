"""RolloutEngine: many episodes at once, one batched policy call per turn.

Each iteration every live episode that needs an action contributes one request; the backend
answers them all in one call; the engine parses each reply with the agent protocol, steps the
game (a forfeit when the reply names no valid action) and records the step. Finished episodes
are handed to ``on_episode`` at once (so a job can write them before the next turn) and their
slots are refilled from the queue.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Any, Callable, Iterable, Mapping

from ..agent.harness import BasicHarness, HarnessConfig, Turn
from ..agent.parse import parse_action
from ..core.registry import get_spec
from ..replay.schema import Step, Trajectory
from .backend import GenRequest, Generation, PolicyBackend
from .chat_tokens import ChatTokens


@dataclass(frozen=True)
class EpisodeSpec:
    task_id: str
    seed: int
    overrides: Mapping[str, Any] = field(default_factory=dict)
    tag: Any = None                     # carried to the trajectory's meta (group ids, ...)


@dataclass
class _Live:
    spec: EpisodeSpec
    task: Any
    harness: BasicHarness
    traj: Trajectory
    system_ids: list[int] | None = None


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
        if self.harness.reply_prefix and self.chat is None:
            raise ValueError(f"harness.reply_prefix needs a token backend (hf, vllm); backend "
                             f"{self.meta['backend']!r} sends chat messages")
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
        live: dict[int, _Live] = {}
        next_index = 0
        t0 = time.perf_counter()
        try:
            while live or next_index < len(queue):
                while len(live) < self.max_episodes and next_index < len(queue):
                    live[next_index] = self._start(queue[next_index])
                    next_index += 1
                keys = list(live)
                requests = [self._request(k, live[k]) for k in keys]
                tb = time.perf_counter()
                replies = self.backend.generate(requests)
                self.stats.backend_s += time.perf_counter() - tb
                self.stats.calls += 1
                if len(replies) != len(requests):
                    raise RuntimeError(f"backend {self.meta['backend']} answered {len(replies)} "
                                       f"of {len(requests)} requests")
                for k, req, gen in zip(keys, requests, replies):
                    ep = live[k]
                    self._apply(ep, req, gen)
                    if ep.task.done:
                        del live[k]
                        ep.traj.context_drops = ep.harness.context_drops
                        if keep:
                            results[k] = ep.traj
                        if on_episode is not None:
                            on_episode(ep.traj)
        finally:
            self.stats.total_s += time.perf_counter() - t0
        return [t for t in results if t is not None]

    # -- one episode ---------------------------------------------------------------------------------
    def _start(self, spec: EpisodeSpec) -> _Live:
        task = get_spec(spec.task_id).make(**dict(spec.overrides))
        obs, _ = task.reset(seed=spec.seed)
        system = task.system_prompt()
        meta = dict(self.meta)
        if spec.tag is not None:
            meta["tag"] = spec.tag
        traj = Trajectory(spec.task_id, spec.seed, system_prompt=system, initial_observation=obs,
                          meta=meta)
        ep = _Live(spec, task, BasicHarness(system, self.harness), traj)
        if self.chat is not None:
            ep.system_ids = self.chat.system(system)
            ep.harness.measure = lambda item, part, ep=ep: self._measure(ep, item, part)
        return ep

    def _measure(self, ep: _Live, item: Turn | str, part: str) -> int:
        if isinstance(item, str):
            return len(ep.system_ids)
        if part == "user":
            if item.user_ids is None:
                item.user_ids = self.chat.user(item.user)
            return len(item.user_ids)
        return len(item.reply_ids or ())

    def _request(self, key: int, ep: _Live) -> GenRequest:
        turn = ep.harness.observe(ep.task.frame)
        prompt_ids = None
        if self.chat is not None:
            if turn.user_ids is None:
                turn.user_ids = self.chat.user(turn.user)
            prompt_ids = list(ep.system_ids)
            for t in ep.harness.kept():
                prompt_ids += t.user_ids
                if t.reply_ids is not None:
                    prompt_ids += t.reply_ids
            prompt_ids += self.chat.gen_ids
        return GenRequest(key, ep.spec.task_id, ep.task.turn, ep.harness.messages(),
                          ep.task.actions, turn.user, prompt_ids, ep.spec.seed)

    def _apply(self, ep: _Live, req: GenRequest, gen: Generation) -> None:
        text = self.harness.reply_prefix + (gen.text if isinstance(gen.text, str) else "")
        reply_ids = self.chat.reply(gen.token_ids) if self.chat is not None and gen.token_ids is not None else None
        ep.harness.record(text, reply_ids)
        parsed = parse_action(text, ep.task.actions)
        if parsed.valid:
            _, reward, term, trunc, _ = ep.task.step(parsed.index)
        else:
            _, reward, term, trunc, _ = ep.task.forfeit(parsed.reason)
        prompt_tokens = gen.prompt_tokens or (len(req.prompt_ids) if req.prompt_ids is not None else 0)
        completion_tokens = gen.completion_tokens or (len(gen.token_ids) if gen.token_ids is not None else 0)
        ep.traj.steps.append(Step(
            turn=ep.task.turn, observation=req.observation, reply=text, action=parsed.name,
            forfeit_reason=parsed.reason, reward=reward, terminated=term, truncated=trunc,
            prompt_tokens=prompt_tokens, completion_tokens=completion_tokens,
            finish_reason=gen.finish_reason, prompt_ids=req.prompt_ids,
            completion_ids=gen.token_ids, logprobs=gen.logprobs))
        self.stats.turns += 1
        if ep.task.done:
            ep.traj.episode_return = ep.task.episode_return
            ep.traj.terminated, ep.traj.truncated = term, trunc
            ep.traj.won = ep.task.won
            ep.traj.final_observation = ep.task.frame.render()

