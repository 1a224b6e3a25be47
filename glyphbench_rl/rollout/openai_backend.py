"""OpenAIBackend: any OpenAI-compatible ``/chat/completions`` endpoint as a text policy.

Stdlib only (urllib + a thread pool), so the core package needs no HTTP client. Every request
of a ``generate`` call is posted concurrently (at most ``max_concurrency`` at once); transient
failures (timeouts, dropped connections, 429, 5xx, a garbled 200) are retried with exponential
backoff and jitter; anything else, or running out of retries, raises ``BackendError`` with one
line naming the endpoint and the status. The API key is read from an environment variable at
construction, sent only as a Bearer header and scrubbed from every message this module writes.
"""

from __future__ import annotations

import http.client
import json
import logging
import os
import random
import socket
import threading
import time
import urllib.error
import urllib.parse
import urllib.request
from concurrent.futures import FIRST_EXCEPTION, ThreadPoolExecutor, wait
from typing import Any, Mapping, Sequence

from .backend import BackendError, GenRequest, Generation

DEFAULT_BASE_URL = "https://api.openai.com/v1"
log = logging.getLogger(__name__)


def reply_text(message: Mapping[str, Any] | None) -> str:
    """A chat message as the parser reads it: reasoning a server returns in a separate field
    goes first, wrapped in <think>...</think>, so "the action after the last </think> wins"
    ignores tags the model only considered."""
    message = message or {}
    content = message.get("content")
    content = content if isinstance(content, str) else ""
    # vLLM/SGLang/DeepSeek name the field reasoning_content; newer vLLM and OpenRouter reasoning
    reasoning = message.get("reasoning_content") or message.get("reasoning")
    if isinstance(reasoning, str) and reasoning:
        return f"<think>{reasoning}</think>{content}"
    return content


def _public_url(url: str) -> str:
    """``url`` without user:password@ (credentials never reach a message)."""
    p = urllib.parse.urlsplit(url)
    host = p.hostname or ""
    netloc = f"[{host}]" if ":" in host else host
    if p.port:
        netloc += f":{p.port}"
    return urllib.parse.urlunsplit((p.scheme, netloc, p.path, "", ""))


class _Retryable(Exception):
    def __init__(self, status: str, retry_after: float | None = None) -> None:
        super().__init__(status)
        self.status = status
        self.retry_after = retry_after


