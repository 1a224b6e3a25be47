"""HFBackend: a transformers causal LM as a token-in/token-out policy (CPU or GPU).

The engine hands over exact prompt ids; they are left-padded into micro-batches (sorted by the
number of ids the model must read, so padding stays small) and sampled with ``generate`` (KV cache
on). For every sampled token the backend returns its log-probability under the distribution it
was drawn from (after temperature and top-p), which is what a trainer's importance ratio needs.

Prefix cache: an episode's prompt at turn k+1 starts with its prompt at turn k and the ids
sampled for it, so the backend keeps, per episode (``GenRequest.key``), the keys and values of
every id it has already run through the model, and next turn feeds the model only the ids after
the longest common prefix. Reuse is decided by comparing ids, never by trusting the key, so it
stays exact when the harness window slides (the system prompt is still shared) or a key is reused.
Rows with and without a cached prefix share one batch, laid out on a common split point::

    cache part (past_key_values)     | fed part (input_ids)
    0 0 0 k k k k k k                | pad pad t t t      row with 6 cached ids, 3 to feed
    0 0 0 0 0 0 0 0 0                | t t t t t          row with nothing cached

Padded slots hold zero keys/values and attention-mask 0. ``generate`` derives position ids from
the mask's running count, so every fed id gets its true (unpadded) position, matching the
positions already rotated into the cached keys.
"""

from __future__ import annotations

import dataclasses
import functools
import warnings
from dataclasses import dataclass
from typing import Any, Hashable, Iterable, Sequence

from .backend import GenRequest, Generation


@functools.cache
def _cache_arg() -> str:
    """What ``generate`` calls a KV cache, in its argument and its output: ``cache`` in
    transformers 5 (``past_key_values`` is deprecated there), ``past_key_values`` before."""
    try:
        from transformers.generation.utils import GenerateDecoderOnlyOutput
    except ImportError:
        return "past_key_values"
    names = {f.name for f in dataclasses.fields(GenerateDecoderOnlyOutput)}
    return "cache" if "cache" in names else "past_key_values"


@dataclass
class CachedPrefix:
    """The ids whose keys and values are held, and those tensors: one ``(keys, values)`` pair per
    layer, each shaped ``[kv_heads, len(ids), head_dim]``."""

    ids: list[int]
    layers: list[tuple[Any, Any]]


class PrefixCache:
    """Cached prefixes by episode key, holding at most ``max_tokens`` ids in all.

    Entries live for one ``generate`` call: the next call takes those of its requests and drops the
    rest (every live episode asks each turn, so a missing key is a finished episode). An entry
    that would pass the budget is not kept; its episode is prefilled in full next turn.
    """

    def __init__(self, max_tokens: int) -> None:
        self.max_tokens = max_tokens
        self.tokens = 0
        self._entries: dict[Hashable, CachedPrefix] = {}
        self._weights_version: int | None = None

    def __len__(self) -> int:
        return len(self._entries)

    def take(self, keys: Iterable[Hashable], weights_version: int) -> dict[Hashable, CachedPrefix]:
        """Remove and return the entries of ``keys``, dropping all others. Keys and values computed
        with other weights are useless, so a changed ``weights_version`` returns nothing."""
        entries = self._entries if weights_version == self._weights_version else {}
        taken = {k: entries[k] for k in keys if k in entries}
        self._entries, self.tokens, self._weights_version = {}, 0, weights_version
        return taken

    def put(self, key: Hashable, prefix: CachedPrefix) -> bool:
        old = self._entries.pop(key, None)
        self.tokens -= len(old.ids) if old is not None else 0
        if self.tokens + len(prefix.ids) > self.max_tokens:
            return False
        self._entries[key] = prefix
        self.tokens += len(prefix.ids)
        return True


def reusable_length(cached: CachedPrefix | None, prompt: Sequence[int]) -> int:
    """How many leading prompt ids have cached keys and values: the common prefix of the cached ids
    and the prompt, less one if it is the whole prompt (the last id must be fed for its logits)."""
    if cached is None:
        return 0
    n = 0
    for a, b in zip(cached.ids, prompt):
        if a != b:
            break
        n += 1
    return max(0, min(n, len(prompt) - 1))


