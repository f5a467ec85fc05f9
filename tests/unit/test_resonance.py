"""Resonances inside a requested range (issue 21, items 6 and 7): refined FRF and unbalance grids,
crossings of the excitation orders with API 684 amplification factors and separation margins, the
amplitude convention of the unbalance response, the static compliance, the axial mode shape.

The reference system: a short, thick (practically rigid) shaft with a disk at its centre on two equal
isotropic damped bearings.  Its cylindrical mode is a single degree of freedom m x'' + 2 c x' + 2 k x = F
(m the whole mass, shaft included), uncoupled from the conical mode at the centre node, so the
closed forms of the damped oscillator hold (Den Hartog; Genta, Dynamics of Rotating Systems, 2005,
ch. 4: Jeffcott rotor):

* receptance peak |H|max = 1 / (2 zeta sqrt(1 - zeta^2) k) at f_n sqrt(1 - 2 zeta^2);
* unbalance response (0-peak) |x| = (U / m) r^2 / sqrt((1 - r^2)^2 + (2 zeta r)^2), r = W / w_n, whose
  maximum (U / m) / (2 zeta sqrt(1 - zeta^2)) is at r = 1 / sqrt(1 - 2 zeta^2);
* static compliance at the centre 1 / (2 k) + L^3 / (48 E I) + L / (4 kappa G A) (simply supported
  Timoshenko beam, Cowper's kappa = 6 (1 + nu) / (7 + 6 nu) for a solid circle).

The shaft's own flexibility shifts the FE model from the rigid-rotor closed forms by ~1e-4.
"""

import h5py
import numpy as np
import pytest
from click.testing import CliRunner

from spindlesim.analysis.campbell import solve_campbell
from spindlesim.analysis.frf import solve_frf, solve_unbalance
from spindlesim.analysis.resonance import required_separation_margin
from spindlesim.cli import main
from spindlesim.output.summary import summary_of
from tests.rotor_helpers import cli_with_result, deck_text, isotropic_bearing, rotor_from, uniform_rows

L, D, KB, MD = 0.2, 0.1, 2e5, 20.0  # shaft length and diameter [m], bearing stiffness [N/m], disk mass [kg]
E, G, NU, RHO = 211e9, 81.2e9, 0.3, 7810.0  # tests.rotor_helpers.uniform_rows' material
MASS = MD + RHO * np.pi / 4 * D**2 * L
K = 2 * KB
WN = np.sqrt(K / MASS)  # rad/s
FN = WN / (2 * np.pi)  # 17.72 Hz, 1063 rpm


def _body(zeta: float) -> str:
    c = float(zeta * np.sqrt(2 * KB * MASS))  # per bearing: zeta = 2 c / (2 sqrt(2 KB MASS))
    return (uniform_rows(4, L * 1e3, D * 1e3) + f"disks:\n  - {{node: 3, mass_kg: {MD!r}, Ip_kg_m2: 0.05, "
            "Id_kg_m2: 0.03}\n" + "bearings:\n" + isotropic_bearing("a", 1, KB, c) + isotropic_bearing("b", 5, KB, c))


def _rotor(zeta: float, speed_rpm: float = 0.0):
    return rotor_from(_body(zeta), speed_rpm)


def test_refined_frf_finds_a_peak_between_grid_points():
    zeta = 0.01
    coarse = np.arange(2.0, 40.1, 2.0)  # 17.72 Hz lies between 16 and 18 Hz
    peak_f = FN * np.sqrt(1 - 2 * zeta**2)
    peak_h = 1 / (2 * zeta * np.sqrt(1 - zeta**2) * K)
    plain = solve_frf(_rotor(zeta), coarse, 3, "x", 3, "x")
    assert np.max(np.abs(plain.receptance_m_N)) < 0.7 * peak_h  # what the coarse grid alone shows
    r = solve_frf(_rotor(zeta), coarse, 3, "x", 3, "x", refine=True)
    h = np.abs(r.receptance_m_N)
    i = int(np.argmax(h))
    assert h[i] == pytest.approx(peak_h, rel=1e-3)
    assert r.frequency_hz[i] == pytest.approx(peak_f, rel=1e-3)
    # the user's grid is recoverable, and the half-power band f_n (1 +- zeta) holds at least 5 points
    np.testing.assert_array_equal(r.frequency_hz[~r.added], coarse)
    band = np.abs(r.frequency_hz - FN) <= zeta * FN
    assert band.sum() >= 5
    assert np.all(np.diff(r.frequency_hz) > 0)


