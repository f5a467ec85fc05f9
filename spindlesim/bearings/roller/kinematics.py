"""Cage and roller kinematics of a rolling bearing (seed 000, eqs. 1-4).

Seed 000 writes the no-slip rolling conditions at the inner and outer raceway
with slip ratios zeta_i, zeta_o:

    (1 - zeta_i) D_ri/2 (theta_s - theta_o) = D_ba/2 theta_ba      (eq. 1)
    (1 - zeta_o) D_ro/2 theta_o            = D_ba/2 theta_ba      (eq. 2)

so that the cage angle and the roller spin angle follow the shaft angle:

    theta_o  = (1-zeta_i) D_ri / ((1-zeta_i) D_ri + (1-zeta_o) D_ro) theta_s          (eq. 3)
    theta_ba = D_ro/D_ba (1-zeta_i)(1-zeta_o) D_ri / ((1-zeta_i) D_ri + (1-zeta_o) D_ro) theta_s  (eq. 4)

With no slip eq. 3 is the textbook cage ratio (1 - D/d_m)/2 for a zero
contact angle (Harris, Rolling Bearing Analysis, 4th ed., ch. 7) because
D_ri = d_m - D and D_ro = d_m + D.  For seed 000's raceways (18.738 and
28.262 mm) the ratio is 18.738/47.000 = 0.39868: 33.22 Hz cage at 5000 rpm.
(Seed 000 rounds to 0.4 and quotes roller-pass 166.7/266.7/400 Hz.)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class CageKinematics:
    """Cage ratio and roller spin ratio of a bearing with a stationary outer race.

    Attributes are ratios to the shaft (inner race) angle, eqs. 3 and 4.
    """

    inner_raceway_diameter_m: float
    outer_raceway_diameter_m: float
    roller_diameter_m: float
    slip_inner: float = 0.0
    slip_outer: float = 0.0

    def __post_init__(self) -> None:
        if not (0.0 <= self.slip_inner < 1.0 and 0.0 <= self.slip_outer < 1.0):
            raise ValueError("slip ratios must lie in [0, 1)")
        if min(self.inner_raceway_diameter_m, self.outer_raceway_diameter_m, self.roller_diameter_m) <= 0:
            raise ValueError("diameters must be positive")

    @property
    def cage_ratio(self) -> float:
        """theta_o / theta_s, seed 000 eq. 3."""
        a = (1.0 - self.slip_inner) * self.inner_raceway_diameter_m
        b = (1.0 - self.slip_outer) * self.outer_raceway_diameter_m
        return a / (a + b)

    @property
    def spin_ratio(self) -> float:
        """theta_ba / theta_s (roller spin about its own axis), seed 000 eq. 4."""
        a = (1.0 - self.slip_inner) * self.inner_raceway_diameter_m
        b = (1.0 - self.slip_outer) * self.outer_raceway_diameter_m
        return self.outer_raceway_diameter_m / self.roller_diameter_m * (1.0 - self.slip_outer) * a / (a + b)

    def cage_frequency_hz(self, shaft_speed_rpm: float) -> float:
        """Cage rotation frequency [Hz] for a shaft speed [rpm]."""
        return self.cage_ratio * shaft_speed_rpm / 60.0

    def roller_pass_frequency_hz(self, shaft_speed_rpm: float, rollers: int) -> float:
        """Varying-compliance (roller-pass over the outer race) frequency N f_cage [Hz]."""
        return rollers * self.cage_frequency_hz(shaft_speed_rpm)

    def roller_angles(self, t_s: float | np.ndarray, shaft_speed_rad_s: float, rollers: int,
                      phase_rad: float = 0.0) -> np.ndarray:
        """Orbit angle of every roller, theta_j = phase + 2 pi j/N + ratio omega t.

        Returns shape (N,) for scalar t or (len(t), N) for an array of times.
        Angles are measured from +x towards +y (spindlesim frame).
        """
        base = phase_rad + 2.0 * np.pi * np.arange(rollers) / rollers
        wc = self.cage_ratio * shaft_speed_rad_s
        t = np.asarray(t_s, dtype=float)
        return base + wc * t[..., None] if t.ndim else base + wc * float(t)
