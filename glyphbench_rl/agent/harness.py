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

from dataclasses import dataclass, field
from typing import Annotated, Callable, ClassVar, Literal, get_args

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


@dataclass
class Turn:
    user: str                              # the observation message of this turn
    legend: tuple                          # the legend the message carries, () if left out
    reply: str | None = None               # the model's full reply (reasoning included)
    user_ids: list[int] | None = None      # token ids of the user message (trainable backends)
    reply_ids: list[int] | None = None     # prompt-side ids of the reply: sampled ids + closing


def _estimate_tokens(text: str) -> int:
    return len(text) // 4 + 1


@dataclass
class BasicHarness:
    """Per-episode prompt state. ``observe`` a frame, send ``messages()``, then ``record`` the reply."""

    system: str
    config: HarnessConfig = field(default_factory=HarnessConfig)
    #: token length of a message, when known (a trainable backend's tokenizer); else estimated
    measure: Callable[[Turn | str, str], int] | None = None
    turns: list[Turn] = field(default_factory=list)
    first_kept: int = 0          # index of the oldest turn still in the prompt
    context_drops: int = 0       # turns dropped to fit the context budget (beyond the window)

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
        self.first_kept = start
        self.turns.append(turn)
        return turn

    def record(self, reply: str, reply_ids: list[int] | None = None) -> None:
        turn = self.turns[-1]
        turn.reply = reply
        turn.reply_ids = reply_ids

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

    # -- context budget --------------------------------------------------------------------------
    def _size(self, item: Turn | str, part: str) -> int:
        if self.measure is not None:
            return self.measure(item, part)
        text = item if isinstance(item, str) else (item.user if part == "user" else item.reply or "")
        return _estimate_tokens(text)

    def _fit(self, start: int, current: Turn) -> int:
        budget = self.config.max_context_tokens
        if budget is None:
            return start
        total = self._size(self.system, "system") + self._size(current, "user")
        past = [self._size(t, "user") + self._size(t, "reply") for t in self.turns[start:]]
        total += sum(past)
        dropped = 0
        while total > budget and dropped < len(past):
            total -= past[dropped]
            dropped += 1
        self.context_drops += dropped
        return start + dropped
