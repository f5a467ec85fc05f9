"""Numerical sphere-on-flat contact against Hertz (REFERENCES.md: a = 0.3201 mm, p0 = 4.6585 GPa)."""

import numpy as np
import pytest

from spindlesim.contact import combined_modulus, point_contact_circular, solve_point_contact

E, NU, R, W = 208e9, 0.3, 5e-3, 1000.0
A_REF, P0_REF = 0.3201e-3, 4.6585e9  # REFERENCES.md, "Hertz sphere on flat"


@pytest.fixture(scope="module")
def sphere128():
    return solve_point_contact(W, R, n=128, tol=1e-9)


def test_sphere_p0_and_radius_within_half_percent(sphere128):
    r = sphere128
    assert abs(r.max_pressure_Pa / P0_REF - 1) < 5e-3
    j = np.argmin(np.abs(r.y_m))
    assert abs(r.half_width_m[j] / A_REF - 1) < 5e-3  # radius from the edge of the pressure
    assert abs(np.sqrt(r.area_m2 / np.pi) / A_REF - 1) < 5e-3  # radius from the loaded area


def test_sphere_load_balance_and_approach(sphere128):
    r = sphere128
    assert r.load_N == pytest.approx(W, rel=1e-9)
    _, _, delta = point_contact_circular(W, R, combined_modulus(E, NU, E, NU))
    assert r.approach_m == pytest.approx(delta, rel=5e-3)


def test_sphere_pressure_is_hertzian_inside(sphere128):
    """p(r) = p0 sqrt(1 - r^2/a^2) (Johnson eq. 4.24) within 1% of p0 inside r < 0.9 a."""
    r = sphere128
    a, p0, _ = point_contact_circular(W, R, combined_modulus(E, NU, E, NU))
    X, Y = np.meshgrid(r.x_m, r.y_m, indexing="ij")
    rr = np.hypot(X, Y)
    inside = rr < 0.9 * a
    ref = p0 * np.sqrt(1 - (rr[inside] / a) ** 2)
    assert np.max(np.abs(r.pressure_Pa[inside] - ref)) < 0.01 * p0


def test_sphere_symmetry(sphere128):
    p = sphere128.pressure_Pa
    scale = p.max()
    assert np.max(np.abs(p - p[::-1, :])) < 1e-6 * scale
    assert np.max(np.abs(p - p[:, ::-1])) < 1e-6 * scale
    assert np.max(np.abs(p - p.T)) < 1e-6 * scale


def test_sphere_converges_with_grid():
    """The peak-pressure error falls by at least 3x from 32 to 64 cells (O(h^2) expected)."""
    errs = [abs(solve_point_contact(W, R, n=n, tol=1e-10).max_pressure_Pa / P0_REF - 1) for n in (32, 64)]
    assert errs[1] < errs[0] / 3


def test_elliptic_contact_is_elongated_along_larger_radius():
    r = solve_point_contact(1000.0, 5e-3, 20e-3, n=64)
    i, j = np.argmin(np.abs(r.x_m)), np.argmin(np.abs(r.y_m))
    len_x = np.count_nonzero(r.pressure_Pa[:, j]) * (r.x_m[1] - r.x_m[0])
    len_y = np.count_nonzero(r.pressure_Pa[i, :]) * (r.y_m[1] - r.y_m[0])
    assert len_y > 1.5 * len_x
    assert r.load_N == pytest.approx(1000.0, rel=1e-9)


def test_elliptic_contact_matches_exact_hertz_ellipticity():
    """Ellipticity of an elliptical Hertz contact (Johnson 1985, eq. 4.39, exact elliptic integrals).

    With curvature ratio q = Ry/Rx > 1 the short/long axis ratio k solves
    q = (E(m)/k^2 - K(m)) / (K(m) - E(m)), m = 1 - k^2.  Checked with scipy's elliptic
    integrals (independent of the grid-sizing approximations in spindlesim).
    """
    from scipy.optimize import brentq
    from scipy.special import ellipe, ellipk

    from spindlesim.contact.grid import edge_positions

    rx, ry, w = 5e-3, 20e-3, 1000.0
    q = ry / rx

    def f(k):
        m = 1 - k * k
        return (ellipe(m) / k**2 - ellipk(m)) / (ellipk(m) - ellipe(m)) - q

    k_exact = brentq(f, 0.05, 0.999)
    r = solve_point_contact(w, rx, ry, n=128, tol=1e-9)
    lx, rx_ = edge_positions(r.x_m, r.pressure_Pa)
    ly, ry_ = edge_positions(r.y_m, r.pressure_Pa.T)
    ax = 0.5 * np.nanmax(rx_ - lx)
    ay = 0.5 * np.nanmax(ry_ - ly)
    assert ax / ay == pytest.approx(k_exact, rel=5e-3)
    # p0 = 3 W / (2 pi a b) for the measured axes (Johnson eq. 4.37)
    assert r.max_pressure_Pa == pytest.approx(3 * w / (2 * np.pi * ax * ay), rel=5e-3)
