"""ROSS vs spindlesim, side by side, on the same rotor (issue "Speed").

The rotor is the seed 003 spindle with the paper's linear bearing coefficients (embedded deck
``spindle_linear`` = decks/seed003_spindle_linear.yaml): 25 Timoshenko shaft elements from the
deck's element table, no disks, two linear K/C bearings.  Both programs solve, in this one run,
single-threaded BLAS, in-process with the imports excluded:

* a Campbell diagram over 50 speeds 0..12000 rpm (8 modes);
* an FRF over 1000 frequencies 10..5000 Hz at the nose (x -> x).

ROSS is never a dependency of spindlesim: it is installed (once) into a throwaway virtual
environment outside the repository (``$SPINDLESIM_ROSS_VENV`` or
~/.cache/spindlesim-bench/ross-venv) and driven through a small script written to a temporary
directory, which prints its results as JSON.  When no such environment can be made (no package
index, no matching wheel), the ROSS half is reported as skipped and the script exits 0.

Before any timing is trusted the first natural frequencies of the two models are printed side by
side (ROSS's axial and torsional modes, which a 4-DOF-per-node lateral model does not have, are
left out) and the FRF of both at a few frequencies, so that the two are timed on the same problem.

Note on the FRF: ROSS's ``run_freq_response`` evaluates H(w) with the rotor speed equal to the
excitation frequency (synchronous) and inverts the full dynamic stiffness at every frequency;
spindlesim's FRF is at the deck's fixed speed.  The work per frequency is the same kind (ROSS
also re-assembles M, C, K, G); for the accuracy check ROSS's ``transfer_matrix`` is called at the
deck speed.

Targets: issue "Lobes in seconds" (target 5) raised those of issue "Speed" (Campbell >= 20x faster than ROSS,
FRF >= 200x) to Campbell >= 40x, FRF >= 300x; the table prints the raised ones.

Usage: python benchmarks/bench_ross.py [--repeat N] [--no-install] [--deck PATH]
"""

from __future__ import annotations

import argparse
import json
import os
import pathlib
import subprocess
import sys
import tempfile
import textwrap
import time

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

ROSS_SPEC = "ross-rotordynamics==2.3.0"
CAMPBELL_TARGET, FRF_TARGET = 40, 300  # how many times faster than ROSS (issue "Lobes in seconds", target 5)
# ROSS 2.3.0 builds a plotly template at import time that plotly 7 rejects (scattermapbox).
ROSS_EXTRA = ["plotly<7"]
VENV = pathlib.Path(os.environ.get("SPINDLESIM_ROSS_VENV",
                                   pathlib.Path.home() / ".cache" / "spindlesim-bench" / "ross-venv"))

SPEEDS_RPM = (0.0, 12000.0, 50)
FREQS_HZ = (10.0, 5000.0, 1000)
N_MODES = 8
CHECK_FREQS_HZ = [100.0, 1000.0, 2500.0, 4000.0]

