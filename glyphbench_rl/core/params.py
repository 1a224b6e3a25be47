"""Game parameters: each field declares its range once, and one checker validates them all.

A game's ``Params`` is a frozen dataclass whose fields are declared with :func:`param`; the field's
annotation gives its type and ``param`` its range or choices::

    @dataclass(frozen=True)
    class SnakeParams:
        size: int = param(8, 5, 26)                              # an int in 5..26
        width: int = param(13, 7, 31, odd=True)                  # an odd int in 7..31
        death_penalty: float = param(0.5, 0, 1)                  # a number in [0, 1]
        time_weight: float = param(0.5, 0, 1, open_hi=True)      # a number in [0, 1)
        view: str = param("partial", choices=("partial", "full"))
        random_start: bool = param(False)                        # a bool: the type is the range
        fleet: tuple[int, ...] = param((5, 4), 1, lambda p: p.size)   # every element in range
        target: int = param(8, 1, lambda p: p.size ** 2 - 3)     # a bound computed from fields

        def check(self) -> None:                 # only constraints that are not one field's range
            require(self.gate_width % 2 == 1, "gate_width", "odd", self.gate_width)

``GlyphTask`` runs :func:`check_params` on every instance it builds, so no game writes a range
check: types first (an int field refuses floats and bools, a float field takes ints), then the
ranges in field order, then the ``check()`` hook. Every error is one line, ``"<field> must be
<requirement>, got <value>"``. A subclass that only changes a field's default writes the plain
default (``room_size: int = 6``) and keeps the range its base declared.
"""

from __future__ import annotations

import dataclasses
import typing
from dataclasses import dataclass
from functools import lru_cache
from typing import Any, Callable, Sequence, Union

PARAM = "glyphbench_param"           # the field-metadata key holding a field's ParamSpec

Bound = Union[int, float, Callable[[Any], Union[int, float]], None]


class ParamError(ValueError):
    """A game parameter outside its declared type or range (one line, naming the field)."""


@dataclass(frozen=True)
class ParamSpec:
    lo: Bound = None
    hi: Bound = None
    choices: tuple | None = None
    open_lo: bool = False
    open_hi: bool = False
    odd: bool = False


def param(default: Any, lo: Bound = None, hi: Bound = None, *, choices: Sequence | None = None,
          open_lo: bool = False, open_hi: bool = False, odd: bool = False) -> Any:
    """A dataclass field with a declared range: ``lo``..``hi`` inclusive unless ``open_lo`` /
    ``open_hi`` (a bound may be a function of the params, evaluated after the types are
    checked), and odd if ``odd``; or one of ``choices``. For a tuple field the range applies to
    every element."""
    spec = ParamSpec(lo, hi, None if choices is None else tuple(choices), open_lo, open_hi, odd)
    return dataclasses.field(default=default, metadata={PARAM: spec})


def require(ok: bool, name: str, requirement: str, value: object) -> None:
    """Raise the one-line parameter error unless ``ok``: for ``check()`` hooks."""
    if not ok:
        raise ParamError(f"{name} must be {requirement}, got {value!r}")


@lru_cache(maxsize=None)
def param_specs(cls: type) -> dict[str, tuple[Any, ParamSpec | None]]:
    """Field name -> (resolved type, declared spec or None) for a Params dataclass, in field
    order; a field redeclared without metadata takes the spec of the nearest base declaring it."""
    try:
        hints = typing.get_type_hints(cls)
    except (NameError, TypeError):      # an annotation that does not resolve: no type check
        hints = {}
    out = {}
    for f in dataclasses.fields(cls):
        spec = next((base.__dataclass_fields__[f.name].metadata[PARAM] for base in cls.__mro__
                     if f.name in getattr(base, "__dataclass_fields__", {})
                     and PARAM in base.__dataclass_fields__[f.name].metadata), None)
        out[f.name] = (hints.get(f.name, Any), spec)
    return out


