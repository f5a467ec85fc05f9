"""Element matrices: closed-form Timoshenko stiffness (Przemieniecki / Nelson 1980), mass and symmetry."""

import numpy as np
import pytest

from spindlesim.fe.timoshenko import lateral_element_matrices, planar_matrices


def _props(L=0.1, d=0.05, k=0.9):
    A, I = np.pi * d**2 / 4, np.pi * d**4 / 64
    return dict(length=[L], area=[A], second_moment=[I], density=[7800.0], youngs=[2e11],
                shear_modulus=[8e10], kappa=[k], axial_force=[0.0]), A, I


def test_stiffness_matches_closed_form():
    props, A, I = _props()
    L, E = 0.1, 2e11
    phi = 12 * E * I / (0.9 * 8e10 * A * L**2)
    ref = E * I / (L**3 * (1 + phi)) * np.array([
        [12, 6 * L, -12, 6 * L],
        [6 * L, (4 + phi) * L**2, -6 * L, (2 - phi) * L**2],
        [-12, -6 * L, 12, -6 * L],
        [6 * L, (2 - phi) * L**2, -6 * L, (4 + phi) * L**2]])
    K = planar_matrices(**props).stiffness_bending[0]
    np.testing.assert_allclose(K, ref, rtol=1e-12, atol=1e-6 * np.abs(ref).max())


def test_mass_total_and_rotary_inertia():
    props, A, I = _props()
    p = planar_matrices(**props)
    # rigid translation: total mass rho A L; rigid rotation about the centre: rho A L^3/12 + rho I L
    t = np.array([1.0, 0.0, 1.0, 0.0])
    r = np.array([-0.05, 1.0, 0.05, 1.0])
    Mt = p.mass_translational[0] + p.mass_rotary[0]
    assert t @ Mt @ t == pytest.approx(7800 * A * 0.1, rel=1e-12)
    assert r @ Mt @ r == pytest.approx(7800 * A * 0.1**3 / 12 + 7800 * I * 0.1, rel=1e-12)


def test_lateral_matrices_structure():
    props, A, I = _props()
    e = lateral_element_matrices(**props)
    np.testing.assert_allclose(e.mass[0], e.mass[0].T)
    np.testing.assert_allclose(e.gyroscopic[0], -e.gyroscopic[0].T)
    np.testing.assert_allclose(e.circulatory[0], -e.circulatory[0].T)
    # gyroscopic: theta_x row, theta_y column positive (Id th_x'' + Ip W th_y' = M_x); total polar inertia
    assert e.gyroscopic[0][2, 3] > 0
    # rigid tilts about the element centre: about x (y = -a (z - zc), theta_x = a) and about y
    r_x = np.array([0, 0.05, 1, 0, 0, -0.05, 1, 0])
    r_y = np.array([-0.05, 0, 0, 1, 0.05, 0, 0, 1])
    assert r_x @ e.gyroscopic[0] @ r_y == pytest.approx(2 * 7800 * I * 0.1, rel=1e-12)
    assert e.gravity_unit[0][[1, 5]].sum() == pytest.approx(-7800 * A * 0.1)


def test_axial_tension_stiffens():
    props, A, I = _props()
    props["axial_force"] = [1e4]
    Ka = planar_matrices(**props).stiffness_axial[0]
    assert np.all(np.linalg.eigvalsh(Ka) > -1e-9)
    np.testing.assert_allclose(Ka @ np.array([1.0, 0, 1.0, 0]), 0, atol=1e-9)
