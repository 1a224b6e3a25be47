"""A scripted OpenAI-compatible chat-completions server for tests (loopback only).

    with StubOpenAI(reply=lambda body: "<action>UP</action>") as stub:
        backend = OpenAIBackend("stub", base_url=stub.base_url)

``reply(body)`` decides each answer from the request body: a string (the content), or a dict
with ``content`` / ``reasoning_content`` / ``finish_reason``. ``fail_times`` answers the first N
chat requests with ``fail_status`` (``fail_message`` may echo the auth header, to test that
clients scrub it); ``delay_s`` sleeps before the first ``delay_times`` answers (all when None)
to provoke client timeouts. Streaming requests (``"stream": true``) get SSE
``data:`` chunks ending in ``data: [DONE]``. ``requests`` records path, headers and body of
every request; ``max_in_flight`` is the highest number of chat requests served at once.
"""

from __future__ import annotations

import json
import threading
import time
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from typing import Any, Callable

MAX_BODY = 8 << 20          # bounded: refuse request bodies above 8 MiB
MAX_RECORDED = 10_000       # bounded: keep at most this many request records
MAX_DELAY_S = 30.0


class StubOpenAI:
    def __init__(self, reply: Callable[[dict], str | dict] | None = None, *, model: str = "stub-model",
                 fail_times: int = 0, fail_status: int = 500, delay_s: float = 0.0,
                 delay_times: int | None = None, chunk_chars: int = 7,
                 fail_message: str = "scripted failure {status}") -> None:
        self.reply = reply or (lambda body: "<action>UP</action>")
        self.model = model
        self.fail_times = fail_times
        self.fail_status = fail_status
        self.fail_message = fail_message     # may name {status} and {auth} (echo the auth header)
        self.delay_s = min(float(delay_s), MAX_DELAY_S)
        self.delay_times = delay_times
        self.chunk_chars = max(1, chunk_chars)
        self.requests: list[dict[str, Any]] = []
        self.chat_calls = 0
        self.in_flight = 0
        self.max_in_flight = 0
        self._lock = threading.Lock()
        self._closing = threading.Event()
        self._server: ThreadingHTTPServer | None = None
        self._thread: threading.Thread | None = None

    # -- lifecycle -------------------------------------------------------------------------------
    def __enter__(self) -> "StubOpenAI":
        stub = self

        class Handler(_Handler):
            server_stub = stub

        self._server = ThreadingHTTPServer(("127.0.0.1", 0), Handler)   # port 0: a free port
        self._server.daemon_threads = True
        self._server.block_on_close = False     # never wait on a handler sleeping for a timeout
        self._thread = threading.Thread(target=self._server.serve_forever, kwargs={"poll_interval": 0.05},
                                        name="stub-openai", daemon=True)
        self._thread.start()
        return self

    def __exit__(self, *exc) -> None:
        self._closing.set()                     # wakes handlers sleeping in a delay
        assert self._server is not None and self._thread is not None
        self._server.shutdown()
        self._server.server_close()
        self._thread.join(timeout=5)

    @property
    def port(self) -> int:
        assert self._server is not None, "use StubOpenAI as a context manager"
        return self._server.server_address[1]

    @property
    def base_url(self) -> str:
        return f"http://127.0.0.1:{self.port}/v1"

    def chat_bodies(self) -> list[dict]:
        with self._lock:
            return [r["body"] for r in self.requests if r["path"].endswith("/chat/completions")]

    # -- behaviour ---------------------------------------------------------------------------------
    def _plan(self) -> tuple[int | None, float]:
        """(error status or None, delay) for the next chat request, in arrival order."""
        with self._lock:
            n = self.chat_calls
            self.chat_calls += 1
        status = self.fail_status if n < self.fail_times else None
        delay = self.delay_s if self.delay_times is None or n < self.delay_times else 0.0
        return status, delay

    def _answer(self, body: dict) -> dict:
        out = self.reply(body)
        out = {"content": out} if isinstance(out, str) else dict(out)
        out.setdefault("finish_reason", "stop")
        return out


