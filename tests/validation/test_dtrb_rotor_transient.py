"""Seed 001 rotor (decks/seed001_dtrb_rotor.yaml): transient with the nonlinear DTRB against the modal
analysis linearised at the same static state, and seed 001's trends of natural frequency."""

from pathlib import Path

import numpy as np
import pytest

from spindlesim.analysis.modal import solve_modal
from spindlesim.analysis.transient.engine import simulate
from spindlesim.deck import load_deck, parse_deck
from spindlesim.model.build import build_rotor
from spindlesim.runs.transient import rotor_setup

DECK = Path(__file__).parents[2] / "decks" / "seed001_dtrb_rotor.yaml"


def _deck(**replace):
    text = DECK.read_text()
    for old, new in replace.items():
        assert old in text, old
        text = text.replace(old, new)
    return parse_deck(text, "seed001.yaml").deck


def _run(deck):
    rotor, settings = rotor_setup(deck, {})
    return rotor, simulate(rotor, settings)


@pytest.mark.slow
def test_transient_peaks_match_linearised_natural_frequencies():
    """Free vibration (a released 500 N force at the disk) on top of the unbalance response: the two
    strongest spectral lines at the record node (the ball pair's node 1, the deck's first bearing entry;
    the DTRB is at node 5) are the first backward/forward pair of the modal
    analysis linearised at the nonlinear static equilibrium, within one FFT bin."""
    deck = _deck(**{"duration_s: 0.5": "duration_s: 0.25"})
    rotor, res = _run(deck)
    assert res.complete
    f, a = res.spectrum.frequency_hz, res.spectrum.amplitude[:, 0]
    bin_hz = f[1] - f[0]
    band = (f > 100) & (f < 1000)
    peaks = [i for i in np.flatnonzero(band)[1:-1] if a[i] >= a[i - 1] and a[i] >= a[i + 1]]
    top = sorted(peaks, key=lambda i: -a[i])[:2]
    lin = np.sort(solve_modal(rotor, n_modes=2).frequency_hz)
    assert lin[1] - lin[0] > 2 * bin_hz  # the pair is resolved: the check can fail
    np.testing.assert_allclose(np.sort(f[top]), lin, atol=bin_hz)


def test_rotor_at_static_equilibrium_stays_there():
    deck = _deck(**{"duration_s: 0.5": "duration_s: 0.005", "unbalance: true": "unbalance: false",
                    "  perturbation: {node: 9, dof: x, force_N: 500.0}": "  perturbation: null"})
    rotor, res = _run(deck)
    static = res.displacement_m[0]
    drift = np.abs(res.displacement_m - static).max()
    # what remains is the varying compliance of the orbiting rollers (eq. 3): ~1e-10 m here
    assert drift < 1e-3 * np.abs(static).max()
    # the DTRB carries the disk's radial and axial load (lever arm: it also carries more than the load)
    fb = res.bearing_force_N[res.bearing_names.index("dtrb")][-1]
    fa = res.bearing_force_N[res.bearing_names.index("acbb")][-1]
    # axial: the two 5-DOF bearings share the 2 kN (to the roller-passage ripple); the DTRB, axially
    # much stiffer than the lightly preloaded ball pair, carries most of it
    assert fb[2] + fa[2] == pytest.approx(-2000.0, rel=1e-3)
    assert fb[2] < -1500.0
    assert fb[1] > 2000.0  # radial: more than the disk load (overhung)


@pytest.mark.parametrize("key,values", [
    ("preload_um: 60.0", ["preload_um: 50.0", "preload_um: 60.0", "preload_um: 80.0"]),
    ("crown_radius_mm: 2680.0", ["crown_radius_mm: 1300.0", "crown_radius_mm: 2600.0", "crown_radius_mm: 3900.0"]),
])
def test_natural_frequency_rises_with_preload_and_crown_radius(key, values):
    """Seed 001 Figs. 15 and 19: the first natural frequency rises with preload and crowning radius."""
    f1 = [solve_modal(build_rotor(_deck(**{key: v})), n_modes=2).frequency_hz[0] for v in values]
    assert np.all(np.diff(f1) > 0), f1


def test_transient_command_writes_roller_contact(tmp_path):
    """`spindlesim transient` on the rotor deck also writes the most loaded roller's contact pressure."""
    import h5py
    from click.testing import CliRunner

    from spindlesim.cli import main

    deck = tmp_path / "rotor.yaml"
    deck.write_text(DECK.read_text().replace("duration_s: 0.5", "duration_s: 0.02"))
    res = CliRunner().invoke(main, ["transient", str(deck), "-o", str(tmp_path / "out")])
    assert res.exit_code == 0, res.output
    with h5py.File(tmp_path / "out" / "transient.h5") as f:
        assert f["/transient/displacement_m"].shape[1] == 2
        assert f["/transient"].attrs["method"] == "newmark"
    with h5py.File(tmp_path / "out" / "contact.h5") as f:
        g = f["/contact"]
        assert g.attrs["row"] in (1, 2) and g.attrs["load_N"] > 1000
        assert not g.attrs["edge_singular"]  # 2680 mm crown: the contact stays off the roller ends
