"""``glyphbench replay``: look at what an agent did, in the terminal, as an HTML page or a GIF.

    glyphbench replay FILE [--episode N] [--task ID_OR_GLOB] [--html OUT] [--gif OUT]

FILE is a trajectory file (an evaluation job's ``episodes.jsonl``, a training run's
``rollouts/step_NNNNNN.jsonl``) or a job or run directory. Without ``--html``/``--gif`` it opens
the terminal viewer (plain text when stdout is not a terminal).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..replay.html import MAX_EPISODES, write_html
from ..replay.index import EpisodeIndex
from ..replay.terminal import replay_terminal

WARNINGS_SHOWN = 10


def parse_episodes(spec: str) -> list[int]:
    """``"3"``, ``"0,4,7"``, ``"10-19"`` or a mix -> episode numbers, in order, once each."""
    out: list[int] = []
    for part in spec.split(","):
        part = part.strip()
        lo, sep, hi = part.partition("-")
        try:
            first, last = (int(lo), int(hi)) if sep else (int(part), int(part))
        except ValueError:
            raise ValueError(f"--episode {spec!r}: expected numbers like 3, 0,4,7 or 10-19") from None
        if first < 0 or last < first:
            raise ValueError(f"--episode {spec!r}: {part!r} is not a valid number or range")
        out += [i for i in range(first, last + 1) if i not in out]
    return out


def select(index: EpisodeIndex, episodes: str | None, task: str | None) -> list[int]:
    """The episodes the options name: ``--episode`` numbers (of the file's readable episodes,
    from 0), kept when they match ``--task`` too; all episodes when neither is given."""
    chosen = index.select(task)
    if task is not None and not chosen:
        tasks = sorted({e.task_id for e in index.entries})
        listed = ", ".join(tasks[:5]) + (", ..." if len(tasks) > 5 else "")
        raise ValueError(f"no episode of task {task!r} in {index.path} (it holds {listed})")
    if episodes is None:
        return chosen
    numbers = parse_episodes(episodes)
    for i in numbers:
        if i >= len(index):
            raise ValueError(f"--episode {i} is out of range: {index.path} has {len(index)} "
                             f"episode(s), numbered 0-{len(index) - 1}")
    if task is not None:
        allowed = set(chosen)
        numbers = [i for i in numbers if i in allowed]
        if not numbers:
            raise ValueError(f"none of --episode {episodes} is an episode of task {task!r}")
    return numbers


def cmd_replay(args: argparse.Namespace) -> int:
    try:
        return _replay(args)
    except (OSError, RuntimeError) as e:       # an unwritable output, a missing package
        print(f"glyphbench: error: {e}", file=sys.stderr)
        return 2


def _replay(args: argparse.Namespace) -> int:
    index = EpisodeIndex(args.file, on_warning=lambda message: None)    # printed here, capped
    for message in index.warnings[:WARNINGS_SHOWN]:
        print(f"glyphbench: warning: {message}", file=sys.stderr)
    if len(index.warnings) > WARNINGS_SHOWN:
        print(f"glyphbench: warning: {len(index.warnings) - WARNINGS_SHOWN} more unreadable line(s) skipped",
              file=sys.stderr)
    selection = select(index, args.episode, args.task)
    for out in (args.html, args.gif):
        if out is not None and not Path(out).resolve().parent.is_dir():
            raise ValueError(f"cannot write {out}: directory {Path(out).resolve().parent} does not exist")
    if args.html:
        shown = write_html(index, args.html, selection, limit=args.max_episodes)
        more = f" (the first {shown} of {len(selection)} selected)" if shown < len(selection) else ""
        print(f"wrote {args.html}: {shown} episode(s){more} from {index.path}")
    if args.gif:
        from ..replay.image import write_gif
        write_gif(index.load(selection[0]), args.gif, fps=args.fps)
        entry = index.entries[selection[0]]
        print(f"wrote {args.gif}: episode {selection[0]} ({entry.task_id}, seed {entry.seed})")
    if args.html or args.gif:
        return 0
    return replay_terminal(index, selection)


def _positive(text: str) -> int:
    value = int(text)
    if value < 1:
        raise argparse.ArgumentTypeError("must be at least 1")
    return value


def _fps(text: str) -> float:
    value = float(text)
    if not 0 < value <= 50:
        raise argparse.ArgumentTypeError("must be in (0, 50]")
    return value


def register(subparsers: argparse._SubParsersAction) -> None:
    """Add the ``replay`` subcommand to the ``glyphbench`` parser."""
    s = subparsers.add_parser(
        "replay", help="replay episodes from a trajectory file: terminal, HTML page or GIF",
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    s.add_argument("file", help="trajectory JSONL file, or an evaluation job / training run directory")
    s.add_argument("--episode", metavar="N",
                   help="episode number(s) in the file, from 0: 3, 0,4,7 or 10-19 (default: all)")
    s.add_argument("--task", metavar="ID_OR_GLOB", help="only episodes of this task, e.g. '*snake*'")
    s.add_argument("--html", metavar="OUT", help="write a self-contained HTML replay page")
    s.add_argument("--max-episodes", type=_positive, default=MAX_EPISODES,
                   help=f"most episodes embedded in the HTML page (default {MAX_EPISODES})")
    s.add_argument("--gif", metavar="OUT", help="write an animated GIF of the first selected episode")
    s.add_argument("--fps", type=_fps, default=4.0, help="GIF frames per second (default 4)")
    s.set_defaults(func=cmd_replay)
