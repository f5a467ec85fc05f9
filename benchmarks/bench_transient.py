"""Transient benchmark: the one engine on seed 000's rig and on FE rotors.

    python benchmarks/bench_transient.py [--duration 1.0] [--rollers 5 8 12] [--no-process] [--no-rotor]
                                         [--rotor-only] [--no-full-film] [--old DIR] [--old-process DIR]
                                         [--runs 3]

1. Seed 000's rig (rigid journal in the roller bearing), explicit RK4 with compiled forces, as the
   command sets it up (``runs.transient.rig_setup``): model, rollers, step, simulated seconds, wall and
   CPU time of the integration alone (compiled loop, best of ``--runs``) and wall time of the whole
   ``simulate`` (static equilibrium, step choice, outputs), and the dominant spectral line against
   N f_cage.  Target: no slower than the dedicated kernels before the one engine (``--old DIR``, a
   checkout of that version: its compiled loops of both models, 8 rollers, timed side by side).
2. FE rotors with Newmark: the seed 003 spindle (104 DOF) on two 3-lobe bearings, 0.1 s at a step
   resolving 5 kHz (target: under 60 s on one core), with the tabulated film (the default) and with
   the full Reynolds solve at every call (its cost, and the table's error against it), and the seed
   001 rotor on its DTRB.
3. The whole process ``spindlesim transient --rollers 8 --duration 0.5 --model rigid_race``: the CPU
   time of importing what it imports, then wall and CPU time (the figure process's included) of the
   whole command, median of ``--runs``, with the compiled code cached on disk and with the figures
   drawn in the main process (SPINDLESIM_FIGURE_PROCESS=0), and once with the cache cleared
   (compilation included); against the compiled loop of the same run (target: within 3 times).
   ``--old-process DIR``: the same command from a checkout DIR, side by side.
Not a test; numbers depend on the machine.
"""

from __future__ import annotations

import argparse
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


def kernel_time(rotor, settings, runs: int = 1) -> tuple[float, float, float]:
    """(wall s, CPU s, step s) of the compiled RK4 loop alone (after compilation), best of ``runs``."""
    import dataclasses

    from spindlesim.analysis.transient.engine import integrate, prepare

    p = prepare(rotor, settings)
    short = prepare(rotor, dataclasses.replace(settings, duration_s=1e-3, settle_s=0.0))
    integrate(short, settings)  # compile
    wall = cpu = float("inf")
    for _ in range(runs):
        w0, c0 = time.perf_counter(), time.process_time()
        integrate(p, settings)
        wall, cpu = min(wall, time.perf_counter() - w0), min(cpu, time.process_time() - c0)
    return wall, cpu, p.plan.step_s


def old_kernel_time(old: Path, T: float, model: str, runs: int) -> tuple[float, float, float] | None:
    """(wall, CPU, step) of the dedicated kernel of ``model`` before the one engine (best of ``runs``), 8
    rollers, T simulated at its default step, in a subprocess with the checkout ``old`` first on the path."""
    code = f"""
import sys, time, numpy as np
sys.path.insert(0, {str(old)!r})
from spindlesim.deck import default_deck
from spindlesim.bearings.rolling.build import system_from_section
from spindlesim.analysis.fixed_step import plan_steps
s, _ = system_from_section(default_deck("transient").deck.transient, rollers=8, model={model!r}, duration_s={T})
st = s.compiled_stepper()
y = s.initial_state()
h = s.default_step_s(y)
p = plan_steps({T}, h, max(2000.0, 50 * s.roller_pass_frequency_hz), s.roller_pass_frequency_hz)
out = np.empty((p.n_samples, y.size))
st(y.copy(), 0.0, p.step_s, 100, p.steps_per_sample, out)
wall = cpu = float("inf")
for _ in range({runs}):
    yy = y.copy()
    w, c = time.perf_counter(), time.process_time()
    st(yy, 0.0, p.step_s, p.n_samples * p.steps_per_sample, p.steps_per_sample, out)
    wall, cpu = min(wall, time.perf_counter() - w), min(cpu, time.process_time() - c)
print(wall, cpu, p.step_s)
"""
    try:
        r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd="/")
        return tuple(float(v) for v in r.stdout.split()[-3:])
    except (subprocess.CalledProcessError, ValueError, IndexError):
        return None


