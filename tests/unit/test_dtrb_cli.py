"""`spindlesim dtrb`: deck section, HDF5 contract (DESIGN.md section 5: /dtrb/stiffness 5x5,
/dtrb/reaction (5), /dtrb/roller_load_N [row, roller]), PNGs, bad decks, bearing type."""

from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

from spindlesim.commands.dtrb import command
from spindlesim.deck import DeckError, parse_deck

from .test_dtrb_geometry import registered_dtrb_deck

ROOT = Path(__file__).resolve().parents[2]

SMALL = """title: small dtrb
dtrb:
  bearing:
    rollers_per_row: 16
    cup_angle_deg: 15.64
    pitch_diameter_mm: 70.0
    large_end_diameter_mm: 10.0
    roller_length_mm: 14.0
    large_end_offset_mm: 18.0
    crown_radius_mm: 2680.0
    slices: 8
  preload_um: 20.0
  speed_rpm: 1000.0
  load: {fx_N: 4000.0, fz_N: 3000.0}
  preload_sweep_um: {start: 1.0, stop: 40.0, count: 3}
  radial_sweep_N: {start: 2000.0, stop: 10000.0, count: 3}
  polar_preloads_um: [5.0]
  polar_radial_loads_N: [8000.0]
"""


@pytest.fixture(autouse=True)
def _dtrb_registered():
    yield from registered_dtrb_deck()


def _run(args):
    return CliRunner().invoke(command, [str(a) for a in args], catch_exceptions=False)


def test_default_deck_writes_contract(tmp_path):
    h5py = pytest.importorskip("h5py")
    res = _run(["-o", tmp_path, "--no-sweeps"])
    assert res.exit_code == 0, res.output
    assert (tmp_path / "dtrb_load_distribution.png").stat().st_size > 0
    with h5py.File(tmp_path / "dtrb.h5") as f:
        g = f["dtrb"]
        K, F, Q = g["stiffness"][()], g["reaction"][()], g["roller_load_N"][()]
        assert K.shape == (5, 5) and F.shape == (5,) and Q.shape == (2, 20)
        for k in g:
            if isinstance(g[k], h5py.Dataset):
                assert "units" in g[k].attrs
        load = g.attrs["applied_load"]
        assert np.allclose(F, -load, atol=1e-5 * np.abs(load).max())
        assert np.allclose(K, K.T, rtol=1e-9, atol=1e-6 * np.abs(K).max())
        assert "deck_sha256" in f.attrs


def test_small_deck_with_sweeps(tmp_path):
    h5py = pytest.importorskip("h5py")
    deck = tmp_path / "small.yaml"
    deck.write_text(SMALL)
    res = _run([deck, "-o", tmp_path / "out", "--preload", "25", "--speed", "0"])
    assert res.exit_code == 0, res.output
    for name in ("dtrb.h5", "dtrb_load_distribution.png", "dtrb_stiffness_preload.png", "dtrb_stiffness_radial.png"):
        assert (tmp_path / "out" / name).stat().st_size > 0
    with h5py.File(tmp_path / "out" / "dtrb.h5") as f:
        assert f["dtrb"].attrs["preload_m"] == pytest.approx(25e-6)
        assert f["dtrb/preload_sweep/KXX_N_m"].shape == (3,)
        assert f["dtrb/radial_sweep/loaded_rollers"].shape == (3, 2)
        assert f["dtrb/roller_load_N"].shape == (2, 16)
        assert f["dtrb/polar/1/roller_load_N"].shape == (2, 16)


def test_example_deck_is_valid():
    text = (ROOT / "decks" / "dtrb_wheel_hub.yaml").read_text()
    d = parse_deck(text, "dtrb_wheel_hub.yaml").deck
    assert d.dtrb.bearing.rollers_per_row == 20 and d.dtrb.bearing.crown_radius_mm == 2680.0


