"""The import graph of ``glyphbench_rl.games``, read from the source with ``ast``:

(a) a family (a subpackage of ``games`` other than ``common``) never imports another family;
(b) ``games.common`` imports no family;
(c) inside a family, modules import only the family's engine-level modules (declared below), so
    a game module never imports another game module; only the family's ``__init__`` imports its
    games (that is how they register);
(d) nothing under ``games`` imports a ``glyphbench_rl`` package other than ``core`` and ``games``.
"""

from __future__ import annotations

import ast
from pathlib import Path

import glyphbench_rl

PACKAGE = "glyphbench_rl"
GAMES = Path(glyphbench_rl.__file__).parent / "games"

# The modules of each family that its game modules may import. A new family declares its own.
ENGINE_LEVEL = {
    "arcade": {"engine", "bodies", "arena", "chase", "climbing", "dungeon", "duel", "hopping", "pinball", "platform", "rooms", "scroller", "sectors", "shooter", "sidescroll"},
    "classics": {"versus"},
    "minigrid": {"engine", "world", "grid", "rooms", "solver"},
    "procgen": {"engine", "mazes", "platforms", "scrolling", "shooting"},
    "craftax": {"bestiary", "full", "hud", "kernel", "kernel_mobs", "kernel_rules", "kernel_view", "mobs", "packed", "noise", "planner", "rules", "scenarios", "state", "suite", "tables", "task", "upkeep", "view", "worldgen"},
    "nethack": {"engine", "render", "levels", "boxoban", "boxoban_env", "custom", "lean", "rawstep"},
}
SHARED = "common"


