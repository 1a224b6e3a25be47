"""Training: group-relative advantages, the paper's losses, memory-safe log-probs (the trainer
loop, configs and checkpoints build on these)."""

from .advantages import group_advantages

__all__ = ["group_advantages"]
