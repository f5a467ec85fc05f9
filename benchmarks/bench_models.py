"""Issue "Lobes in seconds", target 5 and the in-process part of target 4 (one BLAS thread, imports excluded;
median of N after a warm-up, wall and CPU).

4. (for the record; the target is on whole processes, benchmarks/bench_lobes.py) The Campbell diagram of the seed
   003 spindle on its 3-lobe bearings, thermal equilibrium at each of 60 speeds (decks/seed003_three_lobe.yaml,
   200..12000 rpm, 8 modes), against the same diagram on the paper's linear coefficients
   (decks/seed003_spindle_linear.yaml), each from fresh operating points (nothing solved before).
5. The model evaluations calibration and optimisation make, on the milling deck, each from the deck's model
   built again (a new design): the static stiffness at the deck's point, the first natural frequency at the
   operating speed, the tool-point FRF on 600 frequencies at the operating speed: target 20 ms each.

Usage: python benchmarks/bench_models.py [--repeat N]
"""

from __future__ import annotations

import argparse
import os
import pathlib
import statistics
import sys
import time

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

from spindlesim.analysis.campbell_study import campbell_study  # noqa: E402
from spindlesim.analysis.modal import solve_modal  # noqa: E402
from spindlesim.analysis.points import OperatingPoints  # noqa: E402
from spindlesim.analysis.static import solve_static  # noqa: E402
from spindlesim.analysis.tool_point import tool_point_model  # noqa: E402
from spindlesim.deck import load_deck  # noqa: E402
from spindlesim.model.build import build_rotor  # noqa: E402
from spindlesim.runs.common import RunContext  # noqa: E402

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from bench_campbell_fluidfilm import clear_caches  # noqa: E402
from bench_process import ROOT  # noqa: E402


def timed(fn, repeat: int) -> tuple[float, float]:
    """(median wall, median CPU) [s] of ``repeat`` calls after one warm-up call."""
    fn()
    wall, cpu = [], []
    for _ in range(repeat):
        t, c = time.perf_counter(), time.process_time()
        fn()
        wall.append(time.perf_counter() - t)
        cpu.append(time.process_time() - c)
    return statistics.median(wall), statistics.median(cpu)


def campbell_of(deck: str):
    loaded = load_deck(str(ROOT / "decks" / deck))
    speeds = np.linspace(200.0, 12000.0, 60)

    def run():
        clear_caches()  # nothing solved before: every operating point (and thermal equilibrium) afresh
        campbell_study(RunContext(loaded).points, speeds, 8)
    return run


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    d = load_deck(str(ROOT / "decks" / "milling_spindle.yaml")).deck
    rpm = float(d.operating.speed_rpm)
    at = d.static.stiffness_at
    freqs = np.linspace(1.0, 3000.0, 600)

    def static():
        pts = OperatingPoints(build_rotor(d))
        return solve_static(pts, at.node - 1, at.dof, speed_rpm=rpm).static_stiffness_N_m

    def first_mode():
        return solve_modal(OperatingPoints(build_rotor(d)), rpm, n_modes=d.modal.modes).frequency_hz[0]

    def tool_frf():
        return tool_point_model(OperatingPoints(build_rotor(d)), rpm).frf(freqs)

    rows = [("4. campbell 60 speeds, 3-lobe at thermal equilibrium", campbell_of("seed003_three_lobe.yaml"), None),
            ("4. campbell 60 speeds, linear coefficients", campbell_of("seed003_spindle_linear.yaml"), None),
            ("5. static stiffness (milling, new model)", static, 0.020),
            ("5. first natural frequency (milling, new model)", first_mode, 0.020),
            ("5. tool-point FRF, 600 frequencies (milling, new model)", tool_frf, 0.020)]
    got = {}
    print(f"{'case':58s} {'wall [ms]':>10s} {'cpu [ms]':>9s} {'target':>7s}")
    for name, fn, target in rows:
        wall, cpu = timed(fn, args.repeat)
        got[name] = wall
        mark = "" if target is None else f"{1e3 * target:5.0f}  {'MET' if wall <= target else 'NOT MET'}"
        print(f"{name:58s} {1e3 * wall:10.1f} {1e3 * cpu:9.1f} {mark}", flush=True)
    r = got[rows[0][0]] / got[rows[1][0]]
    print(f"4. in process, 3-lobe / linear: {r:.2f}x (the target, 1.5x, is on whole processes: bench_lobes.py)")


if __name__ == "__main__":
    main()
