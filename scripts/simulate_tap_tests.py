"""Simulated tap tests for decks/calibration/ (not measurements): the milling spindle of decks/milling_spindle.yaml
with a holder-tool joint other than the deck's (the "truth" below), its direct receptance in x at the tool tip
(node 26) and at the holder's nose end (node 22) at rest, 100-5000 Hz, with 2 % complex noise (normal, seed 13) on
each value.  Run from the repository's root: python scripts/simulate_tap_tests.py [OUTDIR]"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

from spindlesim.analysis.frf import receptance
from spindlesim.analysis.points import OperatingPoints
from spindlesim.deck import load_deck, parse_deck
from spindlesim.model.build import build_rotor
from spindlesim.deck.paths import replace_in_text

ROOT = Path(__file__).parents[1]
TRUTH = {"tool.joint.translational_N_m": 2.5e8, "tool.joint.rotational_Nm_rad": 1.2e6,
         "tool.joint.translational_Ns_m": 450.0}
FREQUENCIES = np.linspace(100.0, 5000.0, 491)
NOISE = 0.02
SEED = 13


def main(out: Path, seed: int = SEED, noise: float = NOISE, truth_values: dict | None = None) -> None:
    """Write tap_tip_x.csv and tap_holder_x.csv into ``out`` (module note)."""
    values = TRUTH if truth_values is None else truth_values
    loaded = load_deck(ROOT / "decks" / "milling_spindle.yaml")
    deck = parse_deck(replace_in_text(loaded.text, values, digits=17), "truth").deck
    rotor = build_rotor(deck)
    points = OperatingPoints(rotor)
    sysm = points.system(points.state(0.0))
    rng = np.random.default_rng(seed)
    truth = ", ".join(f"{k} = {v:g}" for k, v in values.items())
    for node, name in ((26, "tap_tip_x.csv"), (22, "tap_holder_x.csv")):
        i = rotor.dofs.index(node - 1, "x")
        H = receptance(sysm, i, i, 2 * np.pi * FREQUENCIES)
        H = H * (1 + noise * (rng.standard_normal(H.shape) + 1j * rng.standard_normal(H.shape)) / np.sqrt(2))
        lines = [f"# SIMULATED tap test, not a measurement: direct receptance x at node {node} of",
                 "# decks/milling_spindle.yaml at rest with the holder-tool joint changed to",
                 f"# {truth}",
                 f"# plus {100 * noise:g} % complex normal noise (seed {seed}); scripts/simulate_tap_tests.py writes it.",
                 "frequency_hz,real_m_N,imag_m_N"]
        lines += [f"{f:.6g},{h.real:.9e},{h.imag:.9e}" for f, h in zip(FREQUENCIES, H)]
        (out / name).write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "decks" / "calibration")
