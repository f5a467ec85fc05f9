"""Sweep benchmarks (issue 7): parallel efficiency of a 32-case transient sweep on 2 local workers vs 1
(target >= 1.8x), and the overhead per case on Dask (LocalCluster) against the process pool.
Prints a table. Cases are fresh each time (a temporary directory), so nothing is skipped."""

from __future__ import annotations

import os
import tempfile
import time

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("MPLBACKEND", "Agg")

from spindlesim.deck import default_deck  # noqa: E402
from spindlesim.sweep import build_cases, run_sweep  # noqa: E402


def timed(cases, **kw) -> float:
    with tempfile.TemporaryDirectory() as tmp:
        t = time.perf_counter()
        res = run_sweep(cases, tmp, **kw)
        dt = time.perf_counter() - t
    assert all(r["status"] == "done" for r in res.records), [r.get("error") for r in res.records]
    return dt


def main():
    deck = default_deck("transient").text
    transient = build_cases(deck, {"transient.rollers": [5, 6, 7, 8, 9, 10, 11, 12],
                                   "transient.speed_rpm": [3000, 4000, 5000, 6000],
                                   "transient.duration_s": [0.1]}, "transient", options={"plots": False})
    t1 = timed(transient, workers=1)
    t2 = timed(transient, workers=2)
    small = build_cases(default_deck("spindle_linear").text, {"operating.speed_rpm": list(range(1000, 33000, 1000))},
                        "static", options={"plots": False})
    tp = timed(small, workers=2)
    td = timed(small, workers=2, scheduler="local")
    print(f"{'case':52s} {'value':>10s}")
    print(f"{'32 transient cases (rigid race, 0.1 s each), 1 worker':52s} {t1:9.1f}s")
    print(f"{'32 transient cases, 2 workers':52s} {t2:9.1f}s")
    print(f"{'speed-up 2 workers vs 1 (target >= 1.8)':52s} {t1 / t2:10.2f}")
    print(f"{'32 static cases, process pool (2 workers)':52s} {tp:9.2f}s")
    print(f"{'32 static cases, Dask LocalCluster (2 workers), incl. start':52s} {td:9.2f}s")
    print(f"{'Dask overhead per case incl. cluster start':52s} {(td - tp) / 32 * 1e3:8.0f}ms")


if __name__ == "__main__":
    main()
