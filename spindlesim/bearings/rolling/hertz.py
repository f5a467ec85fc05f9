"""Hertz/Palmgren contact stiffness and quasi-static load distribution.

Sources:
- Hertz line contact (Johnson, Contact Mechanics, 1985, sec. 4.2):
  b = sqrt(4 w' R / (pi E*)), p0 = sqrt(w' E* / (pi R)), 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2.
- Hertz sphere on flat (Johnson sec. 4.2): a = (3 Q R / (4 E*))^(1/3), p0 = 3 Q / (2 pi a^2).
- Palmgren's line contact load-deflection, both contacts of a steel roller
  (Harris, Rolling Bearing Analysis, 4th ed., eq. 6.42): delta = 3.84e-5 Q^0.9 / l^0.8
  (delta, l in mm; Q in N), i.e. Q = K delta^(10/9).
- Stribeck/Sjovall load distribution for a radial load on Z rolling elements
  (Harris ch. 7): F_r = sum_j K (delta_r cos psi_j - c_d/2)_+^n cos psi_j, with
  Q_max ~ 4.37 F_r/Z (balls) and ~ 4.08 F_r/Z (line contact) at zero clearance.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

#: load-deflection exponent of a Hertz point contact (ball)
EXPONENT_BALL = 1.5
#: load-deflection exponent of a line contact (roller), Palmgren
EXPONENT_ROLLER = 10.0 / 9.0


def effective_modulus(E1_Pa: float, nu1: float, E2_Pa: float | None = None, nu2: float | None = None) -> float:
    """Contact modulus E* with 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2 (same body twice by default)."""
    E2 = E1_Pa if E2_Pa is None else E2_Pa
    n2 = nu1 if nu2 is None else nu2
    return 1.0 / ((1.0 - nu1**2) / E1_Pa + (1.0 - n2**2) / E2)


def line_contact(load_per_length_N_m: float, radius_m: float, E_star_Pa: float) -> tuple[float, float]:
    """Hertz line contact: (half-width b [m], peak pressure p0 [Pa]), Johnson sec. 4.2."""
    b = np.sqrt(4.0 * load_per_length_N_m * radius_m / (np.pi * E_star_Pa))
    p0 = np.sqrt(load_per_length_N_m * E_star_Pa / (np.pi * radius_m))
    return float(b), float(p0)


def sphere_on_flat(load_N: float, radius_m: float, E_star_Pa: float) -> tuple[float, float, float]:
    """Hertz sphere on flat: (contact radius a [m], peak pressure p0 [Pa], approach delta [m])."""
    a = (3.0 * load_N * radius_m / (4.0 * E_star_Pa)) ** (1.0 / 3.0)
    p0 = 3.0 * load_N / (2.0 * np.pi * a**2)
    return float(a), float(p0), float(a**2 / radius_m)


def palmgren_roller_stiffness(roller_length_m: float) -> float:
    """K [N/m^(10/9)] of Q = K delta^(10/9), delta the total (inner + outer) roller deflection.

    Palmgren: delta_mm = 3.84e-5 Q^0.9 / l_mm^0.8 (Harris 4th ed. eq. 6.42), so
    Q = (l_mm^0.8 / 3.84e-5)^(10/9) delta_mm^(10/9); delta_mm = 1e3 delta_m.
    """
    l_mm = roller_length_m * 1e3
    return float((l_mm**0.8 / 3.84e-5) ** (10.0 / 9.0) * 1e3 ** (10.0 / 9.0))


def per_contact_stiffness(total_stiffness: float, exponent: float) -> float:
    """Stiffness of one of two equal contacts in series, k_c with Q = k_c delta_c^n.

    Two equal contacts share the total deflection, delta = 2 delta_c, so
    k_c = K 2^n.  (Inner and outer contacts of a roller differ by a few per cent
    in curvature; seed 000 gives no separate values.)
    """
    return float(total_stiffness * 2.0**exponent)


@dataclass(frozen=True)
class LoadDistribution:
    """Quasi-static roller loads for a radial load (Stribeck/Sjovall)."""

    angle_rad: np.ndarray  # roller positions measured from the load line
    load_N: np.ndarray  # contact load of each roller
    displacement_m: float  # shaft displacement along the load line

    @property
    def q_max_N(self) -> float:
        return float(self.load_N.max())


def static_load_distribution(stiffness: float, exponent: float, rollers: int, radial_load_N: float,
                             diametral_clearance_m: float = 0.0, phase_rad: float = 0.0) -> LoadDistribution:
    """Solve F_r = sum K (delta_r cos psi - c_d/2)_+^n cos psi for delta_r (Harris ch. 7).

    psi_j = phase + 2 pi j / Z measured from the load line.  Returns the roller loads.
    """
    if radial_load_N <= 0:
        raise ValueError("radial load must be positive")
    psi = phase_rad + 2.0 * np.pi * np.arange(rollers) / rollers
    c = np.cos(psi)
    half = 0.5 * diametral_clearance_m

    def residual(d: float) -> float:
        pen = np.maximum(d * c - half, 0.0)
        return float(np.sum(stiffness * pen**exponent * c) - radial_load_N)

    hi = half + (radial_load_N / stiffness) ** (1.0 / exponent) + 1e-12
    while residual(hi) < 0:
        hi *= 2.0
    d = brentq(residual, half, hi, xtol=1e-16, rtol=1e-13, maxiter=200)
    q = stiffness * np.maximum(d * c - half, 0.0) ** exponent
    return LoadDistribution(angle_rad=psi, load_N=q, displacement_m=float(d))
