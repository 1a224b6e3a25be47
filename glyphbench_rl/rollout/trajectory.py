"""The trajectory record: what one episode did, turn by turn.

Every layer may import this module (it depends on nothing else in the package). One schema
serves the rollout engine (in memory, with token ids for training), evaluation jobs
(one JSON line per episode) and the replay viewers. ``Step.observation`` is what the model saw
before it answered; the observation after the last step is ``Trajectory.final_observation``.
Token ids and log-probs stay in memory only unless ``to_dict(tokens=True)`` asks for them.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field, fields
from typing import Any, Iterator

SCHEMA_VERSION = 1


class TrajectoryFormatError(ValueError):
    """A trajectory record that cannot be read; the message names the file, line and field."""


@dataclass
class Step:
    turn: int                        # 1-based turn number this step produced
    observation: str                 # the observation the model answered (as sent)
    reply: str                       # the full reply, reasoning included
    action: str | None               # canonical action name, None on forfeit
    forfeit_reason: str | None       # why the reply was not a valid action
    reward: float
    terminated: bool = False
    truncated: bool = False
    prompt_tokens: int = 0
    completion_tokens: int = 0
    finish_reason: str | None = None  # "stop" or "length" from the backend
    memory: str | None = None         # harness memory at this step, when the harness keeps one
    # training data (token backends): exact ids the policy saw and sampled, with log-probs
    prompt_ids: list[int] | None = field(default=None, repr=False)
    completion_ids: list[int] | None = field(default=None, repr=False)
    logprobs: list[float] | None = field(default=None, repr=False)

    _TOKEN_FIELDS = ("prompt_ids", "completion_ids", "logprobs")


@dataclass
class Trajectory:
    task_id: str
    seed: int
    system_prompt: str = ""
    steps: list[Step] = field(default_factory=list)
    initial_observation: str = ""
    final_observation: str = ""
    episode_return: float = 0.0
    terminated: bool = False
    truncated: bool = False
    won: bool | None = None
    context_drops: int = 0
    meta: dict[str, Any] = field(default_factory=dict)   # model, backend, harness, run ids
    group: int | None = None     # the rollout group this episode belongs to (training), if any

    @property
    def length(self) -> int:
        return len(self.steps)

    @property
    def forfeits(self) -> int:
        return sum(s.action is None for s in self.steps)

    @property
    def prompt_tokens(self) -> int:
        return sum(s.prompt_tokens for s in self.steps)

    @property
    def completion_tokens(self) -> int:
        return sum(s.completion_tokens for s in self.steps)

    def summary(self) -> dict[str, Any]:
        """The scalar fields of an episode record (no turn-by-turn data)."""
        return {"task_id": self.task_id, "seed": self.seed, "return": self.episode_return,
                "length": self.length, "terminated": self.terminated, "truncated": self.truncated,
                "won": self.won, "forfeits": self.forfeits, "prompt_tokens": self.prompt_tokens,
                "completion_tokens": self.completion_tokens, "context_drops": self.context_drops}

    def to_dict(self, *, tokens: bool = False) -> dict[str, Any]:
        steps = []
        for s in self.steps:
            d = {f.name: getattr(s, f.name) for f in fields(Step)}
            if not tokens:
                for k in Step._TOKEN_FIELDS:
                    d.pop(k)
            steps.append(d)
        out = {"schema": SCHEMA_VERSION, **self.summary(), "system_prompt": self.system_prompt,
               "initial_observation": self.initial_observation,
               "final_observation": self.final_observation, "meta": self.meta, "group": self.group,
               "steps": steps}
        return out

    @classmethod
    def from_dict(cls, d: Any, where: str = "record") -> "Trajectory":
        if not isinstance(d, dict):
            raise TrajectoryFormatError(f"{where}: expected a JSON object, got {type(d).__name__}")
        version = d.get("schema")
        if version != SCHEMA_VERSION:
            raise TrajectoryFormatError(f"{where}: unsupported schema version {version!r} "
                                        f"(this glyphbench_rl reads {SCHEMA_VERSION})")
        try:
            steps = [_step(s, f"{where}: step {i + 1}") for i, s in enumerate(d.get("steps", []))]
            return cls(task_id=_req(d, "task_id", str, where), seed=_req(d, "seed", int, where),
                       system_prompt=d.get("system_prompt", ""), steps=steps,
                       initial_observation=d.get("initial_observation", ""),
                       final_observation=d.get("final_observation", ""),
                       episode_return=float(_req(d, "return", (int, float), where)),
                       terminated=bool(d.get("terminated", False)),
                       truncated=bool(d.get("truncated", False)), won=d.get("won"),
                       context_drops=int(d.get("context_drops", 0)), meta=dict(d.get("meta") or {}),
                       group=_opt(d, "group", int, where))
        except TrajectoryFormatError:
            raise
        except (TypeError, ValueError, AttributeError) as e:
            raise TrajectoryFormatError(f"{where}: {e}") from None


def _req(d: dict, key: str, kind, where: str):
    if key not in d:
        raise TrajectoryFormatError(f"{where}: missing field {key!r}")
    value = d[key]
    if isinstance(value, bool) or not isinstance(value, kind):
        raise TrajectoryFormatError(f"{where}: field {key!r} has the wrong type ({type(value).__name__})")
    return value


def _opt(d: dict, key: str, kind, where: str):
    value = d.get(key)
    return None if value is None else _req(d, key, kind, where)


_STEP_FIELDS = {f.name for f in fields(Step)}


def _step(s: Any, where: str) -> Step:
    if not isinstance(s, dict):
        raise TrajectoryFormatError(f"{where}: expected a JSON object")
    unknown = set(s) - _STEP_FIELDS
    if unknown:
        raise TrajectoryFormatError(f"{where}: unknown field {sorted(unknown)[0]!r}")
    for key in ("turn", "observation", "reply", "reward"):
        if key not in s:
            raise TrajectoryFormatError(f"{where}: missing field {key!r}")
    step = Step(**{"action": None, "forfeit_reason": None, **s})
    # the fields every reader computes with or draws
    if not (isinstance(step.observation, str) and isinstance(step.reply, str)
            and isinstance(step.reward, (int, float)) and not isinstance(step.reward, bool)
            and isinstance(step.action, (str, type(None))) and isinstance(step.memory, (str, type(None)))):
        raise TrajectoryFormatError(f"{where}: a field has the wrong type")
    return step


def parse_record(line: str | bytes, where: str) -> Trajectory:
    """One JSONL line as a Trajectory; any problem is a one-line TrajectoryFormatError at ``where``."""
    return Trajectory.from_dict(decode_record(line, where), where)


def decode_record(line: str | bytes, where: str) -> Any:
    """The JSON value of one line (UTF-8 when given bytes), or a one-line TrajectoryFormatError."""
    if isinstance(line, bytes):
        try:
            line = line.decode("utf-8")
        except UnicodeDecodeError as e:
            raise TrajectoryFormatError(f"{where}: not UTF-8 text (byte {e.start + 1})") from None
    try:
        return json.loads(line)
    except json.JSONDecodeError as e:
        raise TrajectoryFormatError(f"{where}: not valid JSON ({e.msg} at column {e.colno})") from None


def read_jsonl(path, *, strict: bool = True) -> Iterator[Trajectory]:
    """Trajectories from a JSONL file, one per line.

    A line that is not valid JSON raises a one-line error naming the file and line, except a
    final line with no newline (a write cut short by a crash), which ``strict=False`` skips.
    """
    with open(path, encoding="utf-8") as fh:
        lines = fh.readlines()
    for n, line in enumerate(lines, 1):
        if not line.strip():
            continue
        where = f"{path}:{n}"
        try:
            record = decode_record(line, where)
        except TrajectoryFormatError:
            if not strict and n == len(lines) and not line.endswith("\n"):
                return
            raise
        yield Trajectory.from_dict(record, where)
