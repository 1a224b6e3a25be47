"""From trajectories to training sequences (token-in, token-out).

Each step of a trajectory holds the exact prompt ids the policy saw and the ids it sampled with
their sampling log-probs. While a turn's prompt extends the previous turn's prompt and reply
(the harness window has not slid), consecutive turns share one sequence: its loss mask marks every
sampled reply in it, so a window of eight turns costs one forward pass, not eight. Only sampled
tokens are trainable; prompt tokens and the template's closing tokens are context.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Iterable, Sequence

from ..rollout.trajectory import Trajectory


@dataclass
class Sample:
    ids: list[int] = field(default_factory=list)
    mask: list[int] = field(default_factory=list)        # 1 where the token was sampled
    sampling_logprobs: list[float] = field(default_factory=list)
    advantage: float = 0.0
    task_id: str = ""

    def __len__(self) -> int:
        return len(self.ids)

    @property
    def trainable(self) -> int:
        return sum(self.mask)


def trajectory_samples(traj: Trajectory, advantage: float, seq_len: int) -> tuple[list[Sample], int]:
    """The sequences of one trajectory, and how many sampled tokens did not fit ``seq_len``."""
    out: list[Sample] = []
    cur: Sample | None = None
    skipped = 0
    for step in traj.steps:
        if step.prompt_ids is None or step.completion_ids is None or step.logprobs is None:
            raise ValueError(f"{traj.task_id} seed {traj.seed}: step {step.turn} has no token ids; "
                             f"training needs a token-in/token-out backend (hf, vllm)")
        prompt, comp = step.prompt_ids, step.completion_ids
        if len(prompt) + len(comp) > seq_len:
            skipped += len(comp)
            cur = None
            continue
        extends = (cur is not None and len(prompt) >= len(cur.ids)
                   and prompt[:len(cur.ids)] == cur.ids and len(prompt) + len(comp) <= seq_len)
        if not extends:
            cur = Sample(advantage=advantage, task_id=traj.task_id)
            out.append(cur)
        context = prompt[len(cur.ids):]
        cur.ids += context + comp
        cur.mask += [0] * len(context) + [1] * len(comp)
        cur.sampling_logprobs += [0.0] * len(context) + list(step.logprobs)
    return [s for s in out if s.trainable], skipped


def micro_batches(samples: Sequence[Sample], max_tokens: int) -> Iterable[list[Sample]]:
    """Groups of samples whose padded size (count x longest) stays within ``max_tokens``; samples
    sorted by length so padding stays small. A sample longer than ``max_tokens`` goes alone."""
    batch: list[Sample] = []
    longest = 0
    for s in sorted(samples, key=len):
        width = max(longest, len(s))
        if batch and width * (len(batch) + 1) > max_tokens:
            yield batch
            batch, width = [], len(s)
        batch.append(s)
        longest = width
    if batch:
        yield batch
