"""VLLMBackend: vLLM's offline engine as a token-in/token-out policy (GPU machines).

Prompts go in as token ids (``TokensPrompt``), so the engine's exact ids are what the model
sees; each sampled token comes back with its log-probability. vLLM is asked for processed
log-probs (after temperature/top-p) where the installed version supports it, matching what
HFBackend records. A GGUF model (the embedded default) is exported once to a safetensors folder
under ``~/.cache/glyphbench_rl/models`` because vLLM wants the HF layout.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any, Sequence

from .backend import GenRequest, Generation

CACHE = Path(os.environ.get("GLYPHBENCH_CACHE", Path.home() / ".cache" / "glyphbench_rl"))


def hf_folder(name: str) -> str:
    """A folder vLLM can load for ``name`` (GGUF models are exported on first use)."""
    from ..models import load_model, resolve_model

    where, kw = resolve_model(name)
    if "gguf_file" not in kw:
        return where
    out = CACHE / "models" / Path(kw["gguf_file"]).stem
    if not (out / "config.json").exists():
        model, tokenizer = load_model(name, device="cpu", dtype="float32")
        model.save_pretrained(out)
        tokenizer.save_pretrained(out)
    return str(out)


class VLLMBackend:
    name = "vllm"

    def __init__(self, model: str, *, temperature: float = 1.0, top_p: float = 1.0,
                 max_new_tokens: int = 512, seed: int = 0, dtype: str = "bfloat16",
                 gpu_memory_utilization: float = 0.85, max_model_len: int | None = None,
                 llm_kwargs: dict[str, Any] | None = None) -> None:
        try:
            import vllm
        except ImportError:
            raise ImportError("the vllm backend needs vLLM on a GPU machine: pip install vllm") from None
        from ..models import load_tokenizer

        self.model_name = model
        folder = hf_folder(model)
        self.tokenizer = load_tokenizer(folder)
        kw = dict(model=folder, dtype=dtype, seed=seed, gpu_memory_utilization=gpu_memory_utilization,
                  **({"max_model_len": max_model_len} if max_model_len else {}), **(llm_kwargs or {}))
        try:
            self.llm = vllm.LLM(logprobs_mode="processed_logprobs", **kw)
        except TypeError:      # older vLLM: raw log-probs only
            self.llm = vllm.LLM(**kw)
        self.params = vllm.SamplingParams(temperature=temperature, top_p=top_p,
                                          max_tokens=max_new_tokens, logprobs=0)
        self._vllm = vllm

    def generate(self, requests: Sequence[GenRequest]) -> list[Generation]:
        prompts = [{"prompt_token_ids": list(r.prompt_ids)} for r in requests]
        outputs = self.llm.generate(prompts, self.params, use_tqdm=False)
        gens = []
        for r, out in zip(requests, outputs):
            c = out.outputs[0]
            ids = list(c.token_ids)
            logprobs = [float(step[tok].logprob) for tok, step in zip(ids, c.logprobs or [])]
            if len(logprobs) != len(ids):
                raise RuntimeError("vLLM returned no log-prob for some sampled tokens")
            gens.append(Generation(text=c.text, token_ids=ids, logprobs=logprobs,
                                   finish_reason="length" if c.finish_reason == "length" else "stop",
                                   prompt_tokens=len(r.prompt_ids), completion_tokens=len(ids)))
        return gens
