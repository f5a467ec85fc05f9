"""Campbell diagram of the milling spindle on angular-contact ball bearings (issue target: with the
bearing states re-solved at each of 50 speeds, within 2x the same diagram with linear bearings).

Deck: spindlesim/decks/milling_spindle.yaml (rotor, tool and two ball-bearing sets), 0-24000 rpm,
50 speeds, 8 tracked modes.  "linear bearings" is the same rotor with every bearing held at its
linear coefficients of 0 rpm (``frozen_rpm=0``: the same model size, no bearing solve per speed);
"re-solved" solves each set's quasi-static state at every speed (contact angles, centrifugal and
gyroscopic loads) and linearises it there.  Medians of --repeat runs, one BLAS thread.

    python benchmarks/bench_campbell_ball.py [--repeat 5]
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np

from spindlesim.analysis.campbell import solve_campbell
from spindlesim.deck import default_deck
from spindlesim.model.build import build_rotor

TARGET_RATIO = 2.0


def _median(fn, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    return statistics.median(times)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    rotor = build_rotor(default_deck("milling_spindle").deck)
    speeds = np.linspace(0.0, 24000.0, 50)
    solve_campbell(rotor, speeds[:3], n_modes=8)  # compile kernels, fill caches of the deck's parts
    t_lin = _median(lambda: solve_campbell(rotor, speeds, n_modes=8, frozen_rpm=0.0), args.repeat)
    t_ball = _median(lambda: solve_campbell(rotor, speeds, n_modes=8), args.repeat)
    exact = _median(lambda: solve_campbell(rotor, speeds, n_modes=8, exact=True), max(1, args.repeat // 2))
    r = solve_campbell(rotor, speeds, n_modes=8)
    print(f"milling spindle, 50 speeds 0-24000 rpm, 8 modes (median of {args.repeat})")
    print(f"  {'linear bearings (frozen at 0 rpm)':44s} {t_lin:8.3f} s")
    print(f"  {'ball sets re-solved at every speed':44s} {t_ball:8.3f} s   ratio {t_ball / t_lin:5.2f} "
          f"(target <= {TARGET_RATIO}: {'ok' if t_ball / t_lin <= TARGET_RATIO else 'SLOW'})")
    print(f"  {'re-solved, full state-space QR (--exact)':44s} {exact:8.3f} s")
    print(f"  model used: {r.model}")


if __name__ == "__main__":
    main()
