"""What a replay viewer shows for one episode, parsed once from a trajectory record.

A trajectory keeps each observation as the text the model read (HUD line, grid, ``Legend:`` line,
optional message). The viewers need those parts separately: the grid to draw in colour, the legend
to name the glyphs, the HUD and message as text. ``EpisodeView`` holds one frame per position
(position ``k`` is the world after ``k`` actions; the last one is the final observation) and one
turn per step (the reply, parsed action or forfeit, reward, return so far, memory), plus whether
the world changed. The HTML page, the terminal viewer and image export all read this one model.

Glyph classes (agent, hazard, goal, item, water, wall, empty, other) and tints are a reading aid
derived from the legend text; they never feed back into anything the model saw. ``glyph_class``
is the only place they are decided: each viewer only maps a (class, tint) to its own colours.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass
from typing import Any, Mapping

from ..rollout.trajectory import Trajectory

GLYPH_CLASSES = ("agent", "hazard", "goal", "item", "water", "wall", "empty", "other")
TINTS = ("red", "green", "blue", "yellow", "purple", "grey", "orange")
TINTED_CLASSES = frozenset({"goal", "item", "other"})    # agents, hazards, walls keep their class colour

LEGEND_PREFIX = "Legend: "
LegendEntry = tuple[str, str, str, str]          # glyph, meaning, class, tint


def _words(*classes: tuple[str, str]) -> tuple[tuple[str, re.Pattern[str]], ...]:
    """(class, pattern) rules from space-separated vocabularies; ``_`` joins a phrase's words."""
    return tuple((cls, re.compile(r"\b(?:" + "|".join(w.replace("_", " ") for w in words.split()) + r")\b"))
                 for cls, words in classes)


# Ordered, on whole words of the lower-cased meaning: the first rule that matches wins ("your
# trail" is the agent, "opponent trail" a hazard, "empty home" a goal, "falling piece" the agent).
# A '·' or '.' is empty unless an agent, hazard, goal, item or water word says otherwise, so that
# "· ground" is ground to walk on and "= ground" a wall.
_RULES_BEFORE_EMPTY_GLYPHS = _words(
    ("agent", "you your yours player agent hero head frog bird skier lander forklift avatar "
              "falling_piece"),
    ("hazard", "lava mine mines enemy enemies guard sentry spike spikes car_driving cars_driving bomb blast "
               "opponent invader monster trap ghost zombie fire bullet shell alien hazard skeleton watched "
               "crashed"),
    ("agent", "body tail"),
    ("goal", "goal exit target pad dock home stairs flag portal drain source"),
    ("item", "key gem ball box package card object tile seed sprout diamond door piece disc item potion "
             "sword tower log food coin coins treasure apple mirror vehicle car light_on filled"),
    ("water", "water pond river sea"),
)
_EMPTY_GLYPHS = frozenset("·.")
_RULES_AFTER_EMPTY_GLYPHS = _words(
    ("wall", "wall walls fence hedge rock pipe block solid tree rack boundary border stone obstacle crate "
             "ground hidden face_down"),
    ("empty", "empty floor blank air sky space open snow grass ice unseen buildable path soil dark nothing"),
)
_CHAR_CLASSES = {"█": "wall", "▓": "wall", "#": "wall", "░": "empty", "@": "agent"}
_TINT_WORD = re.compile(r"\b(" + "|".join((*TINTS, "gray")) + r")\b")


def glyph_class(glyph: str, meaning: str) -> tuple[str, str]:
    """(class, tint) of a legend entry, the one colouring every viewer uses: the class from the
    meaning's words, else from the glyph; the tint is a colour word of the meaning (``red door``),
    kept only for goals, items and others (a hazard stays hazard-coloured), else ''."""
    text = meaning.lower().strip()
    cls = _classify(glyph, text)
    tint = _TINT_WORD.search(text) if cls in TINTED_CLASSES else None
    return cls, "" if tint is None else tint.group(1).replace("gray", "grey")


def _classify(glyph: str, text: str) -> str:
    if text.startswith(("no ", "not ")):            # "no mine around", "not fired at"
        return "empty"
    if re.search(r"\baround\b", text):             # "2 mines around": a hint, not a mine
        return "other"
    for cls, rule in _RULES_BEFORE_EMPTY_GLYPHS:
        if rule.search(text):
            return cls
    if glyph in _EMPTY_GLYPHS:
        return "empty"
    for cls, rule in _RULES_AFTER_EMPTY_GLYPHS:
        if rule.search(text):
            return cls
    return _CHAR_CLASSES.get(glyph, "other")


