"""Task registry: TaskSpec rows, ``make``, ``list_tasks``; every task also goes to gymnasium.

Games register their variants next to their class, as data::

    register_variants(Snake, "Classics", {
        "glyphbench/classics-snake-easy-v0": dict(size=8, max_turns=128),
    })

A spec's ``game`` may also be a ``"module:Class"`` string: the module is imported only when one
of its tasks is made (``TaskSpec.load_class``); registering, listing, ``get_spec`` and
``game_name`` never import it. This is how families over heavy engines register, so that
``import glyphbench_rl`` and ``glyphbench list`` stay light (``tests/test_light_import.py``
checks that neither loads jax, nle, minihack, torch or transformers). Such a family (NetHack
and MiniHack over ``nle``/``minihack``, the full Craftax over ``craftax``/JAX) keeps two kinds of
module:

- its package ``__init__`` (imported by ``games/__init__.py``) and a light variants module that
  import nothing heavy and hold only the variants table, registered with strings::

      register_variants("glyphbench_rl.games.nethack.full:NetHackFull", "NetHack", {
          "glyphbench/nethack-full-v0": dict(max_turns=10_000),
      }, tier="extended")

  (parameter values are plain data, checked by the class's ``Params`` when the task is made);
- the engine module (``full.py`` above) that imports ``nle`` / ``jax`` at module level and
  defines the ``GlyphTask`` subclass, imported by nothing but the registry; without its extra
  installed it raises ``MissingExtraError``, one line naming the extra.

Engines seed from the task seed through ``core.seeding`` (``nle_seeds``, ``jax_key_data``).
"""

from __future__ import annotations

import difflib
import fnmatch
import importlib
import re
from dataclasses import dataclass, field
from pathlib import Path
from types import MappingProxyType
from typing import Any, Iterable, Mapping

import gymnasium as gym

from .task import STANDARD_TURN_CAP, GlyphTask

ID_PATTERN = re.compile(r"^glyphbench/[a-z0-9]+(?:-[a-z0-9]+)*-v\d+$")
SUITES = ("Classics", "MiniGrid", "MiniHack", "Craftax", "MiniAtari", "Procgen",
          "Atari", "FullCraftax", "NetHack")
TIERS = ("standard", "extended")


class UnknownTaskError(LookupError):
    pass


class MissingExtraError(ModuleNotFoundError):
    """A task's engine needs an optional extra that is not installed; the message is one line
    naming it (``pip install 'glyphbench_rl[nethack]'``). Raised by engine modules at import."""


@dataclass(frozen=True)
class TaskSpec:
    id: str
    suite: str
    tier: str
    game: type | str
    params: Mapping[str, Any] = field(default_factory=dict)
    max_turns: int = 100

    def __post_init__(self) -> None:
        if not ID_PATTERN.match(self.id):
            raise ValueError(f"task id {self.id!r} does not match glyphbench/<suite>-<game>[-<variant>]-vN")
        if self.suite not in SUITES:
            raise ValueError(f"{self.id}: unknown suite {self.suite!r}; suites: {', '.join(SUITES)}")
        if self.tier not in TIERS:
            raise ValueError(f"{self.id}: tier must be one of {TIERS}, got {self.tier!r}")
        if self.tier == "standard" and not 1 <= self.max_turns <= STANDARD_TURN_CAP:
            raise ValueError(f"{self.id}: standard tasks end by {STANDARD_TURN_CAP} turns")
        object.__setattr__(self, "params", MappingProxyType(dict(self.params)))

    @property
    def game_name(self) -> str:
        g = self.game
        return g.__name__ if isinstance(g, type) else g.rsplit(":", 1)[-1]

    def load_class(self) -> type[GlyphTask]:
        if isinstance(self.game, type):
            return self.game
        module, _, name = self.game.partition(":")
        return getattr(importlib.import_module(module), name)

    def make(self, **overrides: Any) -> GlyphTask:
        params = dict(self.params)
        max_turns = overrides.pop("max_turns", self.max_turns)
        render_mode = overrides.pop("render_mode", None)
        params.update(overrides)
        cls = self.load_class()
        env = cls(max_turns=max_turns, tier=self.tier, task_id=self.id, render_mode=render_mode, **params)
        env.spec = _gym_spec(self)
        return env


_REGISTRY: dict[str, TaskSpec] = {}


def register(spec: TaskSpec) -> TaskSpec:
    if spec.id in _REGISTRY and _REGISTRY[spec.id] != spec:
        raise ValueError(f"task {spec.id} is already registered")
    _REGISTRY[spec.id] = spec
    if spec.id not in gym.registry:
        # gymnasium.make returns the task itself: GlyphTask refuses a step before reset and the
        # contract tests run gymnasium's full checker on every task, so the order and passive
        # checker wrappers add nothing, and check_env(gymnasium.make(id)) checks the task unwrapped
        gym.register(id=spec.id, entry_point="glyphbench_rl.core.registry:_gym_entry",
                     kwargs={"task_id": spec.id}, nondeterministic=False,
                     disable_env_checker=True, order_enforce=False)
    return spec


