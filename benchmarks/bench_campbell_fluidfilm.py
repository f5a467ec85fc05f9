"""Campbell diagram of the seed 003 spindle on its 3-lobe fluid-film bearings (issue "Speed").

Deck: embedded ``spindle`` (= decks/seed003_three_lobe.yaml), 60 speeds 200..12000 rpm (a
hydrodynamic film needs a positive speed, so the sweep cannot start at 0 rpm).  At every speed
``solve_campbell`` finds the static equilibrium with each bearing at its thermal equilibrium
(``static_states`` -> ``operating_state`` -> bearing ``analyze`` -> ``solve_thermal``: secant steps
on the film temperature from the previous speed, a bracket and Brent's method without one or when
they do not settle, each trial one isoviscous journal equilibrium =
Reynolds solves + 8 coefficients), then the damped modes of every speed.

Target: under 2 s.  Reported:
* in-process, imports excluded: the first Campbell of a process (Reynolds grids built, caches
  empty) and later ones with the operating-point caches cleared (what a fresh process pays
  beyond the one-off set-up);
* the same as a whole process (`spindlesim campbell --speeds 200:12000:60`, median of 3);
* where the time goes: wall time and calls of thermal equilibria, isoviscous operating points,
  Reynolds solves, static-equilibrium states, reduced-basis check and eigen solves (timers wrapped
  around the library's functions for this run only), and the top of a cProfile.

Usage: python benchmarks/bench_campbell_fluidfilm.py [--speeds START:STOP:COUNT] [--repeat N] [--no-process]
"""

from __future__ import annotations

import argparse
import cProfile
import collections
import functools
import os
import pathlib
import pstats
import shutil
import subprocess
import sys
import tempfile
import threading
import time

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")
os.environ.setdefault("MPLBACKEND", "Agg")

import numpy as np  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent
TARGET_S = 2.0


def median(xs):
    return float(np.median(xs))


def clear_caches():
    """Forget every operating point solved so far, and any warm start kept from it (the Reynolds
    grids and film models stay: a process builds them once)."""
    from spindlesim.bearings.fluidfilm import bearing as ffb

    keep = {"cached_solver", "film_model"}
    for name, obj in vars(ffb).items():
        if name not in keep and hasattr(obj, "cache_clear"):
            obj.cache_clear()
        elif name in ("_NEAR", "_OFFSETS") and isinstance(obj, dict):  # warm starts, journal offsets
            obj.clear()


class Timers:
    """Wall time and calls of selected library functions, patched for the duration of a ``with``."""

    def __init__(self, targets):
        self.targets = targets  # (label, module or class, attribute name)
        self.t = collections.defaultdict(float)
        self.n = collections.Counter()
        self.saved = []
        self.local = threading.local()

    def wrap(self, label, fn):
        timers = self

        @functools.wraps(fn)
        def inner(*a, **k):
            depth = getattr(timers.local, label, 0)
            setattr(timers.local, label, depth + 1)
            t = time.perf_counter()
            try:
                return fn(*a, **k)
            finally:
                setattr(timers.local, label, depth)
                if depth == 0:  # recursion / re-entry: count the outer call only
                    timers.t[label] += time.perf_counter() - t
                    timers.n[label] += 1
        return inner

    def __enter__(self):
        for label, owner, name in self.targets:
            fn = owner.__dict__[name] if isinstance(owner, type) else getattr(owner, name)
            self.saved.append((owner, name, fn))
            setattr(owner, name, self.wrap(label, fn))
        return self

    def __exit__(self, *exc):
        for owner, name, fn in reversed(self.saved):
            setattr(owner, name, fn)


def breakdown(rotor, speeds, n_modes):
    import spindlesim.analysis.campbell as camp
    import spindlesim.analysis.modal as modal
    import spindlesim.bearings.fluidfilm.bearing as ffb
    import spindlesim.bearings.fluidfilm.equilibrium as ffe
    import spindlesim.bearings.fluidfilm.performance as ffp
    import spindlesim.bearings.fluidfilm.thermal as fft
    from spindlesim.bearings.fluidfilm.reynolds import ReynoldsSolver

    targets = [
        ("static_states (all speeds)", camp, "static_states"),
        ("  thermal equilibrium (solve_thermal)", ffb, "solve_thermal"),
        ("    isoviscous operating point", fft, "operating_point"),
        ("  journal offset (load_N alone, isoviscous)", ffb, "_offset"),
        ("      journal equilibrium (Newton)", ffp, "solve_newton"),
        ("      journal equilibrium (axisymmetric)", ffp, "solve_axisymmetric"),
        ("        Reynolds solve", ReynoldsSolver, "solve"),
        ("reduced basis + check (checked_basis)", camp, "checked_basis"),
        ("eigen solves (modal_from_matrices, summed over threads)", camp, "modal_from_matrices"),
        ("  numpy eig inside modal (state-space eigenproblem)", modal.np.linalg, "eig"),
    ]
    targets = [t for t in targets if hasattr(t[1], t[2])]
    _ = ffe
    clear_caches()
    with Timers(targets) as tm:
        t = time.perf_counter()
        res = camp.solve_campbell(rotor, speeds, n_modes)
        total = time.perf_counter() - t
    return total, tm, res


