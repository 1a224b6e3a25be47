"""Seed ranges, derived random streams and seeds for external engines.

Training draws game instances from [0, 1,000,000) and held-out evaluation from
[1,000,000, 2,000,000), so the two never overlap. Independent streams are derived with
``numpy.random.SeedSequence`` (never ``seed + i``, whose streams collide across runs): a stream
is named by keys (strings hash stably across processes), and the same (seed, names) always
gives the same numbers.

Engines with their own generators get their seeds from the task seed the same way, under
fixed names: ``nle_seeds(seed)`` gives NetHack's (core, disp, lgen), ``jax_key_data(seed)`` /
``jax_seed(seed)`` a JAX PRNG key's two words / an int for ``jax.random.PRNGKey``. Each also
takes an episode's ``SeedSequence`` (``GlyphTask.seed_sequence``), so an unseeded reset that
continues the stream gives the engine fresh, reproducible seeds too. Nothing here imports the
engines.
"""

from __future__ import annotations

import hashlib
from numbers import Integral
from typing import Callable

import numpy as np

TRAIN_SEEDS = range(0, 1_000_000)
HELDOUT_SEEDS = range(1_000_000, 2_000_000)
MAX_SEED = 2**63 - 1


def check_seed(seed: object) -> int:
    """Return ``seed`` as an int, or raise TypeError/ValueError saying what is wrong with it."""
    if isinstance(seed, bool) or not isinstance(seed, Integral):
        raise TypeError(
            f"reset() needs an int seed, got {seed!r} ({type(seed).__name__}): every glyphbench "
            f"episode is reproducible from its seed (training seeds {TRAIN_SEEDS.start:,}.."
            f"{TRAIN_SEEDS.stop - 1:,}, held-out seeds {HELDOUT_SEEDS.start:,}..{HELDOUT_SEEDS.stop - 1:,})")
    seed = int(seed)
    if not 0 <= seed <= MAX_SEED:
        raise ValueError(f"seed must be in 0..{MAX_SEED}, got {seed}")
    return seed


def split_of(seed: int) -> str:
    """'train', 'heldout' or 'other' for a seed."""
    if seed in TRAIN_SEEDS:
        return "train"
    if seed in HELDOUT_SEEDS:
        return "heldout"
    return "other"


def _key(part: int | str) -> int:
    if isinstance(part, str):  # stable across processes, unlike hash()
        return int.from_bytes(hashlib.blake2b(part.encode(), digest_size=8).digest(), "little")
    return int(part)


def seed_sequence(seed: int, *keys: int | str) -> np.random.SeedSequence:
    """The stream for ``seed`` named by ``keys`` (strings hash stably), e.g. ("level",)."""
    return np.random.SeedSequence(seed, spawn_key=tuple(_key(k) for k in keys))


def derive(parent: np.random.SeedSequence, *keys: int | str) -> np.random.SeedSequence:
    """The child of ``parent`` named by ``keys``: ``derive(SeedSequence(s), *k)`` is
    ``seed_sequence(s, *k)``. A string key is a 64-bit hash, so named children do not meet the
    ``spawn()`` children (keys 0, 1, 2 ...) that unseeded resets use."""
    return np.random.SeedSequence(parent.entropy, spawn_key=(*parent.spawn_key, *map(_key, keys)),
                                  pool_size=parent.pool_size)


def generator(seed: int, *keys: int | str) -> np.random.Generator:
    return np.random.Generator(np.random.PCG64(seed_sequence(seed, *keys)))


def int_sampler(rng: np.random.Generator) -> Callable[[int, int], int]:
    """A function ``(low, high) -> int`` that returns what ``int(rng.integers(low, high))`` would,
    call for call, and leaves ``rng`` where those calls would, at about a third of their cost
    (a scalar ``integers`` call spends most of its time on argument handling).

    It reads the bit generator's 32-bit outputs through its ctypes interface (the very function
    ``integers`` uses, so the generator's buffered half-word is shared) and reduces them as numpy
    does for ranges of 2 to 2**32 - 1 numbers: Lemire's multiply-shift with its rejection rule.
    Anything else (one number, which numpy returns without a draw, ``low >= high``, numpy ints)
    goes to ``rng.integers`` itself."""
    iface = rng.bit_generator.ctypes
    next32, state = iface.next_uint32, iface.state_address
    integers = rng.integers

    def draw(low: int, high: int) -> int:
        span = high - low
        if type(span) is not int or not 1 < span < 0x100000000:   # numpy ints would overflow
            return int(integers(low, high))
        m = next32(state) * span
        if m & 0xFFFFFFFF < span:
            threshold = (0x100000000 - span) % span
            while m & 0xFFFFFFFF < threshold:
                m = next32(state) * span
        return low + (m >> 32)

    # the generator must outlive its state address
    draw.rng = rng  # type: ignore[attr-defined]
    return draw


def training_seeds(run_seed: int, count: int, *keys: int | str) -> list[int]:
    """``count`` distinct training seeds for a run, reproducible from ``run_seed`` and ``keys``."""
    if count > len(TRAIN_SEEDS):
        raise ValueError(f"at most {len(TRAIN_SEEDS)} distinct training seeds")
    rng = generator(run_seed, "training-seeds", *keys)
    return [int(s) + TRAIN_SEEDS.start for s in rng.choice(len(TRAIN_SEEDS), size=count, replace=False)]


def heldout_seeds(count: int, start: int = 0) -> list[int]:
    """The first ``count`` held-out seeds after ``start``: identical for every model (paired)."""
    if start < 0 or count < 0 or start + count > len(HELDOUT_SEEDS):
        raise ValueError(f"held-out seeds {start}..{start + count} exceed the held-out range")
    return list(HELDOUT_SEEDS[start:start + count])



# -- seeds for external engines ---------------------------------------------------------------
def _root(seed: int | np.random.SeedSequence) -> np.random.SeedSequence:
    if isinstance(seed, np.random.SeedSequence):
        return seed
    return np.random.SeedSequence(check_seed(seed))


def nle_seeds(seed: int | np.random.SeedSequence) -> tuple[int, int, int]:
    """NetHack's three generator seeds ``(core, disp, lgen)`` for a task seed (or an episode's
    SeedSequence), for NLE's ``env.seed(core, disp, reseed=False, lgen=lgen)``. Each is below
    2**63, so it fits NLE's unsigned long and a signed 64-bit integer alike."""
    words = derive(_root(seed), "nle").generate_state(3, np.uint64)
    return tuple(int(w) >> 1 for w in words)


def jax_key_data(seed: int | np.random.SeedSequence) -> np.ndarray:
    """The two uint32 words of a JAX threefry key for a task seed (or an episode's
    SeedSequence): ``jax.random.wrap_key_data(jax_key_data(s))``, or the array itself where a
    raw ``uint32[2]`` key is expected. 64 bits of key space, unlike ``PRNGKey(int32)``."""
    return derive(_root(seed), "jax").generate_state(2, np.uint32)


def jax_seed(seed: int | np.random.SeedSequence) -> int:
    """An int in [0, 2**31) for ``jax.random.PRNGKey(...)``: accepted with or without x64."""
    return int(derive(_root(seed), "jax-seed").generate_state(1, np.uint32)[0]) >> 1
