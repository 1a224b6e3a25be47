"""Framework-free agent protocol: action parsing, prompt composition, harnesses."""

from .parse import REASONS, ParsedAction, final_tag, parse_action, split_reasoning

__all__ = ["REASONS", "ParsedAction", "final_tag", "parse_action", "split_reasoning"]
