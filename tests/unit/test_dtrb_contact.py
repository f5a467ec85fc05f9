"""DTRB contact laws (seed 001 eqs. 23-29) against Palmgren and Hertz."""

import math

import numpy as np
import pytest

from spindlesim.bearings.dtrb.roller_equilibrium import contact_loads
from spindlesim.contact.hertz import (combined_modulus, line_contact_constant, palmgren_deflection_m, point_contact,
                                      point_contact_constant, power_law)

from .test_dtrb_geometry import geometry

E, NU = 208e9, 0.3  # REFERENCES.md steel


def test_seed_modulus_is_E_over_one_minus_nu2_for_equal_steels():
    # eq. 26: 1/E' = 0.5 (2 (1 - nu^2)/E)
    assert 2 * combined_modulus(E, NU) == pytest.approx(E / (1 - NU ** 2), rel=1e-14)


@pytest.mark.parametrize("length_mm", [8.0, 14.0, 25.0])
@pytest.mark.parametrize("load_N", [200.0, 2000.0, 20000.0])
def test_line_law_matches_palmgren_within_four_percent(length_mm, load_N):
    """Palmgren (Harris & Kotzalas 2007, ch. 6): delta = 3.84e-5 Q^0.9 / l^0.8 (mm, N), one contact.

    Eq. 25 with E' = E/(1 - nu^2) gives K = 7.82e4 l^(8/9) N/mm^(10/9) against Palmgren's
    8.06e4: the approaches differ by (8.06/7.82)^0.9 - 1 = 2.7 %, inside the issue's 3-4 %.
    With E* (half of E') the difference would be 2^0.9 = 87 %."""
    l = 1e-3 * length_mm
    K = line_contact_constant(l, 2 * combined_modulus(E, NU))
    ours = (load_N / K) ** 0.9
    palm = palmgren_deflection_m(load_N, l)
    assert abs(ours / palm - 1.0) < 0.04
    K_wrong = line_contact_constant(l, 0.5 * 2 * combined_modulus(E, NU))
    assert abs((load_N / K_wrong) ** 0.9 / palm - 1.0) > 0.5


def test_sliced_uniform_roller_carries_K_delta_10_9():
    # eq. 27: a straight roller pressed uniformly: the slice loads sum to K delta^(10/9)
    g = geometry(crown_radius_m=math.inf, n_slices=17)
    delta = np.zeros((1, g.n_contacts))
    delta[0, : 2 * g.n_slices] = 3e-6
    Q, k = contact_loads(g, delta)
    assert g.inner(Q).sum() == pytest.approx(g.line_constant * 3e-6 ** (10 / 9), rel=1e-12)
    Qp, kp = power_law(delta, g.stiffness, g.exponent)
    assert np.allclose(Q, Qp, rtol=1e-13, atol=0) and np.allclose(k, kp, rtol=1e-12, atol=0)
    h = 1e-12
    Qh, _ = contact_loads(g, delta + h)
    assert np.allclose(g.inner(Qh - Q) / h, g.inner(k), rtol=1e-4)


def test_hertz_sphere_on_flat_reference():
    """REFERENCES.md: sphere R = 5 mm on a flat, 1000 N, steel: a = 0.3201 mm, p0 = 4.6585 GPa."""
    E_star = 1.0 / (2 * (1 - NU ** 2) / E)
    a, b, delta, p0 = point_contact(1000.0, 1 / 5e-3, 1 / 5e-3, E_star)
    assert a == pytest.approx(0.3201e-3, rel=2e-4)
    assert b == pytest.approx(a, rel=1e-12)
    assert p0 == pytest.approx(4.6585e9, rel=2e-4)
    assert delta == pytest.approx(a ** 2 / 5e-3, rel=1e-10)  # Hertz: delta = a^2 / R
    assert point_contact_constant(1 / 5e-3, 1 / 5e-3, E_star) * delta ** 1.5 == pytest.approx(1000.0, rel=1e-9)


@pytest.mark.parametrize("ratio", [2.0, 5.0, 20.0])
def test_hertz_ellipse_against_hamrock_brewe(ratio):
    """Hamrock and Brewe (1983) curve fits of the Hertz ellipse (accurate to ~3 %):
    k = a/b = 1.0339 (Ry/Rx)^0.636, E(e) = 1.0003 + 0.5968 Rx/Ry, F(e) = 1.5277 + 0.6023 ln(Ry/Rx),
    delta = F [(9 / (2 E(e) R')) (W / (pi k E'))^2]^(1/3) with 1/R' = 1/Rx + 1/Ry, E' = 2 E*;
    and delta proportional to W^(2/3) exactly."""
    E_star = 1.0 / (2 * (1 - NU ** 2) / E)
    Rx = 5e-3
    Ry = ratio * Rx
    a, b, delta, _ = point_contact(500.0, 1 / Rx, 1 / Ry, E_star)
    assert a / b == pytest.approx(1.0339 * ratio ** 0.636, rel=0.03)
    k = 1.0339 * ratio ** 0.636
    Ee = 1.0003 + 0.5968 * Rx / Ry
    Fe = 1.5277 + 0.6023 * math.log(Ry / Rx)
    Rp = 1.0 / (1 / Rx + 1 / Ry)
    Ebar = 2 * E_star
    delta_hb = Fe * ((9.0 / (2 * Ee * Rp)) * (500.0 / (math.pi * k * Ebar)) ** 2) ** (1 / 3)
    assert delta == pytest.approx(delta_hb, rel=0.03)
    _, _, delta2, _ = point_contact(4000.0, 1 / Rx, 1 / Ry, E_star)
    assert delta2 / delta == pytest.approx(8.0 ** (2 / 3), rel=1e-9)