def parse_legend(text: str, glyphs: set[str] | None = None) -> list[tuple[str, str]]:
    """``"· empty, ▶ head, ● body"`` -> [("·", "empty"), ("▶", "head"), ("●", "body")].

    An entry starts at ``", X "`` where X is a glyph on the grid (any character when ``glyphs`` is
    None), so a meaning may itself hold a comma."""
    entries: list[tuple[str, str]] = []
    pos = 0
    while pos < len(text):
        glyph = text[pos]
        start = pos + 2 if text[pos + 1:pos + 2] == " " else pos + 1
        end = start
        while end < len(text):
            if (text.startswith(", ", end) and end + 3 < len(text) and text[end + 3] == " "
                    and text[end + 2] != " " and (glyphs is None or text[end + 2] in glyphs)):
                break
            end += 1
        entries.append((glyph, text[start:end]))
        pos = end + 2
    return entries


@dataclass(frozen=True)
class FrameView:
    """One observation split into its parts; ``legend`` entries are (glyph, meaning, class, tint)."""

    hud: str
    grid: tuple[str, ...]
    axes: bool
    legend: tuple[LegendEntry, ...]
    legend_carried: bool       # the observation left the legend out; named from earlier legends
    message: str
    above: tuple[str, ...] = ()     # with axes: lines above the column letters, as shown (clues)
    beside: tuple[str, ...] = ()    # with axes: per row, the text right of it ("" for none)

    def to_json(self) -> dict[str, Any]:
        return {"hud": self.hud, "grid": list(self.grid), "axes": self.axes,
                "above": list(self.above), "beside": list(self.beside),
                "legend": [list(e) for e in self.legend], "legendCarried": self.legend_carried,
                "message": self.message}

    def shown_rows(self) -> list[tuple[str, str, str]]:
        """The grid as the observation showed it, as (label, cells, note) lines: with axes, the
        lines above the board and the column letters (all label, no cells), then each row behind
        its right-aligned number and before its note (a nonogram's clue)."""
        if not self.axes:
            return [("", row, "") for row in self.grid]
        width = len(str(len(self.grid)))
        cols = max((len(r) for r in self.grid), default=0)
        header = " " * (width + 1) + "".join(chr(65 + c) for c in range(cols))
        notes = self.beside or ("",) * len(self.grid)
        return ([(line, "", "") for line in self.above] + [(header, "", "")] +
                [(f"{r + 1:>{width}} ", row, f" {note}" if note else "")
                 for r, (row, note) in enumerate(zip(self.grid, notes))])


_AXES_ROW = re.compile(r"^ *(\d+) (\S+)(?: (.*))?$")    # number, cells (never spaces), note


def _is_axes_header(line: str) -> bool:
    """The column letters a board game renders above its grid: spaces, then A, B, C, ... in order."""
    letters = line.lstrip(" ")
    return bool(letters) and len(letters) < len(line) and letters == "".join(
        chr(65 + c) for c in range(len(letters)))


def _axes_header_at(body: list[str]) -> int | None:
    """Where the column letters are: the first line, or after lines above the board (indented
    like the letters); None for a board without axes."""
    for i, line in enumerate(body):
        if _is_axes_header(line):
            return i
        if not line.startswith(" "):
            return None
    return None


def _axes_rows(lines: list[str]) -> list[re.Match[str]]:
    """The numbered rows 1, 2, ... at the start of ``lines``, all as wide as the first."""
    rows: list[re.Match[str]] = []
    for line in lines:
        m = _AXES_ROW.match(line)
        if not m or int(m.group(1)) != len(rows) + 1 or (rows and len(m.group(2)) != len(rows[0].group(2))):
            break
        rows.append(m)
    return rows


def parse_observation(text: str, known: Mapping[str, LegendEntry] | None = None) -> FrameView:
    """Split an observation's text. Without a legend line (the ``legend="changed"`` harness left
    it out because an earlier one is still in the prompt), the glyphs on the grid are named from
    ``known``: the latest legend entry seen for each glyph."""
    lines = text.split("\n")
    hud, body = lines[0], lines[1:]
    head = _axes_header_at(body)
    axes = head is not None
    legend_at = next((i for i, line in enumerate(body) if line.startswith(LEGEND_PREFIX)), None)
    if legend_at is not None:
        grid_lines, rest = body[:legend_at], body[legend_at + 1:]
    else:
        grid_lines, rest = _split_grid(body, head)
    above: tuple[str, ...] = ()
    beside: tuple[str, ...] = ()
    if head is not None:
        above = tuple(grid_lines[:head])
        rows = _axes_rows(grid_lines[head + 1:])
        grid_lines = [m.group(2) for m in rows]
        if any(m.group(3) for m in rows):
            beside = tuple(m.group(3) or "" for m in rows)
    grid = tuple(grid_lines)
    if legend_at is not None:
        pairs = parse_legend(body[legend_at][len(LEGEND_PREFIX):], set("".join(grid)) or None)
        legend = tuple((g, m, *glyph_class(g, m)) for g, m in pairs)
        carried = False
    else:
        present = set("".join(grid))
        legend = tuple(entry for glyph, entry in (known or {}).items() if glyph in present)
        carried = bool(legend)
    return FrameView(hud, grid, axes, legend, carried, "\n".join(rest).strip("\n"), above, beside)


