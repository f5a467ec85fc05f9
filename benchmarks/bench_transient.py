"""Transient benchmark (issue 4): wall time per simulated time for both bearing models.

    python benchmarks/bench_transient.py [--flexible-duration 0.01] [--rigid-duration 0.3]

Prints a table: model, rollers, simulated seconds, wall time, RHS evaluations,
dominant spectral line vs N f_cage.  Not a test; numbers depend on the machine.
"""

from __future__ import annotations

import argparse
import time

from spindlesim.analysis.transient import run_transient
from spindlesim.bearings.rolling.build import system_from_section
from spindlesim.deck.sections.transient import TransientSection


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--rigid-duration", type=float, default=0.3)
    ap.add_argument("--flexible-duration", type=float, default=0.01)
    ap.add_argument("--rollers", type=int, nargs="+", default=[5, 8, 12])
    args = ap.parse_args()
    sec = TransientSection()
    print(f"{'model':<14} {'rollers':>7} {'sim [s]':>8} {'wall [s]':>9} {'wall/sim':>9} {'rhs evals':>10} "
          f"{'N f_cage [Hz]':>13} {'peak x [Hz]':>11} {'peak y [Hz]':>11} {'bin [Hz]':>8}")
    for model, T in (("rigid_race", args.rigid_duration), ("flexible_race", args.flexible_duration)):
        for n in args.rollers:
            system, settings = system_from_section(sec, rollers=n, model=model, duration_s=T)
            w0 = time.perf_counter()
            res = run_transient(system, settings)
            wall = time.perf_counter() - w0
            sp = res.spectrum
            px = sp.dominant_frequency_hz(0, 20.0) if sp.frequency_hz.size > 2 else float("nan")
            py = sp.dominant_frequency_hz(1, 20.0) if sp.frequency_hz.size > 2 else float("nan")
            print(f"{model:<14} {n:>7d} {T:>8.3g} {wall:>9.2f} {wall / T:>9.1f} {res.rhs_evaluations:>10d} "
                  f"{res.roller_pass_frequency_hz:>13.2f} {px:>11.2f} {py:>11.2f} {sp.resolution_hz:>8.2f}"
                  + ("" if res.complete else f"  INCOMPLETE: {res.reason}"))


if __name__ == "__main__":
    main()
