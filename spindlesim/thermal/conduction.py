"""Conduction and contact conductances from geometry (SI).

- Radial conduction through a cylindrical shell (Incropera et al., Fundamentals of Heat and Mass
  Transfer, 6th ed., eq. 3.28): R = ln(r2/r1) / (2 pi k L).
- Axial conduction in a rod or tube: R = L / (k A), A = pi (d_o^2 - d_i^2) / 4.
- Contact (interface) conductance of a seat, G = h_c A.  h_c of metal interfaces: Incropera Table
  3.1 lists contact resistances of stainless steel interfaces (vacuum) of 6-25e-4 m^2 K/W at
  0.1 MPa and 0.7-4.0e-4 m^2 K/W at 10 MPa, i.e. h_c ~ 400-14,000 W/(m^2 K); a gas or oil film in
  the gaps raises it.  A bearing seat (interference or transition fit, ground surfaces) sits in
  the middle: default :data:`SEAT_CONDUCTANCE_W_M2K` = 5000 W/(m^2 K), range 1000-20,000.
- Pressure-dependent h_c of conforming rough surfaces, plastic asperities (Cooper, Mikic and
  Yovanovich 1969; in the form of Yovanovich, IEEE Trans. Compon. Packag. Technol. 28 (2005)
  182-206): h_c = 1.25 k_s (m / sigma) (P / H_c)^0.95 with k_s = 2 k1 k2 / (k1 + k2),
  sigma = sqrt(sigma1^2 + sigma2^2) (rms roughness), m = sqrt(m1^2 + m2^2) (rms asperity slope),
  P the contact pressure and H_c the microhardness; for 1e-6 < P / H_c < 2e-2.
"""

from __future__ import annotations

import math

#: default contact conductance of a bearing ring seat [W/(m^2 K)] (see module docstring)
SEAT_CONDUCTANCE_W_M2K = 5000.0
#: the range quoted with it
SEAT_CONDUCTANCE_RANGE_W_M2K = (1000.0, 20000.0)


def _positive(**kw) -> None:
    for k, v in kw.items():
        if not (math.isfinite(v) and v > 0.0):
            raise ValueError(f"{k} must be finite and > 0, got {v!r}")


def cylindrical_shell_resistance(r_inner_m: float, r_outer_m: float, length_m: float, conductivity_W_mK: float) -> float:
    """Radial conduction resistance [K/W] of a cylindrical shell, ln(r2/r1) / (2 pi k L)."""
    _positive(r_inner_m=r_inner_m, length_m=length_m, conductivity_W_mK=conductivity_W_mK)
    if not r_outer_m > r_inner_m:
        raise ValueError("outer radius must exceed the inner radius")
    return math.log(r_outer_m / r_inner_m) / (2.0 * math.pi * conductivity_W_mK * length_m)


def cylindrical_shell_conductance(r_inner_m: float, r_outer_m: float, length_m: float, conductivity_W_mK: float) -> float:
    """1 / :func:`cylindrical_shell_resistance` [W/K]."""
    return 1.0 / cylindrical_shell_resistance(r_inner_m, r_outer_m, length_m, conductivity_W_mK)


def annulus_area(outer_diameter_m: float, inner_diameter_m: float = 0.0) -> float:
    """Cross-section pi (d_o^2 - d_i^2) / 4 [m^2]."""
    if not outer_diameter_m > inner_diameter_m >= 0.0:
        raise ValueError("need outer diameter > inner diameter >= 0")
    return 0.25 * math.pi * (outer_diameter_m ** 2 - inner_diameter_m ** 2)


def axial_conductance(length_m: float, area_m2: float, conductivity_W_mK: float) -> float:
    """Axial conduction k A / L [W/K] of a rod or tube of cross-section ``area_m2``."""
    _positive(length_m=length_m, area_m2=area_m2, conductivity_W_mK=conductivity_W_mK)
    return conductivity_W_mK * area_m2 / length_m


def seat_conductance(diameter_m: float, width_m: float, h_c_W_m2K: float = SEAT_CONDUCTANCE_W_M2K) -> float:
    """Contact conductance h_c pi d B [W/K] of a cylindrical seat of diameter d and width B."""
    _positive(diameter_m=diameter_m, width_m=width_m, h_c_W_m2K=h_c_W_m2K)
    return h_c_W_m2K * math.pi * diameter_m * width_m


def contact_conductance_cmy(k1_W_mK: float, k2_W_mK: float, roughness1_m: float, roughness2_m: float,
                            slope1: float, slope2: float, pressure_Pa: float, microhardness_Pa: float) -> float:
    """h_c [W/(m^2 K)] of a plastic rough-surface contact (Cooper-Mikic-Yovanovich, see module doc)."""
    _positive(k1_W_mK=k1_W_mK, k2_W_mK=k2_W_mK, pressure_Pa=pressure_Pa, microhardness_Pa=microhardness_Pa)
    ks = 2.0 * k1_W_mK * k2_W_mK / (k1_W_mK + k2_W_mK)
    sigma = math.hypot(roughness1_m, roughness2_m)
    m = math.hypot(slope1, slope2)
    _positive(roughness=sigma, slope=m)
    ratio = pressure_Pa / microhardness_Pa
    if not 1e-6 <= ratio <= 2e-2:
        raise ValueError(f"P/H_c = {ratio:.3g} outside the correlation's range 1e-6..2e-2")
    return 1.25 * ks * (m / sigma) * ratio ** 0.95


def series(*resistances_K_W: float) -> float:
    """Sum of resistances [K/W]."""
    return float(sum(resistances_K_W))


def conductance_in_series(*conductances_W_K: float) -> float:
    """1 / sum(1/G_i) [W/K]; 0 if any path has zero conductance."""
    if any(g <= 0.0 for g in conductances_W_K):
        return 0.0
    return 1.0 / sum(1.0 / g for g in conductances_W_K)
