"""Terminal replay for people on SSH: the HTML page's content as a rich panel, driven by keys.

``render_step(view, pos)`` (a rich renderable) and ``plain_step(view, pos)`` (text without ANSI
codes) are pure functions of an ``EpisodeView`` and a position (0 = before the first action,
``view.length`` = the final observation). ``browse`` is the thin interactive loop: it reads keys
from the terminal in cbreak mode (termios) and redraws. When stdin or stdout is not a terminal,
``replay_terminal`` prints every step of the selected episodes as plain text instead.

Keys: Left/Right (h/l) step, Home/End (g/G) first/final, Up/Down (k/j) scroll the reply,
n/p next/previous episode, q quit.
"""

from __future__ import annotations

import importlib.util
import os
import sys
from contextlib import contextmanager
from typing import IO, Any, Callable, Iterator, Sequence

from .index import EpisodeIndex
from .view import EpisodeView, FrameView

CLASS_STYLES = {"agent": "bold yellow", "hazard": "bold red", "goal": "bold green", "item": "cyan",
                "water": "dodger_blue1", "wall": "grey62", "empty": "grey35", "other": ""}
TINT_STYLES = {"red": "bright_red", "green": "green3", "blue": "dodger_blue1", "yellow": "yellow1",
               "purple": "medium_purple1", "grey": "grey70", "orange": "dark_orange"}

# control characters in model text would drive the terminal (colours, cursor, title): shown as \xNN
_CONTROLS = {c: f"\\x{c:02x}" for c in [*range(0x20), *range(0x7f, 0xa0)] if c not in (0x09, 0x0a)}

KEY_HELP = "←/→ h/l step · Home/End first/final · ↑/↓ j/k scroll reply · n/p episode · q quit"

_SEQUENCES = {
    b"\x1b[D": "left", b"\x1bOD": "left", b"h": "left",
    b"\x1b[C": "right", b"\x1bOC": "right", b"l": "right",
    b"\x1b[H": "home", b"\x1bOH": "home", b"\x1b[1~": "home", b"\x1b[7~": "home", b"g": "home",
    b"\x1b[F": "end", b"\x1bOF": "end", b"\x1b[4~": "end", b"\x1b[8~": "end", b"G": "end",
    b"\x1b[A": "up", b"\x1bOA": "up", b"k": "up", b"\x1b[B": "down", b"\x1bOB": "down", b"j": "down",
    b"\x1b[5~": "page_up", b"\x1b[6~": "page_down",
    b"n": "next", b"p": "prev", b"q": "quit", b"Q": "quit", b"\x1b": "quit", b"\x03": "quit",
}


def decode_keys(data: bytes) -> list[str]:
    """Key names in a chunk read from the terminal (several keys may arrive at once); bytes
    that are no known key are dropped."""
    keys, i = [], 0
    while i < len(data):
        for size in (4, 3, 2, 1):
            name = _SEQUENCES.get(data[i:i + size])
            if name is not None:
                keys.append(name)
                i += size
                break
        else:
            i += 1
    return keys


class Navigator:
    """Where the viewer is: which selected episode, which position, how far the reply scrolled."""

    def __init__(self, episodes: int, length_of: Callable[[int], int], *, page: int = 10) -> None:
        self.episodes, self.length_of, self.page = episodes, length_of, page
        self.slot = self.pos = self.scroll = 0
        self.length = length_of(0)

    def press(self, key: str) -> bool:
        """Apply one key; False when it asks to quit."""
        moves = {"left": self.pos - 1, "right": self.pos + 1, "home": 0, "end": self.length}
        if key == "quit":
            return False
        if key in moves:
            pos = max(0, min(self.length, moves[key]))
            if pos != self.pos:
                self.pos, self.scroll = pos, 0
        elif key in ("next", "prev"):
            slot = max(0, min(self.episodes - 1, self.slot + (1 if key == "next" else -1)))
            if slot != self.slot:
                self.slot, self.pos, self.scroll = slot, 0, 0
                self.length = self.length_of(slot)
        elif key in ("up", "down", "page_up", "page_down"):
            step = {"up": -1, "down": 1, "page_up": -self.page, "page_down": self.page}[key]
            self.scroll = max(0, self.scroll + step)
        return True


def safe(text: str) -> str:
    """``text`` with terminal control characters written out visibly (newlines and tabs kept)."""
    return text.translate(_CONTROLS)


