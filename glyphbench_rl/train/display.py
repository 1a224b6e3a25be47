"""What a training run shows while it works.

On a terminal: a live rich panel with a progress bar over steps (elapsed, time left), the phase
in progress (rollouts with episodes finished so far, the update, a held-out evaluation), and a
table of the last step's numbers next to the first step's, so a trend is visible at a glance.
Anywhere else (a log file, a Slurm job, a pipe): plain lines, nothing redrawn, each flushed at
once: a line when a phase starts (rollouts, update, evaluation, checkpoint), progress within a
phase at most every ``every`` seconds, and one summary line per step.
"""

from __future__ import annotations

import sys
import time
from typing import Any, Callable, TextIO

# (metric key, label, format) of the table; missing keys are left out
ROWS = (("train/return_mean", "return", "{:+.3f}"), ("train/forfeit_rate", "forfeit rate", "{:.1%}"),
        ("train/format_score", "format score", "{:.3f}"), ("train/episode_length", "episode length", "{:.1f}"),
        ("train/win_rate", "win rate", "{:.1%}"), ("train/loss", "loss", "{:+.4f}"),
        ("train/grad_norm", "grad norm", "{:.3f}"), ("train/masked_fraction", "masked fraction", "{:.2%}"),
        ("train/trainable_tokens", "trainable tokens", "{:,}"),
        ("train/zero_advantage_groups", "flat groups", "{}"), ("time/rollout_s", "rollout s", "{:.1f}"),
        ("time/train_s", "update s", "{:.1f}"))


def progress_line(m: dict[str, Any], steps: int) -> str:
    """The one-line summary of a step, for logs."""
    line = (f"step {m['step']}/{steps}  return {m['train/return_mean']:+.3f}  "
            f"forfeit {m['train/forfeit_rate']:.0%}  len {m['train/episode_length']:.1f}  "
            f"loss {m['train/loss']:+.4f}  grad {m['train/grad_norm']:.3f}  "
            f"tokens {m['train/trainable_tokens']}  "
            f"rollout {m['time/rollout_s']:.1f}s train {m['time/train_s']:.1f}s")
    if "eval/return_mean" in m:
        line += f"  eval {m['eval/return_mean']:+.3f}"
    return line


def log_line(text: str) -> None:
    """Print and flush: a log file shows the line now, not when a buffer fills."""
    print(text, flush=True)


class PlainDisplay:
    """Lines through ``log``: phases as they start, progress within one at most every ``every``
    seconds, a summary per step."""

    def __init__(self, steps: int, log: Callable[[str], None] = log_line, *, start: int = 0,
                 every: float = 30.0, clock: Callable[[], float] = time.monotonic) -> None:
        self.steps, self.log, self.every, self.clock = steps, log, every, clock
        self.current = start + 1            # the step in progress
        self._phase: str | None = None
        self._since = self._printed = clock()

    def __enter__(self) -> "PlainDisplay":
        return self

    def __exit__(self, *exc) -> None:
        pass

    def phase(self, text: str, done: int | None = None, total: int | None = None) -> None:
        now = self.clock()
        name = text.split(" (", 1)[0]
        if name != self._phase:
            self._phase, self._since = name, now
        elif now - self._printed < self.every and (total is None or done != total):
            return
        count = f" {done}/{total}" if total is not None else ""
        took = f" ({now - self._since:.0f}s)" if now > self._since else ""
        self.log(f"step {self.current}/{self.steps}: {text}{count}{took}")
        self._printed = now

    def step_done(self, metrics: dict[str, Any]) -> None:
        self.current = metrics["step"] + 1
        self._phase = None
        self.log(progress_line(metrics, self.steps))

    def message(self, text: str) -> None:
        self.log(text)


class RichDisplay:
    """The live panel; ``message`` lines print above it and stay in the scrollback."""

    def __init__(self, steps: int, *, start: int = 0, title: str = "", file: TextIO | None = None) -> None:
        from rich.console import Console
        from rich.progress import (BarColumn, MofNCompleteColumn, Progress, TextColumn,
                                   TimeElapsedColumn, TimeRemainingColumn)

        self.console = Console(file=file or sys.stdout)
        self.steps, self.title = steps, title
        self.progress = Progress(TextColumn("[bold]step"), MofNCompleteColumn(), BarColumn(),
                                 TimeElapsedColumn(), TextColumn("left"), TimeRemainingColumn(),
                                 console=self.console)
        self.task = self.progress.add_task("train", total=steps, completed=start)
        self.first: dict[str, Any] | None = None
        self.last: dict[str, Any] | None = None
        self.evals: list[tuple[int, float]] = []     # (step, held-out mean return)
        self.phase_text = "starting"
        self.phase_since = time.monotonic()
        self.live = None

    def __enter__(self) -> "RichDisplay":
        from rich.live import Live
        self.live = Live(self, console=self.console, refresh_per_second=2, transient=False)
        self.live.__enter__()
        return self

    def __exit__(self, *exc) -> None:
        if self.live is not None:
            self.live.__exit__(*exc)

    def phase(self, text: str, done: int | None = None, total: int | None = None) -> None:
        if text != self.phase_text.split(" ", 1)[0]:
            self.phase_since = time.monotonic()
        self.phase_text = text if total is None else f"{text} {done}/{total}"

    def step_done(self, metrics: dict[str, Any]) -> None:
        self.first = self.first or metrics
        self.last = metrics
        if "eval/return_mean" in metrics:
            self.evals.append((metrics["step"], metrics["eval/return_mean"]))
        self.progress.update(self.task, completed=metrics["step"])
        self.console.print(progress_line(metrics, self.steps), highlight=False)

    def message(self, text: str) -> None:
        self.console.print(text, highlight=False)

    def __rich__(self):
        from rich.console import Group
        from rich.panel import Panel
        from rich.table import Table

        parts: list[Any] = [self.progress.get_renderable()]
        parts.append(f"[dim]now:[/] {self.phase_text} ({time.monotonic() - self.phase_since:.0f}s)")
        if self.last is not None:
            table = Table(box=None, pad_edge=False, show_header=True, header_style="dim")
            table.add_column("")
            table.add_column(f"step {self.first['step']}", justify="right")
            table.add_column(f"step {self.last['step']}", justify="right")
            for key, label, fmt in ROWS:
                if key in self.last:
                    first = self.first.get(key)
                    table.add_row(label, "" if first is None else fmt.format(first), fmt.format(self.last[key]))
            parts.append(table)
        if self.evals:
            shown = ", ".join(f"step {s}: {r:+.3f}" for s, r in self.evals[-4:])
            parts.append(f"held-out return  {shown}")
        return Panel(Group(*parts), title=self.title or "glyphbench-train", expand=False)


def make_display(steps: int, *, start: int = 0, title: str = "", log: Callable[[str], None] = log_line,
                 rich: bool | None = None):
    """A RichDisplay on an interactive terminal (or when ``rich`` is True), else a PlainDisplay."""
    if rich is None:
        rich = sys.stdout.isatty()
    if rich:
        try:
            return RichDisplay(steps, start=start, title=title)
        except ImportError:
            pass
    return PlainDisplay(steps, log, start=start)
