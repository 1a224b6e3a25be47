"""The Basic harness: task instructions plus the growing conversation (paper appendix C).

A prompt is the system prompt, the last ``history`` observation/reply pairs, and the current
observation. Each message is composed once, when its turn happens, and never rewritten: a
trainable backend tokenises every message once and reuses those ids in every later prompt
(token-in, token-out). When the window slides or the context budget forces it, whole old turns
leave the prompt; the system prompt and the current observation always stay.

``legend="changed"`` leaves the legend line out of an observation when the same legend is
already in the prompt, so every prompt still holds the current legend exactly once or more.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Annotated, ClassVar, Literal, Protocol, get_args

from pydantic import ConfigDict, Field

from ..core.frame import Frame
from ..settings import Settings

Legend = Literal["always", "changed"]
LEGEND_MODES = get_args(Legend)


class HarnessConfig(Settings):
    """How prompts are composed. A bad value fails here with a one-line ValueError naming it."""

    model_config = ConfigDict(frozen=True)      # hashable by value
    where: ClassVar[str] = "harness"

    history: int = Field(8, ge=0)               # past observation/reply pairs kept in each prompt
    legend: Legend = "always"                   # "changed": see the module docstring
    #: prompt budget (tokens, or chars/4 for text backends); None: no budget
    max_context_tokens: Annotated[int, Field(ge=1)] | None = None
    #: text the reply starts with, written by the harness before the model continues (assistant
    #: prefill, e.g. "<action>"); part of the prompt, never trained on. Token backends only.
    reply_prefix: str = Field("", max_length=200)


def observation_text(frame: Frame, *, legend: bool = True) -> str:
    """The frame as the model reads it; without the legend line when ``legend`` is False."""
    text = frame.render()
    if legend:
        return text
    lines = text.split("\n")
    return "\n".join(line for line in lines if not line.startswith("Legend: "))


class MessageTokens(Protocol):
    """Token ids of chat messages framed by a model's chat template, each message on its own
    (``rollout.chat_tokens.ChatTokens``): what a harness needs to hand a token backend the exact
    ids of its prompt."""

    gen_ids: list[int]           # the generation prompt (and any reply prefix)

    def system(self, content: str) -> list[int]: ...
    def user(self, content: str) -> list[int]: ...
    def reply(self, sampled_ids: list[int]) -> list[int]: ...


def check_prompt_kind(config: HarnessConfig, tokens: bool, backend: str = "") -> None:
    """Refuse settings that need token prompts when the policy reads chat messages."""
    if config.reply_prefix and not tokens:
        who = f"; backend {backend!r} sends chat messages" if backend else ""
        raise ValueError(f"harness.reply_prefix needs a token backend (hf, vllm): chat messages "
                         f"cannot carry an assistant prefill{who}")


@dataclass
class Turn:
    user: str                              # the observation message of this turn
    legend: tuple                          # the legend the message carries, () if left out
    reply: str | None = None               # the model's full reply (reasoning included)
    user_ids: list[int] | None = None      # token ids of the user message (with MessageTokens)
    reply_ids: list[int] | None = None     # prompt-side ids of the reply: sampled ids + closing


def _estimate_tokens(text: str) -> int:
    return len(text) // 4 + 1


class BasicHarness:
    """Per-episode prompt state. ``observe`` a frame, send ``messages()`` (or ``prompt_ids()``
    with ``tokens``), then ``record`` the reply.

    With ``tokens`` every message is tokenised once, when it is composed, and the context budget
    counts those ids; without, text backends get the messages and the budget estimates chars/4.
    """

    def __init__(self, system: str, config: HarnessConfig | None = None,
                 tokens: MessageTokens | None = None) -> None:
        self.system = system
        self.config = config or HarnessConfig()
        self.tokens = tokens
        check_prompt_kind(self.config, tokens is not None)
        self.system_ids = tokens.system(system) if tokens is not None else None
        self.turns: list[Turn] = []
        self.first_kept = 0          # index of the oldest turn still in the prompt
        self.context_drops = 0       # turns dropped to fit the context budget (beyond the window)

    # -- one turn ------------------------------------------------------------------------------
    def observe(self, frame: Frame) -> Turn:
        """Compose the current observation message and choose the turns the prompt keeps."""
        legend = frame.legend
        full = Turn(observation_text(frame), legend)
        start = max(self.first_kept, len(self.turns) - self.config.history)
        start = self._fit(start, full)
        turn = full
        if self.config.legend == "changed" and legend and any(
                t.legend == legend for t in self.turns[start:]):
            turn = Turn(observation_text(frame, legend=False), ())
        self._user_ids(turn)
        self.first_kept = start
        self.turns.append(turn)
        return turn

    def record(self, sampled: str, sampled_ids: list[int] | None = None) -> str:
        """Store the reply to the current turn; returns it as the model's whole reply (the
        ``reply_prefix`` the harness wrote, then what the model sampled)."""
        turn = self.turns[-1]
        turn.reply = self.config.reply_prefix + sampled
        if self.tokens is not None and sampled_ids is not None:
            turn.reply_ids = self.tokens.reply(sampled_ids)
        return turn.reply

    # -- the prompt ------------------------------------------------------------------------------
    def kept(self) -> list[Turn]:
        """The turns of the current prompt: past turns in the window, then the current one."""
        return self.turns[self.first_kept:]

    def messages(self) -> list[dict[str, str]]:
        out = [{"role": "system", "content": self.system}]
        for t in self.kept():
            out.append({"role": "user", "content": t.user})
            if t.reply is not None:
                out.append({"role": "assistant", "content": t.reply})
        return out

    def prompt_ids(self) -> list[int] | None:
        """The current prompt as token ids: the stored ids of every kept message, then the
        generation prompt; None without ``tokens``."""
        if self.tokens is None:
            return None
        ids = list(self.system_ids)
        for t in self.kept():
            ids += t.user_ids
            if t.reply_ids is not None:
                ids += t.reply_ids
        return ids + self.tokens.gen_ids

    # -- context budget --------------------------------------------------------------------------
    def _user_ids(self, turn: Turn) -> list[int] | None:
        if self.tokens is not None and turn.user_ids is None:
            turn.user_ids = self.tokens.user(turn.user)
        return turn.user_ids

    def _size(self, turn: Turn, part: str) -> int:
        if self.tokens is not None:
            return len(self._user_ids(turn)) if part == "user" else len(turn.reply_ids or ())
        return _estimate_tokens(turn.user if part == "user" else turn.reply or "")

    def _system_size(self) -> int:
        return len(self.system_ids) if self.system_ids is not None else _estimate_tokens(self.system)

    def _fit(self, start: int, current: Turn) -> int:
        budget = self.config.max_context_tokens
        if budget is None:
            return start
        total = self._system_size() + self._size(current, "user")
        past = [self._size(t, "user") + self._size(t, "reply") for t in self.turns[start:]]
        total += sum(past)
        dropped = 0
        while total > budget and dropped < len(past):
            total -= past[dropped]
            dropped += 1
        self.context_drops += dropped
        return start + dropped


def make_harness(system: str, config: HarnessConfig | None = None,
                 tokens: MessageTokens | None = None) -> BasicHarness:
    """The harness a config asks for: the one place a new harness (Guided Memory) plugs in."""
    return BasicHarness(system, config, tokens)
