"""A held-out-seed evaluation job: every task on the same seeds, one durable record per episode.

Evaluation is paired: the seeds are ``heldout_seeds(episodes, seed_start)`` for every task and
every model, so two runs can be compared seed by seed. A job directory holds ``config.json``
(its settings), ``episodes.jsonl`` (one ``Trajectory.to_dict()`` line per finished episode,
fsync'd as it finishes) and ``summary.json`` / ``summary.txt``. Rerunning a job resumes it: the
(task, seed) pairs already in the log are skipped. Everything that can be refused (task IDs,
seed range, harness, the log, the config of an existing directory) is checked before the
backend is built, since building one can mean minutes of model loading.
"""

from __future__ import annotations

import json
import sys
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Annotated, Any, Callable, ClassVar

from pydantic import Field

from .._version import __version__
from ..agent.harness import HarnessConfig
from ..core.registry import get_spec
from ..core.seeding import HELDOUT_SEEDS, heldout_seeds
from ..rollout.trajectory import Trajectory
from ..rollout.backend import BackendError, PolicyBackend
from ..rollout.engine import EpisodeSpec, RolloutEngine
from ..rollout.factory import make_backend
from ..settings import Settings
from .store import EpisodeWriter, deferred_interrupt, move_aside_partial, scan, write_atomic
from .summary import format_summary, summarize

CONFIG, EPISODES, SUMMARY_JSON, SUMMARY_TXT = "config.json", "episodes.jsonl", "summary.json", "summary.txt"
# settings that change what the episodes are; a rerun into the same directory must match them
IDENTITY = ("backend", "model", "backend_options", "harness", "seed_start")
# where a model is served, not which model: a restarted server may come back on another port
UNTRACKED_OPTIONS = frozenset({"base_url"})


class EvalError(ValueError):
    """A job that cannot run as asked; the message is one line and nothing was modified."""


class EvalConfig(Settings):
    error: ClassVar[type[Exception]] = EvalError

    tasks: list[str]
    backend: str
    episodes: Annotated[int, Field(ge=1)]
    model: str | None = None
    seed_start: int = 0                   # offset into the held-out range
    max_episodes_at_once: Annotated[int, Field(ge=1)] = 64
    backend_options: dict[str, Any] = Field(default_factory=dict)   # only what the user set
    harness: dict[str, Any] = Field(default_factory=dict)           # HarnessConfig fields
    tokens: bool = False                  # keep token ids and log-probs in the records
    selection: str | None = None          # the task selection as typed, for the record
    #: who ran the job and why, for the record only (e.g. a training run's step); not a setting
    #: of the episodes, so never a reason to refuse a rerun
    context: dict[str, Any] = Field(default_factory=dict)

    def check(self) -> None:
        if not self.tasks:
            raise EvalError("no tasks selected")
        for task_id in self.tasks:
            get_spec(task_id)             # UnknownTaskError names the closest IDs
        self.seeds()
        self.harness_config()

    def seeds(self) -> list[int]:
        try:
            return heldout_seeds(self.episodes, self.seed_start)
        except ValueError:
            raise EvalError(f"--seed-start {self.seed_start} with {self.episodes} episodes leaves the "
                            f"held-out range ({len(HELDOUT_SEEDS):,} seeds)") from None

    def harness_config(self) -> HarnessConfig:
        try:
            return HarnessConfig(**self.harness)
        except ValueError as e:           # one line naming harness.<key>
            raise EvalError(str(e)) from None

    def plan(self) -> list[EpisodeSpec]:
        # seed-major order: an interrupted job has a few episodes of every task rather than all
        # episodes of the first tasks, so its partial summary already covers the whole task list
        return [EpisodeSpec(t, s) for s in self.seeds() for t in self.tasks]

    def to_json(self) -> dict[str, Any]:
        seeds = self.seeds()
        return {"backend": self.backend, "model": self.model, "backend_options": self.backend_options,
                "harness": self.harness_config().model_dump(), "tasks": self.tasks,
                "task_selection": self.selection, "episodes": self.episodes,
                "seed_start": self.seed_start,
                "seed_range": {"first": seeds[0], "last": seeds[-1], "count": len(seeds)},
                "max_episodes_at_once": self.max_episodes_at_once, "tokens": self.tokens,
                **({"context": self.context} if self.context else {}),
                "glyphbench_rl": __version__}


