"""Influence coefficients of the elastic half-space and their DC-FFT kernels.

Surface normal displacement of a half-space under a normal pressure (Boussinesq;
seed 001 eq. 43), written for the *combined* compliance of two bodies:

    u(x, y) = 1 / (pi E*) * integral p(x', y') / sqrt((x - x')^2 + (y - y')^2) dx' dy',
    1 / E* = (1 - nu1^2) / E1 + (1 - nu2^2) / E2.

For a pressure that is uniform over each rectangular cell of size dx x dy (seed 001
eq. 44-45; Love 1929, Johnson, Contact Mechanics 1985, eq. 3.25) the integral over one
cell is a closed form.  With X = x - x', Y = y - y' and r = sqrt(X^2 + Y^2) the function

    H(X, Y) = X ln(Y + r) + Y ln(X + r)

has d^2 H / dX dY = 1 / r, so the integral over a cell centred at the origin, seen from
(x, y), is the four-corner sum

    I(x, y) = H(x + a, y + b) - H(x + a, y - b) - H(x - a, y + b) + H(x - a, y - b)

with a = dx / 2, b = dy / 2.  (Seed 001 prints eq. 45 with x and y mixed up; the form
above is re-derived and checked against numerical quadrature in the tests.)

DC-FFT (Liu, Wang and Liu, Wear 243 (2000) 101-111): the discrete convolution
u_i = sum_j K_{i-j} p_j on an n_x x n_y grid is computed without periodic wrap-around by
placing the (2 n_x - 1) x (2 n_y - 1) kernel in wrap-around order into a 2 n_x x 2 n_y
array (the extra row/column is zero), zero-padding the pressure to the same size,
multiplying the spectra and keeping the first n_x x n_y block of the inverse transform.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import fft as sfft

__all__ = [
    "rect_patch_integral",
    "strip_integral_2d",
    "HalfSpace3D",
    "HalfSpace2D",
]


def _log_sum_stable(X: np.ndarray, Y: np.ndarray, r: np.ndarray) -> np.ndarray:
    """Return Y * ln(X + r) without cancellation when X < 0.

    For X < 0, X + r = Y^2 / (r - X), which is computed accurately.  Where Y = 0 the
    product Y ln(...) is 0 (its limit), also on the negative X axis where X + r = 0.
    """
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.where(X >= 0.0, X + r, Y * Y / (r - X))
        out = np.where(Y == 0.0, 0.0, Y * np.log(np.where(s > 0.0, s, 1.0)))
    return out


def _corner(X: np.ndarray, Y: np.ndarray) -> np.ndarray:
    """H(X, Y) = X ln(Y + r) + Y ln(X + r), with its limits on the axes."""
    r = np.hypot(X, Y)
    return _log_sum_stable(Y, X, r) + _log_sum_stable(X, Y, r)


def rect_patch_integral(x: np.ndarray, y: np.ndarray, dx: float, dy: float) -> np.ndarray:
    """Integral of 1/r over the cell [-dx/2, dx/2] x [-dy/2, dy/2], seen from (x, y) [m].

    Love's closed form (seed 001 eq. 45, re-derived; see module docstring).  Multiply
    by p / (pi E*) to get the displacement [m] due to a uniform pressure p on the cell.
    At the cell centre of a square cell of side s it equals 4 s asinh(1).
    """
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    a, b = 0.5 * dx, 0.5 * dy
    return (
        _corner(x + a, y + b)
        - _corner(x + a, y - b)
        - _corner(x - a, y + b)
        + _corner(x - a, y - b)
    )


def strip_integral_2d(x: np.ndarray, dx: float) -> np.ndarray:
    """-integral of ln|x - s| ds over the strip |s| <= dx/2 (plane strain kernel) [m].

    Plane-strain surface displacement of two bodies under a line pressure p(s)
    (Johnson 1985, eq. 2.25 summed over both bodies):
    u(x) = -(2 / (pi E*)) integral p(s) ln|x - s| ds + const.  With F(t) = t ln|t| - t,
    the strip integral of ln|x - s| is F(x + a) - F(x - a), a = dx / 2.
    """
    x = np.asarray(x, dtype=float)
    a = 0.5 * dx

    def F(t: np.ndarray) -> np.ndarray:
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(t == 0.0, 0.0, t * np.log(np.abs(t)) - t)

    return -(F(x + a) - F(x - a))


@dataclass(frozen=True)
class HalfSpace3D:
    """Deflection operator u = K * p on a uniform n_x x n_y cell grid (DC-FFT).

    Arguments: ``nx, ny`` cells, cell sizes ``dx, dy`` [m], combined modulus
    ``e_star`` [Pa].  ``apply(p)`` takes pressures [Pa] of shape (nx, ny) and returns
    the surface displacement [m] at the cell centres.
    """

    nx: int
    ny: int
    dx: float
    dy: float
    e_star: float

    def __post_init__(self) -> None:
        nx, ny = self.nx, self.ny
        ix = np.arange(2 * nx)
        iy = np.arange(2 * ny)
        # wrap-around order: offsets 0..n-1, (unused n), -(n-1)..-1
        ox = np.where(ix < nx, ix, ix - 2 * nx).astype(float)
        oy = np.where(iy < ny, iy, iy - 2 * ny).astype(float)
        # Love's four-corner sum (eq. 45): H on the cell corners around each offset
        xp, xm = (ox + 0.5) * self.dx, (ox - 0.5) * self.dx
        yp, ym = (oy + 0.5) * self.dy, (oy - 0.5) * self.dy
        Hpp = _corner(xp[:, None], yp[None, :])
        Hpm = _corner(xp[:, None], ym[None, :])
        Hmp = _corner(xm[:, None], yp[None, :])
        Hmm = _corner(xm[:, None], ym[None, :])
        k = (Hpp - Hpm - Hmp + Hmm) / (np.pi * self.e_star)
        k[nx, :] = 0.0
        k[:, ny] = 0.0
        object.__setattr__(self, "_kernel_hat", sfft.fft(sfft.rfft(k, axis=1), axis=0))
        object.__setattr__(self, "self_coefficient", float(k[0, 0]))

    def apply(self, p: np.ndarray) -> np.ndarray:
        """Surface displacement [m] from cell pressures ``p`` [Pa], shape (nx, ny).

        The zero padding is exploited: the real transform along y runs on the n_x
        non-zero rows only, and the inverse along y only on the n_x rows kept.
        """
        a = sfft.rfft(p, n=2 * self.ny, axis=1)
        a = sfft.fft(a, n=2 * self.nx, axis=0)
        a *= self._kernel_hat
        a = sfft.ifft(a, axis=0)[: self.nx]
        return sfft.irfft(a, n=2 * self.ny, axis=1)[:, : self.ny]


@dataclass(frozen=True)
class HalfSpace2D:
    """Plane-strain deflection operator on n uniform strips of width dx (DC-FFT, 1D).

    u_i = (2 / (pi E*)) sum_j S(x_i - x_j) p_j, with S from :func:`strip_integral_2d`;
    the additive constant of the 2D solution is absorbed by the rigid approach.
    """

    n: int
    dx: float
    e_star: float

    def __post_init__(self) -> None:
        n = self.n
        i = np.arange(2 * n)
        off = np.where(i < n, i, i - 2 * n).astype(float) * self.dx
        k = 2.0 * strip_integral_2d(off, self.dx) / (np.pi * self.e_star)
        k[n] = 0.0
        object.__setattr__(self, "_kernel_hat", sfft.rfft(k))

    def apply(self, p: np.ndarray) -> np.ndarray:
        """Displacement [m] (up to a constant) from strip pressures ``p`` [Pa]."""
        m = 2 * self.n
        return sfft.irfft(sfft.rfft(p, n=m) * self._kernel_hat, n=m)[: self.n]
