"""Whole-process timings of the CLI against the "stack floor" (issue "Speed").

The stack floor is the least any spindlesim command that writes results can cost: a Python process
that imports numpy, scipy.linalg, h5py and matplotlib, writes one small HDF5 file and saves one
2-panel PNG.  Target: `spindlesim modal`, `spindlesim campbell --speeds 0:12000:50` and
`spindlesim frf` each within 1.3x of the floor (median of 5 whole-process runs after a warm-up,
single-threaded BLAS).

The commands are timed on the default deck (embedded ``spindle``: seed 003, 3-lobe fluid-film
bearings at thermal equilibrium) and on the linear-bearing deck of the same spindle
(decks/seed003_spindle_linear.yaml), each with -o to a temporary directory; on the linear deck
also with SPINDLESIM_FIGURE_PROCESS=0 (figures drawn in the main process, spindlesim/output/drawing.py),
to show what the figure process brings.  spindlesim's modules are byte-compiled first, as an
installed package's are (an editable install under PYTHONDONTWRITEBYTECODE=1 would otherwise
compile them again in every process, about 50 ms).

Then, to show where the time goes:
* ``python -X importtime -c "import spindlesim.cli"`` and the imports of each command (top entries);
* cProfile of each command (top functions by cumulative and by own time).

Usage: python benchmarks/bench_process.py [--runs N] [--no-profile] [--deck-set default|linear|both]
"""

from __future__ import annotations

import argparse
import os
import pathlib
import pstats
import re
import resource
import shutil
import subprocess
import sys
import tempfile
import textwrap
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
ENV = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1", MKL_NUM_THREADS="1", MPLBACKEND="Agg")
TARGET = 1.3
LINEAR_DECK = ROOT / "decks" / "seed003_spindle_linear.yaml"

FLOOR = textwrap.dedent('''
    """Stack floor: import numpy, scipy.linalg, h5py, matplotlib; one small HDF5 file; one 2-panel PNG."""
    import pathlib
    import sys

    import h5py
    import matplotlib
    import numpy as np
    import scipy.linalg

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out = pathlib.Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    x = np.linspace(0.0, 1.0, 200)
    with h5py.File(out / "floor.h5", "w") as f:
        f["x"] = x
        f["y"] = scipy.linalg.norm(x) * x
    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
    a.plot(x, np.sin(6 * x))
    b.plot(x, np.cos(6 * x))
    fig.savefig(out / "floor.png", dpi=110)
''')


def spindlesim_exe() -> list[str]:
    exe = pathlib.Path(sys.executable).with_name("spindlesim")
    return [str(exe)] if exe.exists() else [sys.executable, "-m", "spindlesim"]


