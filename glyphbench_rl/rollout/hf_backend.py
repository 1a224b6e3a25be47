"""HFBackend: a transformers causal LM as a token-in/token-out policy (CPU or GPU).

The engine hands over exact prompt ids; they are left-padded into micro-batches (sorted by
length, so padding stays small) and sampled with ``generate`` (KV cache on). For every sampled
token the backend returns its log-probability under the distribution it was drawn from (after
temperature and top-p), which is what a trainer's importance ratio needs.
"""

from __future__ import annotations

from typing import Any, Sequence

from .backend import GenRequest, Generation


class HFBackend:
    name = "hf"

    def __init__(self, model: Any, *, tokenizer: Any = None, device: str | None = None,
                 dtype: str | None = None, temperature: float = 1.0, top_p: float = 1.0,
                 max_new_tokens: int = 512, batch_size: int = 32, seed: int = 0) -> None:
        import torch

        if isinstance(model, str):
            from ..models import load_model
            self.model_name = model
            model, tokenizer = load_model(model, device=device, dtype=dtype)
        else:
            if tokenizer is None:
                raise ValueError("HFBackend given a model object needs its tokenizer too")
            self.model_name = getattr(model.config, "_name_or_path", type(model).__name__)
        if temperature < 0 or not 0 < top_p <= 1 or max_new_tokens < 1 or batch_size < 1:
            raise ValueError("HFBackend: need temperature >= 0, 0 < top_p <= 1, "
                             "max_new_tokens >= 1, batch_size >= 1")
        self.model, self.tokenizer = model, tokenizer
        self.device = next(model.parameters()).device
        self.temperature, self.top_p = temperature, top_p
        self.max_new_tokens, self.batch_size = max_new_tokens, batch_size
        self.pad_id = tokenizer.pad_token_id if tokenizer.pad_token_id is not None else tokenizer.eos_token_id
        self.eos_id = tokenizer.eos_token_id
        self._gen = torch.Generator().manual_seed(seed)
        self._torch = torch

    def generate(self, requests: Sequence[GenRequest]) -> list[Generation]:
        order = sorted(range(len(requests)), key=lambda i: len(requests[i].prompt_ids))
        out: list[Generation | None] = [None] * len(requests)
        for start in range(0, len(order), self.batch_size):
            chunk = order[start:start + self.batch_size]
            for i, g in zip(chunk, self._generate([requests[i].prompt_ids for i in chunk])):
                out[i] = g
        return out  # type: ignore[return-value]

    def _generate(self, prompts: list[list[int]]) -> list[Generation]:
        torch = self._torch
        width = max(len(p) for p in prompts)
        ids = torch.full((len(prompts), width), self.pad_id, dtype=torch.long)
        mask = torch.zeros((len(prompts), width), dtype=torch.long)
        for row, p in enumerate(prompts):
            ids[row, width - len(p):] = torch.tensor(p, dtype=torch.long)
            mask[row, width - len(p):] = 1
        sample = self.temperature > 0
        kw = dict(do_sample=True, temperature=self.temperature, top_p=self.top_p, top_k=0) if sample \
            else dict(do_sample=False)
        # generate() draws from torch's global generator: seed it from ours, per call, so a run
        # is reproducible without disturbing anything else's random state for long
        seed = int(torch.randint(0, 2**62, (1,), generator=self._gen))
        with torch.no_grad(), torch.random.fork_rng(devices=[self.device] if self.device.type == "cuda" else []):
            torch.manual_seed(seed)
            res = self.model.generate(
                input_ids=ids.to(self.device), attention_mask=mask.to(self.device),
                max_new_tokens=self.max_new_tokens, pad_token_id=self.pad_id, eos_token_id=self.eos_id,
                return_dict_in_generate=True, output_scores=True, **kw)
        seqs = res.sequences[:, width:]
        # one step at a time: stacking every step's scores would hold steps x batch x vocab floats
        logp = torch.stack([torch.log_softmax(score.float(), dim=-1).gather(-1, seqs[:, t, None])[:, 0]
                            for t, score in enumerate(res.scores)], dim=1).cpu()
        new = seqs.cpu()
        gens = []
        for row, p in enumerate(prompts):
            toks = new[row].tolist()
            n = toks.index(self.eos_id) + 1 if self.eos_id in toks else len(toks)
            finish = "stop" if self.eos_id in toks[:n] else "length"
            sampled = toks[:n]
            gens.append(Generation(
                text=self.tokenizer.decode(sampled, skip_special_tokens=True), token_ids=sampled,
                logprobs=[float(x) for x in logp[row, :n]], finish_reason=finish,
                prompt_tokens=len(p), completion_tokens=n))
        return gens