def _children_cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def process_time(args: list[str], env: dict, old: Path | None = None) -> tuple[float, float]:
    """(wall s, CPU s of the process and its figure process) of ``spindlesim *args``; from the checkout
    ``old`` when given."""
    if old is None:
        cmd = [str(Path(sys.executable).with_name("spindlesim"))]
    else:
        cmd = [sys.executable, "-c", f"import sys; sys.path.insert(0, {str(old)!r}); sys.argv[0] = 'spindlesim'; "
                                     "from spindlesim.cli import console; console()"]
    with tempfile.TemporaryDirectory() as out:
        w0, c0 = time.perf_counter(), _children_cpu()
        subprocess.run([*cmd, *args, "--outdir", out], check=True, env=env, cwd="/",
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        return time.perf_counter() - w0, _children_cpu() - c0


def rig(args) -> None:
    from spindlesim.analysis.transient.engine import simulate
    from spindlesim.deck.transient import TransientSection
    from spindlesim.runs.transient import rig_setup

    T = args.duration
    print(f"{'model':<14} {'rollers':>7} {'step [us]':>9} {'sim [s]':>8} {'loop [s]':>8} {'loop CPU':>8} "
          f"{'run [s]':>8} {'N f_cage [Hz]':>13} {'peak x [Hz]':>11} {'peak y [Hz]':>11} {'bin [Hz]':>8}")
    for model in ("rigid_race", "flexible_race"):
        for n in args.rollers:
            rotor, settings = rig_setup(TransientSection(model=model), {"rollers": n, "duration_s": T})
            kernel, cpu, h = kernel_time(rotor, settings, args.runs)
            w0 = time.perf_counter()
            res = simulate(rotor, settings)
            wall = time.perf_counter() - w0
            sp = res.spectrum
            px, py = sp.dominant_frequency_hz(0, 20.0), sp.dominant_frequency_hz(1, 20.0)
            print(f"{model:<14} {n:>7d} {h * 1e6:>9.3f} {T:>8.3g} {kernel:>8.2f} {cpu:>8.2f} {wall:>8.2f} "
                  f"{res.frequencies_hz['bearing.roller_pass']:>13.2f} {px:>11.2f} {py:>11.2f} "
                  f"{sp.resolution_hz:>8.2f}" + ("" if res.complete else f"  INCOMPLETE: {res.reason}"))
        if args.old:
            old = old_kernel_time(Path(args.old), T, model, args.runs)
            print(f"{'  previous':<14} {8:>7d} " + (f"{old[2] * 1e6:>9.3f} {T:>8.3g} {old[0]:>8.2f} {old[1]:>8.2f}  "
                                                   "(its dedicated kernel, same machine)" if old else "not available"))


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
    ap.add_argument("--old", default=None, help="a checkout of the version with dedicated kernels")
    ap.add_argument("--old-process", default=None, help="a checkout to run the whole command from, side by side")
    ap.add_argument("--runs", type=int, default=3, help="repeats (best of for loops, median for processes)")
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
    if not args.no_process:
        whole_process(args)


def whole_process(args) -> None:
    """Section 3 of the module note."""
    from spindlesim.deck.transient import TransientSection
    from spindlesim.runs.transient import rig_setup

    cmd = ["transient", "--rollers", "8", "--duration", "0.5", "--model", "rigid_race"]
    rotor, settings = rig_setup(TransientSection(model="rigid_race"), {"rollers": 8, "duration_s": 0.5})
    loop, loop_cpu, _ = kernel_time(rotor, settings, args.runs)
    code = ("import time; c = time.process_time(); import spindlesim.cli, spindlesim.runs.transient, "
            "spindlesim.analysis.transient.engine, spindlesim.output.transient_writer, spindlesim.model.rig, "
            "spindlesim.analysis.modal; print(time.process_time() - c)")
    imports = statistics.median(float(subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                                                     cwd="/").stdout) for _ in range(args.runs))
    print(f"\nspindlesim {' '.join(cmd)}: compiled loop {loop:.2f} s ({loop_cpu:.2f} s CPU); the command's "
          f"imports {imports:.2f} s CPU")
    versions = [("this", None)] + ([("previous", Path(args.old_process))] if args.old_process else [])
    for label, old in versions:
        cache = Path(tempfile.mkdtemp(prefix="numba-cache-"))
        env = dict(os.environ, NUMBA_CACHE_DIR=str(cache))
        cold = process_time(cmd, env, old)
        rows = {"figure process": env, "figures in the main process": dict(env, SPINDLESIM_FIGURE_PROCESS="0")}
        for what, e in rows.items():
            runs = [process_time(cmd, e, old) for _ in range(args.runs)]
            wall, cpu = statistics.median(r[0] for r in runs), statistics.median(r[1] for r in runs)
            print(f"  {label:<8} {what:<28} wall {wall:5.2f} s ({wall / loop:4.1f} x the loop), CPU {cpu:5.2f} s "
                  f"({cpu / loop_cpu:4.1f} x)")
        print(f"  {label:<8} {'empty numba cache (compiling)':<28} wall {cold[0]:5.2f} s, CPU {cold[1]:5.2f} s")
        shutil.rmtree(cache, ignore_errors=True)


if __name__ == "__main__":
    main()
