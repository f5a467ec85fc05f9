"""Hertz closed forms: references for the tests and estimates for grid sizing.

Johnson, Contact Mechanics (1985), sections 4.2-4.3 and 5.1; REFERENCES.md
("Hertz line contact", "Hertz sphere on flat").  All SI.
"""

from __future__ import annotations

import math

__all__ = [
    "combined_modulus",
    "line_contact",
    "point_contact_circular",
    "point_contact_semi_axes_estimate",
    "stribeck_max_roller_load",
]


def combined_modulus(e1_pa: float, nu1: float, e2_pa: float, nu2: float) -> float:
    """E* [Pa] with 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (Johnson eq. 4.22).

    Seed 001's E' of eq. 26 is 2 E*.
    """
    return 1.0 / ((1.0 - nu1 * nu1) / e1_pa + (1.0 - nu2 * nu2) / e2_pa)


def line_contact(load_per_length_n_m: float, r_eq_m: float, e_star_pa: float) -> tuple[float, float]:
    """Hertz line (cylinder) contact: half-width b [m] and peak pressure p0 [Pa].

    b = sqrt(4 w' R' / (pi E*)), p0 = sqrt(w' E* / (pi R')) = 2 w' / (pi b)
    (Johnson eqs. 4.43-4.45).
    """
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


def point_contact_semi_axes_estimate(
    load_n: float, rx_m: float, ry_m: float, e_star_pa: float
) -> tuple[float, float]:
    """Approximate semi-axes (a_x, a_y) [m] of an elliptical Hertz contact.

    Hamrock and Brewe, J. Lubr. Technol. 105 (1983) 171-177, simplified formulas
    (ellipticity k = 1.0339 (R_long/R_short)^0.636, elliptic integral
    E ~ 1.0003 + 0.5968 R_short/R_long).  Used only to size the grid (a few % error).
    """
    r_short, r_long = min(rx_m, ry_m), max(rx_m, ry_m)
    k = 1.0339 * (r_long / r_short) ** 0.636
    ell = 1.0003 + 0.5968 * r_short / r_long
    r = 1.0 / (1.0 / rx_m + 1.0 / ry_m)
    e_prime = 2.0 * e_star_pa
    a_long = (6.0 * k * k * ell * load_n * r / (math.pi * e_prime)) ** (1.0 / 3.0)
    a_short = (6.0 * ell * load_n * r / (math.pi * k * e_prime)) ** (1.0 / 3.0)
    if rx_m <= ry_m:
        return a_short, a_long
    return a_long, a_short


def stribeck_max_roller_load(radial_load_n: float, n_rollers: int, line_contact_: bool = True) -> float:
    """Most loaded rolling element of a zero-clearance bearing under radial load [N].

    Stribeck: Q_max ~ 4.08 F_r / Z for line contact, 4.37 F_r / Z for balls
    (REFERENCES.md, "Rolling bearings"; Harris, Rolling Bearing Analysis, ch. 7).
    """
    if n_rollers < 1:
        raise ValueError("n_rollers must be >= 1")
    return (4.08 if line_contact_ else 4.37) * radial_load_n / n_rollers
