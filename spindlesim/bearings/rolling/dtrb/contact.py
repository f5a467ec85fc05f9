"""Contact laws of the DTRB model (seed 001 eqs. 23-29), SI units.

Line contact of a roller slice (eqs. 23-26)::

    q = (K / l) delta^(10/9)          load per unit length of a slice [N/m]
    K = pi E' l^(8/9) / 7.358^(10/9)  [N / m^(10/9)]
    1/E' = 0.5 ((1 - nu1^2)/E1 + (1 - nu2^2)/E2)

so a uniformly compressed line of length l carries Q = K delta^(10/9) (eq. 27).  With
E' of eq. 26 (E' = 2 E*, E/(1 - nu^2) for equal steels) this is within 3 % of
Palmgren's delta = 3.84e-5 Q^0.9 / l^0.8 (mm, N) for one roller/raceway contact; a
reduced modulus E* in place of E' would halve K.

Rib (flange) contact of the spherical roller end on the conical rib (eq. 28)::

    Q_f = c_f E' Rs^2 (delta_f / Rs)^(3/2) = K_f delta_f^(3/2)

The seed gives c_f only as a function of the conformity kappa (eq. 29); here K_f is
computed exactly from Hertz's elliptical point contact (Johnson, Contact Mechanics,
1985, section 4.2, eqs. 4.39-4.41 with complete elliptic integrals), so
c_f = K_f / (E' sqrt(Rs)).
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk

LINE_CONSTANT = 7.358  # seed 001 eq. 25
LINE_EXPONENT = 10.0 / 9.0
POINT_EXPONENT = 1.5


def seed_modulus(E1_Pa: float, nu1: float, E2_Pa: float | None = None, nu2: float | None = None) -> float:
    """E' of seed 001 eq. 26: 1/E' = 0.5 ((1 - nu1^2)/E1 + (1 - nu2^2)/E2) (= 2 E*)."""
    E2_Pa = E1_Pa if E2_Pa is None else E2_Pa
    nu2 = nu1 if nu2 is None else nu2
    return 1.0 / (0.5 * ((1.0 - nu1 ** 2) / E1_Pa + (1.0 - nu2 ** 2) / E2_Pa))


def line_contact_constant(length_m: float, E_prime_Pa: float) -> float:
    """K of seed 001 eq. 25 [N/m^(10/9)]: Q = K delta^(10/9) for a uniform line of length l."""
    return math.pi * E_prime_Pa * length_m ** (8.0 / 9.0) / LINE_CONSTANT ** LINE_EXPONENT


def palmgren_deflection_m(load_N: float, length_m: float) -> float:
    """Palmgren's line-contact approach delta = 3.84e-5 Q^0.9 / l^0.8 (mm, N), returned in m.

    Steel on steel, one roller/raceway contact (Harris and Kotzalas, Rolling Bearing
    Analysis, 2007, ch. 6; its inverse is K = 8.06e4 l^(8/9) N/mm^(10/9)).
    """
    return 1e-3 * 3.84e-5 * load_N ** 0.9 / (1e3 * length_m) ** 0.8


def _ellipse_eccentricity_m(ratio_B_over_A: float) -> float:
    """m = e^2 = 1 - (b/a)^2 solving B/A = [(a/b)^2 E(e) - K(e)] / [K(e) - E(e)] (Johnson 4.39)."""
    if ratio_B_over_A < 1.0:
        raise ValueError("B/A must be >= 1 (B the larger relative curvature)")
    if ratio_B_over_A - 1.0 < 1e-12:
        return 0.0

    def f(m: float) -> float:
        K, E = ellipk(m), ellipe(m)
        return (E / (1.0 - m) - K) / (K - E) - ratio_B_over_A

    return brentq(f, 1e-12, 1.0 - 1e-14, xtol=1e-15, rtol=1e-14)


def point_contact(load_N: float, curvature_1: float, curvature_2: float, E_star_Pa: float):
    """Hertz elliptical contact: (semi-axis a, semi-axis b, approach delta, p0).

    ``curvature_1`` and ``curvature_2`` are the sums of the principal relative
    curvatures of both bodies in the two principal planes (1/R' + 1/R'').
    ``E_star_Pa`` is the contact modulus 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2.
    Johnson (1985) eqs. 4.39-4.41: A + B = (c1 + c2)/2; a^3 = 3 P (K - E) / (2 pi E* e^2 A);
    delta = 3 P K(e) / (2 pi a E*); p0 = 3 P / (2 pi a b).
    """
    B, A = 0.5 * max(curvature_1, curvature_2), 0.5 * min(curvature_1, curvature_2)
    if A <= 0.0:
        raise ValueError("both relative curvatures must be positive (non-conforming contact)")
    m = _ellipse_eccentricity_m(B / A)
    K, E = ellipk(m), ellipe(m)
    if m == 0.0:
        a = (3.0 * load_N / (8.0 * E_star_Pa * A)) ** (1.0 / 3.0)
    else:
        a = (3.0 * load_N * (K - E) / (2.0 * math.pi * E_star_Pa * m * A)) ** (1.0 / 3.0)
    b = a * math.sqrt(1.0 - m)
    delta = 3.0 * load_N * K / (2.0 * math.pi * a * E_star_Pa)
    p0 = 3.0 * load_N / (2.0 * math.pi * a * b)
    return a, b, delta, p0


def point_contact_constant(curvature_1: float, curvature_2: float, E_star_Pa: float) -> float:
    """K_f [N/m^1.5] with Q = K_f delta^(3/2) for the Hertz contact of :func:`point_contact`."""
    _, _, delta, _ = point_contact(1.0, curvature_1, curvature_2, E_star_Pa)
    return delta ** -1.5


def power_law(delta: np.ndarray, K: np.ndarray | float, n: np.ndarray | float):
    """(Q, dQ/ddelta) of Q = K <delta>^n, zero for delta <= 0 (C1 for n > 1)."""
    d = np.maximum(delta, 0.0)
    dn1 = d ** (np.asarray(n) - 1.0)
    k = K * n * dn1
    return K * d * dn1, k
