"""Benchmark and error study of the dynamic fluid-film force (exact Reynolds vs table).

For each bearing: cold table build time (empty cache), time per call of both methods, and
the error of the table against the exact solve over random states in the region a transient
visits: journal anywhere in the disk e/Cb <= 0.9, velocity of any direction with magnitude
up to that of a synchronous whirl orbit at the full clearance (|v| <= omega Cb), 80 % of the
states at the operating speed and 20 % at omega = 0 (pure squeeze, start of a run-up).

Errors are relative to the exact film force at that state ("load capacity at that point"):
force |F_t - F_e| / |F_e|; tangents max|K_t - K_e| / max|K_e| (same for C).  Max, RMS and
99th percentile are printed.
Run:  python benchmarks/bench_film_force.py [n_states] [n_radial,n_angle,n_direction]
"""

from __future__ import annotations

import math
import os
import sys
import tempfile
import time

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")

import numpy as np  # noqa: E402

from spindlesim.bearings.fluidfilm.film_force import ExactFilmForce  # noqa: E402
from spindlesim.bearings.fluidfilm.film_table import TableFilmForce, TableResolution  # noqa: E402
from spindlesim.bearings.fluidfilm.geometry import multilobe_geometry, plain_geometry  # noqa: E402

OMEGA = 2170 * math.pi / 30
D = 0.069965
MU = 0.002


def states(n: int, omega: float, eps_max: float = 0.9, seed: int = 0):
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < n:
        X = rng.uniform(-eps_max, eps_max, 2)
        if X @ X > eps_max**2:
            continue
        vm = rng.uniform(0.0, 1.0) * omega
        d = rng.uniform(0.0, 2 * math.pi)
        w = omega if len(out) < 0.8 * n else 0.0
        out.append((X, vm * np.array([math.cos(d), math.sin(d)]), w))
    return out


def stats(e: np.ndarray) -> str:
    return (f"max {100 * e.max():6.3f} %  rms {100 * math.sqrt(np.mean(e**2)):6.3f} %  "
            f"p99 {100 * np.percentile(e, 99):6.3f} %")


def study(name: str, geo, n: int, res: TableResolution) -> None:
    print(f"\n== {name} (L/D {geo.l_over_d:g}, mp {geo.preload:g}, {len(geo.lands)} land(s)) ==")
    with tempfile.TemporaryDirectory() as tmp:
        t0 = time.perf_counter()
        table = TableFilmForce(geo, resolution=res, directory=tmp)
        tb = time.perf_counter() - t0
        t0 = time.perf_counter()
        TableFilmForce(geo, resolution=res, directory=tmp + "/")  # new key path: from disk
        tl = time.perf_counter() - t0
    print(f"table {res.n_radial} x {res.n_angle} x {res.n_direction} (e/Cb <= "
          f"{res.eccentricity_max}): cold build {tb:.2f} s (incl. compile), reload {tl * 1e3:.1f} ms")
    exact = ExactFilmForce(geo)
    c = geo.clearance_m
    sts = states(n, OMEGA)
    ef, ek, ec, e0 = [], [], [], []
    t_exact = 0.0
    for X, V, w in sts:
        q, v = X * c, V * c
        t0 = time.perf_counter()
        fe, Ke, Ce = exact.force_and_tangent(q, v, w, MU)
        t_exact += time.perf_counter() - t0
        ft, Kt, Ct = table.force_and_tangent(q, v, w, MU)
        ef.append(np.hypot(*(ft - fe)) / np.hypot(*fe))
        ek.append(np.abs(Kt - Ke).max() / np.abs(Ke).max())
        ec.append(np.abs(Ct - Ce).max() / np.abs(Ce).max())
        e0.append(w == 0.0)
    ef, ek, ec, e0 = map(np.array, (ef, ek, ec, e0))
    print(f"states: {n} ({int(e0.sum())} at omega = 0), e/Cb <= 0.9, |v| <= omega Cb")
    print(f"  force   (all)      {stats(ef)}")
    print(f"  force   (omega=0)  {stats(ef[e0])}")
    print(f"  K_t     (all)      {stats(ek)}")
    print(f"  C_t     (all)      {stats(ec)}")
    # timings: a Newton-like sequence (small moves) for the exact model (warm start), and
    # the table on the same sequence
    X0, V0 = np.array([0.3, -0.5]) * c, np.array([0.2, 0.1]) * OMEGA * c
    seq = [(X0 + 1e-3 * c * k * np.array([1.0, -0.5]), V0) for k in range(50)]
    t0 = time.perf_counter()
    for q, v in seq:
        exact.force_and_tangent(q, v, OMEGA, MU)
    te = (time.perf_counter() - t0) / len(seq)
    reps = 20
    t0 = time.perf_counter()
    for _ in range(reps):
        for q, v in seq:
            table.force_and_tangent(q, v, OMEGA, MU)
    tt = (time.perf_counter() - t0) / (reps * len(seq))
    print(f"time per call: exact {1e3 * te:.2f} ms (warm-started; random states "
          f"{1e3 * t_exact / n:.2f} ms), table {1e6 * tt:.1f} us")


def main() -> None:
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 400
    res = TableResolution(*map(int, sys.argv[2].split(","))) if len(sys.argv) > 2 else TableResolution()
    study("seed 003 3-lobe, load on lobe", multilobe_geometry(D, D, 12e-6, 0.5, 3), n, res)
    study("3-lobe L/D 0.5, between lobes",
          multilobe_geometry(D, D / 2, 12e-6, 0.5, 3, orientation="between_lobes"), n, res)
    study("plain 360 deg, max_film", plain_geometry(0.05, 0.025, 40e-6), n, res)
    study("plain, 2 axial grooves", plain_geometry(0.05, 0.025, 40e-6, grooves=2), n, res)
    study("3-lobe L/D 0.5, mp 0.3 (table contains the lobe centre)",
          multilobe_geometry(D, D / 2, 12e-6, 0.3, 3), n, res)


if __name__ == "__main__":
    main()