def config_mismatch(old: dict[str, Any], new: dict[str, Any]) -> str | None:
    """What differs between two configs in the settings that define the episodes, else None."""
    diffs = []
    for key in IDENTITY:
        a, b = old.get(key), new.get(key)
        if key == "backend_options":
            a = {k: v for k, v in (a or {}).items() if k not in UNTRACKED_OPTIONS}
            b = {k: v for k, v in (b or {}).items() if k not in UNTRACKED_OPTIONS}
        elif key == "harness" and isinstance(a, dict) and isinstance(b, dict):
            # a field added to HarnessConfig after the job started is not a difference
            common = a.keys() & b.keys()
            a, b = {k: a[k] for k in common}, {k: b[k] for k in common}
        if a == b:
            continue
        if isinstance(a, dict) and isinstance(b, dict):   # name the fields, not whole dicts
            diffs += [f"{key}.{k} was {json.dumps(a.get(k))}, now {json.dumps(b.get(k))}"
                      for k in sorted(a.keys() | b.keys()) if a.get(k) != b.get(k)]
        else:
            diffs.append(f"{key} was {json.dumps(a)}, now {json.dumps(b)}")
    # any other episode count is refused too: fewer would leave records the new config and
    # summary do not account for, and more is a different job (--force-config extends one: its
    # held-out seeds are the first seeds of the longer job, so finished pairs are kept)
    a, b = old.get("episodes"), new.get("episodes")
    if a != b:
        diffs.append(f"episodes was {json.dumps(a)}, now {json.dumps(b)}")
    return "; ".join(diffs) or None


def read_config(out: Path) -> dict[str, Any] | None:
    path = out / CONFIG
    if not path.exists():
        return None
    try:
        cfg = json.loads(path.read_text(encoding="utf-8"))
    except ValueError as e:
        raise EvalError(f"{path}: not valid JSON ({e})") from None
    if not isinstance(cfg, dict):
        raise EvalError(f"{path}: expected a JSON object")
    return cfg


def planned_pairs(cfg: dict[str, Any] | None) -> set[tuple[str, int]] | None:
    if not cfg or "tasks" not in cfg or "episodes" not in cfg:
        return None
    seeds = heldout_seeds(int(cfg["episodes"]), int(cfg.get("seed_start", 0)))
    return {(t, s) for t in cfg["tasks"] for s in seeds}


def write_summary(out: Path, records: list[dict[str, Any]], cfg: dict[str, Any] | None) -> dict[str, Any]:
    plan = planned_pairs(cfg)
    have = {(r["task_id"], r["seed"]) for r in records}
    summary = summarize(records, order=(cfg or {}).get("tasks"), config=cfg,
                        planned=None if plan is None else len(plan),
                        missing=None if plan is None else len(plan - have))
    write_atomic(out / SUMMARY_JSON, json.dumps(summary, indent=1, ensure_ascii=False) + "\n")
    write_atomic(out / SUMMARY_TXT, format_summary(summary, title(cfg)))
    return summary


def title(cfg: dict[str, Any] | None) -> str | None:
    if not cfg:
        return None
    h = cfg.get("harness") or {}
    opts = ", ".join(f"{k}={v}" for k, v in (cfg.get("backend_options") or {}).items())
    rng = cfg.get("seed_range") or {}
    seeds = [f"{s:,}" if isinstance(s, int) else "?" for s in (rng.get("first"), rng.get("last"))]
    return (f"glyphbench-eval: backend {cfg.get('backend')}, model {cfg.get('model') or '-'}"
            + (f" ({opts})" if opts else "")
            + f"; harness history {h.get('history')}, legend {h.get('legend')}"
            + f"; held-out seeds {seeds[0]}..{seeds[-1]} for every task")


@dataclass
class JobResult:
    out: Path
    saved: int                # episodes in the log now
    new: int                  # episodes this run finished
    planned: int              # (task, seed) pairs of this job
    missing: int              # of those, how many have no record yet
    summary: dict[str, Any]
    interrupted: bool = False  # KeyboardInterrupt: what was written stays; rerun resumes
    error: str | None = None   # a BackendError stopped the run; rerun resumes


def _stderr(msg: str) -> None:
    print(msg, file=sys.stderr, flush=True)