def test_refined_unbalance_finds_the_critical_speed_between_grid_points():
    zeta, U = 0.01, 1e-4  # unbalance m e [kg m]
    grid = np.arange(200.0, 2001.0, 200.0)  # the critical speed 1063 rpm lies between 1000 and 1200
    peak = (U / MASS) / (2 * zeta * np.sqrt(1 - zeta**2))
    peak_rpm = WN * 30 / np.pi / np.sqrt(1 - 2 * zeta**2)
    plain = solve_unbalance(_rotor(zeta), grid, 3, U, 0.0, 3, "x")
    assert np.max(np.abs(plain.response_m[:, 2, 0])) < 0.5 * peak
    r = solve_unbalance(_rotor(zeta), grid, 3, U, 0.0, 3, "x", refine=True)
    amp = np.abs(r.response_m[:, 2, 0])
    i = int(np.argmax(amp))
    assert amp[i] == pytest.approx(peak, rel=0.01)
    assert r.speed_rpm[i] == pytest.approx(peak_rpm, rel=0.01)
    np.testing.assert_array_equal(r.speed_rpm[~r.added], grid)
    # the amplitude is the closed form's single (0-peak) amplitude at every speed of the sweep
    ratio = r.speed_rpm * np.pi / 30 / WN
    closed = (U / MASS) * ratio**2 / np.sqrt((1 - ratio**2) ** 2 + (2 * zeta * ratio) ** 2)
    np.testing.assert_allclose(amp, closed, rtol=2e-3)
    # the crossing the grid was refined at, with its response peak and half-power amplification factor
    res = r.resonances
    j = int(np.argmin(np.abs(res.crossings.speed_rpm - peak_rpm)))
    assert res.crossings.speed_rpm[j] == pytest.approx(FN * np.sqrt(1 - zeta**2) * 60, rel=1e-3)
    assert res.peak_amplitude_m[j] == pytest.approx(peak, rel=0.01)
    # half-power speeds of the closed form: r^2 = 1 - 2 zeta^2 -+ 2 zeta sqrt(1 - zeta^2) (to O(zeta^2))
    r1, r2 = np.sqrt(1 - 2 * zeta**2 - 2 * zeta), np.sqrt(1 - 2 * zeta**2 + 2 * zeta)
    assert res.half_power_af[j] == pytest.approx(1 / np.sqrt(1 - 2 * zeta**2) / (r2 - r1), rel=0.02)


def test_campbell_crossings_with_api684_amplification_factor_and_separation_margin():
    """1x and 2x cross the speed-independent cylindrical mode at 60 f_d and 30 f_d; with zeta = 0.05,
    AF = 10, API 684 asks 17 (1 - 1/8.5) = 15.0 % below the minimum operating speed and 25.0 % above the
    maximum continuous speed; the operating range 600-800 rpm puts the 2x crossing (531 rpm) 11.5 %
    below it (not met) and the 1x crossing (1063 rpm) 32.9 % above it (met)."""
    zeta = 0.05
    c = solve_campbell(_rotor(zeta), np.linspace(0.0, 1500.0, 16), n_modes=4, orders=(1.0, 2.0),
                       operating=(600.0, 800.0)).crossings
    fd = FN * np.sqrt(1 - zeta**2)
    for order, want_sep, want_need, met in ((1.0, None, 0.25, True), (2.0, None, 0.15, False)):
        nc = 60 * fd / order
        sel = (c.order == order) & (np.abs(c.speed_rpm - nc) < 1e-3 * nc)
        assert sel.sum() == 2  # the x and y translations (forward and backward at rest)
        np.testing.assert_allclose(c.amplification_factor[sel], 1 / (2 * zeta), rtol=1e-3)
        np.testing.assert_allclose(c.required_margin[sel], want_need, rtol=1e-3)
        sep = (nc - 800.0) / 800.0 if order == 1.0 else (600.0 - nc) / 600.0
        np.testing.assert_allclose(c.separation_margin[sel], sep, rtol=2e-3)
        assert np.all(c.meets_api684[sel] == met) and np.all(c.critical[sel])
    assert required_separation_margin(1 / (2 * zeta), below=True) == pytest.approx(0.17 * (1 - 1 / 8.5))
    assert required_separation_margin(1 / (2 * 0.25), below=False) == 0.0  # AF 2 < 2.5: critically damped