class OpenAIBackend:
    name = "openai"
    tokenizer = None          # a text backend: the engine sends messages, never token ids

    def __init__(self, model: str, *, base_url: str | None = None,
                 api_key_env: str = "OPENAI_API_KEY", max_concurrency: int = 8,
                 timeout_s: float = 120, max_retries: int = 4, backoff_s: float = 1.0,
                 temperature: float = 1.0, top_p: float = 1.0, max_tokens: int | None = 4096,
                 extra_body: dict | None = None) -> None:
        if not isinstance(model, str) or not model:
            raise ValueError("openai backend: model must be a non-empty string")
        if isinstance(max_concurrency, bool) or not isinstance(max_concurrency, int) or max_concurrency < 1:
            raise ValueError(f"openai backend: max_concurrency must be an int >= 1, got {max_concurrency!r}")
        if isinstance(max_retries, bool) or not isinstance(max_retries, int) or max_retries < 0:
            raise ValueError(f"openai backend: max_retries must be an int >= 0, got {max_retries!r}")
        if not timeout_s > 0 or backoff_s < 0:
            raise ValueError(f"openai backend: timeout_s must be > 0 and backoff_s >= 0, "
                             f"got {timeout_s!r}, {backoff_s!r}")
        base_url = (base_url or os.environ.get("OPENAI_BASE_URL") or DEFAULT_BASE_URL).rstrip("/")
        if urllib.parse.urlsplit(base_url).scheme not in ("http", "https"):
            raise ValueError(f"openai backend: base_url must be an http(s) URL, got {_public_url(base_url)!r}")
        self.model = model
        self.url = base_url + "/chat/completions"
        self.endpoint = _public_url(self.url)
        self._key = os.environ.get(api_key_env) or None   # None: a local server without auth
        self.max_concurrency = max_concurrency
        self.timeout_s = float(timeout_s)
        self.max_retries = max_retries
        self.backoff_s = float(backoff_s)
        self.body: dict[str, Any] = {"model": model, "temperature": temperature, "top_p": top_p}
        if max_tokens is not None:
            self.body["max_tokens"] = max_tokens
        self.body.update(extra_body or {})
        self._pool: ThreadPoolExecutor | None = None
        self._lock = threading.Lock()

    def __repr__(self) -> str:    # never the key
        return f"OpenAIBackend(model={self.model!r}, endpoint={self.endpoint!r})"

    # -- PolicyBackend ------------------------------------------------------------------------------
    def generate(self, requests: Sequence[GenRequest]) -> list[Generation]:
        if not requests:
            return []
        if len(requests) == 1:     # no thread hop for the common single-episode case
            return [self._complete(requests[0].messages)]
        with self._lock:
            if self._pool is None:
                self._pool = ThreadPoolExecutor(self.max_concurrency, thread_name_prefix="openai-backend")
        futures = [self._pool.submit(self._complete, r.messages) for r in requests]
        done, pending = wait(futures, return_when=FIRST_EXCEPTION)
        for f in pending:          # a failure stops the run: do not start what is still queued
            f.cancel()
        for f in futures:
            if f.done() and not f.cancelled() and f.exception() is not None:
                raise f.exception()
        return [f.result() for f in futures]

    def close(self) -> None:
        if self._pool is not None:
            self._pool.shutdown(wait=False, cancel_futures=True)
            self._pool = None

    # -- one request --------------------------------------------------------------------------------
    def _complete(self, messages: list[dict[str, str]]) -> Generation:
        payload = json.dumps({**self.body, "messages": messages}).encode()
        for attempt in range(self.max_retries + 1):
            try:
                return self._post(payload)
            except _Retryable as e:
                if attempt == self.max_retries:
                    raise BackendError(self._scrub(
                        f"openai backend: POST {self.endpoint} failed after {attempt + 1} "
                        f"attempts: {e.status}")) from None
                # exponential backoff with full-range jitter, so parallel requests spread out
                delay = self.backoff_s * 2 ** attempt * (0.5 + random.random())
                if e.retry_after is not None:
                    delay = max(delay, min(e.retry_after, 60.0))
                log.warning(self._scrub(f"POST {self.endpoint}: {e.status}; retry "
                                        f"{attempt + 1}/{self.max_retries} in {delay:.1f}s"))
                time.sleep(delay)
        raise AssertionError("unreachable")

    def _post(self, payload: bytes) -> Generation:
        headers = {"Content-Type": "application/json", "Accept": "application/json"}
        if self._key:
            headers["Authorization"] = f"Bearer {self._key}"
        req = urllib.request.Request(self.url, data=payload, headers=headers, method="POST")
        try:
            with urllib.request.urlopen(req, timeout=self.timeout_s) as resp:
                raw = resp.read()
        except urllib.error.HTTPError as e:
            detail = _detail(e)
            status = f"HTTP {e.code}" + (f" ({detail})" if detail else "")
            if e.code == 429 or e.code >= 500:
                raise _Retryable(status, _retry_after(e.headers)) from None
            raise BackendError(self._scrub(f"openai backend: POST {self.endpoint} failed: {status}")) from None
        except (TimeoutError, socket.timeout):
            raise _Retryable(f"timed out after {self.timeout_s:g}s") from None
        except urllib.error.URLError as e:
            if isinstance(e.reason, (TimeoutError, socket.timeout)):
                raise _Retryable(f"timed out after {self.timeout_s:g}s") from None
            raise _Retryable(f"connection failed ({_oneline(str(e.reason))})") from None
        except (ConnectionError, http.client.HTTPException, OSError) as e:
            raise _Retryable(f"connection failed ({type(e).__name__}: {_oneline(str(e))})") from None
        try:
            data = json.loads(raw)
            choice = data["choices"][0]
            message = choice["message"]
        except (ValueError, KeyError, IndexError, TypeError):
            raise _Retryable(f"malformed response ({_oneline(raw[:120].decode('utf-8', 'replace'))})") from None
        usage = data.get("usage") or {}
        return Generation(reply_text(message), finish_reason=choice.get("finish_reason") or "stop",
                          prompt_tokens=int(usage.get("prompt_tokens") or 0),
                          completion_tokens=int(usage.get("completion_tokens") or 0))

    def _scrub(self, text: str) -> str:
        """Belt and braces: a server may echo the key back in an error body."""
        return text.replace(self._key, "***") if self._key else text


def _oneline(text: str, limit: int = 200) -> str:
    text = " ".join(text.split())
    return text if len(text) <= limit else text[:limit] + "..."


def _detail(e: urllib.error.HTTPError) -> str:
    """The error message of an OpenAI-style error body (or its first bytes)."""
    try:
        body = e.read(4096).decode("utf-8", "replace")
    except Exception:
        return ""
    try:
        err = json.loads(body).get("error")
        if isinstance(err, dict) and err.get("message"):
            return _oneline(str(err["message"]))
        if isinstance(err, str):
            return _oneline(err)
    except (ValueError, AttributeError):
        pass
    return _oneline(body)


def _retry_after(headers) -> float | None:
    try:
        return float(headers.get("Retry-After"))
    except (TypeError, ValueError):
        return None
