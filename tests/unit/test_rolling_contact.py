"""Contact search (seed 000 eqs. 18-29) and compliant contact force (eqs. 30-31)."""

import numpy as np
import pytest

from spindlesim.bearings.roller.contact_force import CompliantContact
from spindlesim.bearings.roller.contact_search import outer_race_contact


def test_contact_search_penetration_and_normal():
    R_race, R_roller = 14.131e-3, 2.381e-3
    psi = np.array([0.3, 2.0, -1.2])
    # roller centres 10 nm beyond touching, 5 nm short of touching, exactly touching
    l = R_race - R_roller + np.array([10e-9, -5e-9, 0.0])
    xy = l[:, None] * np.column_stack([np.cos(psi), np.sin(psi)])
    oc = outer_race_contact(xy, R_roller, R_race, np.zeros(3))
    assert oc.penetration_m == pytest.approx([10e-9, -5e-9, 0.0], abs=1e-15)
    assert list(oc.in_contact[:2]) == [True, False]  # the third touches exactly (round-off decides)
    assert np.allclose(oc.normal, np.column_stack([np.cos(psi), np.sin(psi)]))
    assert oc.psi_rad == pytest.approx(psi)
    # an outward race deflection v opens the contact by v (eq. 25)
    oc2 = outer_race_contact(xy, R_roller, R_race, np.full(3, 4e-9))
    assert oc2.penetration_m == pytest.approx(oc.penetration_m - 4e-9, abs=1e-15)


def test_contact_search_in_a_moved_housing_frame():
    # eqs. 18-19: the result does not depend on where the housing is, only on the relative position
    R_race, R_roller = 14.131e-3, 2.381e-3
    xy = np.array([[0.0, -(R_race - R_roller + 7e-9)]])
    shift = np.array([1e-3, 2e-3])
    a = outer_race_contact(xy, R_roller, R_race, np.zeros(1))
    b = outer_race_contact(xy + shift, R_roller, R_race, np.zeros(1), housing_xy=shift, housing_angle_rad=0.4)
    assert b.penetration_m == pytest.approx(a.penetration_m, abs=1e-15)
    assert b.normal == pytest.approx(a.normal)
    assert b.psi_rad == pytest.approx(a.psi_rad - 0.4)


def test_compliant_force_law():
    c = CompliantContact(stiffness=2e9, exponent=10 / 9, damping=1e9, velocity_exponent=1.0,
                         indentation_exponent=1.0, friction=0.1, slip_regularisation_m_s=1e-3)
    d = np.array([-1e-9, 0.0, 3e-8, 3e-8, 3e-8])
    dd = np.array([1.0, 1.0, 0.0, 1e-3, -1e-3])
    f = c.normal_force(d, dd)
    k = 2e9 * 3e-8 ** (10 / 9)
    assert f[0] == 0 and f[1] == 0  # no contact, no force (eq. 30 only for delta > 0)
    assert f[2] == pytest.approx(k)
    assert f[3] == pytest.approx(k + 1e9 * 1e-3 * 3e-8)
    assert f[4] == pytest.approx(k - 1e9 * 1e-3 * 3e-8)
    # separating fast: clipped at zero, a contact never pulls
    assert c.normal_force(np.array([3e-8]), np.array([-10.0]))[0] == 0.0
    # eq. 31: mu |f_n| against the slip; regularised sign reaches 1 well above v_reg
    ff = c.friction_force(np.array([10.0, 10.0, 10.0]), np.array([1.0, -1.0, 0.0]))
    assert ff == pytest.approx([-1.0, 1.0, 0.0], rel=1e-6, abs=1e-12)
    # energy consistent with the spring term
    h = 1e-12
    e = c.energy_J(np.array([3e-8 + h, 3e-8 - h]))
    assert (e[0] - e[1]) / (2 * h) == pytest.approx(k, rel=1e-6)
