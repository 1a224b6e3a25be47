"""Framework-free agent protocol: action parsing, prompt composition, harnesses."""

from .harness import LEGEND_MODES, BasicHarness, HarnessConfig, Turn, observation_text
from .parse import REASONS, ParsedAction, final_tag, parse_action, split_reasoning

__all__ = ["LEGEND_MODES", "REASONS", "BasicHarness", "HarnessConfig", "ParsedAction", "Turn",
           "final_tag", "observation_text", "parse_action", "split_reasoning"]