def run_job(config: EvalConfig, out: str | Path, *, backend: PolicyBackend | None = None,
            backend_factory: Callable[..., PolicyBackend] | None = None, force_config: bool = False,
            log: Callable[[str], None] | None = _stderr, verbose: bool = False,
            progress_every: float = 15.0) -> JobResult:
    out = Path(out)
    say = log or (lambda msg: None)
    log_path = out / EPISODES
    existing = scan(log_path)                 # a corrupt middle line raises here, untouched
    new_cfg = config.to_json()
    old_cfg = read_config(out)
    if old_cfg is not None and not force_config:
        diff = config_mismatch(old_cfg, new_cfg)
        if diff:
            raise EvalError(f"{out} holds another evaluation ({diff}); use a new --out, or "
                            f"--force-config to add to it anyway")
    done = existing.pairs()
    todo = [spec for spec in config.plan() if (spec.task_id, spec.seed) not in done]
    if existing.records:
        say(f"resuming {out}: {len(existing.records)} episodes already saved, {len(todo)} to run")
    if existing.duplicates:
        say(f"{log_path}: {existing.duplicates} duplicate (task, seed) records; the first of each counts")
    built = todo and backend is None
    if built:                                 # built last: it may load a model for minutes
        try:
            backend = (backend_factory or make_backend)(config.backend, config.model,
                                                        **config.backend_options)
        except TypeError as e:                # an option this backend does not take
            raise EvalError(f"backend {config.backend!r}: {e}") from None
    out.mkdir(parents=True, exist_ok=True)
    if existing.partial is not None:
        aside = move_aside_partial(log_path, existing.partial)
        say(f"{log_path}: line {existing.partial.line} was cut short by an earlier stop; "
            f"moved it to {aside.name} and continuing")
    new_cfg["created"] = (old_cfg or {}).get("created") or time.strftime("%Y-%m-%dT%H:%M:%S%z")
    write_atomic(out / CONFIG, json.dumps(new_cfg, indent=1) + "\n")

    records = list(existing.records)
    state = {"new": 0, "last": time.monotonic()}
    t0 = time.monotonic()
    interrupted, error = False, None

    def on_episode(traj: Trajectory) -> None:
        with deferred_interrupt():            # on disk and counted, or neither
            writer.append(traj)
            records.append(traj.summary())
        state["new"] += 1
        now = time.monotonic()
        if verbose:
            say(f"  {traj.task_id} seed {traj.seed}: return {traj.episode_return:+.3f}")
        elif now - state["last"] >= progress_every:
            state["last"] = now
            say(f"  {state['new']}/{len(todo)} episodes ({state['new'] / (now - t0):.2f}/s)")

    try:
        if todo:
            engine = RolloutEngine(backend, config.harness_config(),
                                   max_episodes=config.max_episodes_at_once,
                                   meta={"model": config.model, "split": "heldout"})
            with EpisodeWriter(log_path, tokens=config.tokens,
                               needs_newline=existing.needs_newline) as writer:
                engine.run(todo, on_episode, keep=False)
    except KeyboardInterrupt:
        interrupted = True
    except BackendError as e:
        error = str(e).splitlines()[0] if str(e) else type(e).__name__
    finally:                                  # also when a bug stops the run: summarize what exists
        summary = write_summary(out, records, new_cfg)
        if built and callable(getattr(backend, "close", None)):
            backend.close()                   # servers, client pools: ours to release
    planned = len(config.tasks) * config.episodes
    missing = len({(s.task_id, s.seed) for s in config.plan()} - {(r["task_id"], r["seed"]) for r in records})
    return JobResult(out, len(records), state["new"], planned, missing, summary, interrupted, error)


def rebuild_summary(out: str | Path, log: Callable[[str], None] | None = _stderr) -> tuple[dict, str]:
    """Summary files from ``episodes.jsonl`` alone (read-only on the log); returns (json, text)."""
    out = Path(out)
    if not (out / EPISODES).exists():
        raise EvalError(f"{out / EPISODES} does not exist")
    existing = scan(out / EPISODES)
    if existing.partial is not None and log:
        log(f"{out / EPISODES}: line {existing.partial.line} is cut short and was left out "
            f"(the next run of the job moves it aside)")
    cfg = read_config(out)
    summary = write_summary(out, existing.records, cfg)
    return summary, (out / SUMMARY_TXT).read_text(encoding="utf-8")
