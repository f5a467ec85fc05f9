"""Benchmark: fluid-film bearing equilibrium + eight coefficients (issue 3).

Target: one 3-lobe equilibrium plus 8 coefficients at the default (1 %) grid under 0.1 s.
Run:  python benchmarks/bench_fluidfilm.py
"""

from __future__ import annotations

import math
import os
import time

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import numpy as np  # noqa: E402

from spindlesim.bearings.fluidfilm.bearing import FluidFilmBearing  # noqa: E402
from spindlesim.bearings.fluidfilm.geometry import multilobe_geometry, plain_geometry  # noqa: E402
from spindlesim.bearings.fluidfilm.performance import operating_point  # noqa: E402
from spindlesim.bearings.fluidfilm.reynolds import (  # noqa: E402
    DEFAULT_AXIAL,
    DEFAULT_CIRCUMFERENTIAL,
    ReynoldsSolver,
)
from spindlesim.bearings.fluidfilm.thermal import ThermalParameters  # noqa: E402
from spindlesim.bearings.fluidfilm.viscosity import WaltherViscosity  # noqa: E402

OMEGA = 2170 * math.pi / 30
D = 0.069965


def best_of(fn, repeat=5):
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t)
    return min(times), float(np.median(times)), out


def main() -> None:
    cases = [
        ("3-lobe L/D 1, 400 N (seed 003)", multilobe_geometry(D, D, 12e-6, 0.5, 3), 0.002, 400.0),
        ("3-lobe L/D 0.5, 400 N", multilobe_geometry(D, D / 2, 12e-6, 0.5, 3), 0.002, 400.0),
        ("3-lobe L/D 0.5, 3000 N (eps 0.8)",
         multilobe_geometry(D, D / 2, 12e-6, 0.5, 3, orientation="between_lobes"), 0.002, 3000.0),
        ("plain 360 L/D 0.5, 3000 N", plain_geometry(0.05, 0.025, 40e-6), 0.01, 3000.0),
    ]
    print(f"grid: {DEFAULT_CIRCUMFERENTIAL} intervals / 360 deg x {DEFAULT_AXIAL} across L/2")
    print(f"{'case':38s} {'unknowns':>8s} {'build ms':>9s} {'eq+8 coef ms (best/median)':>28s} {'eps':>7s}")
    for name, geo, mu, W in cases:
        tb, _, solver = best_of(lambda: ReynoldsSolver(geo), 3)
        load = np.array([0.0, -W])
        t_best, t_med, r = best_of(lambda: operating_point(solver, mu, OMEGA, load))
        print(f"{name:38s} {solver.grid.n_unknown:8d} {tb * 1e3:9.1f} "
              f"{t_best * 1e3:13.1f} / {t_med * 1e3:8.1f}     {r.eccentricity_ratio:7.4f}")
    b = FluidFilmBearing("front", 6, multilobe_geometry(D, D, 12e-6, 0.5, 3),
                         WaltherViscosity.from_grade("ISO VG 3", 805.0),
                         ThermalParameters(25.0, 20.0, 805.0, 1940.681, 0.1), 400.0)
    tt, tm, res = best_of(lambda: b.analyze(OMEGA), 3)
    print(f"{'thermal equilibrium, seed 003 node 7':38s} {'':8s} {'':9s} {tt * 1e3:13.1f} / "
          f"{tm * 1e3:8.1f}     ({res.iterations} film solutions, {res.temperature_mean_C:.2f} degC)")


if __name__ == "__main__":
    main()
