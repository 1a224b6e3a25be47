"""What the rollout engine asks of a policy, and the two backends that need no model.

Every turn the engine sends one ``generate`` call with a request per live episode. A request
carries the chat messages; for a backend with a ``tokenizer`` (a trainable one) it also carries
the exact prompt token ids, and the backend must answer with the sampled ids and their
log-probabilities under the sampling distribution.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable, Protocol, Sequence

import numpy as np

from ..core.actions import ActionSet
from ..core.seeding import generator


class BackendError(RuntimeError):
    """A backend could not produce a reply (after its own retries); the run stops, resumable."""


@dataclass
class GenRequest:
    key: Any                              # the engine's episode handle
    task_id: str
    turn: int                             # 0-based index of the turn being decided
    messages: list[dict[str, str]]
    actions: ActionSet
    observation: str
    prompt_ids: list[int] | None = None   # token backends only
    seed: int | None = None               # the episode's seed (per-episode streams)


@dataclass
class Generation:
    text: str
    token_ids: list[int] | None = None    # sampled ids (token backends)
    logprobs: list[float] | None = None   # their sampling log-probabilities
    finish_reason: str = "stop"           # "stop" or "length"
    prompt_tokens: int = 0
    completion_tokens: int = 0


class PolicyBackend(Protocol):
    name: str
    #: a transformers-style tokenizer for token-in/token-out backends, None for text backends
    tokenizer: Any

    def generate(self, requests: Sequence[GenRequest]) -> list[Generation]: ...


@dataclass
class RandomBackend:
    """Uniformly random valid actions, as replies in the action format; no model involved.

    Each episode draws from its own stream, named by (task, episode seed), so an episode's
    actions do not depend on which other episodes share its batches (resumed or regrouped jobs
    reproduce the same numbers).
    """

    seed: int = 0
    name: str = "random"
    tokenizer: Any = None
    _streams: dict = field(init=False, repr=False, default_factory=dict)

    def generate(self, requests: Sequence[GenRequest]) -> list[Generation]:
        out = []
        for r in requests:
            key = (r.task_id, r.seed)
            rng = self._streams.get(key)
            if rng is None or r.turn == 0:
                rng = self._streams[key] = generator(self.seed, "random-backend", r.task_id, r.seed or 0)
            name = r.actions[int(rng.integers(len(r.actions)))].name
            out.append(Generation(f"<action>{name}</action>"))
        return out


@dataclass
class ScriptedBackend:
    """Replies from a callable ``policy(request) -> str | int``: a reply text, or an action
    index (wrapped in the action format). Useful for tests, heuristics and replaying logs.
    An index outside ``0..len(actions)-1`` (negative ones too) is written as it is, so it is a
    forfeit turn (``unknown_name``) like any other reply naming no action."""

    policy: Callable[[GenRequest], str | int]
    name: str = "scripted"
    tokenizer: Any = None

    def generate(self, requests: Sequence[GenRequest]) -> list[Generation]:
        out = []
        for r in requests:
            reply = self.policy(r)
            if isinstance(reply, (int, np.integer)) and not isinstance(reply, bool):
                index = int(reply)
                name = r.actions[index].name if 0 <= index < len(r.actions) else str(index)
                reply = f"<action>{name}</action>"
            elif not isinstance(reply, str):
                raise BackendError(f"scripted policy returned {type(reply).__name__}; expected str or int")
            out.append(Generation(reply))
        return out
