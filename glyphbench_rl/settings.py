"""One way to check run configs: pydantic models whose errors are one line naming the key.

The train, eval, sweep and harness configs subclass ``Settings``: strict types (no bool for an
int, no ``"5"`` for an int; an int is accepted for a float), unknown keys refused, ranges and
choices declared with ``Field(ge=..., le=...)`` and ``Literal``. ``one_line`` turns pydantic's
report into one sentence about its first error: the dotted key and what it must be, phrased from
the field's JSON schema (``lr must be a number in (0, 1], got 0``), or ``unknown config key
'lrr'; did you mean 'lr'?``. A field whose shape has no short phrase states it in its
``description`` (``tasks``: "a task-list file, glob or comma list, or a non-empty list of task
IDs").
"""

from __future__ import annotations

import difflib
from contextlib import contextmanager
from typing import Any, ClassVar, Iterator

from pydantic import BaseModel, ConfigDict, ValidationError

__all__ = ["STRICT", "Settings", "one_line", "reported", "unknown_key"]


#: the rules every config follows; a plain ``BaseModel`` nested inside a ``Settings`` uses them too
STRICT = ConfigDict(strict=True, extra="forbid", allow_inf_nan=False, validate_assignment=True)


class Settings(BaseModel):
    """A validated config: constructing one with a bad value raises ``error`` with one line.

    Nest plain ``BaseModel``s (``model_config = STRICT``), not ``Settings``: a nested model's
    errors then keep their dotted location (``variants.long.grids``).
    """

    model_config = STRICT

    error: ClassVar[type[Exception]] = ValueError   # what a bad value raises
    where: ClassVar[str] = ""          # dotted path of these settings in a larger file ("harness")
    kind: ClassVar[str] = "config"     # "unknown config key ...", "unknown sweep key ..."

    def __init__(self, **data: Any) -> None:
        with reported(type(self)):
            super().__init__(**data)
        self.check()

    def __setattr__(self, name: str, value: Any) -> None:
        with reported(type(self)):
            super().__setattr__(name, value)

    def check(self) -> None:
        """Checks a schema cannot state (the task registry, files); raise ``self.error``."""


@contextmanager
def reported(model: type[Settings]) -> Iterator[None]:
    """Re-raise a ``ValidationError`` from inside as ``model.error`` with ``one_line``'s text."""
    try:
        yield
    except ValidationError as e:
        raise model.error(one_line(e, model)) from None


def unknown_key(key: str, known: list[str], kind: str = "config", where: str = "") -> str:
    """``unknown config key 'lrr'; did you mean 'lr'?`` (or the known keys, when they are few)."""
    prefix = f"{where}." if where else ""
    close = difflib.get_close_matches(key, known, n=1)
    if close:
        hint = f"; did you mean {prefix + close[0]!r}?"
    else:
        hint = f"; the keys are {', '.join(known)}" if len(known) <= 10 else ""
    return f"unknown {kind} key {prefix + key!r}{hint}"


def one_line(error: ValidationError, model: type[BaseModel]) -> str:
    """The first error of ``error`` (raised validating ``model``) as one line naming its key."""
    first = error.errors(include_url=False)[0]
    root = model.model_json_schema()
    loc = list(first["loc"])
    node, path = root, []
    for i, part in enumerate(loc):        # follow the location as far as the schema goes
        child = _child(root, node, part)
        if child is None or loc[i + 1:i + 2] == ["[key]"]:   # a union member's tag, an extra
            break                                             # key, a mapping's bad key
        node, path = child, path + [part]
    where = getattr(model, "where", "")
    dotted = ".".join(str(p) for p in ([where] if where else []) + path)
    name = dotted or "the config"
    kind = first["type"]
    if kind == "extra_forbidden":
        known = list(_resolve(root, node).get("properties", {}))
        return unknown_key(str(loc[len(path)]), known, getattr(model, "kind", "config"), dotted)
    if kind == "missing":
        return f"{name} is required"
    if kind == "frozen_instance":
        return f"{name} cannot be changed"
    if "[key]" in loc:
        return f"{name} keys must be strings, got {_show(first['input'])}"
    if kind in ("value_error", "assertion_error"):
        return f"{name}: {first['msg'].split(', ', 1)[-1]}"
    return f"{name} must be {_phrase(root, node)}, got {_show(first['input'])}"


def _resolve(root: dict, node: dict) -> dict:
    while "$ref" in node:
        node = root["$defs"][node["$ref"].rsplit("/", 1)[-1]]
    return node


def _child(root: dict, node: dict, part: Any) -> dict | None:
    node = _resolve(root, node)
    if isinstance(part, str) and part in node.get("properties", {}):
        return node["properties"][part]
    if isinstance(part, int) and not isinstance(part, bool):
        items = node.get("prefixItems")
        if items and part < len(items):
            return items[part]
        if isinstance(node.get("items"), dict):
            return node["items"]
    if part != "[key]" and isinstance(node.get("additionalProperties"), dict):
        return node["additionalProperties"]
    for member in node.get("anyOf", []):  # an optional value: look inside its non-null shape
        if member.get("type") != "null" and (child := _child(root, member, part)) is not None:
            return child
    return None


def _phrase(root: dict, node: dict) -> str:
    """What a value of this JSON-schema node is, in words: ``an int >= 1``, ``true or false``."""
    if "description" in node:             # a field's own words (a model's docstring is not)
        return node["description"]
    node = _resolve(root, node)
    if "anyOf" in node:
        shapes = [m for m in node["anyOf"] if m.get("type") != "null"]
        text = " or ".join(_phrase(root, m) for m in shapes)
        return text + " or null" if len(shapes) < len(node["anyOf"]) else text
    if "enum" in node:
        return "one of " + ", ".join(repr(v) for v in node["enum"])
    if "const" in node:
        return repr(node["const"])
    kind = node.get("type")
    if kind in ("integer", "number"):
        return ("an int" if kind == "integer" else "a number") + _range(node)
    if kind == "boolean":
        return "true or false"
    if kind == "string":
        text = "a non-empty string" if node.get("minLength", 0) > 0 else "a string"
        return text + (f" of at most {node['maxLength']} characters" if "maxLength" in node else "")
    if kind == "array":
        n = node.get("minItems", 0)
        return "a non-empty list" if n == 1 else f"a list of at least {n} items" if n else "a list"
    if kind == "object":
        return "a mapping"
    return "valid"


def _range(node: dict) -> str:
    lo = node.get("minimum", node.get("exclusiveMinimum"))
    hi = node.get("maximum", node.get("exclusiveMaximum"))
    lo_open, hi_open = "exclusiveMinimum" in node, "exclusiveMaximum" in node
    if lo is not None and hi is not None:
        return f" in {'(' if lo_open else '['}{_num(lo)}, {_num(hi)}{')' if hi_open else ']'}"
    if lo is not None:
        return f" {'>' if lo_open else '>='} {_num(lo)}"
    if hi is not None:
        return f" {'<' if hi_open else '<='} {_num(hi)}"
    return ""


def _num(x: float) -> str:
    return f"{x:g}" if isinstance(x, float) else str(x)


def _show(value: Any, limit: int = 80) -> str:
    text = repr(value)
    return text if len(text) <= limit else text[:limit - 3] + "..."
