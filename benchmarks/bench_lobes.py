"""Issue "Lobes in seconds": its whole-process targets side by side in one run (median of N after a warm-up,
single-threaded BLAS).

1. `spindlesim chatter decks/milling_spindle.yaml` against the stack floor (bench_process.py's): target 5x.
2. `spindlesim tools` with the chatter section and ten tools (bench_taptest.py's deck) against one tool's
   `spindlesim chatter` of the same deck: target 3x.
3. `spindlesim thermal decks/milling_spindle.yaml` (the warm-up's stable depth at each instant's speed by the
   chatter section's method, docs/decisions.md), for the record of "no slower than today".
4. `spindlesim campbell decks/seed003_three_lobe.yaml --speeds 200:12000:60` (thermal equilibrium at every speed)
   against the same on the paper's linear coefficients (decks/seed003_spindle_linear.yaml): target 1.5x.
   Target 5 (in process) is benchmarks/bench_models.py.

Also `spindlesim chatter --map` (the stability map asked for), for the record.

Usage: python benchmarks/bench_lobes.py [--runs N] [--only WORDS]
"""

from __future__ import annotations

import argparse
import pathlib
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from bench_process import FLOOR, ROOT, spindlesim_exe, time_process  # noqa: E402
from bench_taptest import ten_tools_deck  # noqa: E402

MILL = ROOT / "decks" / "milling_spindle.yaml"


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--only", default="", help="comma-separated words: measure only the rows whose name has one "
                    "(e.g. --only floor,campbell); the ten tools alone take about four minutes")
    args = ap.parse_args()
    exe = spindlesim_exe()
    tmp = pathlib.Path(tempfile.mkdtemp())
    floor = tmp / "floor.py"
    floor.write_text(FLOOR)
    ten, _ = ten_tools_deck(tmp)
    rows = [
        ("stack floor", [sys.executable, str(floor)]),
        ("chatter milling", exe + ["chatter", str(MILL), "-q", "-o"]),
        ("chatter milling --map", exe + ["chatter", str(MILL), "--map", "-q", "-o"]),
        ("chatter one tool", exe + ["chatter", str(ten), "-q", "-o"]),
        ("tools, 10 tools, lobes", exe + ["tools", str(ten), "-q", "-o"]),
        ("thermal milling", exe + ["thermal", str(MILL), "-q", "-o"]),
        ("campbell 3-lobe, 60 speeds", exe + ["campbell", str(ROOT / "decks" / "seed003_three_lobe.yaml"), "--speeds",
                                               "200:12000:60", "-q", "-o"]),
        ("campbell linear, 60 speeds", exe + ["campbell", str(ROOT / "decks" / "seed003_spindle_linear.yaml"),
                                              "--speeds", "200:12000:60", "-q", "-o"]),
    ]
    got = {}
    print(f"{'command':30s} {'median s':>9s} {'min':>7s} {'max':>7s} {'cpu s':>7s}", flush=True)
    words = [w for w in args.only.split(",") if w]
    rows = [r for r in rows if not words or any(w in r[0] for w in words)]
    for name, argv in rows:  # the ten tools once, without a warm-up: about three minutes a run
        long = name.startswith("tools")
        med, lo, hi, cpu, rc, err = time_process(argv, tmp / "out", 1 if long else args.runs, warmup=0 if long else 1)
        if med is None:
            print(f"{name:30s} failed (exit {rc}): {err}", flush=True)
            continue
        got[name] = med
        print(f"{name:30s} {med:9.3f} {lo:7.3f} {hi:7.3f} {cpu:7.3f}", flush=True)

    def ratio(a: str, b: str, target: float, label: str) -> None:
        if a in got and b in got:
            r = got[a] / got[b]
            print(f"{label}: {r:.2f}x (target {target:g}x) {'MET' if r <= target else 'NOT MET'}")

    ratio("chatter milling", "stack floor", 5.0, "1. chatter milling / stack floor")
    ratio("tools, 10 tools, lobes", "chatter one tool", 3.0, "2. tools (10, lobes) / one tool's chatter")
    ratio("campbell 3-lobe, 60 speeds", "campbell linear, 60 speeds", 1.5, "4. campbell 3-lobe / linear")


if __name__ == "__main__":
    main()
