"""The command line runs BLAS on one thread unless the user says otherwise (docs/decisions.md, "Dense linear
algebra, single-threaded BLAS in the CLI"): OpenBLAS reads OPENBLAS_NUM_THREADS once, when numpy is first
imported, so the setting must be in the environment by then.  click imports a subcommand's module (and numpy with
it) before the group's own callback runs; until this test the setting was made there, too late, and every
command ran BLAS on two threads (a `campbell` of the milling deck 5.9 s against 4.5 s; a child forked to share a
sweep stalled in the inherited BLAS threads, 10 ms per 130 x 130 solve)."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

WATCH = """
import builtins, os, sys
seen = []
real = builtins.__import__
def watching(name, *args, **kwargs):
    if name.split(".")[0] == "numpy" and not seen:
        seen.append({v: os.environ.get(v) for v in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")})
    return real(name, *args, **kwargs)
builtins.__import__ = watching
sys.argv = ["spindlesim", "campbell", "--speeds", "1000:2000:3", "-q", "-o", sys.argv[1]]
from spindlesim.cli import console
try:
    console()
except SystemExit as exc:
    assert not exc.code, exc.code
print("AT NUMPY IMPORT", seen[0])
"""


def _env_without_blas_settings(**extra):
    env = {k: v for k, v in os.environ.items() if k not in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS",
                                                            "MKL_NUM_THREADS")}
    return env | extra


@pytest.mark.parametrize("user, expected", [(None, "1"), ("2", "2")])
def test_blas_threads_are_set_before_numpy_is_imported(tmp_path, user, expected):
    """`campbell` (its module imports numpy when click resolves it): one thread, or the user's setting."""
    env = _env_without_blas_settings(MPLBACKEND="Agg", SPINDLESIM_FIGURE_PROCESS="0",
                                     **({"OPENBLAS_NUM_THREADS": user} if user else {}))
    out = subprocess.run([sys.executable, "-c", WATCH, str(tmp_path / "out")], env=env, capture_output=True,
                         text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    line = next(x for x in out.stdout.splitlines() if x.startswith("AT NUMPY IMPORT"))
    assert f"'OPENBLAS_NUM_THREADS': '{expected}'" in line  # the user's own setting is kept
    assert "'OMP_NUM_THREADS': '1'" in line and "'MKL_NUM_THREADS': '1'" in line
