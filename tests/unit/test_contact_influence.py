"""Influence coefficients (Love 1929 / seed 001 eq. 45) and the DC-FFT convolution."""

import numpy as np
import pytest
from scipy import integrate

from spindlesim.contact.influence import HalfSpace2D, HalfSpace3D, rect_patch_integral, strip_integral_2d


@pytest.mark.parametrize("x, y", [(1.3e-3, -0.4e-3), (-2e-3, 0.5e-3), (0.5e-3, 0.0),
                                  (-0.5e-3, 0.25e-3), (0.2e-3, 0.1e-3), (0.0, -0.7e-3)])
def test_rect_patch_matches_quadrature(x, y):
    """Closed form equals the numerical integral of 1/r over a 1 x 0.5 mm cell."""
    dx, dy = 1e-3, 0.5e-3
    ref, _ = integrate.dblquad(lambda yy, xx: 1.0 / np.hypot(x - xx, y - yy),
                               -dx / 2, dx / 2, -dy / 2, dy / 2, epsabs=1e-14, epsrel=1e-11)
    assert rect_patch_integral(x, y, dx, dy) == pytest.approx(ref, rel=1e-7)


def test_rect_patch_centre_of_square():
    """Integral of 1/r over a square of side s from its centre: 4 s asinh(1) (polar integration)."""
    s = 2e-4
    assert rect_patch_integral(0.0, 0.0, s, s) == pytest.approx(4 * s * np.arcsinh(1.0), rel=1e-13)


def test_rect_patch_far_field_is_point_load():
    """Far away the cell acts as a point force: integral -> area / r (Boussinesq)."""
    dx, dy, r = 1e-4, 2e-4, 0.05
    assert rect_patch_integral(r, 0.3 * r, dx, dy) == pytest.approx(dx * dy / np.hypot(r, 0.3 * r), rel=1e-5)


def test_dcfft_equals_direct_sum_without_wraparound():
    """DC-FFT deflection equals the dense sum u_i = sum_j K(x_i - x_j) p_j on a 7 x 5 grid."""
    rng = np.random.default_rng(3)
    nx, ny, dx, dy, es = 7, 5, 1e-5, 3e-5, 1.1e11
    p = rng.random((nx, ny)) * 1e9
    op = HalfSpace3D(nx, ny, dx, dy, es)
    xs = np.arange(nx) * dx
    ys = np.arange(ny) * dy
    u_ref = np.zeros((nx, ny))
    for i in range(nx):
        for j in range(ny):
            K = rect_patch_integral(xs[i] - xs[:, None], ys[j] - ys[None, :], dx, dy) / (np.pi * es)
            u_ref[i, j] = (K * p).sum()
    assert np.allclose(op.apply(p), u_ref, rtol=1e-11, atol=0)


def test_dcfft_2d_equals_direct_sum():
    rng = np.random.default_rng(5)
    n, dx, es = 9, 2e-5, 1.1e11
    p = rng.random(n) * 1e9
    x = np.arange(n) * dx
    S = 2.0 * strip_integral_2d(x[:, None] - x[None, :], dx) / (np.pi * es)
    assert np.allclose(HalfSpace2D(n, dx, es).apply(p), S @ p, rtol=1e-11, atol=1e-20)


def test_strip_integral_matches_quadrature():
    dx = 1e-3
    for x in (0.0, 0.3e-3, 2.7e-3):
        ref, _ = integrate.quad(lambda s: -np.log(abs(x - s)), -dx / 2, dx / 2,
                                points=[x] if abs(x) < dx / 2 else None, epsabs=1e-14)
        assert strip_integral_2d(x, dx) == pytest.approx(ref, rel=1e-9)