def register_variants(game: type | str, suite: str, variants: Mapping[str, Mapping[str, Any]],
                      tier: str = "standard") -> None:
    """Register one game's variants; each value holds parameters plus ``max_turns``."""
    for task_id, params in variants.items():
        params = dict(params)
        max_turns = params.pop("max_turns")
        register(TaskSpec(task_id, suite, tier, game, params, max_turns))


def _gym_entry(task_id: str, **overrides: Any) -> GlyphTask:
    return get_spec(task_id).make(**overrides)


def _gym_spec(spec: TaskSpec):
    return gym.registry.get(spec.id)


def check_engines(task_ids: Iterable[str]) -> None:
    """Import the engine of every task in ``task_ids`` (each once): a missing optional extra
    fails here, in one line (``MissingExtraError``), before a run loads any model."""
    for game in {get_spec(t).game for t in task_ids if isinstance(get_spec(t).game, str)}:
        module = game.partition(":")[0]
        importlib.import_module(module)


def is_registered(task_id: str) -> bool:
    return task_id in _REGISTRY


def get_spec(task_id: str) -> TaskSpec:
    try:
        return _REGISTRY[task_id]
    except KeyError:
        raise UnknownTaskError(unknown_task_message(task_id)) from None


_CATALOG = Path(__file__).resolve().parents[2] / "tasks" / "catalog.tsv"


def _catalog_suites() -> dict[str, str]:
    """Catalog task ID -> suite, for every task of the GlyphBench catalog (implemented or not)."""
    if not _CATALOG.exists():       # an installed wheel carries no task lists
        return {}
    lines = _CATALOG.read_text(encoding="utf-8").splitlines()[1:]
    return {fields[2]: fields[0] for fields in (line.split("\t") for line in lines) if len(fields) > 2}


def unknown_task_message(task_id: str) -> str:
    if task_id in _catalog_suites():
        return (f"task {task_id!r} is in the GlyphBench catalog but not implemented in this "
                f"version yet; run `glyphbench list --counts` to see which tasks are")
    close = difflib.get_close_matches(str(task_id), list(_REGISTRY), n=3, cutoff=0.5)
    if not close:  # try the short form "snake-easy" against "classics-snake-easy"
        core = {tid.split("/", 1)[-1].rsplit("-v", 1)[0]: tid for tid in _REGISTRY}
        close = [core[c] for c in difflib.get_close_matches(str(task_id), list(core), n=3, cutoff=0.4)]
    hint = f"; closest: {', '.join(close)}" if close else "; run `glyphbench list` for all IDs"
    return f"unknown task {task_id!r}{hint}"


def unregistered_tasks_message(task_ids: list[str], total: int) -> str:
    """One line for a task list naming ``task_ids`` (of ``total``) that are not registered: the
    first ID not in the catalog by its closest IDs, else how many catalog tasks are not
    implemented yet, by suite, with an example."""
    suites = _catalog_suites()
    unknown = [t for t in task_ids if t not in suites]
    if unknown or len(task_ids) == 1:
        return unknown_task_message((unknown or task_ids)[0])
    counts: dict[str, int] = {}
    for t in task_ids:
        counts[suites[t]] = counts.get(suites[t], 0) + 1
    order = sorted(counts, key=lambda suite: (-counts[suite], SUITES.index(suite)))
    by_suite = ", ".join(f"{suite} {counts[suite]}" for suite in order)
    return (f"{len(task_ids)} of the {total} tasks are not implemented in this version yet "
            f"({by_suite}); e.g. {task_ids[0]}; run `glyphbench list --counts` to see which are")


def make(task_id: str, **overrides: Any) -> GlyphTask:
    """Build a task by ID; keyword overrides replace its parameters (or ``max_turns``)."""
    return get_spec(task_id).make(**overrides)


def list_tasks(suite: str | None = None, pattern: str | None = None,
               tier: str | None = None) -> list[str]:
    """Registered task IDs, in catalog order, filtered by suite (case-insensitive), glob, tier."""
    if suite is not None:
        wanted = {s.lower() for s in SUITES}
        if suite.lower() not in wanted:
            raise ValueError(f"unknown suite {suite!r}; suites: {', '.join(SUITES)}")
    ids = []
    for spec in _REGISTRY.values():
        if suite is not None and spec.suite.lower() != suite.lower():
            continue
        if tier is not None and spec.tier != tier:
            continue
        if pattern is not None and not fnmatch.fnmatchcase(spec.id, pattern):
            continue
        ids.append(spec.id)
    return sorted(ids, key=_sort_key)


def _sort_key(task_id: str) -> tuple[int, str]:
    suite = _REGISTRY[task_id].suite
    return SUITES.index(suite), task_id


def specs() -> Iterable[TaskSpec]:
    return [_REGISTRY[t] for t in list_tasks()]
