"""Issue 30's speed targets, whole processes side by side in one run (median of N after a warm-up, single-threaded
BLAS): `spindlesim calibrate` of three parameters (target: within 30 s on one core) and `spindlesim tools` with
ten tools and no lobes (target: within 1.5x one `spindlesim frf` of the same spindle).  Also the stack floor
(bench_process.py's) and the in-process cost of the coupling alone.

Usage: python benchmarks/bench_taptest.py [--runs N]
"""

from __future__ import annotations

import argparse
import pathlib
import sys
import tempfile
import time

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from bench_process import ENV, FLOOR, ROOT, spindlesim_exe, time_process  # noqa: E402

TEN = """
  - name: extra_8_40
    holder: {elements: [[63.0, 8.0, 20.0, 7850.0, 210.0, 80.8, 0.3, 0.0], [24.0, 8.0, 60.0, 7850.0, 210.0, 80.8, 0.3, 0.0]]}
    joint: {translational_N_m: 1.0e8, rotational_Nm_rad: 5.0e5, translational_Ns_m: 100.0, rotational_Nms_rad: 1.0}
    tool: {elements: [[8.0, 0.0, 15.0, 14500.0, 580.0, 240.0, 0.22, 0.0], [6.4, 0.0, 25.0, 14500.0, 580.0, 240.0, 0.22, 0.0]]}
  - name: extra_12_60
    tool: {elements: [[16.0, 0.0, 30.0, 14500.0, 580.0, 240.0, 0.22, 0.0], [12.8, 0.0, 30.0, 14500.0, 580.0, 240.0, 0.22, 0.0]]}
  - name: extra_16_75
    tool: {elements: [[16.0, 0.0, 35.0, 14500.0, 580.0, 240.0, 0.22, 0.0], [12.8, 0.0, 40.0, 14500.0, 580.0, 240.0, 0.22, 0.0]]}
"""


def ten_tools_deck(folder: pathlib.Path) -> tuple[pathlib.Path, str]:
    """decks/tool_library.yaml with three more tools (ten in all), written into ``folder``: (path, text)."""
    text = (ROOT / "decks" / "tool_library.yaml").read_text().replace("\ndisks:\n", TEN + "disks:\n", 1)
    text = text.replace("path: calibration/tap_", f"path: {ROOT}/decks/calibration/tap_")
    deck = folder / "ten_tools.yaml"
    deck.write_text(text)
    return deck, text


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--runs", type=int, default=3)
    args = ap.parse_args()
    exe = spindlesim_exe()
    tmp = pathlib.Path(tempfile.mkdtemp())
    deck, text = ten_tools_deck(tmp)
    floor = tmp / "floor.py"
    floor.write_text(FLOOR)
    rows = [
        ("stack floor", [sys.executable, str(floor)]),
        ("frf milling_spindle", exe + ["frf", str(ROOT / "decks" / "milling_spindle.yaml"), "-q", "-o"]),
        ("tools, 10 tools, no lobes", exe + ["tools", str(deck), "--no-lobes", "-q", "-o"]),
        ("calibrate, 3 parameters", exe + ["calibrate", str(deck), "-q", "-o"]),
    ]
    got = {}
    print(f"{'command':28s} {'median s':>9s} {'min':>7s} {'max':>7s} {'cpu s':>7s}")
    for name, argv in rows:
        med, lo, hi, cpu, rc, err = time_process(argv, tmp / "out", args.runs)
        if med is None:
            print(f"{name:28s} failed (exit {rc}): {err}")
            continue
        got[name] = med
        print(f"{name:28s} {med:9.3f} {lo:7.3f} {hi:7.3f} {cpu:7.3f}")
    if "tools, 10 tools, no lobes" in got and "frf milling_spindle" in got:
        r = got["tools, 10 tools, no lobes"] / got["frf milling_spindle"]
        print(f"tools (10) / frf: {r:.2f}x (target 1.5x) {'MET' if r <= 1.5 else 'NOT MET'}")
    if "calibrate, 3 parameters" in got:
        c = got["calibrate, 3 parameters"]
        print(f"calibrate (3 parameters): {c:.1f} s (target 30 s) {'MET' if c <= 30 else 'NOT MET'}")
    # in process: the coupling of ten tools at the operating speed
    from spindlesim.analysis.tool_library import couple_tools
    from spindlesim.deck import parse_deck
    from spindlesim.deck.document import library_tools
    from spindlesim.model.tool_library import build_tool_library
    from spindlesim.runs.common import value_range

    d = parse_deck(text, str(deck)).deck
    model = build_tool_library(d, library_tools(d))
    f = value_range(d.frf.frequencies_hz)
    couple_tools(model, 18000.0, f)
    t = time.perf_counter()
    couple_tools(model, 18000.0, f)
    print(f"in process: {len(model.tools)} tools coupled at 18000 rpm on {len(f)} frequencies: "
          f"{time.perf_counter() - t:.3f} s")


if __name__ == "__main__":
    main()
