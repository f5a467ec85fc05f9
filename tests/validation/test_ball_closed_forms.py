"""Ball bearing at rest against closed forms (every reference computed here, not by the model).

- Jones' axial load equation (Jones 1960; Harris and Kotzalas 2007, Essential Concepts, ch. 7):
  Fa / (Z K_n) = sin(a) (cos(a0)/cos(a) - 1)^1.5 (B D)^1.5, B = f_i + f_o - 1, K_n the Hertz
  constant of the inner and outer contacts in series, solved for the loaded contact angle a; then
  Q = Fa / (Z sin a) and the axial deflection delta_a = B D sin(a - a0) / cos(a).
- Stribeck (Harris and Kotzalas, ch. 7): zero-clearance radial bearing, delta_j = delta_r cos(psi_j), so
  Q_max = F_r / sum_j cos(psi_j)^2.5 exactly, and Q_max Z / F_r -> 1 / J_r(1/2) = 4.37 for many balls.
- Hertz point contact (Johnson 1985, eqs. 4.39-4.41; exact elliptic integrals) against the
  Hamrock-Brewe fits (J. Lubr. Technol. 105, 1983) and the circular limit.
- Preloaded pair at rest: each ball is a spring Q = K_n delta^1.5 along the groove-centre line A,
  force -Q A/|A|; its stiffness k_n n n^T + (Q/|A|) t t^T (the second term turns the contact line).
"""

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from spindlesim.bearings.ball import build
from spindlesim.contact.hertz import (point_contact, point_contact_circular, point_contact_constant,
                                      point_contact_semi_axes_estimate)

from ..unit.test_ball_section import bearing, entry

E_STAR_STEEL = 1.0 / (2.0 * (1.0 - 0.3 ** 2) / 208e9)


def curvature_sums(D, dm, f, alpha, inner):
    """Ball/raceway curvature sums (rolling plane, across the groove) [1/m] (Harris and Kotzalas ch. 2)."""
    g = D * math.cos(alpha) / dm
    roll = 2.0 / D + (2.0 * g / (D * (1.0 - g)) if inner else -2.0 * g / (D * (1.0 + g)))
    return roll, 2.0 / D - 1.0 / (f * D)


def series_constant(D, dm, fi, fo, alpha):
    ki = point_contact_constant(*curvature_sums(D, dm, fi, alpha, True), E_STAR_STEEL)
    ko = point_contact_constant(*curvature_sums(D, dm, fo, alpha, False), E_STAR_STEEL)
    return (ki ** (-2.0 / 3.0) + ko ** (-2.0 / 3.0)) ** -1.5


# (label, Z, D [mm], d_m [mm], f_i, f_o, free contact angle [deg])
JONES_CASES = [
    ("7014C row of the default deck", 18, 12.7, 90.0, 0.52, 0.53, 15.0),
    ("Harris and Kotzalas' 218 angular-contact example geometry", 16, 22.225, 125.26, 0.5232, 0.5232, 40.0),
]


@pytest.mark.parametrize("case", JONES_CASES, ids=[c[0] for c in JONES_CASES])
@pytest.mark.parametrize("Fa", [200.0, 2000.0, 20000.0])
def test_pure_axial_load_jones(case, Fa):
    _, Z, D_mm, dm_mm, fi, fo, a0_deg = case
    b = build(entry(balls=Z, ball_diameter_mm=D_mm, pitch_diameter_mm=dm_mm, inner_conformity=fi,
                    outer_conformity=fo, contact_angle_deg=a0_deg))
    D, dm, a0 = D_mm * 1e-3, dm_mm * 1e-3, math.radians(a0_deg)
    BD = (fi + fo - 1.0) * D
    Kn = series_constant(D, dm, fi, fo, a0)
    a = brentq(lambda x: math.sin(x) * (math.cos(a0) / math.cos(x) - 1.0) ** 1.5 * BD ** 1.5 - Fa / (Z * Kn),
               a0 + 1e-12, math.radians(89.0), xtol=1e-15, rtol=1e-15)
    st = b.solve(np.array([0.0, 0.0, Fa, 0.0, 0.0]))
    assert np.allclose(np.radians(st.contact_angle_inner_deg), a, rtol=0, atol=1e-10)
    assert np.allclose(st.element_load_inner_N, Fa / (Z * math.sin(a)), rtol=1e-9)
    assert st.displacement[2] == pytest.approx(BD * math.sin(a - a0) / math.cos(a), rel=1e-8)
    assert np.allclose(st.displacement[[0, 1, 3, 4]], 0.0, atol=1e-15)


