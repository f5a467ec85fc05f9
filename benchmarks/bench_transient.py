"""Transient benchmark: the one engine on seed 000's rig and on FE rotors.

    python benchmarks/bench_transient.py [--duration 1.0] [--rollers 5 8 12] [--no-process] [--no-rotor]
                                         [--rotor-only] [--no-full-film]

1. Seed 000's rig (rigid journal in the roller bearing), explicit RK4 with compiled forces:
   model, rollers, step, simulated seconds, wall time of the integration alone (compiled loop)
   and of the whole ``simulate`` (static equilibrium, step choice, outputs), and the dominant
   spectral line against N f_cage.  Target: rigid race, 8 rollers, 1 s simulated at h = 1 us, no
   slower than the previous dedicated kernel (0.62 s on the reference machine; measured side by
   side with ``--old DIR``, a checkout of that version).
2. FE rotors with Newmark: the seed 003 spindle (104 DOF) on two 3-lobe bearings, 0.1 s at a step
   resolving 5 kHz (target: under 60 s on one core), with the tabulated film (the default) and with
   the full Reynolds solve at every call (its cost, and the table's error against it), and the seed
   001 rotor on its DTRB.
3. The whole process ``spindlesim transient --rollers 8 --duration 0.5`` with the compiled code
   cached on disk, and once with the cache cleared (compilation included).
Not a test; numbers depend on the machine.
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

ROOT = Path(__file__).resolve().parents[1]


def kernel_time(rotor, settings) -> tuple[float, float]:
    """(wall s, step s) of the compiled RK4 loop alone (after compilation)."""
    from spindlesim.analysis.transient.engine import integrate, prepare

    p = prepare(rotor, settings)
    import dataclasses

    short = prepare(rotor, dataclasses.replace(settings, duration_s=1e-3, settle_s=0.0))
    integrate(short, settings)  # compile
    w0 = time.perf_counter()
    integrate(p, settings)
    return time.perf_counter() - w0, p.plan.step_s


def old_kernel_time(old: Path, T: float) -> float | None:
    """The previous version's dedicated rigid-race kernel, 8 rollers, T simulated at h <= 1 us."""
    code = f"""
import sys, time, numpy as np
sys.path.insert(0, {str(old)!r})
from spindlesim.deck import default_deck
from spindlesim.bearings.rolling.build import system_from_section
from spindlesim.analysis.fixed_step import plan_steps
s, _ = system_from_section(default_deck("transient").deck.transient, rollers=8, model="rigid_race", duration_s={T})
st = s.compiled_stepper()
p = plan_steps({T}, 1e-6, 50 * s.roller_pass_frequency_hz, s.roller_pass_frequency_hz)
y = s.initial_state()
out = np.empty((p.n_samples, 4))
st(y.copy(), 0.0, p.step_s, 100, p.steps_per_sample, out)
w = time.perf_counter(); st(y, 0.0, p.step_s, p.n_samples * p.steps_per_sample, p.steps_per_sample, out)
print(time.perf_counter() - w)
"""
    try:
        r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd="/")
        return float(r.stdout.split()[-1])
    except (subprocess.CalledProcessError, ValueError, IndexError):
        return None