def build_batch_cache(rows: Sequence[tuple[CachedPrefix | None, int]], width: int) -> Any:
    """A ``DynamicCache`` of ``width`` positions in which row i holds the first ``n_i`` cached
    positions of its prefix right-aligned (ending at ``width``) and zeros before them."""
    from transformers import DynamicCache

    sample = next(p for p, n in rows if n > 0)
    layers = []
    for layer, (k0, v0) in enumerate(sample.layers):
        keys = k0.new_zeros((len(rows), k0.shape[0], width, k0.shape[2]))
        values = v0.new_zeros((len(rows), v0.shape[0], width, v0.shape[2]))
        for row, (prefix, n) in enumerate(rows):
            if n > 0:
                k, v = prefix.layers[layer]
                keys[row, :, width - n:] = k[:, :n]
                values[row, :, width - n:] = v[:, :n]
        layers.append((keys, values))
    return DynamicCache(ddp_cache_data=layers)


def split_batch_cache(cache: Any, positions: Sequence[Any]) -> list[list[tuple[Any, Any]]]:
    """Per row, the keys and values at ``positions[row]`` (a 1-D index tensor of its real,
    unpadded positions, in order) of every layer of a batched ``DynamicCache``."""
    out: list[list[tuple[Any, Any]]] = [[] for _ in positions]
    for layer in cache.layers:
        for row, pos in enumerate(positions):
            out[row].append((layer.keys[row].index_select(1, pos), layer.values[row].index_select(1, pos)))
    return out


def supports_prefix_cache(model: Any) -> bool:
    """Whether the model's generation cache keeps every position of every layer (plain
    ``DynamicLayer``s), which is what splicing cached prefixes in and out needs."""
    try:
        from transformers import DynamicCache
        from transformers.cache_utils import DynamicLayer

        layers = DynamicCache(config=model.config).layers
    except (ImportError, TypeError, AttributeError, ValueError):
        return False
    return bool(layers) and all(type(layer) is DynamicLayer for layer in layers)