class _Handler(BaseHTTPRequestHandler):
    server_stub: StubOpenAI
    protocol_version = "HTTP/1.1"

    def log_message(self, *args) -> None:      # keep test output quiet
        pass

    def _record(self, body: Any) -> None:
        stub = self.server_stub
        with stub._lock:
            if len(stub.requests) < MAX_RECORDED:
                stub.requests.append({"method": self.command, "path": self.path,
                                      "headers": dict(self.headers.items()), "body": body})

    def _json(self, status: int, obj: dict) -> None:
        data = json.dumps(obj).encode()
        self.send_response(status)
        self.send_header("Content-Type", "application/json")
        self.send_header("Content-Length", str(len(data)))
        self.end_headers()
        self.wfile.write(data)

    def do_GET(self) -> None:
        self._record(None)
        if self.path.rstrip("/") in ("/v1/models", "/models"):
            self._json(200, {"object": "list", "data": [{"id": self.server_stub.model, "object": "model",
                                                          "created": 0, "owned_by": "stub"}]})
        else:
            self._json(404, {"error": {"message": f"no route {self.path}", "type": "not_found"}})

    def do_POST(self) -> None:
        stub = self.server_stub
        length = int(self.headers.get("Content-Length") or 0)
        if length > MAX_BODY:
            self.close_connection = True
            return self._json(413, {"error": {"message": "request body too large"}})
        try:
            body = json.loads(self.rfile.read(length) or b"{}")
        except ValueError:
            return self._json(400, {"error": {"message": "body is not JSON"}})
        self._record(body)
        if not self.path.rstrip("/").endswith("/chat/completions"):
            return self._json(404, {"error": {"message": f"no route {self.path}", "type": "not_found"}})
        with stub._lock:
            stub.in_flight += 1
            stub.max_in_flight = max(stub.max_in_flight, stub.in_flight)
        try:
            status, delay = stub._plan()
            if delay and stub._closing.wait(delay):
                return
            if status is not None:
                message = stub.fail_message.format(status=status, auth=self.headers.get("Authorization", ""))
                return self._json(status, {"error": {"message": message, "type": "server_error"}})
            answer = stub._answer(body)
            if body.get("stream"):
                self._stream(body, answer)
            else:
                self._json(200, self._completion(body, answer))
        except (BrokenPipeError, ConnectionResetError):
            pass                                  # the client gave up (a timeout test)
        finally:
            with stub._lock:
                stub.in_flight -= 1

    # -- response shapes ---------------------------------------------------------------------------
    @staticmethod
    def _usage(body: dict, answer: dict) -> dict:
        prompt = sum(len(str(m.get("content") or "")) for m in body.get("messages", [])) // 4 + 1
        completion = (len(answer.get("content") or "") + len(answer.get("reasoning_content") or "")) // 4 + 1
        return {"prompt_tokens": prompt, "completion_tokens": completion, "total_tokens": prompt + completion}

    def _completion(self, body: dict, answer: dict) -> dict:
        message = {"role": "assistant", "content": answer.get("content")}
        if answer.get("reasoning_content"):
            message["reasoning_content"] = answer["reasoning_content"]
        return {"id": "chatcmpl-stub", "object": "chat.completion", "created": int(time.time()),
                "model": body.get("model") or self.server_stub.model,
                "choices": [{"index": 0, "message": message, "finish_reason": answer["finish_reason"]}],
                "usage": self._usage(body, answer)}

    def _stream(self, body: dict, answer: dict) -> None:
        self.send_response(200)
        self.send_header("Content-Type", "text/event-stream")
        self.send_header("Cache-Control", "no-cache")
        self.send_header("Connection", "close")   # no length: the stream ends with the connection
        self.end_headers()
        self.close_connection = True
        base = {"id": "chatcmpl-stub", "object": "chat.completion.chunk", "created": int(time.time()),
                "model": body.get("model") or self.server_stub.model}

        def chunk(delta: dict, finish: str | None = None, **extra) -> None:
            obj = {**base, "choices": [{"index": 0, "delta": delta, "finish_reason": finish}], **extra}
            self.wfile.write(b"data: " + json.dumps(obj).encode() + b"\n\n")
            self.wfile.flush()

        n = self.server_stub.chunk_chars
        chunk({"role": "assistant", "content": ""})
        for key in ("reasoning_content", "content"):
            text = answer.get(key) or ""
            for i in range(0, len(text), n):
                chunk({key: text[i:i + n]})
        chunk({}, answer["finish_reason"])
        if (body.get("stream_options") or {}).get("include_usage"):
            obj = {**base, "choices": [], "usage": self._usage(body, answer)}
            self.wfile.write(b"data: " + json.dumps(obj).encode() + b"\n\n")
        self.wfile.write(b"data: [DONE]\n\n")
        self.wfile.flush()