def test_stribeck_discrete_sum_and_limit():
    # discrete: 12 balls, ball 0 on the load line
    b = build(entry(balls=12, ball_diameter_mm=12.7, pitch_diameter_mm=65.0, contact_angle_deg=0.0,
                    inner_conformity=0.52, outer_conformity=0.52))
    Fr = 5000.0
    st = b.solve(np.array([Fr, 0.0, 0.0, 0.0, 0.0]))
    psi = 2 * math.pi * np.arange(12) / 12
    c = np.clip(np.cos(psi), 0.0, None)
    Q_ref = Fr / np.sum(c ** 2.5)
    assert st.element_load_inner_N.max() == pytest.approx(Q_ref, rel=1e-9)
    assert np.allclose(st.element_load_inner_N[0], Q_ref * c ** 1.5, rtol=1e-9, atol=1e-9)
    # many balls: Q_max Z / F_r -> 1 / J_r(0.5), J_r = (1/pi) int_0^{pi/2} cos^2.5 = 0.2288 (Stribeck's 4.37)
    Jr = math.gamma(1.75) * math.sqrt(math.pi) / (2.0 * math.gamma(2.25)) / math.pi
    assert 1.0 / Jr == pytest.approx(4.37, abs=1e-3)
    many = build(entry(balls=400, ball_diameter_mm=1.0, pitch_diameter_mm=200.0, contact_angle_deg=0.0,
                       inner_conformity=0.52, outer_conformity=0.52))
    st = many.solve(np.array([Fr, 0.0, 0.0, 0.0, 0.0]))
    assert st.element_load_inner_N.max() * 400 / Fr == pytest.approx(1.0 / Jr, rel=1e-3)


@pytest.mark.parametrize("case", JONES_CASES, ids=[c[0] for c in JONES_CASES])
def test_hertz_exact_against_hamrock_brewe_and_the_state(case):
    _, Z, D_mm, dm_mm, fi, fo, a0_deg = case
    D, dm, a0 = D_mm * 1e-3, dm_mm * 1e-3, math.radians(a0_deg)
    Q = 1500.0
    for inner, f in ((True, fi), (False, fo)):
        roll, cross = curvature_sums(D, dm, f, a0, inner)
        a, bb, delta, p0 = point_contact(Q, roll, cross, E_STAR_STEEL)
        ax, ay = point_contact_semi_axes_estimate(Q, 1.0 / roll, 1.0 / cross, E_STAR_STEEL)
        assert a == pytest.approx(ay, rel=0.03) and bb == pytest.approx(ax, rel=0.03)  # "a few %"
        assert p0 == pytest.approx(3 * Q / (2 * math.pi * a * bb), rel=1e-14)
    # the state's semi-axes and peak pressure: the same Hertz solution at each ball load (Q^(1/3) scaling)
    b = build(entry(balls=Z, ball_diameter_mm=D_mm, pitch_diameter_mm=dm_mm, inner_conformity=fi,
                    outer_conformity=fo, contact_angle_deg=a0_deg))
    st = b.solve(np.array([3000.0, 0.0, 4000.0, 0.0, 0.0]))
    j = int(np.argmax(st.element_load_inner_N[0]))
    Qi, Qo = st.element_load_inner_N[0, j], st.element_load_outer_N[0, j]
    ai, bi, _, pi_ = point_contact(Qi, *curvature_sums(D, dm, fi, a0, True), E_STAR_STEEL)
    ao, bo, _, po = point_contact(Qo, *curvature_sums(D, dm, fo, a0, False), E_STAR_STEEL)
    assert st.semi_axes_inner_m[0, j] == pytest.approx([ai, bi], rel=1e-10)
    assert st.semi_axes_outer_m[0, j] == pytest.approx([ao, bo], rel=1e-10)
    assert st.max_pressure_inner_Pa[0, j] == pytest.approx(pi_, rel=1e-10)
    assert st.max_pressure_outer_Pa[0, j] == pytest.approx(po, rel=1e-10)


