"""Stiffness and damping coefficients: scaling, frames, and the short-bearing reference.

From the dimensionless Jacobians of the film force ``f`` (:mod:`reynolds`)::

    K = -dF/dx  = -(mu omega R^4 / Cb^3) df/dX          [N/m]
    B = -dF/dx' = -(mu R^4 / Cb^3)       df/dX'         [N s/m]   (X' = dX/d(omega t))

and the dimensionless groups ``k = K C / W``, ``c = B C omega / W`` (seed 003 eqs. 15-16
with C = Cp; Lund's convention with C = Cb): ``k_b = -(df/dX) / |f|``,
``c_b = -(df/dX') / |f|``, ``k_p = k_b / (1 - mp)`` (REFERENCES.md).
"""

from __future__ import annotations

import math

import numpy as np


def dimensional(jac_position: np.ndarray, jac_velocity: np.ndarray, viscosity_Pa_s: float,
                speed_rad_s: float, radius_m: float, clearance_m: float):
    """(K [N/m], B [N s/m]) from the dimensionless Jacobians (clearance Cb)."""
    s = viscosity_Pa_s * radius_m**4 / clearance_m**3
    return -s * speed_rad_s * np.asarray(jac_position), -s * np.asarray(jac_velocity)


def load_frame(load_N: np.ndarray) -> np.ndarray:
    """Columns: unit vector along the load, and 90 deg ahead of it in the rotation sense."""
    w = np.asarray(load_N, dtype=float)
    e1 = w / np.hypot(*w)
    e2 = np.array([-e1[1], e1[0]])
    return np.column_stack([e1, e2])


def to_load_frame(M: np.ndarray, load_N: np.ndarray) -> np.ndarray:
    """Rotate a 2x2 coefficient matrix from the x, y frame into the load frame."""
    Q = load_frame(load_N)
    return Q.T @ np.asarray(M) @ Q


def from_load_frame(M: np.ndarray, load_N: np.ndarray) -> np.ndarray:
    """Rotate a 2x2 coefficient matrix from the load frame into the x, y frame."""
    Q = load_frame(load_N)
    return Q @ np.asarray(M) @ Q.T


def ocvirk(eps: float) -> dict:
    """Short (Ocvirk) bearing closed forms, REFERENCES.md (e.g. Friswell et al. 2010, 5.5.1).

    Returns ``S_LD2`` = S (L/D)^2 (S on C with N in rev/s), ``phi_deg``, and ``k``, ``c``
    (2x2, k = K C / W, c = B C omega / W) with x along the load and y 90 deg ahead in the
    direction of rotation.
    """
    if not 0.0 < eps < 1.0:
        raise ValueError("eccentricity ratio must be in (0, 1)")
    e2 = eps * eps
    A = math.pi**2 * (1 - e2) + 16 * e2
    h0 = A**-1.5
    r = math.sqrt(1 - e2)
    pi2 = math.pi**2
    kxx = 4 * h0 * (pi2 * (1 + 2 * e2) + 32 * e2 * (1 + e2) / (1 - e2))
    kyy = 4 * h0 * (pi2 * (2 - e2) + 16 * e2)
    kxy = h0 * math.pi * (pi2 * (1 - e2) * (1 + 2 * e2) + 32 * e2 * (1 + e2)) / (eps * r)
    kyx = -h0 * math.pi * (pi2 * (1 - e2) ** 2 - 16 * e2 * e2) / (eps * r)
    cxx = 2 * math.pi * h0 * (pi2 * (1 - e2) ** 2 + 48 * e2) / (eps * r)
    cyy = 2 * math.pi * h0 * r * (pi2 * (1 + 2 * e2) - 16 * e2) / eps
    cxy = 8 * h0 * (pi2 * (1 + 2 * e2) - 16 * e2)
    return {
        "S_LD2": (1 - e2) ** 2 / (math.pi * eps * math.sqrt(A)),
        "phi_deg": math.degrees(math.atan2(math.pi * r, 4 * eps)),
        "k": np.array([[kxx, kxy], [kyx, kyy]]),
        "c": np.array([[cxx, cxy], [cxy, cyy]]),
    }


def ocvirk_eccentricity(S_LD2: float) -> float:
    """Eccentricity ratio of the short bearing for a given S (L/D)^2 (S on C, N in rev/s)."""
    from scipy.optimize import brentq

    if not S_LD2 > 0:
        raise ValueError("S (L/D)^2 must be positive")
    return brentq(lambda e: ocvirk(e)["S_LD2"] - S_LD2, 1e-9, 1 - 1e-12, xtol=1e-14)


def ocvirk_dimensional(diameter_m: float, width_m: float, clearance_m: float,
                       viscosity_Pa_s: float, speed_rad_s: float, load_N: np.ndarray):
    """Short-bearing (Ocvirk) eccentricity, K [N/m] and B [N s/m] in the x, y frame.

    Reference model for the dimensional check of Friswell et al. (2010) example 5.5.1;
    the finite-difference solver tends to it as L/D -> 0.
    """
    load = np.asarray(load_N, dtype=float)
    W = float(np.hypot(*load))
    R = 0.5 * diameter_m
    S = viscosity_Pa_s * speed_rad_s / (2 * math.pi) * width_m * diameter_m * (R / clearance_m) ** 2 / W
    eps = ocvirk_eccentricity(S * (width_m / diameter_m) ** 2)
    o = ocvirk(eps)
    K = from_load_frame(o["k"], load) * W / clearance_m
    B = from_load_frame(o["c"], load) * W / (clearance_m * speed_rad_s)
    return eps, K, B
