"""Consistency checks between analyses, and the physics of internal damping."""

import numpy as np
import pytest
import scipy.linalg as sla

from spindlesim.analysis.frf import receptance, solve_frf, solve_unbalance
from spindlesim.analysis.modal import solve_modal
from spindlesim.analysis.static import solve_static
from spindlesim.deck import default_deck
from spindlesim.analysis.operating import system_matrices
from spindlesim.model.build import build_rotor
from tests.rotor_helpers import disk_entry, isotropic_bearing, rotor_from, uniform_rows


@pytest.fixture(scope="module")
def spindle():
    return build_rotor(default_deck("spindle_linear").deck)


def test_static_equilibrium_and_reactions(spindle):
    r = solve_static(spindle)
    # 1 N at the nose (seed 003 Fig. 11): bearing reactions balance the applied load
    np.testing.assert_allclose(r.bearing_force_N.sum(axis=0) + r.applied_force_N, 0, atol=1e-9)
    # lever rule for a rigid-ish shaft: the front reaction exceeds the load (overhang)
    assert abs(r.bearing_force_N[0, 0]) > 1.0


def test_frf_modal_sum_equals_direct_solve(spindle):
    sysm = system_matrices(spindle)
    w = 2 * np.pi * np.array([5.0, 300.0, 1117.0, 2500.0])
    i_in, i_out = spindle.dofs.index(0, "x"), spindle.dofs.index(0, "y")
    h = receptance(sysm, i_out, i_in, w)
    for wk, hk in zip(w, h):
        direct = np.linalg.solve(-wk**2 * sysm.M + 1j * wk * sysm.C + sysm.K, np.eye(sysm.size)[:, i_in])[i_out]
        assert hk == pytest.approx(direct, rel=1e-7)


def test_frf_low_frequency_limit_is_static_compliance(spindle):
    st = solve_static(spindle)
    f = solve_frf(spindle, np.array([1e-3]), 1, "x", 1, "x")
    assert f.receptance_m_N[0].real == pytest.approx(1 / st.static_stiffness_N_m, rel=1e-6)


def test_unbalance_equals_frf_with_rotating_force(spindle):
    speed = 3000.0
    u = solve_unbalance(spindle, np.array([speed]), 1, 1e-5, 0.0, 1, "x")
    W = speed * np.pi / 30
    hxx = solve_frf(spindle, [W / (2 * np.pi)], 1, "x", 1, "x", speed_rpm=speed).receptance_m_N[0]
    hxy = solve_frf(spindle, [W / (2 * np.pi)], 1, "y", 1, "x", speed_rpm=speed).receptance_m_N[0]
    F = 1e-5 * W**2
    assert u.response_m[0, 0, 0] == pytest.approx(hxx * F + hxy * (-1j * F), rel=1e-7)


def test_mode_shape_normalisation_and_roots(spindle):
    m = solve_modal(spindle, n_modes=6)
    assert np.all(np.diff(m.frequency_hz) >= 0)
    trans = np.abs(m.mode_shape[:, :, :2]).reshape(len(m.frequency_hz), -1)
    np.testing.assert_allclose(trans.max(axis=1), 1.0)
    # heavily damped fluid-film-like bearings leave overdamped real roots, reported apart
    assert m.overdamped_roots.size > 0 and np.all(m.overdamped_roots.real < 0)
    assert set(m.whirl) <= {"forward", "backward", "mixed"}


def _jeffcott(speed_rpm, eta_v):
    rows = uniform_rows(8, 800.0, 30.0).replace("shaft:\n", "shaft:\n  internal_damping: {viscous_s: %r}\n" % eta_v)
    d, *_ = disk_entry(5, 7800, 0.2, 0.03, 0.03)
    body = rows + "disks:\n" + d + "bearings:\n" + isotropic_bearing("a", 1, 1e10) + isotropic_bearing("b", 9, 1e10)
    return rotor_from(body, speed_rpm)