def process_time(args, runs):
    exe = pathlib.Path(sys.executable).with_name("spindlesim")
    exe = [str(exe)] if exe.exists() else [sys.executable, "-m", "spindlesim"]
    times = []
    with tempfile.TemporaryDirectory() as tmp:
        for i in range(runs + 1):
            shutil.rmtree(pathlib.Path(tmp) / "o", ignore_errors=True)
            t = time.perf_counter()
            r = subprocess.run(exe + args + ["-o", str(pathlib.Path(tmp) / "o")], cwd=ROOT, capture_output=True,
                               text=True)
            if r.returncode != 0:
                return None, (r.stderr.strip().splitlines() or ["?"])[-1]
            if i:
                times.append(time.perf_counter() - t)
    return times, ""


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--speeds", default="200:12000:60", metavar="START:STOP:COUNT")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--no-process", action="store_true")
    ap.add_argument("--profile-top", type=int, default=18)
    a = ap.parse_args()
    lo, hi, n = a.speeds.split(":")
    speeds = np.linspace(float(lo), float(hi), int(n))

    t = time.perf_counter()
    from spindlesim.analysis.campbell import solve_campbell
    from spindlesim.deck import default_deck
    from spindlesim.model.build import build_rotor
    t_import = time.perf_counter() - t

    deck = default_deck("spindle").deck
    n_modes = deck.campbell.modes if getattr(deck, "campbell", None) else 8
    print(f"{deck.title}: {len(speeds)} speeds {speeds[0]:g}..{speeds[-1]:g} rpm, {n_modes} modes; "
          f"BLAS threads 1; {os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f}; "
          f"imports {t_import:.2f} s (excluded)")

    rotor = build_rotor(deck)
    t, c = time.perf_counter(), time.process_time()
    res = solve_campbell(rotor, speeds, n_modes)
    cold, cold_cpu = time.perf_counter() - t, time.process_time() - c
    warm, warm_cpu = [], []
    for _ in range(a.repeat):
        clear_caches()
        rotor = build_rotor(deck)
        t, c = time.perf_counter(), time.process_time()
        res = solve_campbell(rotor, speeds, n_modes)
        warm.append(time.perf_counter() - t)
        warm_cpu.append(time.process_time() - c)
    print(f"model: {res.model}; speeds done {len(res.speed_rpm)}"
          + (f"; incomplete: {res.incomplete_reason}" if res.incomplete_reason else ""))
    print(f"\n{'case':58s} {'wall [s]':>9s} {'cpu [s]':>8s} {'target':>7s}  ok")
    print(f"{'in-process, first Campbell of the process':58s} {cold:9.3f} {cold_cpu:8.3f} {TARGET_S:7.1f}  "
          f"{'yes' if cold < TARGET_S else 'NO'}")
    print(f"{f'in-process, operating points cleared (median of {a.repeat})':58s} {median(warm):9.3f} "
          f"{median(warm_cpu):8.3f} {TARGET_S:7.1f}  {'yes' if median(warm) < TARGET_S else 'NO'}")
    if not a.no_process:
        times, err = process_time(["campbell", "--speeds", a.speeds], 3)
        if times is None:
            print(f"{'whole process: spindlesim campbell --speeds ' + a.speeds:58s} FAILED: {err}")
        else:
            print(f"{'whole process: spindlesim campbell --speeds ' + a.speeds:58s} {median(times):9.3f} "
                  f"{'':8s} {TARGET_S:7.1f}  {'yes' if median(times) < TARGET_S else 'NO'}")

    rotor = build_rotor(deck)
    total, tm, _ = breakdown(rotor, speeds, n_modes)
    print(f"\nwhere the time goes (one Campbell, operating points cleared, timers on: {total:.3f} s)")
    print(f"  {'part':58s} {'wall [s]':>9s} {'share':>6s} {'calls':>7s} {'per call [ms]':>14s}")
    for label, _, _ in tm.targets:
        if tm.n[label]:
            print(f"  {label:58s} {tm.t[label]:9.3f} {100 * tm.t[label] / total:5.0f}% {tm.n[label]:7d} "
                  f"{1e3 * tm.t[label] / tm.n[label]:14.2f}")
    th = tm.n["  thermal equilibrium (solve_thermal)"]
    if th:
        op = tm.n["    isoviscous operating point"]
        print(f"  -> {th} thermal equilibria for {len(speeds)} speeds x {len(rotor.bearings)} bearings, "
              f"{op / th:.1f} film temperatures tried each, "
              f"{tm.n['        Reynolds solve'] / max(op, 1):.1f} Reynolds solves per operating point")

    clear_caches()
    rotor = build_rotor(deck)
    pr = cProfile.Profile()
    pr.enable()
    solve_campbell(rotor, speeds, n_modes)
    pr.disable()
    st = pstats.Stats(pr)
    rows = sorted(st.stats.items(), key=lambda kv: kv[1][2], reverse=True)[: a.profile_top]
    print(f"\ncProfile (main thread; the eigen solves run on worker threads), own time: total {st.total_tt:.3f} s")
    for (file, line, fn), v in rows:
        file = file.replace(str(ROOT) + "/", "")
        file = file.split("site-packages/")[-1]
        print(f"  {v[2]:8.3f} s own {v[3]:8.3f} s cum {v[1]:7d} calls  {file}:{line}({fn})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
