"""Named discrete actions.

An :class:`ActionSet` is the single source of truth for a task's action vocabulary: the
gymnasium ``Discrete`` space, the action list in the system prompt and the name resolution used
by the agent protocol are all derived from it.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Iterable, Mapping, Sequence


def _fold(name: str) -> str:
    """Case- and whitespace-insensitive key ("move left" == "MOVE_LEFT" == "moveleft")."""
    return "".join(ch for ch in name.upper() if ch not in " _-\t\n\r")


@dataclass(frozen=True, slots=True)
class Action:
    name: str
    description: str


class ActionSet:
    """Ordered action names with descriptions.

    ``groups`` lets many similar actions (one per board cell, say) share one description line in
    the system prompt: each group is ``(description, [names...])``. Actions are numbered singles
    first, then the groups' in turn, unless ``order`` lists every name in the order wanted (an
    engine's own action numbers, say); the prompt still shows the groups as one line each.
    """

    __slots__ = ("_actions", "_exact", "_folded", "_aliases", "_groups", "noop")

    def __init__(
        self,
        actions: Sequence[tuple[str, str]] = (),
        *,
        groups: Sequence[tuple[str, Sequence[str]]] = (),
        aliases: Mapping[str, str] | None = None,
        noop: str | None = None,
        order: Sequence[str] | None = None,
    ) -> None:
        items = [Action(n, d) for n, d in actions]
        self._groups: list[tuple[str, tuple[str, ...]]] = []
        for description, names in groups:
            names = tuple(names)
            self._groups.append((description, names))
            items.extend(Action(n, description) for n in names)
        if order is not None:   # indices in a given order (an engine's own action numbers)
            by_name = {a.name: a for a in items}
            if sorted(order) != sorted(by_name):
                raise ValueError("order must name every action exactly once")
            items = [by_name[n] for n in order]
        if not items:
            raise ValueError("an ActionSet needs at least one action")
        self._actions: tuple[Action, ...] = tuple(items)
        self._exact: dict[str, int] = {}
        self._folded: dict[str, int] = {}
        for i, a in enumerate(self._actions):
            if not a.name or a.name != a.name.strip() or " " in a.name:
                raise ValueError(f"bad action name {a.name!r}: use one word without spaces")
            if a.name in self._exact:
                raise ValueError(f"duplicate action name {a.name!r}")
            self._exact[a.name] = i
            key = _fold(a.name)
            if key in self._folded:
                raise ValueError(f"action names {a.name!r} and "
                                 f"{self._actions[self._folded[key]].name!r} differ only in case")
            self._folded[key] = i
        self._aliases: dict[str, int] = {}
        for alias, target in (aliases or {}).items():
            if target not in self._exact:
                raise ValueError(f"alias {alias!r} points to unknown action {target!r}")
            key = _fold(alias)
            if key in self._folded and self._folded[key] != self._exact[target]:
                raise ValueError(f"alias {alias!r} collides with action "
                                 f"{self._actions[self._folded[key]].name!r}")
            self._aliases[key] = self._exact[target]
        if noop is not None and noop not in self._exact:
            raise ValueError(f"noop {noop!r} is not an action name")
        #: index of an action that leaves the world unchanged by design, or None
        self.noop: int | None = None if noop is None else self._exact[noop]

    # -- sequence protocol -------------------------------------------------------------------
    def __len__(self) -> int:
        return len(self._actions)

    def __getitem__(self, index: int) -> Action:
        return self._actions[index]

    def __iter__(self):
        return iter(self._actions)

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(a.name for a in self._actions)

    # -- resolution ----------------------------------------------------------------------------
    def lookup(self, name: str) -> int | None:
        """Index of ``name`` (exact, then case/whitespace-insensitive, then alias) or None."""
        i = self._exact.get(name)
        if i is not None:
            return i
        key = _fold(name)
        i = self._folded.get(key)
        return i if i is not None else self._aliases.get(key)

    def index(self, action: int | str) -> int:
        """Resolve an index or a name; ValueError listing the valid actions otherwise."""
        if type(action) is int and 0 <= action < len(self._actions):   # the common case, first
            return action
        if isinstance(action, str):
            i = self.lookup(action)
            if i is None:
                raise ValueError(f"unknown action {action!r}; valid actions: {self.summary()}")
            return i
        try:
            i = int(action)  # numpy integers from action_space.sample()
        except (TypeError, ValueError):
            raise ValueError(f"action must be an index or a name, got {action!r}; "
                             f"valid actions: {self.summary()}") from None
        if i != action or isinstance(action, bool) or not 0 <= i < len(self._actions):
            raise ValueError(f"action {action!r} out of range 0..{len(self._actions) - 1}; "
                             f"valid actions: {self.summary()}")
        return i

    def summary(self, limit: int = 12) -> str:
        names = self.names
        if len(names) <= limit:
            return ", ".join(names)
        return ", ".join(names[:limit]) + f", ... ({len(names)} in all: {names[0]}..{names[-1]})"

    # -- prompt text -------------------------------------------------------------------------------
    def prompt_lines(self) -> list[str]:
        """One line per action, or one line per group of actions sharing a description."""
        grouped = {n for _, names in self._groups for n in names}
        lines = [f"{a.name}: {a.description}" for a in self._actions if a.name not in grouped]
        lines.extend(f"{' '.join(names)}: {description}" for description, names in self._groups)
        return lines


def cell_names(rows: int, cols: int) -> list[str]:
    """Spreadsheet-style names of board cells, row-major: A1 B1 ... (column letter, row number)."""
    if cols > 26:
        raise ValueError("at most 26 columns can be named with letters")
    return [f"{chr(65 + c)}{r + 1}" for r in range(rows) for c in range(cols)]


def directions(names: Iterable[str] = ("UP", "DOWN", "LEFT", "RIGHT"), verb: str = "move") -> list[tuple[str, str]]:
    """The four compass actions with uniform descriptions."""
    return [(n, f"{verb} one cell {n.lower()}") for n in names]