def test_bad_deck_exit_2_names_the_key(tmp_path):
    deck = tmp_path / "bad.yaml"
    deck.write_text(SMALL.replace("rollers_per_row: 16", "rollers_per_row: 30"))
    res = CliRunner().invoke(command, [str(deck), "-o", str(tmp_path / "o")])
    assert res.exit_code == 2
    assert "bad.yaml:" in res.output and "do not fit" in res.output
    assert not (tmp_path / "o").exists()


def test_dtrb_bearing_type_in_rotor_deck():
    text = """shaft:
  elements:
    - [50.0, 0.0, 100.0, 7850.0, 208.0, 80.0, 0.3, 0.0]
operating:
  speed_rpm: 3000
bearings:
  - type: dtrb
    name: hub
    node: 2
    preload_um: 20
    axial_load_N: 1000
    geometry: {rollers_per_row: 20, cup_angle_deg: 15.64, pitch_diameter_mm: 70, large_end_diameter_mm: 10,
               roller_length_mm: 14, large_end_offset_mm: 18, crown_radius_mm: 2680, slices: 6}
"""
    from spindlesim.model.build import build_rotor

    rotor = build_rotor(parse_deck(text, "rotor.yaml").deck)
    b = rotor.bearings[0]
    w = 3000 * np.pi / 30  # the speed is passed in, never stored on the bearing
    assert b.node == 1 and b.name == "hub" and not hasattr(b, "speed_rad_s")
    assert b.dof_names == ("x", "y", "z", "theta_x", "theta_y") and "z" in rotor.dofs.names
    K, C = b.linearized(w, np.array([2000.0, 0.0]))
    assert K.shape == (5, 5) and C.shape == (5, 5) and K[0, 0] > 1e8 and K[2, 2] > 1e7
    assert np.allclose(K, b.solve([2000.0, 0.0, 1000.0, 0.0, 0.0], w).stiffness)
    f, Kt, Ct = b.force_and_tangent(np.array([1e-6, 0.0, 2e-6, 0.0, 1e-5]), np.zeros(5), 0.0, w)
    assert f.shape == (5,) and np.allclose(Kt, b.stiffness([1e-6, 0.0, 2e-6, 0.0, 1e-5], w))
    two = build_rotor(parse_deck(text.replace("axial_load_N: 1000", "axial_load_N: 1000\n    dofs: 2"),
                                 "rotor.yaml").deck)
    K2, _ = two.bearings[0].linearized(w, np.array([2000.0, 0.0]))
    assert K2.shape == (2, 2) and np.allclose(K2, K[:2, :2]) and "z" not in two.dofs.names
    with pytest.raises(DeckError):
        parse_deck(text.replace("rollers_per_row: 20", "rollers_per_row: 2"), "rotor.yaml")


def test_load_distribution_titles_explain_the_counts_and_ticks_avoid_the_curves():
    """The panel title used to read "loaded rollers 20/7" beside a closed cup curve (issue 23)."""
    from spindlesim.bearings.dtrb.plots import plot_load_distribution, quiet_azimuth_deg
    from spindlesim.bearings.dtrb.results import DtrbState

    psi = np.linspace(0, 2 * np.pi, 20, endpoint=False)
    Qo = np.stack([800 + 700 * np.cos(psi), 300 + 250 * np.cos(psi)])
    Qi = np.stack([Qo[0], np.where(np.cos(psi) > 0.3, Qo[1], 0.0)])
    st = DtrbState.__new__(DtrbState)
    object.__setattr__(st, "psi_rad", np.stack([psi, psi]))
    object.__setattr__(st, "outer_load_N", Qo)
    object.__setattr__(st, "inner_load_N", Qi)
    fig = plot_load_distribution([("applied load", st)])
    ax = fig.axes[0]
    n2 = int(np.sum(Qi[1] > 1e-3))
    assert ax.get_title().endswith(f"rollers the cone loads: row 1 20 of 20, row 2 {n2} of 20")
    quiet = quiet_azimuth_deg(st)  # the loads peak at 0 deg: labels on the far side, on an oblique radius
    assert np.cos(np.radians(quiet)) < -0.7 and abs(np.sin(np.radians(quiet))) >= 0.6
    assert ax.get_rlabel_position() == pytest.approx(quiet)
