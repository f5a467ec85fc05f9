"""Rotor benchmarks on the default deck (seed 003 spindle, 26 nodes, 104 DOF).

Targets (issue 2): modal at one speed < 10 ms in-process, Campbell over 50 speeds < 0.25 s,
FRF over 1000 frequencies < 0.15 s, whole-process `spindlesim modal` < 3 s.
Prints a table: best of N repeats (wall time, single-threaded BLAS).
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import time

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")

import numpy as np  # noqa: E402

from spindlesim.analysis.campbell import solve_campbell  # noqa: E402
from spindlesim.analysis.frf import solve_frf  # noqa: E402
from spindlesim.analysis.modal import solve_modal  # noqa: E402
from spindlesim.deck import default_deck  # noqa: E402
from spindlesim.model.build import build_rotor  # noqa: E402


def best(fn, repeat):
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    return min(times), float(np.median(times))


def main() -> list[tuple[str, float, float, float]]:
    rotor = build_rotor(default_deck("spindle_linear").deck)
    speeds = np.linspace(0, 12000, 50)
    freqs = np.linspace(10, 5000, 1000)
    rows = [
        ("modal, one speed (8 modes)", *best(lambda: solve_modal(rotor, n_modes=8), 30), 0.010),
        ("campbell, 50 speeds", *best(lambda: solve_campbell(rotor, speeds, 8), 5), 0.25),
        ("frf, 1000 frequencies", *best(lambda: solve_frf(rotor, freqs, 1, "x", 1, "x"), 10), 0.15),
    ]
    with tempfile.TemporaryDirectory() as tmp:
        exe = [sys.executable, "-m", "spindlesim", "modal", "-o", tmp]
        rows.append(("process: spindlesim modal", *best(lambda: subprocess.run(exe, check=True, capture_output=True), 3), 3.0))
        exe = [sys.executable, "-m", "spindlesim", "--version"]
        rows.append(("process: spindlesim --version", *best(lambda: subprocess.run(exe, check=True, capture_output=True), 3), 0.5))
    return rows


if __name__ == "__main__":
    print(f"{'case':34s} {'best [s]':>10s} {'median [s]':>11s} {'target [s]':>11s}  ok")
    for name, b, med, target in main():
        print(f"{name:34s} {b:10.4f} {med:11.4f} {target:11.3f}  {'yes' if b <= target else 'NO'}")
