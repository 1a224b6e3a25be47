"""Token ids of chat messages, each message tokenised once (token-in, token-out).

The model's chat template is rendered only to learn how it frames a message; every message's
framed text is then tokenised on its own and the prompt is the concatenation of those pieces,
so a later prompt reuses the exact ids of earlier turns, including the ids the policy sampled.
"""

from __future__ import annotations

from typing import Any

_PROBE = "\x00PROBE\x00"


class ChatTokens:
    def __init__(self, tokenizer: Any, reply_prefix: str = "") -> None:
        self.tokenizer = tokenizer
        if getattr(tokenizer, "chat_template", None):
            sys_msg = {"role": "system", "content": "S"}
            user = {"role": "user", "content": _PROBE}
            base = self._render([sys_msg])
            with_user = self._render([sys_msg, user])
            with_gen = self._render([sys_msg, user], generation=True)
            with_reply = self._render([sys_msg, user, {"role": "assistant", "content": _PROBE}])
            if not with_user.startswith(base) or not with_gen.startswith(with_user):
                raise ValueError("this chat template does not render conversations as a growing "
                                 "prefix; token-in/token-out rollouts need one that does")
            self._system_frame = self._render([{"role": "system", "content": _PROBE}]).split(_PROBE)
            self._user_frame = with_user[len(base):].split(_PROBE)
            self._gen = with_gen[len(with_user):]
            tail = with_reply[len(with_gen):]
            self._reply_close = tail.split(_PROBE, 1)[1]
        else:  # plain language models (tiny test models): a minimal readable framing
            self._system_frame = ["", "\n\n"]
            self._user_frame = ["User: ", "\n"]
            self._gen = "Assistant: "
            self._reply_close = "\n"
        # the generation prompt, followed by the harness's reply prefix when it has one: the
        # model continues from there, and the prefix stays prompt-side (never trained on)
        self.reply_prefix = reply_prefix
        self.gen_ids = self.encode(self._gen + reply_prefix)
        eos = getattr(tokenizer, "eos_token", None)
        self._eos_text = eos or ""
        self._eos_id = getattr(tokenizer, "eos_token_id", None)

    def _render(self, messages, generation: bool = False) -> str:
        return self.tokenizer.apply_chat_template(messages, tokenize=False,
                                                  add_generation_prompt=generation)

    def encode(self, text: str) -> list[int]:
        return list(self.tokenizer.encode(text, add_special_tokens=False))

    def system(self, content: str) -> list[int]:
        return self.encode(content.join(self._system_frame))

    def user(self, content: str) -> list[int]:
        return self.encode(content.join(self._user_frame))

    def reply(self, sampled_ids: list[int]) -> list[int]:
        """The ids a sampled reply occupies in later prompts: the generation prompt, the sampled
        ids unchanged, then the template's closing (less the end token if it was sampled)."""
        close = self._reply_close
        if sampled_ids and sampled_ids[-1] == self._eos_id and close.startswith(self._eos_text):
            close = close[len(self._eos_text):]
        return self.gen_ids + list(sampled_ids) + (self.encode(close) if close else [])

    def decode(self, ids: list[int]) -> str:
        return self.tokenizer.decode(ids, skip_special_tokens=True)