class HFBackend:
    """Samples replies to exact prompt ids with ``model.generate``.

    ``prefix_cache`` keeps each episode's keys and values between turns (see the module docstring);
    ``prefix_cache_max_tokens`` bounds the ids held in all. A cached id costs
    2 x layers x kv_heads x head_dim x dtype bytes (46 KB for SmolLM2-135M in float32, so the
    default is about 1.5 GB); during a call the previous turn's entries and the new ones coexist.
    """

    name = "hf"

    def __init__(self, model: Any, *, tokenizer: Any = None, device: str | None = None,
                 dtype: str | None = None, temperature: float = 1.0, top_p: float = 1.0,
                 max_new_tokens: int = 512, batch_size: int = 32, seed: int = 0,
                 prefix_cache: bool = True, prefix_cache_max_tokens: int = 32768) -> None:
        import torch

        if isinstance(model, str):
            from ..models import load_model
            self.model_name = model
            model, tokenizer = load_model(model, device=device, dtype=dtype)
        else:
            if tokenizer is None:
                raise ValueError("HFBackend given a model object needs its tokenizer too")
            self.model_name = getattr(model.config, "_name_or_path", type(model).__name__)
        if temperature < 0 or not 0 < top_p <= 1 or max_new_tokens < 1 or batch_size < 1 \
                or prefix_cache_max_tokens < 0:
            raise ValueError("HFBackend: need temperature >= 0, 0 < top_p <= 1, "
                             "max_new_tokens >= 1, batch_size >= 1, prefix_cache_max_tokens >= 0")
        self.model, self.tokenizer = model, tokenizer
        self.device = next(model.parameters()).device
        self.temperature, self.top_p = temperature, top_p
        self.max_new_tokens, self.batch_size = max_new_tokens, batch_size
        self.pad_id = tokenizer.pad_token_id if tokenizer.pad_token_id is not None else tokenizer.eos_token_id
        self.eos_id = tokenizer.eos_token_id
        self._gen = torch.Generator().manual_seed(seed)
        self._torch = torch
        if prefix_cache and not supports_prefix_cache(model):
            warnings.warn(f"HFBackend: {self.model_name} keeps no full per-layer KV cache "
                          f"(sliding or linear attention); prefix cache off", stacklevel=2)
            prefix_cache = False
        self.prefix_cache = PrefixCache(prefix_cache_max_tokens) if prefix_cache else None
        # prompt ids asked for, and how many of them were served from the prefix cache
        self.prompt_tokens = self.reused_tokens = 0

    def generate(self, requests: Sequence[GenRequest]) -> list[Generation]:
        cached: dict[Hashable, CachedPrefix] = {}
        if self.prefix_cache is not None:
            version = sum(p._version for p in self.model.parameters())   # bumped by in-place updates
            cached = self.prefix_cache.take([r.key for r in requests], version)
        rows = []
        for r in requests:
            prefix = cached.get(r.key)
            rows.append((prefix, reusable_length(prefix, r.prompt_ids)))
        fed = [len(r.prompt_ids) - n for r, (_, n) in zip(requests, rows)]
        order = sorted(range(len(requests)), key=lambda i: (fed[i], len(requests[i].prompt_ids)))
        out: list[Generation | None] = [None] * len(requests)
        for start in range(0, len(order), self.batch_size):
            chunk = order[start:start + self.batch_size]
            for i, g in zip(chunk, self._generate([requests[i] for i in chunk], [rows[i] for i in chunk])):
                out[i] = g
        return out  # type: ignore[return-value]

    def _generate(self, requests: list[GenRequest],
                  rows: list[tuple[CachedPrefix | None, int]]) -> list[Generation]:
        torch = self._torch
        prompts = [r.prompt_ids for r in requests]
        past = max(n for _, n in rows)
        width = past + max(len(p) - n for p, (_, n) in zip(prompts, rows))
        ids = torch.full((len(prompts), width), self.pad_id, dtype=torch.long)
        mask = torch.zeros((len(prompts), width), dtype=torch.long)
        for row, (p, (_, n)) in enumerate(zip(prompts, rows)):
            ids[row, past - n:past] = torch.tensor(p[:n], dtype=torch.long)
            mask[row, past - n:past] = 1
            ids[row, width - (len(p) - n):] = torch.tensor(p[n:], dtype=torch.long)
            mask[row, width - (len(p) - n):] = 1
            self.prompt_tokens += len(p)
            self.reused_tokens += n
        sample = self.temperature > 0
        kw: dict[str, Any] = dict(do_sample=True, temperature=self.temperature, top_p=self.top_p, top_k=0) \
            if sample else dict(do_sample=False)
        if past:
            # generate() sees a cache of `past` positions and feeds only input_ids[:, past:]
            kw[_cache_arg()] = build_batch_cache(rows, past)
        # generate() draws from torch's global generator: seed it from ours, per call, so a run
        # is reproducible without disturbing anything else's random state for long
        seed = int(torch.randint(0, 2**62, (1,), generator=self._gen))
        with torch.no_grad(), torch.random.fork_rng(devices=[self.device] if self.device.type == "cuda" else []):
            torch.manual_seed(seed)
            res = self.model.generate(
                input_ids=ids.to(self.device), attention_mask=mask.to(self.device),
                max_new_tokens=self.max_new_tokens, pad_token_id=self.pad_id, eos_token_id=self.eos_id,
                return_dict_in_generate=True, output_scores=True, use_cache=True, **kw)
        seqs = res.sequences[:, width:]
        # one step at a time: stacking every step's scores would hold steps x batch x vocab floats
        logp = torch.stack([torch.log_softmax(score.float(), dim=-1).gather(-1, seqs[:, t, None])[:, 0]
                            for t, score in enumerate(res.scores)], dim=1).cpu()
        new = seqs.cpu()
        gens, sampled_ids = [], []
        for row, p in enumerate(prompts):
            toks = new[row].tolist()
            n = toks.index(self.eos_id) + 1 if self.eos_id in toks else len(toks)
            finish = "stop" if self.eos_id in toks[:n] else "length"
            sampled = toks[:n]
            sampled_ids.append(sampled)
            gens.append(Generation(
                text=self.tokenizer.decode(sampled, skip_special_tokens=True), token_ids=sampled,
                logprobs=[float(x) for x in logp[row, :n]], finish_reason=finish,
                prompt_tokens=len(p), completion_tokens=n))
        if self.prefix_cache is not None:
            self._keep_prefixes(requests, sampled_ids, mask, width, getattr(res, _cache_arg()))
        return gens

    def _keep_prefixes(self, requests: list[GenRequest], sampled_ids: list[list[int]], mask: Any,
                       width: int, cache: Any) -> None:
        """Store each row's keys and values (padding stripped) for its episode's next turn."""
        torch = self._torch
        # the last sampled id of the longest reply is never fed back, so it has no keys/values
        fed = cache.get_seq_length() - width
        kept = [min(len(s), fed) for s in sampled_ids]
        positions = [torch.cat([mask[row].nonzero()[:, 0], torch.arange(width, width + k)]).to(self.device)
                     for row, k in enumerate(kept)]
        for r, s, k, layers in zip(requests, sampled_ids, kept, split_batch_cache(cache, positions)):
            self.prefix_cache.put(r.key, CachedPrefix(list(r.prompt_ids) + s[:k], layers))
