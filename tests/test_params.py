"""Game parameters: one declaration per field (core.params.param), one checker, one error format."""

import ast
import dataclasses
from dataclasses import dataclass
from pathlib import Path

import pytest

import glyphbench_rl
from glyphbench_rl.core import ActionSet, GlyphTask
from glyphbench_rl.core.params import ParamError, check_params, param, param_specs, require, undeclared
from glyphbench_rl.core.registry import get_spec, list_tasks

GAMES = Path(glyphbench_rl.__file__).parent / "games"


@dataclass(frozen=True)
class Demo:
    size: int = param(8, 5, 26)
    width: int = param(9, 5, 31, odd=True)
    share: float = param(0.5, 0, 1, open_hi=True)
    chance: float = param(0.5, 0, 1, open_lo=True)
    growth: float = param(1.5, 0, None)
    target: int = param(4, 1, lambda p: p.size * p.size - 3)
    view: str = param("partial", choices=("partial", "full"))
    flag: bool = param(False)
    fleet: tuple[int, ...] = param((3, 2), 1, lambda p: p.size)
    room: tuple[int, int] = param((1, 1), 0, 2)

    def check(self) -> None:
        require(self.target != 7, "target", "anything but 7", self.target)


def error(**changes) -> str:
    with pytest.raises(ParamError) as info:
        check_params(dataclasses.replace(Demo(), **changes))
    assert "\n" not in str(info.value)
    return str(info.value)


def test_defaults_pass_and_the_checker_returns_nothing():
    assert check_params(Demo()) is None


@pytest.mark.parametrize("changes, message", [
    (dict(size=30), "size must be an int in 5..26, got 30"),
    (dict(size=4), "size must be an int in 5..26, got 4"),
    (dict(size=True), "size must be an int, got True"),
    (dict(size=8.0), "size must be an int, got 8.0"),
    (dict(size="8"), "size must be an int, got '8'"),
    (dict(width=10), "width must be an odd int in 5..31, got 10"),
    (dict(share=1), "share must be a number in [0, 1), got 1"),
    (dict(share=-0.5), "share must be a number in [0, 1), got -0.5"),
    (dict(share=False), "share must be a number, got False"),
    (dict(chance=0), "chance must be a number in (0, 1], got 0"),
    (dict(growth=-1.0), "growth must be a number >= 0, got -1.0"),
    (dict(target=62), "target must be an int in 1..61, got 62"),
    (dict(size=5, target=23), "target must be an int in 1..22, got 23"),
    (dict(view="none"), "view must be one of 'partial', 'full', got 'none'"),
    (dict(flag=1), "flag must be a bool, got 1"),
    (dict(fleet=(9,), size=8), "fleet must be a tuple of ints in 1..8, got (9,)"),
    (dict(fleet=()), "fleet must be a non-empty tuple of ints, got ()"),
    (dict(fleet=[3]), "fleet must be a non-empty tuple of ints, got [3]"),
    (dict(fleet=(3, True)), "fleet must be a non-empty tuple of ints, got (3, True)"),
    (dict(room=(1, 1, 1)), "room must be a tuple of 2 ints, got (1, 1, 1)"),
    (dict(room=(1, 3)), "room must be a tuple of ints in 0..2, got (1, 3)"),
    (dict(target=7), "target must be anything but 7, got 7"),
])
def test_one_line_errors_name_the_field_and_the_requirement(changes, message):
    assert error(**changes) == message


def test_types_are_checked_before_ranges_so_bounds_see_well_typed_fields():
    # target's bound reads size: a bad size is reported as a type error, not a crash in the bound
    assert error(size="big", target=99) == "size must be an int, got 'big'"


def test_floats_accept_ints_and_ints_refuse_floats_and_bools():
    check_params(dataclasses.replace(Demo(), share=0, chance=1, growth=3))
    assert "got 5.0" in error(size=5.0)
    assert "got False" in error(size=False)


def test_a_subclass_changing_only_a_default_keeps_the_base_range():
    @dataclass(frozen=True)
    class Narrow(Demo):
        size: int = 6

    assert param_specs(Narrow)["size"][1] == param_specs(Demo)["size"][1]
    assert undeclared(Narrow) == []
    with pytest.raises(ParamError, match="size must be an int in 5..26, got 40"):
        check_params(Narrow(size=40))


def test_undeclared_fields_are_found():
    @dataclass(frozen=True)
    class Sloppy:
        size: int = 8                        # no range
        share: float = param(0.5)            # a number needs a range
        view: str = param("a")               # a string needs choices
        flag: bool = param(True)             # a bool needs nothing more
        fine: int = param(1, 0, 3)

    assert undeclared(Sloppy) == ["size", "share", "view"]


class Probe(GlyphTask):
    title = "Probe"
    rules = "Probe {size}."
    Params = Demo
    ACTIONS = ActionSet([("WAIT", "wait")])
    glyphs = {"·": "floor"}

    def _setup(self, rng):
        pass

    def _act(self, action):
        pass

    def _grid(self):
        return ["·"]


def test_glyphtask_checks_parameters_and_names_the_task():
    assert Probe(size=10).params.size == 10
    with pytest.raises(ValueError) as info:
        Probe(task_id="glyphbench/classics-probe-v0", size=3)
    assert str(info.value) == "glyphbench/classics-probe-v0: size must be an int in 5..26, got 3"
    with pytest.raises(ParamError, match="Probe: target must be anything but 7"):
        Probe(target=7)


def test_registered_games_check_their_parameters_through_glyphtask():
    with pytest.raises(ValueError, match=r"classics-snake-easy-v0: size must be an int in 5\.\.26, got 2$"):
        glyphbench_rl.make("glyphbench/classics-snake-easy-v0", size=2)
    with pytest.raises(ValueError, match="view must be one of 'partial', 'full', got 'wide'"):
        glyphbench_rl.make("glyphbench/minigrid-empty-8x8-v0", view="wide")


@pytest.fixture(scope="module")
def game_classes():
    return {get_spec(t).load_class() for t in list_tasks()}


def test_every_registered_game_declares_every_parameter(game_classes):
    """A new game whose Params has a field without param(...) (range or choices) fails here."""
    missing = {cls.__name__: undeclared(cls.Params) for cls in game_classes if undeclared(cls.Params)}
    assert not missing, f"declare these fields with core.params.param(default, lo, hi | choices=...): {missing}"


def test_every_registered_game_has_valid_defaults(game_classes):
    for cls in game_classes:
        check_params(cls.Params())


def test_no_game_writes_its_own_parameter_checks():
    """Ranges are metadata and cross-field rules a ``check()`` hook: no Params ``__post_init__``
    and no private copy of the checker in any game module."""
    offenders = []
    for path in sorted(GAMES.rglob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, ast.ClassDef) and node.name.endswith("Params"):
                offenders += [f"{path.name}:{node.name}.__post_init__" for item in node.body
                              if isinstance(item, ast.FunctionDef) and item.name == "__post_init__"]
            if isinstance(node, ast.FunctionDef) and node.name in ("check_int", "check_range"):
                offenders.append(f"{path.name}:{node.name}")
    assert not offenders
