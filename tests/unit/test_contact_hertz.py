"""Hertz closed forms against the values quoted in /work/shared/REFERENCES.md."""

import math

import pytest

from spindlesim.contact.hertz import (
    combined_modulus,
    line_contact,
    point_contact_circular,
    point_contact_semi_axes_estimate,
    stribeck_max_roller_load,
)

E, NU = 208e9, 0.3  # steel, REFERENCES.md


def test_line_contact_reference_numbers():
    """REFERENCES.md: R = 5 mm, l = 10 mm, 10 kN on a flat: b = 0.2360 mm, p0 = 2.697 GPa."""
    b, p0 = line_contact(10e3 / 10e-3, 5e-3, combined_modulus(E, NU, E, NU))
    assert b == pytest.approx(0.2360e-3, rel=5e-4)
    assert p0 == pytest.approx(2.697e9, rel=5e-4)
    assert p0 == pytest.approx(2 * 1e6 / (math.pi * b), rel=1e-12)  # load = pi b p0 / 2


def test_sphere_on_flat_reference_numbers():
    """REFERENCES.md: sphere R = 5 mm on a flat, 1000 N: a = 0.3201 mm, p0 = 4.6585 GPa."""
    a, p0, delta = point_contact_circular(1000.0, 5e-3, combined_modulus(E, NU, E, NU))
    assert a == pytest.approx(0.3201e-3, rel=5e-4)
    assert p0 == pytest.approx(4.6585e9, rel=2e-4)
    assert delta == pytest.approx(a * a / 5e-3)


def test_semi_axes_estimate_close_to_circular():
    es = combined_modulus(E, NU, E, NU)
    a, _, _ = point_contact_circular(1000.0, 5e-3, es)
    ax, ay = point_contact_semi_axes_estimate(1000.0, 5e-3, 5e-3, es)
    assert ax == pytest.approx(a, rel=0.05) and ay == pytest.approx(a, rel=0.05)
    ax, ay = point_contact_semi_axes_estimate(1000.0, 5e-3, 50e-3, es)
    assert ay > 2 * ax  # the long axis lies along the larger radius


def test_stribeck():
    """Stribeck (REFERENCES.md): Q_max = 4.08 F_r / Z for line contact."""
    assert stribeck_max_roller_load(20e3, 16) == pytest.approx(5100.0)
    with pytest.raises(ValueError):
        stribeck_max_roller_load(1.0, 0)
