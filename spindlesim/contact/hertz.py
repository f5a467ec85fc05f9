"""Hertz contact closed forms: the one module every rolling model and the contact solver use.

Johnson, Contact Mechanics (1985), sections 4.2-4.3; Harris and Kotzalas, Rolling Bearing
Analysis (2007), ch. 6; REFERENCES.md ("Rolling bearings").  All SI.

- Contact modulus: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (seed 001's E' of eq. 26 is 2 E*).
- Line contact (cylinder on a plane, load per length w'): b = sqrt(4 w' R / (pi E*)),
  p0 = sqrt(w' E* / (pi R)).
- Point contact of two bodies with relative curvatures A <= B (A + B = half the curvature
  sum): the ellipse eccentricity from B/A = [E(e)/(1 - e^2) - K(e)] / [K(e) - E(e)] (complete
  elliptic integrals of the first and second kind, parameter m = e^2), then
  a^3 = 3 P (K - E) / (2 pi E* m A), b = a sqrt(1 - m), delta = 3 P K / (2 pi a E*),
  p0 = 3 P / (2 pi a b) (Johnson eqs. 4.39-4.41).  Q = K_p delta^(3/2).
- Line contact load-deflection: Palmgren's delta = 3.84e-5 Q^0.9 / l^0.8 (mm, N) for ONE
  roller/raceway contact, i.e. Q = K delta^(10/9) with K = 8.06e4 l^(8/9) N/mm^(10/9); seed
  001's slice law K = pi E' l^(8/9) / 7.358^(10/9) (eq. 25) lies within 3 % of it.
- Two contacts of one rolling element in series (same exponent n): K_total = K1 K2 /
  (K1^(1/n) + K2^(1/n))^n, K / 2^n for equal contacts.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.special import ellipe, ellipk

__all__ = [
    "EXPONENT_LINE", "EXPONENT_POINT", "combined_modulus", "ellipticity_estimate", "line_contact",
    "line_contact_constant", "palmgren_deflection_m", "palmgren_stiffness", "point_contact", "point_contact_circular",
    "point_contact_constant", "point_contact_semi_axes_estimate", "power_law", "series_stiffness",
    "stribeck_max_roller_load",
]

#: load-deflection exponent of a line contact (Palmgren; seed 001 eq. 23)
EXPONENT_LINE = 10.0 / 9.0
#: load-deflection exponent of a Hertz point contact
EXPONENT_POINT = 1.5
#: seed 001 eq. 25
SEED001_LINE_CONSTANT = 7.358


def combined_modulus(e1_pa: float, nu1: float, e2_pa: float | None = None, nu2: float | None = None) -> float:
    """E* [Pa] with 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (Johnson eq. 4.22); same body twice by default."""
    e2 = e1_pa if e2_pa is None else e2_pa
    n2 = nu1 if nu2 is None else nu2
    return 1.0 / ((1.0 - nu1 * nu1) / e1_pa + (1.0 - n2 * n2) / e2)


def line_contact(load_per_length_n_m: float, r_eq_m: float, e_star_pa: float) -> tuple[float, float]:
    """Hertz line (cylinder) contact: half-width b [m] and peak pressure p0 [Pa] (Johnson 4.43-4.45)."""
    w = load_per_length_n_m
    b = math.sqrt(4.0 * w * r_eq_m / (math.pi * e_star_pa))
    p0 = math.sqrt(w * e_star_pa / (math.pi * r_eq_m))
    return b, p0


def point_contact_circular(load_n: float, r_eq_m: float, e_star_pa: float) -> tuple[float, float, float]:
    """Hertz circular point contact: radius a [m], p0 [Pa], approach delta [m].

    a^3 = 3 W R / (4 E*), p0 = 3 W / (2 pi a^2), delta = a^2 / R (Johnson eqs. 4.22-4.23);
    R is the equivalent radius (the sphere radius for a sphere on a flat).
    """
    a = (3.0 * load_n * r_eq_m / (4.0 * e_star_pa)) ** (1.0 / 3.0)
    p0 = 3.0 * load_n / (2.0 * math.pi * a * a)
    return a, p0, a * a / r_eq_m


def _ellipse_parameter(ratio_b_over_a: float) -> float:
    """m = e^2 = 1 - (b/a)^2 of the contact ellipse for B/A >= 1 (Johnson eq. 4.39)."""
    if ratio_b_over_a < 1.0:
        raise ValueError("B/A must be >= 1 (B the larger relative curvature)")
    if ratio_b_over_a - 1.0 < 1e-12:
        return 0.0

    def f(m: float) -> float:
        k, e = ellipk(m), ellipe(m)
        return (e / (1.0 - m) - k) / (k - e) - ratio_b_over_a

    from scipy.optimize import brentq  # here: a third of a second of imports the line contacts never need

    return brentq(f, 1e-12, 1.0 - 1e-14, xtol=1e-15, rtol=1e-14)


def point_contact(load_n: float, curvature_1: float, curvature_2: float, e_star_pa: float
                  ) -> tuple[float, float, float, float]:
    """Hertz elliptical contact: (semi-axis a >= b, semi-axis b, approach delta, p0), SI.

    ``curvature_1`` and ``curvature_2`` are the sums of the principal curvatures of both bodies
    in the two principal planes (1/R' + 1/R''), both positive (non-conforming contact); the
    long semi-axis a lies in the plane of the smaller curvature sum.
    """
    B, A = 0.5 * max(curvature_1, curvature_2), 0.5 * min(curvature_1, curvature_2)
    if A <= 0.0:
        raise ValueError("both relative curvatures must be positive (non-conforming contact)")
    m = _ellipse_parameter(B / A)
    k, e = ellipk(m), ellipe(m)
    if m == 0.0:
        a = (3.0 * load_n / (8.0 * e_star_pa * A)) ** (1.0 / 3.0)
    else:
        a = (3.0 * load_n * (k - e) / (2.0 * math.pi * e_star_pa * m * A)) ** (1.0 / 3.0)
    b = a * math.sqrt(1.0 - m)
    delta = 3.0 * load_n * k / (2.0 * math.pi * a * e_star_pa)
    p0 = 3.0 * load_n / (2.0 * math.pi * a * b)
    return a, b, delta, p0


def point_contact_constant(curvature_1: float, curvature_2: float, e_star_pa: float) -> float:
    """K [N/m^1.5] with Q = K delta^(3/2) for the contact of :func:`point_contact`."""
    _, _, delta, _ = point_contact(1.0, curvature_1, curvature_2, e_star_pa)
    return delta ** -1.5


def ellipticity_estimate(r_short_m: float, r_long_m: float) -> float:
    """Hamrock and Brewe's ellipticity k = a/b = 1.0339 (R_long/R_short)^0.636 of an elliptical contact of
    radii R_short <= R_long (below: the semi-axes; the EHL film of the thermal network's contacts)."""
    return 1.0339 * (r_long_m / r_short_m) ** 0.636


def point_contact_semi_axes_estimate(load_n: float, rx_m: float, ry_m: float, e_star_pa: float
                                     ) -> tuple[float, float]:
    """Approximate semi-axes (a_x, a_y) [m] of an elliptical contact of radii rx, ry.

    Hamrock and Brewe, J. Lubr. Technol. 105 (1983) 171-177 (ellipticity k = 1.0339
    (R_long/R_short)^0.636, E ~ 1.0003 + 0.5968 R_short/R_long): a few % off the exact
    :func:`point_contact`; used to size grids, as the reference the exact form is checked against, and for
    the contact ellipses of the thermal network's conductances (``bearings/conductance.py``).
    """
    r_short, r_long = min(rx_m, ry_m), max(rx_m, ry_m)
    k = ellipticity_estimate(r_short, r_long)
    ell = 1.0003 + 0.5968 * r_short / r_long
    r = 1.0 / (1.0 / rx_m + 1.0 / ry_m)
    e_prime = 2.0 * e_star_pa
    a_long = (6.0 * k * k * ell * load_n * r / (math.pi * e_prime)) ** (1.0 / 3.0)
    a_short = (6.0 * ell * load_n * r / (math.pi * k * e_prime)) ** (1.0 / 3.0)
    if rx_m <= ry_m:
        return a_short, a_long
    return a_long, a_short


def palmgren_deflection_m(load_n: float, length_m: float) -> float:
    """Palmgren's approach of ONE steel roller/raceway contact, delta = 3.84e-5 Q^0.9 / l^0.8 (mm, N), in m."""
    return 1e-3 * 3.84e-5 * load_n ** 0.9 / (1e3 * length_m) ** 0.8


def palmgren_stiffness(length_m: float) -> float:
    """K [N/m^(10/9)] of Q = K delta^(10/9) for ONE roller/raceway contact (Palmgren, steel).

    delta_mm = 3.84e-5 Q^0.9 / l_mm^0.8 inverted: K = (l_mm^0.8 / 3.84e-5)^(10/9) N/mm^(10/9)
    (= 8.06e4 l_mm^(8/9)), times 1e3^(10/9) for metres.
    """
    l_mm = length_m * 1e3
    return float((l_mm ** 0.8 / 3.84e-5) ** (10.0 / 9.0) * 1e3 ** (10.0 / 9.0))


def line_contact_constant(length_m: float, e_prime_pa: float) -> float:
    """K of seed 001 eq. 25 [N/m^(10/9)]: Q = K delta^(10/9) for a uniform line of length l, E' = 2 E*."""
    return math.pi * e_prime_pa * length_m ** (8.0 / 9.0) / SEED001_LINE_CONSTANT ** EXPONENT_LINE


def series_stiffness(k1: float, k2: float, exponent: float) -> float:
    """K of two contacts Q = k_i delta_i^n in series (same Q, deflections add):
    K = k1 k2 / (k1^(1/n) + k2^(1/n))^n (k / 2^n for equal contacts)."""
    return float((k1 ** (-1.0 / exponent) + k2 ** (-1.0 / exponent)) ** -exponent)


def power_law(delta: np.ndarray, K: np.ndarray | float, n: np.ndarray | float) -> tuple[np.ndarray, np.ndarray]:
    """(Q, dQ/ddelta) of Q = K <delta>^n, zero for delta <= 0 (C1 for n > 1)."""
    d = np.maximum(delta, 0.0)
    dn1 = d ** (np.asarray(n) - 1.0)
    return K * d * dn1, K * n * dn1


def stribeck_max_roller_load(radial_load_n: float, n_rollers: int, line_contact_: bool = True) -> float:
    """Most loaded rolling element of a zero-clearance bearing under radial load [N].

    Stribeck: Q_max ~ 4.08 F_r / Z for line contact, 4.37 F_r / Z for balls (Harris ch. 7).
    """
    if n_rollers < 1:
        raise ValueError("n_rollers must be >= 1")
    return (4.08 if line_contact_ else 4.37) * radial_load_n / n_rollers