def test_hertz_circular_limit_is_exact():
    """Equal curvature sums: the elliptic solution must be the circular one (Johnson eqs. 4.22-4.23)."""
    R = 6.35e-3  # a ball of radius R on a flat: curvature sum 1/R in both planes
    a, b, delta, p0 = point_contact(1000.0, 1.0 / R, 1.0 / R, E_STAR_STEEL)
    ac, p0c, dc = point_contact_circular(1000.0, R, E_STAR_STEEL)
    assert a == pytest.approx(ac, rel=1e-13) and b == pytest.approx(ac, rel=1e-13)
    assert delta == pytest.approx(dc, rel=1e-13) and p0 == pytest.approx(p0c, rel=1e-13)


@pytest.mark.parametrize("axial_um", [10.0, 30.0])
def test_preloaded_pair_stiffness_at_rest(axial_um):
    b = bearing(preload={"kind": "position", "axial_um": axial_um})
    st = b.solve(np.zeros(5))
    D, dm, a0 = 12.7e-3, 90e-3, math.radians(15.0)
    BD = 0.05 * D
    A = np.array([BD * math.sin(a0) + 0.5 * axial_um * 1e-6, BD * math.cos(a0)])  # (axial, radial)
    L = np.linalg.norm(A)
    delta = L - BD
    Kn = series_constant(D, dm, 0.52, 0.53, a0)
    Q, kn = Kn * delta ** 1.5, 1.5 * Kn * delta ** 0.5
    sa, ca = A / L
    assert np.allclose(st.element_load_inner_N, Q, rtol=1e-12)
    assert np.allclose(st.contact_angle_inner_deg, math.degrees(math.atan2(*A)), rtol=1e-12)
    assert st.row_axial_load_N == pytest.approx([18 * Q * sa] * 2, rel=1e-12)
    Kxx = 2 * 9.0 * (kn * ca ** 2 + Q / L * sa ** 2)  # two rows, sum of cos^2 psi = Z / 2
    Kzz = 2 * 18.0 * (kn * sa ** 2 + Q / L * ca ** 2)
    assert st.stiffness[0, 0] == pytest.approx(Kxx, rel=1e-11)
    assert st.stiffness[1, 1] == pytest.approx(Kxx, rel=1e-11)
    assert st.stiffness[2, 2] == pytest.approx(Kzz, rel=1e-11)
    assert abs(st.stiffness[0, 2]) < 1e-9 * Kxx


@pytest.mark.parametrize("Fa", [1.0, 1000.0])
def test_deep_groove_with_clearance_under_thrust(Fa):
    """Jones' equation from the free contact angle cos(a_f) = 1 - P_d / (2 B D) of a deep-groove bearing
    with clearance P_d (Harris and Kotzalas 2007, Essential Concepts, eq. 2.11 and ch. 7)."""
    b = build(entry(contact_angle_deg=0.0, radial_clearance_um=20.0, inner_conformity=0.52, outer_conformity=0.52))
    D, dm, BD = 12.7e-3, 90e-3, 0.04 * 12.7e-3
    af = math.acos(1.0 - 20e-6 / (2 * BD))
    Kn = series_constant(D, dm, 0.52, 0.52, af)
    a = brentq(lambda x: math.sin(x) * (math.cos(af) / math.cos(x) - 1.0) ** 1.5 * BD ** 1.5 - Fa / (18 * Kn),
               af + 1e-14, math.radians(89.0), xtol=1e-15, rtol=1e-15)
    st = b.solve(np.array([0.0, 0.0, Fa, 0.0, 0.0]))
    assert np.allclose(np.radians(st.contact_angle_inner_deg), a, rtol=0, atol=1e-9)
    assert np.allclose(st.element_load_inner_N, Fa / (18 * math.sin(a)), rtol=1e-8)
