"""Backends by name, so command lines and configs can pick one: ``make_backend("hf", model=...)``.

Heavy backends (torch, vLLM, HTTP clients) are imported only when asked for.
"""

from __future__ import annotations

import importlib
from typing import Any

from .backend import PolicyBackend

# name -> "module:Class" (relative to this package) and whether it needs a model
BACKENDS: dict[str, tuple[str, bool]] = {
    "random": ("backend:RandomBackend", False),
    "hf": ("hf_backend:HFBackend", True),
    "openai": ("openai_backend:OpenAIBackend", True),
    "vllm": ("vllm_backend:VLLMBackend", True),
}


def make_backend(name: str, model: str | None = None, **options: Any) -> PolicyBackend:
    """Build the backend ``name``; ``options`` are its keyword arguments (unknown ones raise)."""
    if name not in BACKENDS:
        raise ValueError(f"unknown backend {name!r}; backends: {', '.join(BACKENDS)} "
                         f"(and 'scripted' from Python)")
    target, needs_model = BACKENDS[name]
    if needs_model and not model:
        raise ValueError(f"backend {name!r} needs a model (--model)")
    module, _, cls_name = target.partition(":")
    cls = getattr(importlib.import_module(f"{__package__}.{module}"), cls_name)
    try:
        return cls(model, **options) if needs_model else cls(**options)
    except TypeError as e:  # unknown keyword: say which backend refused it
        raise ValueError(f"backend {name!r}: {e}") from None