def module_name(path: Path, root: Path) -> str:
    parts = list(path.relative_to(root.parent).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join([PACKAGE, *parts])


def imports_of(name: str, source: str, is_package: bool, known: set[str]) -> list[tuple[int, str]]:
    """(line, absolute module) for every import statement in ``source``, wherever it stands
    (function bodies and ``if TYPE_CHECKING`` blocks included)."""
    out = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Import):
            out += [(node.lineno, alias.name) for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = name.split(".")
                base = base[:len(base) - node.level + (1 if is_package else 0)]
                parent = ".".join(base + ([node.module] if node.module else []))
            else:
                parent = node.module
            for alias in node.names:        # `from pkg import module` imports the module
                sub = f"{parent}.{alias.name}"
                is_module = sub in known or parent in (PACKAGE, f"{PACKAGE}.games")
                out.append((node.lineno, sub if is_module else parent))
    return sorted(set(out))


def violations(modules: dict[str, tuple[str, bool]]) -> list[str]:
    """Every broken rule in ``modules`` (absolute name -> (source, is_package))."""
    known = set(modules)
    found = []
    for name, (source, is_package) in sorted(modules.items()):
        parts = name.split(".")
        family = parts[2] if len(parts) > 2 else None
        is_family_init = is_package and len(parts) == 3
        for line, target in imports_of(name, source, is_package, known):
            where = f"{name}:{line} imports {target}"
            t = target.split(".")
            if t[0] != PACKAGE:
                continue                                   # stdlib and third-party packages
            if len(t) < 2 or t[1] not in ("core", "games"):
                found.append(f"{where}: games may import only core and games.common (d)")
                continue
            if t[1] == "core":
                continue
            t_family = t[2] if len(t) > 2 else None
            if t_family is None:
                found.append(f"{where}: import a family or common, not the games package (d)")
            elif family == SHARED and t_family != SHARED:
                found.append(f"{where}: games.common must not import a family (b)")
            elif family not in (None, SHARED) and t_family not in (family, SHARED):
                found.append(f"{where}: a family must not import another family (a)")
            elif (family not in (None, SHARED) and t_family == family and not is_family_init
                  and len(t) > 3 and t[3] not in ENGINE_LEVEL.get(family, set())):
                found.append(f"{where}: {family} modules import only its engine-level modules "
                             f"{sorted(ENGINE_LEVEL.get(family, ()))} (c)")
    return found


def load_games() -> dict[str, tuple[str, bool]]:
    return {module_name(p, GAMES): (p.read_text(encoding="utf-8"), p.name == "__init__.py")
            for p in sorted(GAMES.rglob("*.py"))}


# -- the real tree ----------------------------------------------------------------------------------
def test_games_import_graph_follows_the_rules():
    problems = violations(load_games())
    assert not problems, "\n".join(problems)


def test_every_family_declares_its_engine_level_modules_and_they_exist():
    families = {p.name for p in GAMES.iterdir() if (p / "__init__.py").exists()} - {SHARED}
    assert families == set(ENGINE_LEVEL), "declare the new family's engine-level modules in ENGINE_LEVEL"
    for family, modules in ENGINE_LEVEL.items():
        for module in modules:
            assert (GAMES / family / f"{module}.py").exists(), f"{family}.{module}"


def test_the_checker_reads_the_real_tree():
    modules = load_games()
    assert "glyphbench_rl.games.common.grid" in modules and "glyphbench_rl.games.classics.snake" in modules
    name = "glyphbench_rl.games.classics.snake"
    targets = {t for _, t in imports_of(name, modules[name][0], False, set(modules))}
    assert {"glyphbench_rl.core", "glyphbench_rl.games.common.grid"} <= targets


# -- the checker catches violations -------------------------------------------------------------------
def fake(**sources: str) -> dict[str, tuple[str, bool]]:
    """Synthetic modules: keyword ``classics__snake`` is glyphbench_rl.games.classics.snake;
    a trailing ``__init`` makes a package."""
    out = {}
    for key, source in sources.items():
        parts = key.split("__")
        is_package = parts[-1] == "init"
        if is_package:
            parts.pop()
        out[".".join([PACKAGE, "games", *parts])] = (source, is_package)
    return out


BASE = dict(
    classics__init="from . import snake, maze\n",
    classics__versus="from ...core import GlyphTask\n",
    classics__snake="from ...core import GlyphTask\nfrom ..common.grid import DELTAS\nfrom .versus import choose\n",
    classics__maze="from glyphbench_rl.games.common import palette\n",
    minigrid__init="from . import empty\n",
    minigrid__engine="from ...core import GlyphTask\nfrom .world import WALL\n",
    minigrid__world="from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    from .engine import MiniGridTask\n",
    minigrid__empty="import numpy as np\nfrom .engine import MiniGridTask\nfrom .world import Goal\n",
    common__init="",
    common__grid="from ...core.actions import ActionSet\n",
    common__palette="",
)


def check(**changes: str) -> list[str]:
    return violations(fake(**{**BASE, **changes}))


def test_a_clean_synthetic_tree_passes():
    assert check() == []


def test_a_family_importing_another_family_is_caught():
    assert any("(a)" in v for v in check(classics__snake="from ..minigrid.engine import beside\n"))
    assert any("(a)" in v for v in check(classics__snake="from glyphbench_rl.games.minigrid import world\n"))
    assert any("(a)" in v for v in check(minigrid__empty="def f():\n    from ..classics import grid\n"))


def test_common_importing_a_family_is_caught():
    assert any("(b)" in v for v in check(common__grid="from ..classics.versus import choose\n"))
    assert any("(b)" in v for v in check(common__grid="import glyphbench_rl.games.minigrid.world\n"))


def test_a_game_importing_another_game_of_its_family_is_caught():
    assert any("(c)" in v for v in check(minigrid__empty="from .doorkey import DoorKeyParams\n",
                                            minigrid__doorkey=""))
    assert any("(c)" in v for v in check(classics__maze="from .snake import Snake\n"))
    assert any("(c)" in v for v in check(classics__maze="from . import snake\n"))
    assert any("(c)" in v for v in check(minigrid__engine="from .empty import Empty\n"))


def test_importing_other_project_packages_is_caught():
    assert any("(d)" in v for v in check(classics__snake="from ...agent import parse_action\n"))
    assert any("(d)" in v for v in check(common__grid="import glyphbench_rl.rollout\n"))
    assert any("(d)" in v for v in check(minigrid__empty="import glyphbench_rl\n"))
    assert any("(d)" in v for v in check(classics__snake="from ... import cli\n"))
    assert check(classics__snake="from ... import core\nfrom .. import common\n") == []
