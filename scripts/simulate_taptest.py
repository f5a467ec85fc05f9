"""Simulated tap test for decks/taptest/ (not a measurement): the milling spindle of decks/milling_spindle.yaml at
rest, its direct receptance in x at the tool tip (node 26; what `spindlesim frf decks/milling_spindle.yaml --speed 0`
computes), struck by a virtual hammer and measured by a virtual accelerometer (spindlesim.measured.simulate):
four impacts of 0.5 s at 8000 samples/s, half-sine pulses of 0.3 ms and about 500 N, normal noise on both channels
(0.2 % and 0.05 % of their peaks), the third a double hit (a second hit 1.5 ms later at 40 %).

Writes tap_impact_x_1.csv .. tap_impact_x_4.csv (the impact records, `spindlesim impact` reads them) and
tap_tip_x.csv (the FRF `spindlesim impact` makes of them, with its coherence; `spindlesim fitmodes` reads it)
into decks/taptest/ and the package's copy spindlesim/decks/taptest/.

Run from the repository's root: python scripts/simulate_taptest.py
"""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np

from spindlesim.analysis.points import OperatingPoints
from spindlesim.analysis.tool_point import tool_point_model
from spindlesim.chatter.frf import ToolPointFrf
from spindlesim.chatter.readers import frf_csv_text
from spindlesim.deck import load_deck
from spindlesim.measured.impact import frf_from_impacts
from spindlesim.measured.simulate import simulate_impacts
from spindlesim.model.build import build_rotor

ROOT = Path(__file__).parents[1]
RATE_HZ, SAMPLES, IMPACTS, DOUBLE_HIT, SEED = 8000, 4000, 4, 3, 30
#: RMS noise of the force and the acceleration channels, as a share of their peaks
FORCE_NOISE, RESPONSE_NOISE = 0.002, 0.0005
WHAT = ["SIMULATED tap test, not a measurement: decks/milling_spindle.yaml at rest (0 rpm), direct receptance x at the",
        "tool tip (node 26), as `spindlesim frf decks/milling_spindle.yaml --speed 0` computes it, struck by a virtual",
        f"hammer (half-sine 0.3 ms, about 500 N) and read by a virtual accelerometer: {IMPACTS} impacts of "
        f"{SAMPLES / RATE_HZ:g} s at {RATE_HZ} samples/s,",
        f"normal noise on both channels ({100 * FORCE_NOISE:g} % and {100 * RESPONSE_NOISE:g} % of their peaks, "
        f"seed {SEED}), impact {DOUBLE_HIT} a double hit (1.5 ms, 40 %);",
        "scripts/simulate_taptest.py writes it."]


def tool_tip_model():
    """The state-space model of the milling deck's tool tip at rest (x and y)."""
    rotor = build_rotor(load_deck(ROOT / "decks" / "milling_spindle.yaml").deck)
    return tool_point_model(OperatingPoints(rotor), 0.0)


def main(out: Path = ROOT / "decks" / "taptest") -> None:
    model = tool_tip_model()
    records = simulate_impacts(lambda f: model.receptance(2 * np.pi * f)[:, 0, 0], RATE_HZ, SAMPLES, IMPACTS,
                               seed=SEED, double_hit=DOUBLE_HIT, force_noise=FORCE_NOISE,
                               response_noise=RESPONSE_NOISE)
    out.mkdir(parents=True, exist_ok=True)
    for k, r in enumerate(records, start=1):
        which = f"# impact {k} of {IMPACTS}" + (" (the double hit)" if k == DOUBLE_HIT else "")
        lines = [f"# {w}" for w in WHAT] + [which, "time_s,force_N,acceleration_m_s2"]
        lines += [f"{t:.8g},{f:.5g},{a:.5g}" for t, f, a in zip(r.time_s, r.force_N, r.response)]
        (out / f"tap_impact_x_{k}.csv").write_text("\n".join(lines) + "\n", encoding="utf-8")
    from spindlesim.measured.records import read_impact_records  # the FRF of the files as written (rounded)

    res = frf_from_impacts([r for k in range(1, IMPACTS + 1)
                            for r in read_impact_records(out / f"tap_impact_x_{k}.csv")])
    H = np.zeros((len(res.frequency_hz), 2, 2), complex)
    C = np.full(H.shape, np.nan)
    H[:, 0, 0], C[:, 0, 0] = res.receptance_m_N, res.coherence
    frf = ToolPointFrf(res.frequency_hz, H, "tap_impact_x_*.csv", C, (res.window_decay_1_s, 0.0))
    header = tuple(WHAT) + (f"H1 of the {res.used} accepted impacts of tap_impact_x_1..{IMPACTS}.csv "
                            f"(`spindlesim impact` on them); receptance [m/N], coherence",)
    (out / "tap_tip_x.csv").write_text(frf_csv_text(frf, "x", header), encoding="utf-8")
    packaged = ROOT / "spindlesim" / "decks" / "taptest"
    packaged.mkdir(parents=True, exist_ok=True)
    for p in sorted(out.glob("tap_*.csv")):
        shutil.copyfile(p, packaged / p.name)


if __name__ == "__main__":
    main()
