"""Oil-whirl benchmark (issue 24): a 20 kg Jeffcott rotor on two plain bearings, Newmark with the tabulated film.

    python benchmarks/bench_whirl.py [--duration 1.0] [--ratios 1.4 0.7] [--cold] [--old DIR] [--old-limit S]

Rotor: decks/validation/jeffcott_plain.yaml with a radial clearance of 50 um (the deck has 75 um) and a
15.38 kg disk (rotor 20.0 kg): D 50 mm, L/D 0.5, 0.01 Pa s, gravity.  Its stability threshold is found as
in tests/validation/test_one_model_oil_whirl.py (bisection on the speed where the largest real part of
the forward modes crosses zero).  Each run starts from a 200 N static force at the disk, released at
t = 0, and integrates with the default step (Newmark, 50 us): wall and CPU time, Newton iterations per
step, the largest e/Cb at the bearings against the film table's range, and above the threshold the limit
cycle over the last 40 % (e/Cb band at the bearings, whirl frequency over the running speed).

--cold      with an empty film-table cache (the table's build included, as on a first run).
--old DIR   the same runs with DIR on the path first (a checkout of an earlier version), each in a
            subprocess stopped after --old-limit seconds (then: how far it got).
Not a test; numbers depend on the machine.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DECK = ROOT / "decks" / "validation" / "jeffcott_plain.yaml"
DISK = 2  # 0-based node of the disk
BEARING_NODES = (0, 4)
CLEARANCE = 50e-6
PUSH_N = 200.0


def rotor_at(rpm: float):
    import dataclasses

    from spindlesim.deck import parse_deck
    from spindlesim.model.build import build_rotor

    text = DECK.read_text().replace("clearance_mm: 0.075", "clearance_mm: 0.05").replace("mass_kg: 14.80",
                                                                                         "mass_kg: 15.38")
    return dataclasses.replace(build_rotor(parse_deck(text, "whirl.yaml").deck), speed_rpm=float(rpm))


def threshold_rpm() -> float:
    """Speed where the least stable forward mode's real part crosses zero (bisection to 1 rpm)."""
    from spindlesim.analysis.modal import solve_modal

    def rate(rpm: float) -> float:
        md = solve_modal(rotor_at(rpm), n_modes=4)
        return max(md.eigenvalues[k].real for k in range(len(md.frequency_hz)) if md.whirl[k] == "forward")

    lo, hi = 2000.0, 40000.0
    while hi - lo > 1.0:
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if rate(mid) < 0 else (lo, mid)
    return 0.5 * (lo + hi)


def run_case(rpm: float, duration: float, report=None) -> dict:
    """One run (module note); ``report(t)`` is called as it goes."""
    import numpy as np

    from spindlesim.analysis.transient.engine import Perturbation, TransientSettings, simulate

    rotor = rotor_at(rpm)
    s = TransientSettings(duration, record_node=DISK, perturbation=Perturbation(rotor.dofs.index(DISK, "x"), PUSH_N))
    w0, c0 = time.perf_counter(), time.process_time()
    res = simulate(rotor, s, progress=(lambda f, t: report(t)) if report else None)
    wall, cpu = time.perf_counter() - w0, time.process_time() - c0
    q = res.rotor_displacement
    ecc = np.max([np.hypot(q[:, rotor.dofs.index(n, "x")], q[:, rotor.dofs.index(n, "y")]) for n in BEARING_NODES],
                 axis=0) / CLEARANCE
    out = {"wall_s": wall, "cpu_s": cpu, "complete": res.complete, "reason": res.reason,
           "newton": float(res.newton_iterations[1:].mean()), "e_max": float(ecc.max())}
    late = res.time_s >= 0.6 * duration
    if late.sum() > 10 and ecc[late].min() > 0.5:  # a whirl orbit (a stable run ends at its static state)
        ix, iy = rotor.dofs.index(DISK, "x"), rotor.dofs.index(DISK, "y")
        z = (q[late, ix] - res.static_displacement[ix]) + 1j * (q[late, iy] - res.static_displacement[iy])
        f = np.polyfit(res.time_s[late], np.unwrap(np.angle(z)), 1)[0] / (2 * np.pi)
        out.update(e_late=(float(ecc[late].min()), float(ecc[late].max())), whirl_ratio=float(f / (rpm / 60.0)))
    return out


