"""Linear coefficient bearing: constant or speed-interpolated 2x2 K and C."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class LinearBearing:
    """f = -(K q + C q') at the node; K, C interpolated linearly in speed, held outside the table."""

    name: str
    node: int
    speeds_rad_s: np.ndarray  # shape (n,), n >= 1
    K_N_m: np.ndarray  # (n, 2, 2)
    C_Ns_m: np.ndarray  # (n, 2, 2)

    def linearized(self, speed_rad_s: float, static_load_N=None) -> tuple[np.ndarray, np.ndarray]:
        if len(self.speeds_rad_s) == 1:
            return self.K_N_m[0], self.C_Ns_m[0]
        s = self.speeds_rad_s
        K = np.empty((2, 2))
        C = np.empty((2, 2))
        for i in range(2):
            for j in range(2):
                K[i, j] = np.interp(speed_rad_s, s, self.K_N_m[:, i, j])
                C[i, j] = np.interp(speed_rad_s, s, self.C_Ns_m[:, i, j])
        return K, C

    def force(self, displacement_m, velocity_m_s, t_s: float = 0.0, speed_rad_s: float = 0.0):
        K, C = self.linearized(speed_rad_s)
        return -(K @ np.asarray(displacement_m) + C @ np.asarray(velocity_m_s))
