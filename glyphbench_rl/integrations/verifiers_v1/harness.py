"""The seat's program: one model call per turn, on exactly the prompt the env composed.

verifiers' chat harnesses keep the whole conversation and run as a uv script in a runtime.
Games need the engine's prompt instead (system prompt + a sliding history window + the
current observation), and nothing to execute, so this harness runs in-process: each segment
posts the messages the env handed to ``turn()`` (the engine's prompt, past replies as the model
returned them: see ``env``) to the rollout's interception endpoint, which
records the call on the trace and relays it to the real model (v1's documented in-process
harness contract: every model call goes through ``endpoint`` + ``secret``).
"""

from __future__ import annotations

import asyncio
import random
import uuid

import httpx
import verifiers.v1 as vf
from pydantic import Field
from verifiers.v1.dialects.chat import message_to_wire
from verifiers.v1.runtimes import ProgramResult


class GlyphbenchHarnessConfig(vf.HarnessConfig):
    """--env.agent.harness.* (name the harness first: --env.agent.harness.id glyphbench-rl)."""

    stream: bool = True
    """Ask for SSE responses: the interception keeps long generations alive with keepalives."""
    max_retries: int = Field(4, ge=0)
    """Retries of one turn's call on 429, 5xx and dropped connections (not on other 4xx)."""
    backoff_s: float = Field(1.0, ge=0)
    """First retry delay; doubles per retry, with jitter."""
    timeout_s: float | None = Field(None, gt=0)
    """Read timeout of one call; None leaves it to the agent's rollout timeout."""


class GlyphbenchHarness(vf.Harness[GlyphbenchHarnessConfig]):
    APPENDS_SYSTEM_PROMPT = True
    SUPPORTS_RESUME = True
    EXECUTES_CODE = False
    NEEDS_CONTAINER = False

    async def launch(self, ctx, trace, runtime, endpoint, secret, mcp_urls, data, **_) -> ProgramResult:
        # Only reached for a task that carries its own prompt and no user; glyphbench rows
        # have none (the env opens every exchange), but answer it the plain way anyway.
        system, prompt = self.resolve_prompt(data)
        messages = [vf.SystemMessage(content=system)] if system else []
        messages += [vf.UserMessage(content=prompt)] if isinstance(prompt, str) else list(prompt or [])
        return await self._call(ctx, trace, endpoint, secret, messages)

    async def resume(self, ctx, trace, runtime, endpoint, secret, mcp_urls, data, messages,
                     tool_interception_url=None) -> ProgramResult:
        # The env hands over the complete prompt of this turn, its past replies the trace's own
        # sampled messages: send it as is. The interception matches it against the trace by
        # prefix, so a prompt that extends the last one continues that branch (in training: its
        # token ids), and only a prompt that does not (the window slid) starts a new one.
        return await self._call(ctx, trace, endpoint, secret, messages)

    async def _call(self, ctx, trace, endpoint, secret, messages) -> ProgramResult:
        cfg = self.config
        url = f"{endpoint.rstrip('/')}/chat/completions"
        body: dict = {"model": ctx.model, "messages": [message_to_wire(m) for m in messages]}
        if cfg.stream:
            body |= {"stream": True, "stream_options": {"include_usage": True}}
        # One key for the logical call: a retry of a turn the server already committed is
        # replayed instead of sampled twice.
        headers = {"Authorization": f"Bearer {secret}", "Idempotency-Key": uuid.uuid4().hex}
        turns = trace.num_turns
        problem = ""
        timeout = httpx.Timeout(cfg.timeout_s, connect=30.0)
        async with httpx.AsyncClient(timeout=timeout, trust_env=False) as client:   # loopback
            for attempt in range(cfg.max_retries + 1):
                if attempt:
                    await asyncio.sleep(cfg.backoff_s * 2 ** (attempt - 1) * (0.5 + random.random()))
                try:
                    r = await client.post(url, json=body,
                                          headers={**headers, "x-stainless-retry-count": str(attempt)})
                    status, text = r.status_code, r.text
                except httpx.TransportError as e:
                    status, text = None, f"{type(e).__name__}: {e}"
                # Success is the turn landing on the trace; the reply is read from there.
                if status is not None and status < 400 and trace.num_turns > turns:
                    return ProgramResult(exit_code=0, stdout="", stderr="")
                problem = f"HTTP {status}: {_oneline(text)}" if status is not None else _oneline(text)
                # 4xx is final (bad request, rollout stopped or concluded); a 2xx that committed
                # nothing is a stream that broke after it started: retry that like a 5xx.
                if status is not None and 400 <= status < 500 and status != 429:
                    break
        return ProgramResult(exit_code=1, stdout="", stderr=f"POST {url}: {problem}")


def _oneline(text: str, limit: int = 300) -> str:
    text = " ".join(str(text).split())
    return text if len(text) <= limit else text[:limit] + "..."
