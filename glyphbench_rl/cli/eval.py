"""``glyphbench-eval``: held-out-seed evaluation jobs, their summaries and paired comparisons.

    glyphbench-eval --tasks TASKS --backend NAME [--model M] --episodes N --out DIR [options]
    glyphbench-eval summary DIR                  rebuild DIR's summary from episodes.jsonl
    glyphbench-eval compare DIR_A DIR_B [--json F]   paired per-task differences, B - A

Every task is played on the same held-out seeds (1,000,000 + seed-start, ...), for every model,
so any two jobs compare seed by seed. Rerunning a job with the same --out resumes it.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path
from typing import Any, Sequence

from ..core.registry import MissingExtraError, UnknownTaskError, check_engines
from ..core.tasklist import resolve_tasks
from ..rollout.factory import BACKENDS
from ..evaluate import job as job_mod
from ..evaluate.compare import compare_records, format_comparison
from ..evaluate.store import EpisodeLogError, scan

PROG = "glyphbench-eval"
EXIT_USAGE, EXIT_BACKEND, EXIT_INTERRUPTED = 2, 1, 130


def _option(text: str) -> tuple[str, Any]:
    key, sep, value = text.partition("=")
    if not sep or not key:
        raise argparse.ArgumentTypeError(f"expected KEY=VALUE, got {text!r}")
    try:
        return key, json.loads(value)   # numbers, true/false, null; anything else stays a string
    except ValueError:
        return key, value


def run_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog=PROG, description=__doc__.replace("``", ""),
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--tasks", required=True, help="task ID, glob, comma list or task-list file")
    p.add_argument("--backend", required=True, help=f"one of: {', '.join(BACKENDS)}")
    p.add_argument("--model", help="model name or path (backends that need one)")
    p.add_argument("--episodes", type=int, required=True, help="held-out episodes per task")
    p.add_argument("--out", required=True, help="job directory (rerun the same to resume)")
    p.add_argument("--seed-start", type=int, default=0,
                   help="offset into the held-out seeds: the first seed is 1,000,000 + this")
    p.add_argument("--max-episodes-at-once", type=int, default=64,
                   help="episodes played concurrently (one batched backend call per turn)")
    g = p.add_argument_group("generation (passed to the backend only when given)")
    g.add_argument("--temperature", type=float)
    g.add_argument("--top-p", type=float)
    g.add_argument("--max-new-tokens", type=int)
    g.add_argument("--base-url", help="endpoint of an OpenAI-compatible server")
    g.add_argument("-o", "--option", action="append", type=_option, default=[], metavar="KEY=VALUE",
                   help="any other backend keyword argument (value parsed as JSON if it can be)")
    h = p.add_argument_group("harness")
    h.add_argument("--history", type=int, help="past observation/reply pairs per prompt (default 8)")
    h.add_argument("--legend", choices=["always", "changed"])
    h.add_argument("--max-context-tokens", type=int)
    p.add_argument("--tokens", action="store_true", help="keep token ids and log-probs in the records")
    p.add_argument("--force-config", action="store_true",
                   help="add to a directory that holds a job with other settings")
    p.add_argument("-v", "--verbose", action="store_true", help="one line per finished episode")
    p.add_argument("-q", "--quiet", action="store_true", help="no progress lines, no table")
    return p


def _set(args: argparse.Namespace, names: dict[str, str]) -> dict[str, Any]:
    """Only what the user gave, so each backend/harness keeps its own defaults for the rest."""
    return {key: getattr(args, attr) for attr, key in names.items() if getattr(args, attr) is not None}


def cmd_run(argv: Sequence[str]) -> int:
    args = run_parser().parse_args(argv)
    if args.backend not in BACKENDS:
        raise job_mod.EvalError(f"unknown backend {args.backend!r}; backends: {', '.join(BACKENDS)}")
    tasks = resolve_tasks(args.tasks)         # before any backend or model is built
    check_engines(tasks)
    options = _set(args, {"temperature": "temperature", "top_p": "top_p",
                          "max_new_tokens": "max_new_tokens", "base_url": "base_url"})
    options.update(dict(args.option))
    config = job_mod.EvalConfig(
        tasks=tasks, backend=args.backend, model=args.model, episodes=args.episodes,
        seed_start=args.seed_start, max_episodes_at_once=args.max_episodes_at_once,
        backend_options=options, tokens=args.tokens, selection=args.tasks,
        harness=_set(args, {"history": "history", "legend": "legend",
                            "max_context_tokens": "max_context_tokens"}))
    log = None if args.quiet else job_mod._stderr
    result = job_mod.run_job(config, args.out, force_config=args.force_config, log=log,
                             verbose=args.verbose, backend_factory=_factory())
    saved = f"{result.saved} episodes saved in {result.out}"
    todo = f"{result.missing} of this job's {result.planned} episodes still to run"
    if result.interrupted:
        print(f"{PROG}: interrupted: {saved} ({todo}); rerun the same command to resume", file=sys.stderr)
        return EXIT_INTERRUPTED
    if result.error is not None:
        print(f"{PROG}: backend error: {result.error}; {saved} ({todo}); rerun the same command "
              f"to resume", file=sys.stderr)
        return EXIT_BACKEND
    if not args.quiet:
        print((Path(result.out) / job_mod.SUMMARY_TXT).read_text(encoding="utf-8"), end="")
        print(f"{saved} ({result.new} new); summary in {result.out / job_mod.SUMMARY_TXT}", file=sys.stderr)
    return 0


def _factory():
    """The backend factory, looked up at call time so tests can stand in for it."""
    return job_mod.make_backend


def cmd_summary(argv: Sequence[str]) -> int:
    p = argparse.ArgumentParser(prog=f"{PROG} summary",
                                description="rebuild DIR/summary.{json,txt} from DIR/episodes.jsonl")
    p.add_argument("dir")
    args = p.parse_args(argv)
    _, text = job_mod.rebuild_summary(args.dir)
    print(text, end="")
    return 0


def _load(d: str) -> tuple[list[dict], str]:
    path = Path(d) / job_mod.EPISODES
    if not path.exists():
        raise job_mod.EvalError(f"{path} does not exist")
    cfg = job_mod.read_config(Path(d)) or {}
    opts = "".join(f", {k}={v}" for k, v in (cfg.get("backend_options") or {}).items())
    name = f"{d} (backend {cfg.get('backend', '?')}, model {cfg.get('model') or '-'}{opts})"
    return scan(path).records, name   # read-only: a cut-short last line is simply left out


def cmd_compare(argv: Sequence[str]) -> int:
    p = argparse.ArgumentParser(prog=f"{PROG} compare",
                                description="paired per-task return differences B - A")
    p.add_argument("dir_a")
    p.add_argument("dir_b")
    p.add_argument("--json", help="also write the comparison to this file")
    args = p.parse_args(argv)
    (a, name_a), (b, name_b) = _load(args.dir_a), _load(args.dir_b)
    result = compare_records(a, b)
    if not result["pairs"]:
        raise job_mod.EvalError(f"{args.dir_a} and {args.dir_b} share no (task, seed) pair")
    print(format_comparison(result, name_a, name_b), end="")
    if args.json:
        Path(args.json).write_text(json.dumps({"a": args.dir_a, "b": args.dir_b, **result}, indent=1),
                                   encoding="utf-8")
    return 0


COMMANDS = {"run": cmd_run, "summary": cmd_summary, "compare": cmd_compare}


def main(argv: Sequence[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    command = cmd_run
    if argv and argv[0] in COMMANDS:        # `run` is the default: `glyphbench-eval --tasks ...`
        command = COMMANDS[argv.pop(0)]
    try:
        return command(argv)
    except (UnknownTaskError, MissingExtraError, EpisodeLogError, ValueError, FileNotFoundError) as e:
        print(f"{PROG}: error: {e}", file=sys.stderr)
        return EXIT_USAGE
    except KeyboardInterrupt:               # outside a job's episode loop: nothing half-written
        print(f"{PROG}: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED


if __name__ == "__main__":
    sys.exit(main())
