"""Held-out-seed evaluation jobs, their summaries and paired comparisons (``glyphbench-eval``)."""

from .compare import compare_records, format_comparison
from .job import EvalConfig, EvalError, JobResult, rebuild_summary, run_job
from .stats import MeanCI, mean_ci, t_critical
from .store import EpisodeLogError
from .summary import format_summary, summarize

__all__ = ["EvalConfig", "EvalError", "EpisodeLogError", "JobResult", "MeanCI", "compare_records",
           "format_comparison", "format_summary", "mean_ci", "rebuild_summary", "run_job",
           "summarize", "t_critical"]
