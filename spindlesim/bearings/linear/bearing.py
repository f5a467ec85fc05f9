"""Linear coefficient bearing: constant or speed-interpolated 2x2 K and C (f = -(K q + C q'))."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..base import RADIAL, BearingBase, CompiledForce

#: kernel number of this family in ``bearings.compiled``
KIND = 1


@dataclass(frozen=True)
class LinearBearing(BearingBase):
    """K and C at the node's (x, y), linear in speed between table rows, held outside the table."""

    name: str
    node: int
    speeds_rad_s: np.ndarray  # shape (n,), n >= 1
    K_N_m: np.ndarray  # (n, 2, 2)
    C_Ns_m: np.ndarray  # (n, 2, 2)
    dof_names: tuple[str, ...] = RADIAL
    iterative = False  # the contract: a linear reaction, nothing to solve at an operating point

    @property
    def speed_independent(self) -> bool:
        """The contract's: one row of coefficients holds at every speed."""
        return len(self.speeds_rad_s) == 1

    def coefficients(self, speed: float) -> tuple[np.ndarray, np.ndarray]:
        if len(self.speeds_rad_s) == 1:
            return self.K_N_m[0], self.C_Ns_m[0]
        s = self.speeds_rad_s
        K = np.array([[np.interp(speed, s, self.K_N_m[:, i, j]) for j in range(2)] for i in range(2)])
        C = np.array([[np.interp(speed, s, self.C_Ns_m[:, i, j]) for j in range(2)] for i in range(2)])
        return K, C

    def linearized(self, speed: float, static_load=None, start=None) -> tuple[np.ndarray, np.ndarray]:
        K, C = self.coefficients(speed)
        return K.copy(), C.copy()

    def force_and_tangent(self, q, v, t=0.0, speed=0.0, angle=None):
        K, C = self.coefficients(speed)
        return -(K @ np.asarray(q, float) + C @ np.asarray(v, float)), K.copy(), C.copy()

    def compiled(self) -> CompiledForce:
        """Table rows as floats: [n, speeds(n), K(n*4), C(n*4)]."""
        n = len(self.speeds_rad_s)
        floats = np.concatenate([[n], self.speeds_rad_s, np.ravel(self.K_N_m), np.ravel(self.C_Ns_m)])
        return CompiledForce(KIND, floats.astype(float), np.zeros(0, np.int64))
