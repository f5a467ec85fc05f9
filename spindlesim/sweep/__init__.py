"""Parameter studies: override any deck value by its path, run cases on an Executor, resume, summarise."""

from .cases import Case, build_cases, parse_set_option
from .runner import SweepInterrupted, SweepResult, run_sweep

__all__ = ["Case", "SweepInterrupted", "SweepResult", "build_cases", "parse_set_option", "run_sweep"]
