"""The package's layers: a module imports only from its own layer and the layers below it.

Every import counts, also those inside functions (a lazy import is still a dependency), so a
circle between two packages cannot hide behind a deferred import.
"""

import ast
from pathlib import Path

import pytest

PKG = Path(__file__).resolve().parents[1] / "glyphbench_rl"

# lowest first; a module in layer k may import layers 0..k
LAYERS = [
    {"_version", "settings"},
    {"core"},
    {"games", "models"},
    {"agent"},
    {"rollout"},
    {"evaluate"},
    {"train"},
    {"replay"},
    {"integrations"},
    {"cli"},
]
RANK = {name: k for k, names in enumerate(LAYERS) for name in names}


def _unit(parts: tuple[str, ...]) -> str:
    return parts[0] if parts else ""


def imports_of(path: Path) -> list[tuple[int, tuple[str, ...]]]:
    """(line, module path inside glyphbench_rl) of every import of the package in ``path``."""
    rel = path.relative_to(PKG).with_suffix("").parts
    package = rel[:-1] if rel[-1] != "__init__" else rel[:-1]
    out = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = package[:len(package) - node.level + 1]
                target = base + tuple(node.module.split(".")) if node.module else base
            elif node.module and node.module.split(".")[0] == "glyphbench_rl":
                target = tuple(node.module.split(".")[1:])
            else:
                continue
            if not target:               # `from .. import x` at the root: a module, or the root
                out += [(node.lineno, (a.name,) if a.name in RANK else ()) for a in node.names]
            else:
                out.append((node.lineno, target))
        elif isinstance(node, ast.Import):
            for a in node.names:
                if a.name.split(".")[0] == "glyphbench_rl":
                    out.append((node.lineno, tuple(a.name.split(".")[1:])))
    return out


def violations(path: Path) -> list[str]:
    rel = path.relative_to(PKG).with_suffix("").parts
    if rel == ("__init__",):             # the root re-exports the public API
        return []
    own = _unit(rel)
    bad = []
    for line, target in imports_of(path):
        unit = _unit(target)
        if unit == "" or unit == "__init__":
            bad.append(f"{path.relative_to(PKG)}:{line} imports the package root")
        elif unit not in RANK:
            bad.append(f"{path.relative_to(PKG)}:{line} imports {'.'.join(target)}: no layer")
        elif RANK[unit] > RANK[own]:
            bad.append(f"{path.relative_to(PKG)}:{line} ({own}) imports {'.'.join(target)} "
                       f"({unit}, a higher layer)")
    return bad


def test_every_top_level_unit_has_a_layer():
    units = {p.stem if p.is_file() else p.name for p in PKG.iterdir()
             if (p.suffix == ".py" and p.stem != "__init__") or (p.is_dir() and (p / "__init__.py").exists())}
    assert units <= set(RANK), f"no layer for {sorted(units - set(RANK))}"


def test_no_module_imports_a_higher_layer_or_the_root():
    problems = [v for path in sorted(PKG.rglob("*.py")) for v in violations(path)]
    assert not problems, "\n".join(problems)


@pytest.mark.parametrize("source, expected", [
    ("from ..train.config import TrainConfig\n", "imports train.config"),
    ("from .. import __version__\n", "imports the package root"),
    ("def f():\n    from glyphbench_rl.cli.main import main\n", "imports cli.main"),
])
def test_the_check_catches_upward_imports(tmp_path, monkeypatch, source, expected):
    fake = tmp_path / "glyphbench_rl"
    (fake / "rollout").mkdir(parents=True)
    (fake / "rollout" / "bad.py").write_text(source)
    monkeypatch.setattr(__import__(__name__), "PKG", fake)
    [problem] = violations(fake / "rollout" / "bad.py")
    assert expected in problem