def median(xs):
    xs = sorted(xs)
    n = len(xs)
    return xs[n // 2] if n % 2 else 0.5 * (xs[n // 2 - 1] + xs[n // 2])


def _child_cpu() -> float:
    ru = resource.getrusage(resource.RUSAGE_CHILDREN)
    return ru.ru_utime + ru.ru_stime


def time_process(argv: list[str], outdir: pathlib.Path, runs: int, warmup: int = 1, env: dict | None = None):
    """(median wall seconds, min, max, median CPU seconds (user + sys), exit code, stderr tail).

    The CPU time is the kernel's account of the finished child and its children (the figure
    process included): on a shared, loaded machine it is the steadier figure (the wall time includes
    waiting for a core)."""
    times, cpus, rc, err = [], [], 0, ""
    for i in range(warmup + runs):
        shutil.rmtree(outdir, ignore_errors=True)
        c = _child_cpu()
        t = time.perf_counter()
        r = subprocess.run(argv + [str(outdir)], env=env or ENV, cwd=ROOT, capture_output=True, text=True)
        dt = time.perf_counter() - t
        dc = _child_cpu() - c
        rc, err = r.returncode, r.stderr.strip().splitlines()[-1:] if r.stderr.strip() else []
        if rc != 0:
            return None, None, None, None, rc, err[0] if err else ""
        if i >= warmup:
            times.append(dt)
            cpus.append(dc)
    return median(times), min(times), max(times), median(cpus), rc, ""


def importtime(argv: list[str], top: int = 12):
    """Top (cumulative us, self us, module) of ``python -X importtime`` for argv (a python argv tail)."""
    r = subprocess.run([sys.executable, "-X", "importtime"] + argv, env=ENV, cwd=ROOT, capture_output=True, text=True)
    rows = []
    for line in r.stderr.splitlines():
        m = re.match(r"import time:\s+(\d+) \|\s+(\d+) \|(\s*)(\S+)", line)
        if m:
            rows.append((int(m.group(2)), int(m.group(1)), len(m.group(3)), m.group(4)))
    total = sum(c for c, _, depth, _ in rows if depth == 1)
    # top-level packages (depth 1) by cumulative time, then any module by its own time
    tops = sorted((r_ for r_ in rows if r_[2] == 1), reverse=True)[:top]
    selfs = sorted(rows, key=lambda r_: r_[1], reverse=True)[:top]
    return total, tops, selfs


def profile(args: list[str], outdir: pathlib.Path, top: int = 15):
    with tempfile.NamedTemporaryFile(suffix=".prof", delete=False) as f:
        prof = f.name
    try:
        driver = pathlib.Path(prof).with_suffix(".py")
        driver.write_text("import sys\nfrom spindlesim.cli import main\n"
                          f"sys.argv = ['spindlesim'] + {args!r} + ['-o', {str(outdir)!r}]\n"
                          "main(standalone_mode=False)\n")
        r = subprocess.run([sys.executable, "-m", "cProfile", "-o", prof, str(driver)], env=ENV, cwd=ROOT,
                           capture_output=True, text=True)
        driver.unlink()
        if not os.path.getsize(prof):
            return None, [], [(0.0, (r.stderr.strip().splitlines() or ["no profile"])[-1])]
        st = pstats.Stats(prof)
        total = st.total_tt
        cum = sorted(st.stats.items(), key=lambda kv: kv[1][3], reverse=True)
        own = sorted(st.stats.items(), key=lambda kv: kv[1][2], reverse=True)[:top]

        def name(k):
            file, line, fn = k
            file = file.replace(str(ROOT) + "/", "")
            m = re.search(r"site-packages/(.*)", file)
            return f"{m.group(1) if m else file}:{line}({fn})"

        # cumulative: skip the generic wrappers (click, runpy, exec) that sit above everything
        skip = ("click/", "runpy", "<string>", "{built-in method builtins.exec}", "cProfile", "<frozen importlib")
        cum = [(k, v) for k, v in cum if not any(s in name(k) for s in skip)][:top]
        return total, [(v[3], name(k)) for k, v in cum], [(v[2], name(k)) for k, v in own]
    finally:
        os.unlink(prof)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--no-profile", action="store_true", help="timings only (no importtime, no cProfile)")
    ap.add_argument("--deck-set", choices=("default", "linear", "both"), default="both")
    a = ap.parse_args()

    exe = spindlesim_exe()
    subprocess.run([sys.executable, "-m", "compileall", "-q", str(ROOT / "spindlesim")], check=True,
                   capture_output=True)
    commands = [("modal", ["modal"]), ("campbell --speeds 0:12000:50", ["campbell", "--speeds", "0:12000:50"]),
                ("frf", ["frf"])]
    decks = []
    if a.deck_set in ("default", "both"):
        decks.append(("default", []))
    if a.deck_set in ("linear", "both"):
        decks.append(("linear", [str(LINEAR_DECK)]))

    print("decks: default = embedded 'spindle' (3-lobe fluid film, thermal equilibrium); "
          f"linear = {LINEAR_DECK.relative_to(ROOT)}")
    print(f"{sys.executable} ({sys.version.split()[0]}), {os.cpu_count()} cores, load average "
          f"{os.getloadavg()[0]:.1f}; median of {a.runs} runs after 1 warm-up; BLAS threads 1")
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        script = tmp / "stack_floor.py"
        script.write_text(FLOOR)
        floor = time_process([sys.executable, str(script)], tmp / "floor", a.runs)
        if floor[0] is None:
            print(f"stack floor script failed: {floor[5]}")
            return 1
        print(f"\n{'case':66s} {'wall med':>8s} {'min':>6s} {'max':>6s} {'/floor':>6s} {'cpu med':>8s} "
              f"{'/floor':>6s}  ok (wall <= {TARGET}x)")
        print(f"{'stack floor (numpy, scipy.linalg, h5py, mpl; .h5 + .png)':66s} "
              f"{floor[0]:8.3f} {floor[1]:6.2f} {floor[2]:6.2f} {1.0:6.2f} {floor[3]:8.3f} {1.0:6.2f}")
        cases = [(d, arg, "") for d, arg in decks]
        if a.deck_set in ("linear", "both"):
            cases.append(("linear", [str(LINEAR_DECK)], "0"))
        for deck_name, deck_arg, figure_process in cases:
            for name, args in commands:
                label = f"spindlesim {name}  [{deck_name}{', figures in-process' if figure_process else ''}]"
                env = dict(ENV, SPINDLESIM_FIGURE_PROCESS=figure_process) if figure_process else ENV
                med, lo, hi, cpu, rc, err = time_process(exe + args + deck_arg + ["-o"], tmp / "cmd", a.runs, env=env)
                if med is None:
                    print(f"{label:66s} {'FAILED':>8s}  exit {rc}: {err[:100]}")
                    continue
                ratio = med / floor[0]
                print(f"{label:66s} {med:8.3f} {lo:6.2f} {hi:6.2f} {ratio:6.2f} {cpu:8.3f} {cpu / floor[3]:6.2f}  "
                      f"{'yes' if ratio <= TARGET else 'NO'}")

        if a.no_profile:
            return 0
        total, tops, selfs = importtime(["-c", "import spindlesim.cli"])
        print(f"\nimporttime: import spindlesim.cli  (total {total / 1e3:.0f} ms)")
        for cum, own, _, mod in tops[:8]:
            print(f"  {cum / 1e3:8.1f} ms cumulative  {mod}")
        for deck_name, deck_arg in decks[:1]:
            for name, args in commands:
                total, tops, selfs = importtime(["-m", "spindlesim"] + args + deck_arg + ["-o", str(tmp / "imp")])
                print(f"\nimporttime: spindlesim {name} [{deck_name}] (all imports {total / 1e3:.0f} ms); "
                      "top-level packages by cumulative time:")
                for cum, own, _, mod in tops[:10]:
                    print(f"  {cum / 1e3:8.1f} ms  {mod}")
                print("  modules by own time:")
                for cum, own, _, mod in selfs[:6]:
                    print(f"  {own / 1e3:8.1f} ms  {mod}")
        for deck_name, deck_arg in decks:
            for name, args in commands:
                total, cum, own = profile(args + deck_arg, tmp / "prof")
                if total is None:
                    print(f"\ncProfile: spindlesim {name} [{deck_name}]: failed ({own[0][1]})")
                    continue
                print(f"\ncProfile: spindlesim {name} [{deck_name}]  (profiled total {total:.2f} s)")
                print("  by cumulative time:")
                for t, n in cum[:12]:
                    print(f"  {t:8.3f} s  {n}")
                print("  by own time:")
                for t, n in own[:8]:
                    print(f"  {t:8.3f} s  {n}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