def process_time(args: list[str], env: dict) -> float:
    with tempfile.TemporaryDirectory() as out:
        w0 = time.perf_counter()
        exe = Path(sys.executable).with_name("spindlesim")
        subprocess.run([str(exe), *args, "--outdir", out], check=True, env=env,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        return time.perf_counter() - w0


def rig(args) -> None:
    from spindlesim.analysis.transient.engine import TransientSettings, simulate
    from spindlesim.bearings.roller.section import TransientSection
    from spindlesim.model.rig import rig_rotor

    T = args.duration
    print(f"{'model':<14} {'rollers':>7} {'step [us]':>9} {'sim [s]':>8} {'kernel [s]':>10} {'run [s]':>8} "
          f"{'N f_cage [Hz]':>13} {'peak x [Hz]':>11} {'peak y [Hz]':>11} {'bin [Hz]':>8}")
    for model in ("rigid_race", "flexible_race"):
        for n in args.rollers:
            rotor = rig_rotor(TransientSection(model=model), rollers=n)
            settings = TransientSettings(T, method="rk4", settle_s=0.4 * T)
            kernel, h = kernel_time(rotor, settings)
            w0 = time.perf_counter()
            res = simulate(rotor, settings)
            wall = time.perf_counter() - w0
            sp = res.spectrum
            px, py = sp.dominant_frequency_hz(0, 20.0), sp.dominant_frequency_hz(1, 20.0)
            print(f"{model:<14} {n:>7d} {h * 1e6:>9.3f} {T:>8.3g} {kernel:>10.2f} {wall:>8.2f} "
                  f"{res.frequencies_hz['bearing.roller_pass']:>13.2f} {px:>11.2f} {py:>11.2f} "
                  f"{sp.resolution_hz:>8.2f}" + ("" if res.complete else f"  INCOMPLETE: {res.reason}"))
    if args.old:
        old = old_kernel_time(Path(args.old), T)
        print(f"previous dedicated rigid-race kernel, 8 rollers, same machine: "
              f"{old:.2f} s" if old is not None else "previous kernel: not available")


def spindle_film_runs(duration: float, films: tuple[str, ...]) -> dict:
    """The seed 003 spindle (104 DOF) on its two 3-lobe bearings, Newmark at h = 10 us (20 steps per
    period of 5 kHz), a 50 N force released at the nose: {film model: (result, wall s)}."""
    from spindlesim.analysis.transient.engine import Perturbation, TransientSettings, simulate
    from spindlesim.deck import default_deck, parse_deck
    from spindlesim.model.build import build_rotor

    out = {}
    for film in films:
        text = default_deck("spindle").text
        for load in ("load_N: 400", "load_N: 300"):
            text = text.replace(load, f"{load}\n    transient_film: {film}")
        rotor = build_rotor(parse_deck(text, "spindle.yaml").deck)
        s = TransientSettings(duration, step_s=1 / (5000 * 20), settle_s=0.2 * duration,
                              perturbation=Perturbation(rotor.dofs.index(0, "x"), 50.0))
        w0 = time.perf_counter()
        res = simulate(rotor, s)
        out[film] = (res, time.perf_counter() - w0)
    return out


def rotors(duration: float = 0.1, full_film: bool = True) -> None:
    """Target (issue "One spindle model"): the seed 003 spindle, 0.1 s at a step resolving 5 kHz, under
    60 s on one core; the film model's cost and its error against the full Reynolds solve."""
    from spindlesim.analysis.transient.engine import simulate
    from spindlesim.deck import load_deck
    from spindlesim.runs.transient import rotor_setup

    print(f"\n{'rotor':<44} {'DOF':>4} {'step [us]':>9} {'sim [s]':>8} {'wall [s]':>8} {'Newton/step':>11}")
    runs = spindle_film_runs(duration, ("table", "reynolds") if full_film else ("table",))
    for film, (res, wall) in runs.items():
        print(f"{'seed 003 spindle, 3-lobe, film ' + film:<44} {res.rotor_displacement.shape[1]:>4d} "
              f"{res.step_s * 1e6:>9.2f} {duration:>8.3g} {wall:>8.2f} {res.newton_iterations[1:].mean():>11.2f}"
              + ("" if res.complete else f"  INCOMPLETE: {res.reason}"))
    if "reynolds" in runs:
        (tab, w_tab), (rey, w_rey) = runs["table"], runs["reynolds"]
        n = min(len(tab.time_s), len(rey.time_s))
        d_rey = rey.displacement_m[:n] - rey.static_displacement[[0, 1]]
        err = np.abs(tab.displacement_m[:n] - rey.displacement_m[:n]).max() / np.abs(d_rey).max()
        print(f"table film: {w_rey / w_tab:.1f} times faster than the full solve; nose response differs by "
              f"{err:.2e} of its peak (max over the run)")
    deck = load_deck(ROOT / "decks" / "seed001_dtrb_rotor.yaml").deck
    rotor, settings = rotor_setup(deck, {})
    w0 = time.perf_counter()
    res = simulate(rotor, settings)
    wall = time.perf_counter() - w0
    print(f"{'seed 001 rotor on its DTRB (newmark)':<44} {rotor.dofs.size:>4d} {res.step_s * 1e6:>9.2f} "
          f"{settings.duration_s:>8.3g} {wall:>8.2f} {res.newton_iterations[1:].mean():>11.2f}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--duration", type=float, default=1.0)
    ap.add_argument("--rollers", type=int, nargs="+", default=[5, 8, 12])
    ap.add_argument("--old", default=None, help="a checkout of the previous version (dedicated kernels)")
    ap.add_argument("--no-process", action="store_true", help="skip the whole-process timings")
    ap.add_argument("--no-rotor", action="store_true", help="skip the FE rotor timings")
    ap.add_argument("--rotor-only", action="store_true", help="only the FE rotor timings")
    ap.add_argument("--no-full-film", action="store_true",
                    help="skip the spindle with the full Reynolds film (some minutes)")
    args = ap.parse_args()
    if args.rotor_only:
        rotors(full_film=not args.no_full_film)
        return
    rig(args)
    if not args.no_rotor:
        rotors(full_film=not args.no_full_film)
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
