"""Contact solver benchmark: Hertz sphere on flat (R = 5 mm, 1000 N, steel E = 208 GPa, nu = 0.3).

Prints grid, wall time (best of --repeat runs), CGM iterations, and the errors of p0 and
the contact radius a against Hertz (REFERENCES.md: a = 0.3201 mm, p0 = 4.6585 GPa).
Targets (issue 5): 256 x 256 under 1 s, 512 x 512 under 5 s, errors within 0.5%.

    python benchmarks/bench_contact.py [--grids 64 128 256 512] [--repeat 3]
"""

from __future__ import annotations

import argparse
import logging
import time

import numpy as np

from spindlesim.contact import combined_modulus, point_contact_circular, solve_point_contact, solve_roller_contact

E, NU, R, W = 208e9, 0.3, 5e-3, 1000.0
TARGET_S = {256: 1.0, 512: 5.0}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--grids", type=int, nargs="+", default=[64, 128, 256, 512])
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    logging.basicConfig(level=logging.ERROR)  # the edge-singularity warnings are shown in the table
    a, p0, _ = point_contact_circular(W, R, combined_modulus(E, NU, E, NU))
    print("sphere on flat, R = 5 mm, W = 1000 N (Hertz a = %.4f mm, p0 = %.4f GPa)" % (a * 1e3, p0 / 1e9))
    print(f"{'grid':>9} {'time s':>8} {'target':>7} {'iter':>5} {'p0 err %':>9} {'a err % (edge)':>15} {'a err % (area)':>15}")
    for n in args.grids:
        times = []
        for _ in range(args.repeat):
            t0 = time.perf_counter()
            r = solve_point_contact(W, R, n=n)
            times.append(time.perf_counter() - t0)
        j = int(np.argmin(np.abs(r.y_m)))
        e_p0 = 100 * (r.max_pressure_Pa / p0 - 1)
        e_a = 100 * (r.half_width_m[j] / a - 1)
        e_area = 100 * (np.sqrt(r.area_m2 / np.pi) / a - 1)
        tgt = TARGET_S.get(n)
        flag = "" if tgt is None else (f"<{tgt:g} ok" if min(times) < tgt else f"<{tgt:g} SLOW")
        print(f"{n:>4}x{n:<4} {min(times):8.3f} {flag:>7} {r.iterations:5d} {e_p0:9.4f} {e_a:15.4f} {e_area:15.4f}")
    print("\nroller R = 5 mm, l = 10 mm, 10 kN on a flat, crown radius 2.6 m (edge check included)")
    print(f"{'grid':>9} {'time s':>8} {'iter':>5} {'p_max GPa':>10} {'edge singular':>14}")
    for nx, ny in ((32, 128), (64, 256), (128, 512)):
        t0 = time.perf_counter()
        r = solve_roller_contact(10e3, R, 10e-3, raceway="flat", profile="crowned", crown_radius_m=2.6, nx=nx, ny=ny)
        t = time.perf_counter() - t0
        print(f"{nx:>4}x{ny:<4} {t:8.3f} {r.iterations:5d} {r.max_pressure_Pa / 1e9:10.3f} {str(r.edge_singular):>14}")


if __name__ == "__main__":
    main()
