"""The spindle's thermal loop on the milling spindle deck (issue 22's speed targets), medians of --repeat runs:

* the steady thermo-mechanical state at one speed (12,000 rpm), from the cold spindle: target under 0.2 s;
* a two-hour warm-up with five speed steps (4000, 8000, 12,000, 8000 rpm, stop; 25 instants), the bearing
  states updated as the temperatures change: target under 10 s;
* Campbell with the thermal equilibrium re-solved at each of 50 speeds (0-13,000 rpm, below the front pair's
  runaway near 18,000 rpm), side by side with the same diagram with speed effects only (the bearings'
  quasi-static states re-solved at every speed at the assembly temperature): target within 3x.

Deck: decks/milling_spindle.yaml (section spindle_thermal: housing, cooling jacket, motor, oil-air); and the
steady state of decks/lathe_headstock.yaml (a DTRB and a cylindrical roller bearing, Palmgren's heat) at
1500 rpm, the same target.

    python benchmarks/bench_spindle_thermal.py [--repeat 3]
"""

from __future__ import annotations

import argparse
import statistics
import time
from pathlib import Path

import numpy as np

from spindlesim.analysis.campbell import solve_campbell
from spindlesim.analysis.points import OperatingPoints
from spindlesim.analysis.spindle_thermal import SpindleThermal
from spindlesim.deck import load_deck
from spindlesim.model.build import build_rotor
from spindlesim.model.thermal import build_spindle_thermal

DECK = Path(__file__).parents[1] / "decks" / "milling_spindle.yaml"
LATHE = Path(__file__).parents[1] / "decks" / "lathe_headstock.yaml"
STEPS_S = (0.0, 1440.0, 2880.0, 4320.0, 5760.0)
STEPS_RPM = (4000.0, 8000.0, 12000.0, 8000.0, 0.0)
TARGETS = {"steady": 0.2, "warm-up": 10.0, "ratio": 3.0}


def _median(fn, repeat: int) -> tuple[float, float, object]:
    """(median wall, median CPU) of ``repeat`` calls, and the last call's result."""
    wall, cpu, out = [], [], None
    for _ in range(repeat):
        t, c = time.perf_counter(), time.process_time()
        out = fn()
        wall.append(time.perf_counter() - t)
        cpu.append(time.process_time() - c)
    return statistics.median(wall), statistics.median(cpu), out


def _row(name: str, wall: float, cpu: float, target: float | None = None, note: str = "") -> None:
    verdict = "" if target is None else ("  meets" if wall <= target else "  MISSES") + f" target {target:g} s"
    print(f"  {name:58s} {wall:8.3f} s wall {cpu:8.3f} s CPU{verdict}  {note}")


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=3)
    r = ap.parse_args().repeat
    deck = load_deck(DECK).deck
    rotor = build_rotor(deck)
    model = build_spindle_thermal(deck, rotor)
    SpindleThermal(rotor, model).steady(4000.0)  # compiled kernels and caches warm before timing
    print(f"milling spindle thermal loop (median of {r})")

    w, c, st = _median(lambda: SpindleThermal(rotor, model).steady(12000.0), r)
    _row("steady state at 12,000 rpm from cold (model built once)", w, c, TARGETS["steady"],
         f"{st.iterations} passes, {st.total_heat_W:.0f} W")

    def warm():
        return SpindleThermal(rotor, model).warm_up(STEPS_S, STEPS_RPM, 7200.0, samples=25)

    w, c, inst = _median(warm, max(1, r - 1))
    _row("2 h warm-up, 5 speed steps, 25 instants", w, c, TARGETS["warm-up"],
         f"front inner ring {max(s.temperatures_C['bearing:front:inner'] for s in inst):.1f} C at most")

    speeds = np.linspace(0.0, 13000.0, 50)
    w0, c0, _ = _median(lambda: solve_campbell(OperatingPoints(rotor), speeds, n_modes=8), r)
    _row("Campbell, 50 speeds, speed effects only", w0, c0)
    w1, c1, res = _median(lambda: solve_campbell(OperatingPoints(rotor, model), speeds, n_modes=8), max(1, r - 1))
    ratio = w1 / w0
    _row("Campbell, 50 speeds, thermal equilibrium at each", w1, c1,
         note=f"ratio {ratio:.2f} (target {TARGETS['ratio']:g}: {'meets' if ratio <= TARGETS['ratio'] else 'MISSES'})")

    lathe = load_deck(LATHE).deck
    lathe_rotor = build_rotor(lathe)
    lathe_model = build_spindle_thermal(lathe, lathe_rotor)
    SpindleThermal(lathe_rotor, lathe_model).steady(500.0)
    w, c, st = _median(lambda: SpindleThermal(lathe_rotor, lathe_model).steady(1500.0), r)
    _row("lathe headstock (DTRB + cylindrical roller) steady at 1500 rpm", w, c, TARGETS["steady"],
         f"{st.iterations} passes, {st.total_heat_W:.0f} W")


if __name__ == "__main__":
    main()
