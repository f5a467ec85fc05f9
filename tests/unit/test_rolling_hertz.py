"""Hertz / Palmgren contact and the Stribeck load distribution (REFERENCES.md, Rolling bearings)."""

import numpy as np
import pytest

from spindlesim.bearings.roller.load_distribution import static_load_distribution
from spindlesim.contact.hertz import (combined_modulus, line_contact, palmgren_stiffness, point_contact_circular,
                                      series_stiffness)

E_STAR = combined_modulus(208e9, 0.3)  # steel on steel, E = 208 GPa, nu = 0.3


def test_hertz_line_contact_reference():
    # REFERENCES.md: roller R = 5 mm, l = 10 mm, 10 kN on a flat: b = 0.2360 mm, p0 = 2.697 GPa
    b, p0 = line_contact(10e3 / 10e-3, 5e-3, E_STAR)
    assert b == pytest.approx(0.2360e-3, rel=1e-3)
    assert p0 == pytest.approx(2.697e9, rel=1e-3)
    # load = mean pressure x contact area: w' = pi b p0 / 2
    assert np.pi * b * p0 / 2 == pytest.approx(1e6, rel=1e-12)


def test_hertz_sphere_on_flat_reference():
    # REFERENCES.md: sphere R = 5 mm, 1000 N: a = 0.3201 mm, p0 = 4.6585 GPa
    a, p0, delta = point_contact_circular(1000.0, 5e-3, E_STAR)
    assert a == pytest.approx(0.3201e-3, rel=1e-3)
    assert p0 == pytest.approx(4.6585e9, rel=1e-3)
    assert delta == pytest.approx(a**2 / 5e-3)


def test_palmgren_stiffness_inverts_palmgren_formula():
    # Palmgren (one contact): delta_mm = 3.84e-5 Q^0.9 / l^0.8; l = 10 mm, Q = 1000 N -> 3.0503e-3 mm
    K = palmgren_stiffness(10e-3)
    delta_mm = 3.84e-5 * 1000.0**0.9 / 10.0**0.8
    assert delta_mm == pytest.approx(3.0503e-3, rel=1e-4)
    assert K * (delta_mm * 1e-3) ** (10 / 9) == pytest.approx(1000.0, rel=1e-10)
    # Harris and Kotzalas: K = 8.06e4 l^(8/9) N/mm^(10/9) per contact (REFERENCES.md)
    assert K / 1e3 ** (10 / 9) == pytest.approx(8.06e4 * 10.0 ** (8 / 9), rel=2e-3)
    # two equal contacts in series share the deflection: K / 2^(10/9)
    kt = series_stiffness(K, K, 10 / 9)
    assert kt * (2 * delta_mm * 1e-3) ** (10 / 9) == pytest.approx(1000.0, rel=1e-10)
    # unequal contacts: the deflections add
    k2 = 3.0 * K
    d = (1000.0 / K) ** 0.9 + (1000.0 / k2) ** 0.9
    assert series_stiffness(K, k2, 10 / 9) * d ** (10 / 9) == pytest.approx(1000.0, rel=1e-12)


@pytest.mark.parametrize("exponent, ratio", [(10 / 9, 4.08), (1.5, 4.37)])
def test_stribeck_constant_zero_clearance(exponent, ratio):
    # Stribeck: Q_max ~ 4.08 F_r/Z (line), 4.37 F_r/Z (point), many elements, zero clearance
    d = static_load_distribution(1e9, exponent, 60, 1000.0)
    assert d.q_max_N * 60 / 1000.0 == pytest.approx(ratio, abs=0.01)
    # equilibrium: the loads balance the applied force
    assert np.sum(d.load_N * np.cos(d.angle_rad)) == pytest.approx(1000.0, rel=1e-10)
    assert np.sum(d.load_N * np.sin(d.angle_rad)) == pytest.approx(0.0, abs=1e-9)


def test_clearance_concentrates_load():
    free = static_load_distribution(1e9, 10 / 9, 12, 1000.0)
    loose = static_load_distribution(1e9, 10 / 9, 12, 1000.0, diametral_clearance_m=2e-6)
    assert loose.q_max_N > free.q_max_N
    assert np.count_nonzero(loose.load_N) < np.count_nonzero(free.load_N)
