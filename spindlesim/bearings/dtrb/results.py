"""Frozen result records of the DTRB model (SI units)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class DtrbState:
    """Quasi-static state of the bearing at one inner-ring displacement.

    Row index 0 is row 1 (Z < 0, loaded by +FZ on the shaft), 1 is row 2.  Roller loads
    are the contact resultants (eq. 27 for the raceways, eq. 28 for the rib).
    """

    displacement: np.ndarray      # (5,) dX, dY, dZ [m], phiX, phiY [rad]
    reaction: np.ndarray          # (5,) FX, FY, FZ [N], MX, MY [N m] on the shaft (eqs. 36-40)
    stiffness: np.ndarray         # (5, 5) -dF/dd
    psi_rad: np.ndarray           # (2, N) roller azimuths (eq. 3)
    roller_u: np.ndarray          # (2, N, 3) u_x, u_z [m], phi_y [rad]
    inner_load_N: np.ndarray      # (2, N) Q_i
    outer_load_N: np.ndarray      # (2, N) Q_o
    rib_load_N: np.ndarray        # (2, N) Q_f
    inner_slice_N_m: np.ndarray   # (2, N, S) q_i per unit length
    outer_slice_N_m: np.ndarray   # (2, N, S) q_o per unit length
    preload_m: float
    speed_rad_s: float
    iterations: int
    converged: bool

    def loaded_rollers(self, threshold_N: float = 1e-3) -> np.ndarray:
        """Number of rollers per row loaded by the inner ring (Q_i > threshold), shape (2,).

        At speed an unloaded roller still presses on the cup and the rib with its centrifugal
        force (eq. 31), so the inner-raceway load is the test."""
        return (self.inner_load_N > threshold_N).sum(axis=1)


@dataclass(frozen=True)
class DtrbSweep:
    """Direct stiffness over a swept parameter (preload or a load component)."""

    name: str                     # e.g. "preload_m", "radial_load_N"
    values: np.ndarray            # (n,)
    stiffness: np.ndarray         # (n, 5, 5)
    loaded_rollers: np.ndarray    # (n, 2)
    max_roller_load_N: np.ndarray # (n, 2) largest Q_o per row
