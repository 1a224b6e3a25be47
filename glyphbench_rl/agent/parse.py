"""Reading the action out of a model reply.

The rule: the last complete ``<action>NAME</action>`` after the last ``</think>`` wins. Names
resolve exactly, then case/whitespace-insensitively, then through the task's aliases (all in
``ActionSet.lookup``). Anything else is a forfeit with a recorded reason; no reply can raise.
Everything here is one linear pass over the reply, so a 100k-character reply costs microseconds
per kilobyte, never a regex backtracking blow-up.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from ..core.actions import ActionSet

THINK_OPEN, THINK_CLOSE = "<think>", "</think>"
# Case-insensitive patterns on the original text (str.lower() can change a string's length).
_TAG = re.compile(r"<(/?)action>", re.IGNORECASE)   # no quantifiers: linear in the reply length
_THINK_CLOSE = re.compile(re.escape(THINK_CLOSE), re.IGNORECASE)
_THINK_OPEN = re.compile(re.escape(THINK_OPEN), re.IGNORECASE)
_STRIP = " \t\r\n\"'`*."                   # quoting and emphasis models wrap names in
MAX_NAME_CHARS = 64

# Forfeit reasons, most specific first.
EMPTY = "empty"                      # nothing but whitespace
UNCLOSED_THINK = "unclosed_think"    # reasoning opened and never closed (ran out of tokens)
ONLY_IN_REASONING = "tag_only_in_reasoning"
NO_TAG = "no_tag"
EMPTY_TAG = "empty_tag"
UNKNOWN_NAME = "unknown_name"
REASONS = (EMPTY, UNCLOSED_THINK, ONLY_IN_REASONING, NO_TAG, EMPTY_TAG, UNKNOWN_NAME)


@dataclass(frozen=True, slots=True)
class ParsedAction:
    index: int | None          # None on forfeit
    name: str | None           # the canonical action name when valid
    reason: str | None = None  # None when valid, else one of REASONS
    raw: str | None = None     # the tag's text as written (cut to MAX_NAME_CHARS)

    @property
    def valid(self) -> bool:
        return self.index is not None


def final_tag(text: str) -> str | None:
    """Content of the last complete <action>...</action> in ``text`` (tags case-insensitive)."""
    open_at = -1
    found: tuple[int, int] | None = None
    for m in _TAG.finditer(text):
        if m.group(1):            # a closing tag completes the most recent unmatched opening
            if open_at >= 0:
                found = (open_at, m.start())
                open_at = -1
        else:
            open_at = m.end()
    return None if found is None else text[found[0]:found[1]]


def split_reasoning(reply: str) -> tuple[str, str]:
    """(reasoning, answer): everything up to the last </think>, and what follows it.

    A <think> that is never closed (the model ran out of tokens mid-thought) makes everything
    from it on reasoning.
    """
    return _split(reply)[:2]


def _split(reply: str) -> tuple[str, str, bool]:
    last = None
    for last in _THINK_CLOSE.finditer(reply):
        pass
    if last is not None:
        return reply[:last.start()], reply[last.end():], False
    opened = _THINK_OPEN.search(reply)
    if opened is not None:
        return reply[opened.start():], reply[:opened.start()], True
    return "", reply, False


def parse_action(reply: str | None, actions: ActionSet) -> ParsedAction:
    if not isinstance(reply, str):
        reply = "" if reply is None else str(reply)
    if not reply.strip():
        return ParsedAction(None, None, EMPTY)
    reasoning, answer, unclosed = _split(reply)
    content = final_tag(answer)
    if content is None:
        if unclosed:
            return ParsedAction(None, None, UNCLOSED_THINK)
        if reasoning and final_tag(reasoning) is not None:
            return ParsedAction(None, None, ONLY_IN_REASONING)
        return ParsedAction(None, None, NO_TAG)
    raw = content[:MAX_NAME_CHARS]
    name = content.strip(_STRIP)
    if not name:
        return ParsedAction(None, None, EMPTY_TAG, raw)
    index = actions.lookup(name) if len(name) <= MAX_NAME_CHARS else None
    if index is None:
        return ParsedAction(None, None, UNKNOWN_NAME, raw)
    return ParsedAction(index, actions[index].name, None, raw)