def _split_grid(body: list[str], head: int | None) -> tuple[list[str], list[str]]:
    """Grid lines and the rest when no legend line marks the end of the grid: grid rows are
    equally long and hold no spaces (with axes: rows numbered 1, 2, ... under the column letters)."""
    if head is not None:
        n = head + 1 + len(_axes_rows(body[head + 1:]))
        return body[:n], body[n:]
    n = 0
    while n < len(body) and body[n] and len(body[n]) == len(body[0]) and " " not in body[n]:
        n += 1
    return body[:n], body[n:]


@dataclass(frozen=True)
class TurnView:
    """One step: what the model answered at a frame and what it caused."""

    turn: int
    reply: str
    action: str | None
    forfeit_reason: str | None
    reward: float
    return_so_far: float
    memory: str | None
    change: str | None          # "forfeit", "unchanged" (grid identical after the action) or None
    finish_reason: str | None

    def to_json(self) -> dict[str, Any]:
        return {"turn": self.turn, "reply": self.reply, "action": self.action,
                "forfeit": self.forfeit_reason, "reward": self.reward, "ret": self.return_so_far,
                "memory": self.memory, "change": self.change, "finish": self.finish_reason}


@dataclass(frozen=True)
class EpisodeView:
    index: int                  # the episode's number in its file's index
    source: str                 # file:line of the record
    task_id: str
    suite: str
    seed: int
    model: str
    meta: dict[str, Any]
    system_prompt: str
    episode_return: float
    won: bool | None
    terminated: bool
    truncated: bool
    forfeits: int
    frames: tuple[FrameView, ...]   # len(turns) + 1: before each action, then the final one
    turns: tuple[TurnView, ...]

    @classmethod
    def from_trajectory(cls, traj: Trajectory, *, index: int = 0, source: str = "",
                        suite: str = "unknown") -> "EpisodeView":
        texts = [shown(s.observation) for s in traj.steps] or [shown(traj.initial_observation)]
        texts.append(shown(traj.final_observation))
        frames: list[FrameView] = []
        known: dict[str, LegendEntry] = {}
        for text in texts:
            frame = parse_observation(text, known)
            known.update((entry[0], entry) for entry in frame.legend)
            frames.append(frame)
        if not traj.steps:
            frames = frames[1:] if traj.final_observation else frames[:1]
        turns, total = [], 0.0
        for i, s in enumerate(traj.steps):
            total += s.reward
            after = frames[i + 1]
            if s.action is None:
                change = "forfeit"
            elif after.grid and after.grid == frames[i].grid:
                change = "unchanged"
            else:
                change = None
            turns.append(TurnView(s.turn, shown(s.reply), shown(s.action), s.forfeit_reason, s.reward,
                                  total, shown(s.memory), change, s.finish_reason))
        meta = json.loads(shown(json.dumps(traj.meta, ensure_ascii=False)))
        return cls(index, source, traj.task_id, suite, traj.seed, model_name(meta), meta,
                   shown(traj.system_prompt), traj.episode_return, traj.won, traj.terminated, traj.truncated,
                   traj.forfeits, tuple(frames), tuple(turns))

    @property
    def length(self) -> int:
        return len(self.turns)

    @property
    def outcome(self) -> str:
        if self.won:
            return "won"
        if self.truncated:
            return "truncated"
        if self.won is False:
            return "lost"
        return "ended" if self.terminated else "unfinished"


_SURROGATE = re.compile("[\ud800-\udfff]")


def shown(text: str | None) -> str | None:
    """Text as a viewer can write it: a lone surrogate (a broken pair some endpoints send, which
    the episode writer stores escaped) becomes U+FFFD; everything else is unchanged."""
    return _SURROGATE.sub("\ufffd", text) if text else text


def model_name(meta: dict[str, Any]) -> str:
    """The policy that played: the model, else the backend name, else '-'."""
    return str(meta.get("model") or meta.get("backend") or "-")