WORKER = textwrap.dedent(r'''
    import json, sys, time, warnings
    import numpy as np
    warnings.filterwarnings("ignore")
    job = json.load(open(sys.argv[1]))
    t0 = time.perf_counter()
    import ross as rs
    t_import = time.perf_counter() - t0

    def build():
        mats, shaft = {}, []
        for i, (do, di, L, rho, E, G, nu, fa) in enumerate(job["elements"]):
            key = (rho, E, G)
            if key not in mats:  # E and G as in the deck (ROSS takes two of E, G, Poisson)
                mats[key] = rs.Material(name=f"deck_mat_{len(mats)}", rho=rho, E=E * 1e9, G_s=G * 1e9)
            shaft.append(rs.ShaftElement(L=L / 1e3, idl=di / 1e3, odl=do / 1e3, material=mats[key], n=i,
                                         axial_force=fa, shear_effects=True, rotary_inertia=True,
                                         gyroscopic=True, shear_method_calc="cowper"))
        bearings = []
        for b in job["bearings"]:
            (kxx, kxy), (kyx, kyy) = b["K"]
            (cxx, cxy), (cyx, cyy) = b["C"]
            bearings.append(rs.BearingElement(n=b["node"] - 1, kxx=kxx, kxy=kxy, kyx=kyx, kyy=kyy,
                                              cxx=cxx, cxy=cxy, cyx=cyx, cyy=cyy, tag=b["name"]))
        return rs.Rotor(shaft, [], bearings)

    def lateral_modes(modal, ndof, n):
        """(wd Hz, zeta) of the first n modes whose shape is mostly lateral (x, y, alpha, beta)."""
        v = np.abs(modal.evectors[:ndof]) ** 2
        lat = v[[i for i in range(v.shape[0]) if i % 6 in (0, 1, 3, 4)]].sum(axis=0) / v.sum(axis=0)
        lam = modal.evalues
        keep = [k for k in np.argsort(np.abs(lam)) if lat[k] > 0.5 and lam[k].imag > 0]
        keep = keep[:n]
        return [float(lam[k].imag / (2 * np.pi)) for k in keep], [float(-lam[k].real / abs(lam[k])) for k in keep]

    out = {"import_s": t_import, "version": rs.__version__, "numpy": np.__version__}
    rotor = build()
    out["ndof"] = int(rotor.ndof)
    checks = {}
    for rpm in job["check_rpm"]:
        m = rotor.run_modal(rpm * np.pi / 30, num_modes=2 * job["n_modes"] + 8, sparse=False)
        checks[str(rpm)] = lateral_modes(m, rotor.ndof, job["n_modes"])
    out["modal"] = checks
    W = job["frf_rpm"] * np.pi / 30
    i_in = 6 * (job["frf_in_node"] - 1) + (0 if job["frf_in_dof"] == "x" else 1)
    i_out = 6 * (job["frf_out_node"] - 1) + (0 if job["frf_out_dof"] == "x" else 1)
    h = [rotor.transfer_matrix(speed=W, frequency=2 * np.pi * f)[i_out, i_in] for f in job["check_hz"]]
    out["frf_check"] = [[float(z.real), float(z.imag)] for z in h]

    speeds = np.asarray(job["speeds_rad_s"])
    omega = np.asarray(job["omega_rad_s"])
    t_camp, t_frf, c_camp, c_frf = [], [], [], []
    for _ in range(job["repeat"]):
        r = build()  # a fresh rotor: ROSS caches run_modal / run_freq_response per instance
        t, c = time.perf_counter(), time.process_time()
        camp = r.run_campbell(speeds, frequencies=job["n_modes"])
        t_camp.append(time.perf_counter() - t)
        c_camp.append(time.process_time() - c)
        t, c = time.perf_counter(), time.process_time()
        r.run_freq_response(speed_range=omega)
        t_frf.append(time.perf_counter() - t)
        c_frf.append(time.process_time() - c)
    out["campbell_s"], out["frf_s"] = t_camp, t_frf
    out["campbell_cpu"], out["frf_cpu"] = c_camp, c_frf
    out["campbell_shape"] = list(np.shape(camp.wd))
    print("JSON" + json.dumps(out))
''')


def ensure_ross_venv(install: bool) -> tuple[pathlib.Path | None, str]:
    """(python of the ROSS venv, "") or (None, reason)."""
    py = VENV / ("Scripts/python.exe" if os.name == "nt" else "bin/python")
    probe = [str(py), "-c", "import importlib.metadata as m; print(m.version('ross-rotordynamics'))"]
    if py.exists() and subprocess.run(probe, capture_output=True).returncode == 0:
        return py, ""
    if not install:
        return None, f"no ROSS environment at {VENV} (--no-install given)"
    print(f"creating a throwaway ROSS environment in {VENV} (once; outside the repository) ...", flush=True)
    try:
        VENV.parent.mkdir(parents=True, exist_ok=True)
        if not py.exists():
            subprocess.run([sys.executable, "-m", "venv", str(VENV)], check=True, capture_output=True, timeout=300)
        pip = [str(py), "-m", "pip", "install", "--quiet", "--disable-pip-version-check"]
        r = subprocess.run(pip + [ROSS_SPEC] + ROSS_EXTRA, capture_output=True, text=True, timeout=1200)
        if r.returncode != 0:  # the exact version may be missing: take the closest available
            r = subprocess.run(pip + ["ross-rotordynamics"] + ROSS_EXTRA, capture_output=True, text=True, timeout=1200)
        if r.returncode != 0:
            return None, "pip could not install ross-rotordynamics: " + (r.stderr.strip().splitlines() or ["?"])[-1]
    except (OSError, subprocess.SubprocessError) as exc:
        return None, f"could not create the ROSS environment: {exc}"
    if subprocess.run(probe, capture_output=True).returncode != 0:
        return None, "ross-rotordynamics installed but does not import"
    return py, ""


