"""Run every benchmarks/bench_*.py script in turn (`make bench`); each prints its own table.

Usage: python benchmarks/run.py [NAME ...]   (NAME: e.g. `ross` or `bench_ross.py`; default all)

Scripts listed in ARGS get those arguments (fewer repeats where one run is long); each script is
stopped after TIMEOUT_S.  The ROSS comparison (bench_ross.py) creates its throwaway ROSS
environment outside the repository on first use; with SPINDLESIM_BENCH_NO_ROSS=1 it only uses an
existing one (and otherwise reports the ROSS half as skipped).  The whole run stays well under
15 minutes on a 2-core machine.
"""

import os
import pathlib
import subprocess
import sys
import time

here = pathlib.Path(__file__).parent
TIMEOUT_S = 600
ARGS = {
    "bench_ross.py": ["--repeat", "3"] + (["--no-install"] if os.environ.get("SPINDLESIM_BENCH_NO_ROSS") else []),
    "bench_process.py": ["--runs", "5"],
    "bench_campbell_fluidfilm.py": ["--repeat", "2"],
    "bench_lobes.py": ["--runs", "1"],
}
env = dict(os.environ)
for var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    env.setdefault(var, "1")
env.setdefault("MPLBACKEND", "Agg")

wanted = {a if a.endswith(".py") else f"bench_{a.removeprefix('bench_')}.py" for a in sys.argv[1:]}
status = 0
start = time.perf_counter()
for script in sorted(here.glob("bench_*.py")):
    if wanted and script.name not in wanted:
        continue
    print(f"\n== {script.name} ==", flush=True)
    t = time.perf_counter()
    try:
        rc = subprocess.run([sys.executable, str(script)] + ARGS.get(script.name, []), cwd=here.parent, env=env,
                            timeout=TIMEOUT_S).returncode
    except subprocess.TimeoutExpired:
        print(f"{script.name}: stopped after {TIMEOUT_S} s")
        rc = 1
    status |= rc
    print(f"-- {script.name}: {time.perf_counter() - t:.0f} s", flush=True)
print(f"\nall benchmarks: {time.perf_counter() - start:.0f} s")
sys.exit(status)
