"""Transient benchmark (issue 4): wall time per simulated second for both bearing models.

    python benchmarks/bench_transient.py [--duration 1.0] [--rollers 5 8 12]

Prints two tables.  1. Integration (compiled RK4 kernels, after compilation):
model, rollers, step, simulated seconds, wall time of the integration alone and
of the whole ``run_transient`` (static equilibrium, step choice, post-processing),
and the dominant spectral line against N f_cage.  2. The whole process
``spindlesim transient --rollers 8 --duration 0.5`` with the compiled kernels
cached on disk, and once with the cache cleared (compilation included).
Targets (issue 4): rigid race 8 rollers 1 s < 1 s wall; flexible race 12 rollers
x 12 segments 1 s < 10 s wall; the process < 20 s.  Not a test; numbers depend
on the machine.
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from spindlesim.analysis.fixed_step import plan_steps
from spindlesim.analysis.transient import run_transient
from spindlesim.bearings.rolling.build import system_from_section
from spindlesim.deck.sections.transient import TransientSection


def integration_only(system, settings) -> tuple[float, float]:
    """(wall s, step s) of the compiled RK4 loop alone over settings.duration_s."""
    y = system.initial_state()
    h_max = system.default_step_s(y)
    plan = plan_steps(settings.duration_s, h_max, 50 * system.roller_pass_frequency_hz,
                      system.roller_pass_frequency_hz)
    stepper = system.compiled_stepper()
    stepper(y.copy(), 0.0, plan.step_s, plan.steps_per_sample, plan.steps_per_sample, np.empty((1, y.size)))
    samples = np.empty((plan.n_samples, y.size))
    w0 = time.perf_counter()
    stepper(y, 0.0, plan.step_s, plan.n_samples * plan.steps_per_sample, plan.steps_per_sample, samples)
    return time.perf_counter() - w0, plan.step_s


def process_time(args: list[str], env: dict) -> float:
    with tempfile.TemporaryDirectory() as out:
        w0 = time.perf_counter()
        exe = Path(sys.executable).with_name("spindlesim")
        subprocess.run([str(exe), *args, "--outdir", out], check=True, env=env,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        return time.perf_counter() - w0


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--duration", type=float, default=1.0)
    ap.add_argument("--rollers", type=int, nargs="+", default=[5, 8, 12])
    ap.add_argument("--no-process", action="store_true", help="skip the whole-process timings")
    args = ap.parse_args()
    sec = TransientSection()
    T = args.duration
    print(f"{'model':<14} {'rollers':>7} {'step [us]':>9} {'sim [s]':>8} {'kernel [s]':>10} {'run [s]':>8} "
          f"{'N f_cage [Hz]':>13} {'peak x [Hz]':>11} {'peak y [Hz]':>11} {'bin [Hz]':>8}")
    for model in ("rigid_race", "flexible_race"):
        for n in args.rollers:
            system, settings = system_from_section(sec, rollers=n, model=model, duration_s=T)
            kernel, h = integration_only(system, settings)
            w0 = time.perf_counter()
            res = run_transient(system, settings)
            wall = time.perf_counter() - w0
            sp = res.spectrum
            px, py = sp.dominant_frequency_hz(0, 20.0), sp.dominant_frequency_hz(1, 20.0)
            print(f"{model:<14} {n:>7d} {h * 1e6:>9.3f} {T:>8.3g} {kernel:>10.2f} {wall:>8.2f} "
                  f"{res.roller_pass_frequency_hz:>13.2f} {px:>11.2f} {py:>11.2f} {sp.resolution_hz:>8.2f}"
                  + ("" if res.complete else f"  INCOMPLETE: {res.reason}"))
    if args.no_process:
        return
    cmd = ["transient", "--rollers", "8", "--duration", "0.5"]
    cache = Path(tempfile.mkdtemp(prefix="numba-cache-"))
    env = dict(os.environ, NUMBA_CACHE_DIR=str(cache))
    cold = process_time(cmd, env)
    warm = process_time(cmd, env)
    shutil.rmtree(cache, ignore_errors=True)
    print(f"\nspindlesim {' '.join(cmd)}: {cold:.2f} s with compilation (empty numba cache), "
          f"{warm:.2f} s with the cache")


if __name__ == "__main__":
    main()