def median(xs):
    xs = sorted(xs)
    n = len(xs)
    return xs[n // 2] if n % 2 else 0.5 * (xs[n // 2 - 1] + xs[n // 2])


def spindlesim_side(deck, repeat: int) -> dict:
    import numpy as np

    from spindlesim.analysis.campbell import solve_campbell
    from spindlesim.analysis.frf import receptance, solve_frf
    from spindlesim.analysis.modal import solve_modal
    from spindlesim.analysis.operating import system_matrices
    from spindlesim.model.build import build_rotor

    speeds = np.linspace(*SPEEDS_RPM)
    freqs = np.linspace(*FREQS_HZ)
    fr = deck.frf
    args = (fr.input.node, fr.input.dof, fr.output.node, fr.output.dof)
    rotor = build_rotor(deck)
    out = {"ndof": rotor.dofs.size, "modal": {}}
    for rpm in (deck.operating.speed_rpm, SPEEDS_RPM[1]):
        m = solve_modal(rotor, rpm, n_modes=N_MODES)
        out["modal"][str(rpm)] = [list(map(float, m.frequency_hz)), list(map(float, m.damping_ratio))]
    sysm = system_matrices(rotor, rotor.speed_rpm)
    h = receptance(sysm, rotor.dofs.index(args[2] - 1, args[3]), rotor.dofs.index(args[0] - 1, args[1]),
                   2 * np.pi * np.asarray(CHECK_FREQS_HZ))
    out["frf_check"] = [[float(z.real), float(z.imag)] for z in h]
    t_camp, t_frf, c_camp, c_frf = [], [], [], []
    for _ in range(repeat):
        r = build_rotor(deck)  # fresh, as for ROSS: no cached state carried between repeats
        t, c = time.perf_counter(), time.process_time()
        solve_campbell(r, speeds, N_MODES)
        t_camp.append(time.perf_counter() - t)
        c_camp.append(time.process_time() - c)
        t, c = time.perf_counter(), time.process_time()
        solve_frf(r, freqs, *args)
        t_frf.append(time.perf_counter() - t)
        c_frf.append(time.process_time() - c)
    out["campbell_s"], out["frf_s"] = t_camp, t_frf
    out["campbell_cpu"], out["frf_cpu"] = c_camp, c_frf
    # solve_campbell spreads its speeds over a thread per core (BLAS itself single-threaded): the
    # same Campbell pinned to one core, for a one-core comparison with ROSS (which is serial)
    out["campbell_1core_s"] = None
    if hasattr(os, "sched_setaffinity") and len(os.sched_getaffinity(0)) > 1:
        cpus = os.sched_getaffinity(0)
        os.sched_setaffinity(0, {min(cpus)})
        try:
            t_one = []
            for _ in range(repeat):
                r = build_rotor(deck)
                t = time.perf_counter()
                solve_campbell(r, speeds, N_MODES)
                t_one.append(time.perf_counter() - t)
            out["campbell_1core_s"] = t_one
        finally:
            os.sched_setaffinity(0, cpus)
    return out


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3, help="repeats of each timing (median reported)")
    ap.add_argument("--no-install", action="store_true", help="use an existing ROSS venv only, never create one")
    ap.add_argument("--deck", type=pathlib.Path, default=None,
                    help="deck with linear bearings [embedded spindle_linear]")
    a = ap.parse_args()

    import numpy as np
    import scipy

    import spindlesim
    from spindlesim.deck import default_deck, load_deck

    deck = (load_deck(a.deck) if a.deck else default_deck("spindle_linear")).deck
    bearings = []
    for b in deck.bearings:
        if getattr(b, "type", None) != "linear" or getattr(b, "table", None):
            raise SystemExit(f"bench_ross needs constant linear bearings; bearing {b.name!r} is {b.type}")
        bearings.append({"name": b.name, "node": b.node, "K": b.K_N_m, "C": b.C_Ns_m})
    if getattr(deck, "disks", None):
        raise SystemExit("bench_ross: disks are not mapped to ROSS yet")

    print(f"rotor: {deck.title}; {len(deck.shaft.elements)} shaft elements, bearings at nodes "
          f"{[b['node'] for b in bearings]}; speed {deck.operating.speed_rpm:g} rpm")
    print(f"spindlesim {spindlesim.__version__}, numpy {np.__version__}, scipy {scipy.__version__}, "
          f"BLAS threads {os.environ.get('OPENBLAS_NUM_THREADS')}, repeats {a.repeat}, "
          f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    ours = spindlesim_side(deck, a.repeat)

    py, why = ensure_ross_venv(not a.no_install)
    ross = None
    if py is None:
        print(f"ROSS: skipped ({why})")
    else:
        fr = deck.frf
        job = {"elements": deck.shaft.elements, "bearings": bearings, "n_modes": N_MODES, "repeat": a.repeat,
               "check_rpm": [deck.operating.speed_rpm, SPEEDS_RPM[1]], "check_hz": CHECK_FREQS_HZ,
               "frf_rpm": deck.operating.speed_rpm,
               "frf_in_node": fr.input.node, "frf_in_dof": fr.input.dof,
               "frf_out_node": fr.output.node, "frf_out_dof": fr.output.dof,
               "speeds_rad_s": list(np.linspace(*SPEEDS_RPM) * np.pi / 30),
               "omega_rad_s": list(2 * np.pi * np.linspace(*FREQS_HZ))}
        with tempfile.TemporaryDirectory() as tmp:
            (pathlib.Path(tmp) / "ross_worker.py").write_text(WORKER)
            (pathlib.Path(tmp) / "job.json").write_text(json.dumps(job))
            env = dict(os.environ, MPLBACKEND="Agg")
            r = subprocess.run([str(py), "ross_worker.py", "job.json"], cwd=tmp, capture_output=True, text=True,
                               env=env, timeout=3600)
        line = [ln for ln in r.stdout.splitlines() if ln.startswith("JSON")]
        if r.returncode != 0 or not line:
            print("ROSS: failed, skipped\n" + "\n".join(r.stderr.strip().splitlines()[-8:]))
        else:
            ross = json.loads(line[-1][4:])
            print(f"ROSS {ross['version']} (numpy {ross['numpy']}) in {VENV}; import {ross['import_s']:.2f} s "
                  f"(excluded); {ross['ndof']} DOF vs spindlesim {ours['ndof']} DOF")

    # --- same problem? -----------------------------------------------------------------------
    if ross is not None:
        worst = 0.0
        for rpm, (f_s, z_s) in ours["modal"].items():
            f_r, z_r = ross["modal"][rpm]
            print(f"\nnatural frequencies at {float(rpm):g} rpm   spindlesim [Hz] (zeta)   ROSS [Hz] (zeta)   diff")
            for k in range(min(len(f_s), len(f_r))):
                d = (f_s[k] - f_r[k]) / f_r[k]
                worst = max(worst, abs(d))
                print(f"  mode {k + 1}   {f_s[k]:12.2f} ({z_s[k]:.4f})   {f_r[k]:12.2f} ({z_r[k]:.4f})   "
                      f"{100 * d:+6.2f} %")
        print(f"\nFRF at {deck.operating.speed_rpm:g} rpm, |H| [m/N]   spindlesim        ROSS      diff")
        for f, hs, hr in zip(CHECK_FREQS_HZ, ours["frf_check"], ross["frf_check"]):
            a_s, a_r = abs(complex(*hs)), abs(complex(*hr))
            print(f"  {f:7.0f} Hz   {a_s:12.4e}  {a_r:12.4e}  {100 * (a_s - a_r) / a_r:+6.2f} %")
        same = worst < 0.05
        print(f"largest natural-frequency difference {100 * worst:.2f} % -> "
              f"{'same problem' if same else 'MODELS DIFFER: timings not comparable'}")

    # --- timings -------------------------------------------------------------------------------
    print("\nrepeats [s]: " + "; ".join(
        f"{who} {k} " + ", ".join(f"{t:.3f}" for t in d[k])
        for who, d in (("spindlesim", ours), ("ROSS", ross or {}))
        for k in ("campbell_s", "campbell_cpu", "campbell_1core_s", "frf_s", "frf_cpu")
        if d.get(k)))
    print("(wall: median wall time; cpu: median CPU time of the process, all threads: the steadier figure "
          "on a loaded machine)")
    print(f"\n{'case':40s} {'ROSS [s]':>10s} {'spindlesim [s]':>15s} {'ratio':>8s} {'target':>7s}  ok")
    rows = [("campbell_s", "campbell_s", f"campbell, {SPEEDS_RPM[2]} speeds, wall", CAMPBELL_TARGET),
            ("campbell_cpu", "campbell_cpu", f"campbell, {SPEEDS_RPM[2]} speeds, cpu", CAMPBELL_TARGET),
            ("campbell_1core_s", "campbell_s", f"campbell, {SPEEDS_RPM[2]} speeds, 1 core, wall", CAMPBELL_TARGET),
            ("frf_s", "frf_s", f"frf, {FREQS_HZ[2]} frequencies, wall", FRF_TARGET),
            ("frf_cpu", "frf_cpu", f"frf, {FREQS_HZ[2]} frequencies, cpu", FRF_TARGET)]
    for key, rkey, name, target in rows:
        if not ours.get(key):
            continue
        s = median(ours[key])
        if ross is None:
            print(f"{name:40s} {'skipped':>10s} {s:15.4f} {'-':>8s} {target:6d}x  -")
            continue
        r_ = median(ross[rkey])
        ok = r_ / s >= target
        print(f"{name:40s} {r_:10.3f} {s:15.4f} {r_ / s:7.0f}x {target:6d}x  {'yes' if ok else 'NO'}")
    return 0  # a missed target is reported in the table, not a failure of the benchmark


if __name__ == "__main__":
    sys.exit(main())