def _deck(tmp_path, body, speed_rpm, extra=""):
    p = tmp_path / "rigid.yaml"
    p.write_text(deck_text(body, speed_rpm) + extra)
    return p


def test_unbalance_file_and_summary_state_the_amplitude_convention(tmp_path, monkeypatch):
    zeta, U_g_mm = 0.01, 100.0
    extra = "unbalance:\n  node: 3\n  amount_g_mm: 100.0\n  output: {node: 3, dof: x}\n  speeds_rpm: {start: 200, " \
            "stop: 2000, count: 10}\n"
    output, written = cli_with_result(monkeypatch, ["unbalance", _deck(tmp_path, _body(zeta), 0.0, extra), "-o",
                                                    tmp_path / "out"])
    assert "um 0-peak" in output and "peak-to-peak" in output
    path = tmp_path / "out" / "unbalance.h5"
    lines, s = summary_of("unbalance")(written.result)
    peak = (U_g_mm * 1e-6 / MASS) / (2 * zeta * np.sqrt(1 - zeta**2))  # closed form: a single amplitude
    assert s["amplitude"] == "0-peak"
    assert s["peak_m"] == pytest.approx(peak, rel=0.01)
    assert s["peak_to_peak_m"] == pytest.approx(2 * peak, rel=0.01)
    with h5py.File(path) as f:
        assert str(f["unbalance"].attrs["amplitude"]).startswith("0-peak")
        assert f["unbalance/added"][:].sum() > 0


def test_frf_reports_the_static_compliance_not_its_first_frequency(tmp_path, monkeypatch):
    """K^-1 at the centre: the bearings in parallel plus the shaft as a simply supported Timoshenko
    beam under a central load; the grid starts at 2 Hz, where |H| is already 1.3 % above it."""
    I, A = np.pi * D**4 / 64, np.pi * D**2 / 4
    kappa = 6 * (1 + NU) / (7 + 6 * NU)
    static = 1 / K + L**3 / (48 * E * I) + L / (4 * kappa * G * A)
    r = solve_frf(_rotor(0.01), np.arange(2.0, 40.1, 2.0), 3, "x", 3, "x", refine=True)
    assert r.static_compliance_m_N == pytest.approx(static, rel=1e-9)
    assert abs(r.receptance_m_N[0]) > 1.01 * static
    extra = "frf:\n  input: {node: 3, dof: x}\n  output: {node: 3, dof: x}\n  frequencies_hz: {start: 2, stop: 40, " \
            "count: 20}\n"
    output, written = cli_with_result(monkeypatch, ["frf", _deck(tmp_path, _body(0.01), 0.0, extra), "-o",
                                                    tmp_path / "o"])
    assert "static compliance (0 Hz, K^-1) 2.5" in output and "static-end" not in output
    _, s = summary_of("frf")(written.result)
    assert s["static_compliance_m_N"] == pytest.approx(static, rel=1e-9)


def test_deck_operating_range_sets_the_separation_margins(tmp_path):
    """operating.min_operating_rpm / max_continuous_rpm are the range API 684 measures from; min > max is a
    deck error (exit 2)."""
    zeta = 0.05
    campbell = "campbell:\n  speeds_rpm: {start: 0, stop: 1500, count: 16}\n  modes: 4\n"
    text = _deck(tmp_path, _body(zeta), 700.0, campbell).read_text()
    ranged = tmp_path / "ranged.yaml"
    ranged.write_text(text.replace("speed_rpm: 700.0", "speed_rpm: 700.0\n  min_operating_rpm: 600\n"
                                                       "  max_continuous_rpm: 800"))
    res = CliRunner().invoke(main, ["campbell", str(ranged), "-o", str(tmp_path / "out")])
    assert res.exit_code == 0, res.output
    with h5py.File(tmp_path / "out" / "campbell.h5") as f:
        g = f["campbell/crossings"]
        assert (g.attrs["min_operating_rpm"], g.attrs["max_continuous_rpm"]) == (600.0, 800.0)
        nc = g["speed_rpm"][:]
        one = g["order"][:] == 1.0
        np.testing.assert_allclose(g["separation_margin"][one], (nc[one] - 800.0) / 800.0)
    bad = tmp_path / "bad.yaml"
    bad.write_text(ranged.read_text().replace("min_operating_rpm: 600", "min_operating_rpm: 900"))
    res = CliRunner().invoke(main, ["campbell", str(bad), "-o", str(tmp_path / "bad")])
    assert res.exit_code == 2 and "min_operating_rpm exceeds max_continuous_rpm" in res.output