def table_range() -> float:
    from spindlesim.bearings.fluidfilm import film_table

    return getattr(film_table, "PLAIN_BORE", film_table.TableResolution()).eccentricity_max


def line(label: str, rpm: float, T: float, r: dict) -> str:
    s = (f"{label:<10} {rpm:>7.0f} {T:>6.3g} {r['wall_s']:>8.2f} {r['cpu_s']:>8.2f} {r['newton']:>7.2f} "
         f"{r['e_max']:>7.4f}")
    if "e_late" in r:
        s += f"  limit cycle e/Cb {r['e_late'][0]:.4f}-{r['e_late'][1]:.4f}, whirl {r['whirl_ratio']:.4f} x"
    return s + ("" if r["complete"] else f"  INCOMPLETE: {r['reason']}")


def old_case(old: Path, rpm: float, T: float, limit: float) -> str:
    """The run with ``old`` first on the path, in a subprocess stopped after ``limit`` s."""
    code = (f"import sys; sys.path.insert(0, {str(old)!r}); sys.path.insert(1, {str(ROOT / 'benchmarks')!r})\n"
            "import json, time, bench_whirl as b\n"
            "last = [0.0]\n"
            "def rep(t):\n"
            "    if time.perf_counter() - last[0] > 2: print('t', t, time.process_time(), flush=True); "
            "last[0] = time.perf_counter()\n"
            f"print('result', json.dumps(b.run_case({rpm}, {T}, rep)), flush=True)\n")
    w0 = time.perf_counter()
    reached = "0"
    with tempfile.TemporaryFile("w+") as out:
        p = subprocess.Popen([sys.executable, "-c", code], stdout=out, stderr=subprocess.DEVNULL, cwd="/")
        try:
            p.wait(timeout=limit)
        except subprocess.TimeoutExpired:
            p.kill()
            p.wait()
        out.seek(0)
        for text in out:
            if text.startswith("result "):
                return line("previous", rpm, T, json.loads(text[7:]))
            if text.startswith("t "):
                reached = f"{float(text.split()[1]):.4f} s simulated, {float(text.split()[2]):.1f} s CPU"
    return (f"{'previous':<10} {rpm:>7.0f} {T:>6.3g}  did not finish in {time.perf_counter() - w0:.0f} s "
            f"(reached {reached})")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--duration", type=float, default=1.0)
    ap.add_argument("--ratios", type=float, nargs="+", default=[1.4, 0.7])
    ap.add_argument("--cold", action="store_true", help="empty film-table cache (build included)")
    ap.add_argument("--old", default=None, help="a checkout of an earlier version to run side by side")
    ap.add_argument("--old-limit", type=float, default=300.0, help="seconds each earlier run may take")
    args = ap.parse_args()
    if args.cold:
        os.environ["SPINDLESIM_CACHE"] = tempfile.mkdtemp(prefix="spindlesim-cache-")
    w0 = time.perf_counter()
    n0 = threshold_rpm()
    print(f"20 kg Jeffcott rotor on two plain bearings (Cb 50 um): threshold {n0:.0f} rpm "
          f"({time.perf_counter() - w0:.1f} s); film table to e/Cb {table_range()}")
    print(f"{'version':<10} {'rpm':>7} {'T [s]':>6} {'wall [s]':>8} {'CPU [s]':>8} {'Newton':>7} {'e/Cb max':>7}")
    for ratio in args.ratios:
        rpm = ratio * n0
        if args.old:
            print(old_case(Path(args.old), rpm, args.duration, args.old_limit), flush=True)
        print(line("this", rpm, args.duration, run_case(rpm, args.duration)), flush=True)


if __name__ == "__main__":
    main()
