"""Issue 21 on the example decks: resonances inside the speed or frequency range are found and
reported, each checked against an independent modal solution at the reported point."""

from pathlib import Path

import h5py
import numpy as np
import pytest

from spindlesim.analysis.modal import solve_modal
from spindlesim.deck import load_deck
from spindlesim.model.build import build_rotor
from spindlesim.output.summary import summary_of
from tests.rotor_helpers import cli_with_result

DECKS = Path(__file__).resolve().parents[2] / "decks"


def test_milling_spindle_axial_crossing_is_in_the_campbell_summary(tmp_path, monkeypatch):
    """The axial mode (zeta 1.15 % there since issue 30's bearing damping; 1e-5 before) crosses 1x near 22,100 rpm
    (issue 21: the summary said "no critical speed").  Independent check: the damped modes solved at the reported speed have the axial
    mode at N/60, and its damping gives the reported AF = 1/(2 zeta)."""
    deck = DECKS / "milling_spindle.yaml"
    out, written = cli_with_result(monkeypatch, ["campbell", deck, "--speeds", "20000:24000:9", "-o", tmp_path])
    lines, s = summary_of("campbell")(written.result)
    axial = [c for c in s["crossings"] if c["order"] == 1.0 and c["whirl"] == "axial"]
    assert len(axial) == 1
    c = axial[0]
    assert 21600 < c["speed_rpm"] < 22600
    m = solve_modal(build_rotor(load_deck(deck).deck), c["speed_rpm"], n_modes=8)
    k = list(m.whirl).index("axial")
    assert m.frequency_hz[k] == pytest.approx(c["speed_rpm"] / 60, rel=1e-3)
    assert c["amplification_factor"] == pytest.approx(1 / (2 * m.damping_ratio[k]), rel=0.05)
    assert 30 < c["amplification_factor"] < 60 and c["critical"]  # 1 / (2 zeta) = 43 (5.0e4 with C = 0)
    assert any(cs["speed_rpm"] == c["speed_rpm"] for cs in s["critical_speeds"])
    row = [ln for ln in out.splitlines() if f"{c['speed_rpm']:.0f}" in ln and "axial" in ln and " 1x " in ln]
    assert row and f"{c['amplification_factor']:.3g}" in row[0]
    assert "no critical speed" not in out
    # the tooth-passing order of the deck's 4-flute cutter is looked at too
    with h5py.File(tmp_path / "campbell.h5") as f:
        np.testing.assert_array_equal(f["campbell/crossings"].attrs["orders"], [1.0, 2.0, 4.0])


def test_seed001_frf_lists_every_mode_in_range(tmp_path, monkeypatch):
    """Seed 001 rotor, 9 x -> 5 x on the deck's 5 Hz grid: every damped mode in 10-3000 Hz is listed with
    its peak, and the peak of the lightly damped 220 Hz mode is resolved: there the receptance is
    (almost) imaginary, |Im H| >> |Re H|, as at any resonance of a single mode."""
    deck = DECKS / "seed001_dtrb_rotor.yaml"
    _, written = cli_with_result(monkeypatch, ["frf", deck, "-o", tmp_path])
    lines, s = summary_of("frf")(written.result)
    m = solve_modal(build_rotor(load_deck(deck).deck), 3000.0, n_modes=12)
    in_range = m.frequency_hz[(m.frequency_hz >= 10) & (m.frequency_hz <= 3000)]
    listed = " ".join(lines)
    for fk in in_range:
        assert f"{fk:.1f} Hz" in listed, (fk, lines)
    with h5py.File(tmp_path / "frf.h5") as f:
        fr, h = f["frf/frequency_hz"][:], f["frf/receptance_m_N"][:]
    near = np.abs(fr - m.frequency_hz[0]) < 1.0
    i = np.flatnonzero(near)[np.argmax(np.abs(h[near]))]
    assert abs(h[i].imag) > 0.9 * abs(h[i])