# ---- plain text ------------------------------------------------------------------------------
def header_line(view: EpisodeView) -> str:
    return safe(f"episode #{view.index}  {view.task_id} ({view.suite})  seed {view.seed}  model {view.model}  "
            f"return {view.episode_return:+.3f}  {view.outcome}  {view.length} turns  "
            f"{view.forfeits} forfeits  [{view.source}]")


def frame_lines(frame: FrameView) -> list[str]:
    """The observation as text again: HUD, grid (with its axes), legend, message."""
    lines = [safe(frame.hud), *(safe(label + cells + note) for label, cells, note in frame.shown_rows())]
    if frame.legend:
        label = "Legend (from an earlier step): " if frame.legend_carried else "Legend: "
        lines.append(label + safe(", ".join(f"{g} {m}" for g, m, _, _ in frame.legend)))
    if frame.message:
        lines.append(safe(frame.message))
    return lines


def turn_summary(view: EpisodeView, pos: int) -> str:
    """One line: the action (or forfeit and its reason), reward, return so far, change marker."""
    if pos >= view.length:
        return f"episode over: {view.outcome} after {view.length} turns, return {view.episode_return:+.3f}"
    t = view.turns[pos]
    reason = safe(t.forfeit_reason or "no reason recorded")
    what = f"action {safe(t.action)}" if t.action is not None else f"FORFEIT ({reason})"
    marks = {"unchanged": "  [no change]", "forfeit": "  [world unchanged]"}.get(t.change or "", "")
    cut = "  [reply cut at token limit]" if t.finish_reason == "length" else ""
    return f"{what}  reward {t.reward:+.3f}  return {t.return_so_far:+.3f}{marks}{cut}"


def plain_step(view: EpisodeView, pos: int) -> str:
    """Everything shown at position ``pos`` as plain text."""
    title = (f"step {pos}/{view.length}, turn {view.turns[pos].turn}" if pos < view.length
             else f"step {pos}/{view.length}, final observation")
    out = [f"--- {title} " + "-" * max(3, 60 - len(title)), *frame_lines(view.frames[pos])]
    if pos < view.length:
        t = view.turns[pos]
        out.append("reply:")
        out += ["  " + line for line in safe(t.reply or "(empty reply)").split("\n")]
        if t.memory is not None:
            out.append("memory:")
            out += ["  " + line for line in safe(t.memory).split("\n")]
    out.append(turn_summary(view, pos))
    return "\n".join(out)


def plain_episode(view: EpisodeView) -> str:
    return "\n".join([f"=== {header_line(view)}", *(plain_step(view, p) for p in range(view.length + 1))])


# ---- rich --------------------------------------------------------------------------------------
def entry_style(cls: str, tint: str) -> str:
    """The rich style of a glyph class and tint (as ``view.glyph_class`` gives them)."""
    return TINT_STYLES[tint] if tint else CLASS_STYLES[cls]


def grid_text(frame: FrameView) -> Any:
    """The grid as a rich Text, each glyph styled by its class (and colour word)."""
    from rich.text import Text
    styles = {g: entry_style(cls, tint) for g, _, cls, tint in frame.legend}
    text = Text(no_wrap=True, overflow="crop")
    rows = frame.shown_rows()
    for r, (label, cells, note) in enumerate(rows):
        if label:
            text.append(safe(label), style="dim")
        run, style = "", ""
        for ch in cells:                   # one span per run of equally styled glyphs
            if styles.get(ch, "") != style and run:
                text.append(run, style=style)
                run = ""
            run, style = run + safe(ch), styles.get(ch, "")
        text.append(run, style=style)
        if note:
            text.append(safe(note), style="dim")
        if r < len(rows) - 1:
            text.append("\n")
    return text