def test_internal_damping_destabilises_forward_whirl_above_first_critical():
    """Rotating (internal) damping alone: forward whirl is damped below the first critical speed
    and self-excited above it (Kimball/Newkirk; Genta 2005 ch. 6)."""
    w1 = solve_modal(_jeffcott(0.0, 0.0), n_modes=1).frequency_hz[0] * 60  # rpm
    below = solve_modal(_jeffcott(0.7 * w1, 2e-5), n_modes=2)
    above = solve_modal(_jeffcott(1.4 * w1, 2e-5), n_modes=2)
    fwd_below = below.damping_ratio[list(below.whirl).index("forward")]
    fwd_above = above.damping_ratio[list(above.whirl).index("forward")]
    bwd_above = above.damping_ratio[list(above.whirl).index("backward")]
    assert fwd_below > 0
    assert fwd_above < 0 and above.unstable.any()
    assert bwd_above > 0


def test_speed_dependent_linear_bearing_is_interpolated():
    body = uniform_rows(4, 400.0, 40.0) + """bearings:
  - name: a
    node: 1
    type: linear
    table:
      speed_rpm: [0, 1000]
      K_N_m: [[[1.0e7, 0], [0, 1.0e7]], [[3.0e7, 0], [0, 3.0e7]]]
      C_Ns_m: [[[0, 0], [0, 0]], [[100, 0], [0, 100]]]
"""
    rotor = rotor_from(body, 250.0)
    K, C = rotor.bearings[0].linearized(250 * np.pi / 30)
    assert K[0, 0] == pytest.approx(1.5e7)
    assert C[1, 1] == pytest.approx(25.0)
    K, _ = rotor.bearings[0].linearized(5000 * np.pi / 30)
    assert K[0, 0] == pytest.approx(3e7)  # held constant outside the table


def test_gravity_load_total():
    body = uniform_rows(6, 500.0, 40.0) + "bearings:\n" + isotropic_bearing("a", 1, 1e8) + isotropic_bearing("b", 7, 1e8)
    from spindlesim.deck import parse_deck
    from tests.rotor_helpers import deck_text

    text = deck_text(body).replace("speed_rpm: 0.0", "speed_rpm: 0.0\n  gravity: true")
    rotor = build_rotor(parse_deck(text, "g.yaml").deck)
    r = solve_static(rotor)
    mass = 7810 * np.pi / 4 * 0.04**2 * 0.5
    assert r.applied_force_N[1] == pytest.approx(-mass * 9.80665, rel=1e-12)
    np.testing.assert_allclose(r.bearing_force_N[:, 1], mass * 9.80665 / 2, rtol=1e-9)
    # symmetric simply supported beam on stiff supports: midspan sag from the closed form
    E, I = 211e9, np.pi * 0.04**4 / 64
    w = mass * 9.80665 / 0.5
    sag = 5 * w * 0.5**4 / (384 * E * I) + mass * 9.80665 / 2 / 1e8
    assert -r.displacement_m[:, 1].min() == pytest.approx(sag, rel=0.02)


def test_campbell_critical_speeds_lie_on_the_1x_line():
    """Friswell 5.9.1 rotor: each reported critical speed N has a forward mode at N/60 Hz (to the
    interpolation error of the sweep), and tracked modes change smoothly between speeds."""
    from spindlesim.analysis.campbell import solve_campbell
    from tests.validation.test_friswell_examples import _rotor

    rotor = _rotor("5.9.1", 0.0)
    c = solve_campbell(rotor, np.linspace(0, 10000, 41), 6)
    assert len(c.critical_speeds_rpm) >= 2
    for n_crit in c.critical_speeds_rpm:
        m = solve_modal(_rotor("5.9.1", n_crit), n_modes=6)
        fwd = m.frequency_hz[np.array(m.whirl) == "forward"]
        assert np.min(np.abs(fwd - n_crit / 60)) < 1e-3 * n_crit / 60
    jumps = np.abs(np.diff(c.frequency_hz, axis=0)) / c.frequency_hz[:-1]
    assert np.nanmax(jumps) < 0.05


def test_campbell_skips_critically_damped_crossings(spindle):
    """The default spindle's 16.8 Hz rigid-body mode has zeta 0.78 (AF 0.64 < 2.5, API 684)."""
    from spindlesim.analysis.campbell import solve_campbell

    c = solve_campbell(spindle, np.linspace(0, 3000, 7), 4)
    assert c.frequency_hz[0, 0] < 20 and c.damping_ratio[0, 0] > 0.5
    assert len(c.critical_speeds_rpm) == 0
