"""Quasi-static load distribution of a radially loaded rolling bearing (Stribeck/Sjovall).

Harris, Rolling Bearing Analysis (ch. 7): F_r = sum_j K (delta_r cos psi_j - c_d/2)_+^n cos psi_j,
with Q_max ~ 4.37 F_r/Z (balls, n = 3/2) and ~ 4.08 F_r/Z (line contact, n = 10/9) at zero
clearance.  The contact laws themselves are in :mod:`spindlesim.contact.hertz`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


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
    from scipy.optimize import brentq  # here: scipy.optimize takes a third of a second to import

    d = brentq(residual, half, hi, xtol=1e-16, rtol=1e-13, maxiter=200)
    q = stiffness * np.maximum(d * c - half, 0.0) ** exponent
    return LoadDistribution(angle_rad=psi, load_N=q, displacement_m=float(d))
