"""Bearing reactions (seed 001 eqs. 36-40) and the analytic 5x5 stiffness.

Ring DOFs d = (dX, dY, dZ, phiX, phiY).  For roller j of row k (sign s_k = +1, -1) at the
azimuth psi the in-plane ring motion is w = T d + (0, delta0, 0) with

    T = [[cos psi, sin psi, 0,   0,            0         ],
         [0,       0,       s_k, 0,            0         ],
         [0,       0,       0,   -s_k sin psi, s_k cos psi]]

(eq. 10 projected on the meridional plane: a_r = dX cos psi + dY sin psi, a_z = s dZ + delta0,
theta = s (phiY cos psi - phiX sin psi)).  The generalised force of the roller on the ring
is f_w = -sum_c Q_c A_w,c, and by virtual work the reaction on the shaft is
F = sum_j T_j^T f_w,j, which written out is eqs. 36-40 (FX = -sum (Q_i cos beta - Q_f sin theta)
cos psi, ..., FZ = -sum s (Q_i sin beta + Q_f cos theta), and the moments from the slice
positions R_i* and the rib point R_f*).

Stiffness K = -dF/dd by the implicit-function theorem on the roller equilibrium: per roller
k_r = K_ww - K_wu K_uu^-1 K_uw (K_ab = sum_c k_c A_a,c A_b,c^T), K = sum_j T_j^T k_r,j T_j.
It is symmetric: the contact forces derive from a potential and the inertia loads are
constant.
"""

from __future__ import annotations

import numpy as np

from .geometry import DtrbGeometry
from .roller_equilibrium import ContactOperators, RollerSolution

ROW_SIGN = np.array([1.0, -1.0])


def azimuths(geom: DtrbGeometry, cage_angle_rad: float = 0.0, row_offset_rad=(0.0, 0.0)) -> np.ndarray:
    """psi_jk = 2 pi (j - 1) / N + Omega_c t + psi0_k (seed 001 eq. 3), shape (2, N)."""
    N = geom.rollers_per_row
    base = 2.0 * np.pi * np.arange(N) / N + cage_angle_rad
    return np.stack([base + row_offset_rad[0], base + row_offset_rad[1]])


def projection(psi: np.ndarray) -> np.ndarray:
    """T per roller, shape (2N, 3, 5), rows then rollers flattened (row-major)."""
    R = psi.size
    c, s = np.cos(psi).ravel(), np.sin(psi).ravel()
    sign = np.repeat(ROW_SIGN, psi.shape[1])
    T = np.zeros((R, 3, 5))
    T[:, 0, 0], T[:, 0, 1] = c, s
    T[:, 1, 2] = sign
    T[:, 2, 3], T[:, 2, 4] = -sign * s, sign * c
    return T


def ring_motion(T: np.ndarray, d: np.ndarray, preload_m: float) -> np.ndarray:
    W = T @ np.asarray(d, float)
    W[:, 1] += preload_m
    return W


def reaction_from(T: np.ndarray, geom: DtrbGeometry, sol: RollerSolution) -> np.ndarray:
    """Reaction on the shaft (FX, FY, FZ, MX, MY) [N, N m] from the solved contact loads."""
    f_w = -(sol.Q @ geom.A_w)  # (R, 3)
    return (T * f_w[:, :, None]).sum(axis=(0, 1))


def condensed_roller_stiffness(ops: ContactOperators, sol: RollerSolution) -> np.ndarray:
    """k_r = K_ww - K_wu K_uu^-1 K_uw per roller, (R, 3, 3) in the (a_r, a_z, theta) frame."""
    k = sol.k
    Kww = (k @ ops.AwAw).reshape(-1, 3, 3)
    Kwu = (k @ ops.AwAu).reshape(-1, 3, 3)
    Kuu = (k @ ops.AuAu).reshape(-1, 3, 3)
    Kuu[:, [0, 1, 2], [0, 1, 2]] += ops.reg
    return Kww - Kwu @ np.linalg.solve(Kuu, np.transpose(Kwu, (0, 2, 1)))


def stiffness_from(T: np.ndarray, ops: ContactOperators, sol: RollerSolution) -> np.ndarray:
    """K = -dF/dd (5x5, N/m, N/rad, N m/m, N m/rad)."""
    kr = condensed_roller_stiffness(ops, sol)
    K = (np.transpose(T, (0, 2, 1)) @ (kr @ T)).sum(axis=0)
    return 0.5 * (K + K.T)
