"""Timing helper shared by the benchmark scripts (not a benchmark itself: benchmarks/run.py runs bench_*.py)."""

from __future__ import annotations

import math
import time
from typing import Callable


def best(fn: Callable[[], object], repeat: int, number: int) -> tuple[float, float]:
    """(best wall time, best process CPU time) per call of ``fn`` over ``repeat`` runs of ``number``
    calls; on a loaded machine the CPU time is the fairer figure (the wall time includes waiting for
    a core)."""
    wall = cpu = math.inf
    for _ in range(repeat):
        t, c = time.perf_counter(), time.process_time()
        for _ in range(number):
            fn()
        wall = min(wall, (time.perf_counter() - t) / number)
        cpu = min(cpu, (time.process_time() - c) / number)
    return wall, cpu