def undeclared(cls: type) -> list[str]:
    """Fields of ``cls`` that declare no range or choices (a bool field needs neither)."""
    def bare(kind: Any, spec: ParamSpec) -> bool:
        return kind is not bool and spec.choices is None and spec.lo is None and spec.hi is None
    return [name for name, (kind, spec) in param_specs(cls).items() if spec is None or bare(kind, spec)]


def check_params(params: Any) -> None:
    """Validate every declared field of ``params``, then its ``check()`` hook; ParamError if not."""
    specs = param_specs(type(params))
    for name, (kind, spec) in specs.items():
        _check_type(name, kind, getattr(params, name))
    for name, (kind, spec) in specs.items():
        if spec is not None:
            _check_range(params, name, kind, spec, getattr(params, name))
    hook = getattr(params, "check", None)
    if callable(hook):
        hook()


# -- internals -----------------------------------------------------------------------------------
def _base(kind: Any) -> Any:
    return typing.get_origin(kind) or kind


def _is(value: object, kind: Any) -> bool:
    if kind is bool:
        return isinstance(value, bool)
    if kind is int:
        return isinstance(value, int) and not isinstance(value, bool)
    if kind is float:
        return isinstance(value, (int, float)) and not isinstance(value, bool)
    if kind is str:
        return isinstance(value, str)
    return True


_NAMES = {bool: "a bool", int: "an int", float: "a number", str: "a string"}


def _check_type(name: str, kind: Any, value: object) -> None:
    if _base(kind) is not tuple:
        if not _is(value, kind):
            raise ParamError(f"{name} must be {_NAMES[kind]}, got {value!r}")
        return
    args = typing.get_args(kind)                 # (int, ...) any length, (int, int) exactly two
    fixed = bool(args) and args[-1] is not Ellipsis
    element = args[0] if args else Any
    if (not isinstance(value, tuple) or not value or (fixed and len(value) != len(args))
            or not all(_is(v, element) for v in value)):
        noun = _NAMES.get(element, "a value").split(" ", 1)[1] + "s"
        what = f"a tuple of {len(args)} {noun}" if fixed else f"a non-empty tuple of {noun}"
        raise ParamError(f"{name} must be {what}, got {value!r}")


def _check_range(params: Any, name: str, kind: Any, spec: ParamSpec, value: Any) -> None:
    element = typing.get_args(kind)[0] if _base(kind) is tuple else kind
    values = value if _base(kind) is tuple else (value,)
    if spec.choices is not None:
        if any(v not in spec.choices for v in values):
            options = ", ".join(repr(c) for c in spec.choices)
            raise ParamError(f"{name} must be one of {options}, got {value!r}")
        return
    lo = spec.lo(params) if callable(spec.lo) else spec.lo
    hi = spec.hi(params) if callable(spec.hi) else spec.hi
    if all((lo is None or (v > lo if spec.open_lo else v >= lo))
           and (hi is None or (v < hi if spec.open_hi else v <= hi)) and (not spec.odd or v % 2 == 1)
           for v in values):
        return
    noun = ("an odd int" if spec.odd else "an int") if element is int else "a number"
    if element is int and not spec.open_lo and not spec.open_hi and lo is not None and hi is not None:
        what = f"{noun} in {lo}..{hi}"
    elif lo is not None and hi is not None:
        what = f"{noun} in {'(' if spec.open_lo else '['}{lo:g}, {hi:g}{')' if spec.open_hi else ']'}"
    elif lo is not None:
        what = f"{noun} {'>' if spec.open_lo else '>='} {lo:g}"
    else:
        what = f"{noun} {'<' if spec.open_hi else '<='} {hi:g}"
    if _base(kind) is tuple:
        what = "a tuple of " + what.replace(noun, noun.split(" ", 1)[1] + "s")
    raise ParamError(f"{name} must be {what}, got {value!r}")
