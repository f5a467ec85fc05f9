"""Run every benchmarks/bench_*.py script in turn (`make bench`); each prints its own table."""

import pathlib
import subprocess
import sys

here = pathlib.Path(__file__).parent
status = 0
for script in sorted(here.glob("bench_*.py")):
    print(f"\n== {script.name} ==", flush=True)
    status |= subprocess.run([sys.executable, str(script)], cwd=here.parent).returncode
sys.exit(status)