def render_step(view: EpisodeView, pos: int, *, reply_offset: int = 0, reply_height: int | None = None) -> Any:
    """A rich renderable of position ``pos``: header, board (HUD, grid, legend, message) beside
    the turn (action or forfeit, reward, return, reply window, memory)."""
    from rich.console import Group
    from rich.panel import Panel
    from rich.table import Table
    from rich.text import Text

    frame = view.frames[pos]
    board: list[Any] = [Text(safe(frame.hud), style="dim"), grid_text(frame)]
    legend = Text()
    for g, meaning, cls, tint in frame.legend:
        legend.append(g, style=entry_style(cls, tint))
        legend.append(f" {safe(meaning)}   ")
    if frame.legend_carried:
        legend.append("(legend from an earlier step)", style="dim italic")
    board.append(legend)
    if frame.message:
        board.append(Text(safe(frame.message), style="italic"))

    turn: list[Any] = []
    if pos < view.length:
        t = view.turns[pos]
        head = Text(f"Turn {t.turn}  ", style="bold")
        if t.action is not None:
            head.append(f"→ {safe(t.action)}", style="bold blue")
        else:
            head.append("FORFEIT", style="bold white on red")
        if t.change == "unchanged":
            head.append("  no change", style="bold black on dark_orange")
        elif t.change == "forfeit":
            head.append("  world unchanged", style="bold black on dark_orange")
        if t.finish_reason == "length":
            head.append("  reply cut at token limit", style="magenta")
        turn.append(head)
        if t.action is None:
            turn.append(Text(f"reason: {safe(t.forfeit_reason or 'no reason recorded')}", style="red"))
        turn.append(Text(f"reward {t.reward:+.3f}   return so far {t.return_so_far:+.3f}"))
        lines = safe(t.reply or "(empty reply)").split("\n")
        start = min(reply_offset, max(0, len(lines) - 1))
        shown = lines[start:start + reply_height] if reply_height else lines[start:]
        hidden = len(lines) - start - len(shown)
        scrolled = [f"{n} line(s) {where}" for n, where in ((start, "above"), (hidden, "below")) if n]
        turn.append(Panel(Text("\n".join(shown)), title="reply", title_align="left", border_style="grey42",
                          subtitle=", ".join(scrolled) + " (↑/↓)" if scrolled else None))
        if t.memory is not None:
            turn.append(Panel(Text(safe(t.memory)), title="memory", title_align="left", border_style="grey42"))
    else:
        turn.append(Text(turn_summary(view, pos), style="bold"))

    layout = Table.grid(expand=True, padding=(0, 2))
    layout.add_column(ratio=1)
    layout.add_column(ratio=1)
    layout.add_row(Group(*board), Group(*turn))
    stale = pos < view.length and view.turns[pos].change is not None
    title = Text(safe(f"{view.task_id}  ·  step {pos}/{view.length}"))     # Text: never read as markup
    return Panel(Group(Text(header_line(view), style="cyan"), Text(""), layout), title=title,
                 title_align="left", subtitle=Text(KEY_HELP), border_style="dark_orange" if stale else "blue")


# ---- drivers ------------------------------------------------------------------------------------
def print_plain(index: EpisodeIndex, selection: Sequence[int], out: IO[str]) -> None:
    """Every step of the selected episodes, as plain text, one episode at a time."""
    for n, i in enumerate(selection):
        out.write(("\n" if n else "") + plain_episode(index.view(i)) + "\n")


@contextmanager
def _cbreak(fd: int) -> Iterator[None]:
    import termios
    import tty
    saved = termios.tcgetattr(fd)
    try:
        tty.setcbreak(fd)
        yield
    finally:
        termios.tcsetattr(fd, termios.TCSADRAIN, saved)


def browse(index: EpisodeIndex, selection: Sequence[int]) -> None:
    """The interactive viewer on the controlling terminal."""
    from rich.console import Console
    from rich.live import Live

    console = Console()
    views: dict[int, EpisodeView] = {}

    def view_at(slot: int) -> EpisodeView:
        i = selection[slot]
        if i not in views:
            views.clear()                    # one episode in memory at a time
            views[i] = index.view(i)
        return views[i]

    nav = Navigator(len(selection), lambda slot: view_at(slot).length)
    fd = sys.stdin.fileno()
    with _cbreak(fd), Live(console=console, screen=True, auto_refresh=False) as live:
        while True:
            view = view_at(nav.slot)
            turn = view.turns[nav.pos] if nav.pos < view.length else None
            memory = len(turn.memory.split("\n")) + 2 if turn and turn.memory is not None else 0
            nav.page = max(5, console.size.height - 12 - memory)     # what fits beside the board
            live.update(render_step(view, nav.pos, reply_offset=nav.scroll, reply_height=nav.page),
                        refresh=True)
            if not all(nav.press(key) for key in decode_keys(os.read(fd, 64))):
                return


def replay_terminal(index: EpisodeIndex, selection: Sequence[int]) -> int:
    """Browse interactively on a terminal; otherwise print the selection as plain text."""
    if sys.stdin.isatty() and sys.stdout.isatty():
        if importlib.util.find_spec("rich") is None:
            raise RuntimeError("the terminal replay needs the 'rich' package (pip install rich), "
                               "or write a page with --html")
        browse(index, selection)
    else:
        try:
            print_plain(index, selection, sys.stdout)
            sys.stdout.flush()
        except BrokenPipeError:                   # e.g. piped into `head`
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
    return 0
