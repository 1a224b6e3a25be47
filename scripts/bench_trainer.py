"""Trainer benchmarks: training-step throughput against a plain forward+backward, and the peak
memory of the log-prob computation at 32k tokens with a 150k vocabulary.

    python scripts/bench_trainer.py [--tokens 1024] [--repeats 3] [--skip-memory]

1. Throughput: the trainer's update path (chunked, checkpointed log-probs + ipo loss + backward)
   against ``model(ids).logits`` -> cross-entropy -> backward on the same model and batch.
   The model has SmolLM2-135M's shape (randomly initialised; 30 layers, hidden 576, vocab
   49,152). Target: overhead <= 15%.
2. Memory: a tiny model (hidden 64) with a 150,000-token vocabulary over 32,768 tokens
   (8 x 4,096), forward+backward through ``token_logprobs``, peak resident memory measured in a
   fresh process at 8k, 16k and 32k tokens, against that process's own baseline: the kernel's
   high-water mark (VmHWM) is reset after the model loads (/proc/self/clear_refs), since a child
   process otherwise starts from its parent's peak and every size would read as +0. Full logits alone would take tokens x vocab x 4 bytes
   (19.7 GB at 32k); the chunked path must stay far below that and grow only linearly.
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
import time

TARGET_OVERHEAD = 0.15


def smollm2_shaped_model():
    import torch
    from transformers import LlamaConfig, LlamaForCausalLM

    torch.manual_seed(0)
    cfg = LlamaConfig(vocab_size=49152, hidden_size=576, intermediate_size=1536, num_hidden_layers=30,
                      num_attention_heads=9, num_key_value_heads=3, max_position_embeddings=8192,
                      tie_word_embeddings=True)
    return LlamaForCausalLM(cfg)


def throughput(tokens: int, repeats: int) -> int:
    import torch

    from glyphbench_rl.train.logprobs import token_logprobs
    from glyphbench_rl.train.losses import ipo_loss

    torch.set_num_threads(max(1, torch.get_num_threads()))
    model = smollm2_shaped_model()
    model.train()
    batch, seq = 2, tokens // 2
    ids = torch.randint(0, model.config.vocab_size, (batch, seq))
    mask = torch.ones(batch, seq)
    mask[:, : seq // 4] = 0                        # the prompt part is context only
    q = torch.full((batch, seq), -3.0)
    adv = torch.tensor([0.5, -0.5])

    def ours():
        lp = token_logprobs(model, ids, chunk=256)
        ipo_loss(lp, q, adv, mask).backward()

    def plain():
        logits = model(ids).logits
        torch.nn.functional.cross_entropy(logits[:, :-1].reshape(-1, logits.shape[-1]),
                                          ids[:, 1:].reshape(-1)).backward()

    times = {"plain": [], "trainer": []}
    for _ in range(repeats):              # interleaved, so drift hits both alike
        for name, fn in (("plain", plain), ("trainer", ours)):
            model.zero_grad(set_to_none=True)
            t0 = time.perf_counter()
            fn()
            times[name].append(time.perf_counter() - t0)
    med = {k: statistics.median(v) for k, v in times.items()}
    overhead = med["trainer"] / med["plain"] - 1
    print(f"throughput, SmolLM2-135M shape, {batch} x {seq} tokens, median of {repeats}:")
    for k in ("plain", "trainer"):
        print(f"  {k:<8} {med[k]:7.2f} s/step  {batch * seq / med[k]:8.0f} tokens/s")
    ok = overhead <= TARGET_OVERHEAD
    print(f"  overhead {overhead:+.1%} (target <= {TARGET_OVERHEAD:.0%}): {'OK' if ok else 'MISSED'}")
    return 0 if ok else 1


MEMORY_CHILD = r"""
import json, sys, torch
from transformers import LlamaConfig, LlamaForCausalLM
from glyphbench_rl.train.logprobs import token_logprobs
tokens, vocab = int(sys.argv[1]), int(sys.argv[2])
torch.manual_seed(0)
cfg = LlamaConfig(vocab_size=vocab, hidden_size=64, intermediate_size=128, num_hidden_layers=2,
                  num_attention_heads=4, num_key_value_heads=2, max_position_embeddings=8192,
                  tie_word_embeddings=True)
model = LlamaForCausalLM(cfg)
ids = torch.randint(0, vocab, (tokens // 4096, 4096))

def status_kb(field):
    for line in open("/proc/self/status"):
        if line.startswith(field + ":"):
            return int(line.split()[1])

with open("/proc/self/clear_refs", "w") as fh:   # reset the high-water mark to the current RSS
    fh.write("5")
base = status_kb("VmRSS")
token_logprobs(model, ids, chunk=512).sum().backward()
peak = status_kb("VmHWM")
print(json.dumps({"base_mb": base / 1024, "peak_mb": peak / 1024}))
"""


def child_memory(tokens: int, vocab: int) -> dict[str, float]:
    """Baseline and peak resident MB of one log-prob forward+backward, in a fresh process."""
    out = subprocess.run([sys.executable, "-c", MEMORY_CHILD, str(tokens), str(vocab)],
                         capture_output=True, text=True, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def memory(vocab: int = 150_000) -> int:
    print(f"log-prob memory, tiny model (hidden 64), vocab {vocab:,}, chunk 512, forward+backward:")
    rows = []
    for tokens in (8192, 16384, 32768):
        r = child_memory(tokens, vocab)
        extra = r["peak_mb"] - r["base_mb"]
        full = tokens * vocab * 4 / 2**20
        rows.append((tokens, extra))
        print(f"  {tokens:>6} tokens: peak {r['peak_mb']:7.0f} MB (+{extra:6.0f} MB over the loaded "
              f"model); full logits alone would be {full:8.0f} MB")
    growth = rows[-1][1] / max(rows[0][1], 1)
    ok = rows[-1][1] < 0.1 * (32768 * vocab * 4 / 2**20)
    print(f"  32k/8k growth x{growth:.1f} (linear in tokens would be x4); "
          f"under a tenth of full logits: {'OK' if ok else 'MISSED'}")
    return 0 if ok else 1


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tokens", type=int, default=1024, help="tokens per throughput batch")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--skip-memory", action="store_true")
    ap.add_argument("--skip-throughput", action="store_true")
    args = ap.parse_args()
    rc = 0
    if not args.skip_throughput:
        rc |= throughput(args.tokens, args.repeats)
    if not args.skip_memory:
        rc |= memory()
    return rc


if __name__ == "__main__":
    raise SystemExit(main())
