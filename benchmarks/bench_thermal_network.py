"""Benchmark: spindle thermal network (issue 22, heat-transfer part).

Targets of the issue for the whole thermo-mechanical model (this script times the network part):
steady state of the milling spindle at one speed under 0.2 s, a two-hour warm-up with five speed
steps under 10 s.  Network-side aims: a linear steady solve ~1 ms, a warm-up well under 1 s.

Prints, for the example milling spindle (spindlesim/model/thermal_example.py, 48 nodes): building the
network, one conductance evaluation, a linear steady solve, the temperature-dependent steady
state (Picard), the two-hour warm-up (BDF, temperature-dependent and frozen conductances,
implicit Euler at 30 s), and a 100-node chain for scale.

    python benchmarks/bench_thermal_network.py [--repeat 5]
"""

from __future__ import annotations

import argparse
import math
import os
import sys
import time

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
sys.path.insert(0, os.path.dirname(__file__))

import numpy as np  # noqa: E402
from timing import best  # noqa: E402

from spindlesim.model.thermal_example import milling_spindle_layout  # noqa: E402
from spindlesim.thermal.network import Conductance, Network, Node  # noqa: E402
from spindlesim.thermal.spindle_network import BearingHeat, build_spindle_network  # noqa: E402
from spindlesim.thermal.transient import StepProfile  # noqa: E402

RPM = math.pi / 30
HEAT = {"front": BearingHeat(108.0, 24.0, 108.0), "rear": BearingHeat(54.0, 12.0, 54.0)}
PROFILE = StepProfile(tuple(np.arange(5) * 1440.0), tuple(np.array([6000, 12000, 18000, 24000, 12000]) * RPM))


def row(name: str, wall: float, cpu: float, note: str = "") -> None:
    print(f"{name:62s} {wall * 1e3:9.3f} ms {cpu * 1e3:9.3f} ms  {note}")


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=5)
    r = ap.parse_args().repeat
    print(f"{'case':62s} {'wall':>12s} {'cpu':>12s}")
    t0, c0 = time.perf_counter(), time.process_time()
    sn = build_spindle_network(milling_spindle_layout())
    row("build the milling spindle network (first, incl. imports)", time.perf_counter() - t0, time.process_time() - c0,
        f"{len(sn.network.names)} nodes, {len(sn.network.conductances)} conductances")
    row("build again", *best(lambda: build_spindle_network(milling_spindle_layout()), r, 3))
    w = 18000 * RPM
    T = sn.steady(w, HEAT, load_fraction=0.3).temperatures_C
    row("conductance evaluation at a speed and temperatures", *best(lambda: sn.conductances(w, T), r, 20))
    g = sn.conductances(w, T)
    src = sn.sources(HEAT, sn.motor_losses(w, load_fraction=0.3))
    row("linear steady solve (given conductances and sources)",
        *best(lambda: sn.network.solve_steady(src, conductances=g), r, 200), "target ~1 ms")
    s = sn.steady(w, HEAT, load_fraction=0.3)
    row("steady, temperature-dependent conductances (Picard, 1e-6 K)",
        *best(lambda: sn.steady(w, HEAT, load_fraction=0.3), r, 3), f"{s.iterations} iterations")
    res = {}

    def warm(**kw):
        res["r"] = sn.warm_up(PROFILE, 7200.0, HEAT, load_fraction=0.3, **kw)

    for label, kw in (("warm-up 2 h, 5 speed steps, BDF, T-dependent (update 0.5 K)", {}),
                      ("warm-up 2 h, 5 steps, BDF, conductances frozen per speed", {"temperature_dependent": False}),
                      ("warm-up 2 h, 5 steps, implicit Euler 30 s, frozen per speed",
                       {"temperature_dependent": False, "method": "implicit_euler", "dt_s": 30.0})):
        wall, cpu = best(lambda: warm(**kw), max(1, r // 2), 1)
        rr = res["r"]
        row(label, wall, cpu, f"{rr.steps} {'steps' if rr.method == 'implicit_euler' else 'rhs evaluations'}, "
                              f"front inner ring {rr['bearing:front:inner'][-1]:.2f} degC at 2 h, target < 1 s")
    n = 100
    chain = Network(tuple(Node(f"n{i}", 50.0) for i in range(n)) + (Node("amb", fixed_C=20.0),),
                    tuple(Conductance(f"n{i}", f"n{i + 1}", 3.0) for i in range(n - 1))
                    + tuple(Conductance(f"n{i}", "amb", 0.05) for i in range(n)))
    q = {f"n{i}": 1.0 for i in range(n)}
    row("100-node network, linear steady solve", *best(lambda: chain.solve_steady(q), r, 200))


if __name__ == "__main__":
    main()
